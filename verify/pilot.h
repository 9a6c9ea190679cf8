// What the pilot renders tell the plan (docs/debugging.md, "verify"): the noise of one sample in
// every pixel, with the channels' correlation, and what a sample costs on each engine.
#pragma once

#include "compare/power.h"
#include "compare/rgb_image.h"
#include "verify/engine.h"

#include <array>
#include <vector>

namespace tp {

struct NoiseEstimate {
    int width = 0, height = 0;
    Planes mean;                         // per pixel-channel, over every pilot's samples
    Planes sample_variance;              // the variance of one sample, pooled over the pilots
    std::array<double, 3> correlation{}; // RG, RB, GB of the tile test between the first two
    // The first two pilots' own estimates and degrees of freedom (compare/power.h,
    // VarianceSplit), from which the error of the pooled one follows.
    std::array<Planes, 2> pilot_variance;
    std::array<double, 2> pilot_dof{};
};

// The one-sided confidence the plan takes the noise with: the signal of compare's power model
// at its lower 97.5 % bound (z = 1.96). The pilots' estimate errs both ways, and on average
// towards less noise (a sample variance of heavy-tailed samples is skewed: most pilots miss
// some of the rare large samples), which made plans from the estimate itself fall short of
// their power (docs/learnt.md, "verify's plan from the pilots' noise as it is").
constexpr double kNoiseConfidenceZ = 1.96;

// Under H0 every engine estimates the same mean with the same per-sample variance sigma^2, so
// the pilots' estimates pool: the means weighted by their samples, the sample variances by
// their degrees of freedom (n - 1), which leaves any difference between the engines' means out
// of sigma^2. An image's per-sample variance is its sample_variance channel where it has one
// (a batch-estimated image, whose n var understates sigma^2: docs/sampling.md), else n var.
// The channels' correlation is the one compare estimates for its tile test from the first two
// pilots, which are independent (seeds.h).
NoiseEstimate estimate_noise(const std::vector<RgbImage>& pilots);

// compare's power model (compare/power.h) of this noise at compare's default tile size, at the
// lower confidence bound of its signal (kNoiseConfidenceZ) when there are two pilots.
PowerModel noise_power_model(const NoiseEstimate& noise);

// What an engine's samples cost, from its pilot (plan.h).
struct EngineCost {
    double setup_s = 0;         // before its first sample
    double seconds_per_spp = 0; // one sample of every pixel
    uint32_t kept_spp = 0;      // samples its image has already (the window's)
    int lane = 0;
};

EngineCost engine_cost(const EngineRun& pilot, int lane);

} // namespace tp
