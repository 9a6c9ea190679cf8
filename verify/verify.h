// `twinpath verify` (docs/debugging.md, "verify"): from a scene to a verdict, and from
// "different" to the diverging field. For engines e_0, e_1, ... (the command line: the CPU
// reference, then the GPU's modes):
//
//   1. pilots: a short render on every engine at once, each with its own seed (seeds.h), which
//      measures the noise of one sample per pixel and what a sample costs (pilot.h);
//   2. plan: the spp of every engine for the least wall time at which compare finds a uniform
//      relative bias of `detect` between every pair with probability `power` (plan.h), within the
//      budget if one is given;
//   3. images: every engine at once, independent seeds;
//   4. compare: every pair at alpha / pairs, so that the whole has false-alarm probability
//      at most alpha;
//   5. triage, for every pair found different (triage.h).
//
// The command line (cli/cmd_verify.cpp) and the viewer's C key (view/) both run this.
#pragma once

#include "compare/compare.h"
#include "compare/power.h"
#include "compare/rgb_image.h"
#include "verify/engine.h"
#include "verify/pilot.h"
#include "verify/plan.h"
#include "verify/seeds.h"
#include "verify/triage.h"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tp {

// The pilot's samples per pixel: 16 give every pixel's per-sample variance 15 degrees of freedom
// from each engine (pooled, 30 for two), and each tile's sum over 64 pixels ~2000, which is what
// the plan reads.
constexpr uint32_t kPilotSpp = 16;

struct VerifyOptions {
    PlanRequest plan; // --detect, --time-budget (for pilots and images together), --spp, --alpha
    uint32_t seed = 0;
    uint32_t pilot_spp = kPilotSpp;
    bool triage = true;
    uint32_t max_depth = 0; // the scene's (triage: the path logs' size)
    // When set by the caller (the viewer, when its view moves), every render ends after its pass
    // in flight and verify throws RuntimeError; null: verify's own flag.
    std::atomic<bool>* stop = nullptr;
};

struct VerifyObserver {
    // A finished step, one line of text (the pilots, the plan, the images, each verdict, the
    // triage); may be empty.
    std::function<void(const std::string& line)> line;
    // While renders run: the phase ("pilots", "images") and each engine's fraction done.
    std::function<void(const std::string& phase, const std::vector<double>& fractions)> progress;
};

struct PairVerdict {
    size_t a = 0, b = 0; // engines
    CompareResult compare;
    // At the spp rendered: the model's power against `detect`, and the least bias found with
    // `power` (compare/power.h).
    double power = 0, detectable = 0;
    std::optional<Triage> triage;
};

struct VerifyResult {
    std::vector<std::string> labels; // per engine
    VerifySeeds seeds;
    std::vector<std::pair<size_t, size_t>> pairs;
    double alpha = 0;
    std::vector<EngineRun> pilots;
    std::vector<EngineCost> costs;
    PowerModel model;
    PlanRequest request;
    Plan plan;
    std::vector<EngineRun> images;
    std::vector<RgbImage> rgb; // the images as compare reads them
    std::vector<PairVerdict> verdicts;
    double pilot_wall_s = 0, image_wall_s = 0, triage_wall_s = 0;

    bool different() const;
};

// `engines`: at least two; the first one's image seed is also the path logs' (seeds.h), and it
// is A in every comparison it is part of. Throws InputError, RuntimeError (a device failure, or
// `stop` set by the caller) like a render.
VerifyResult verify(const std::vector<Engine*>& engines, const VerifyOptions& options,
                    const VerifyObserver& observer);

} // namespace tp
