#include "verify/pilot.h"

#include "compare/compare.h"

#include <algorithm>

namespace tp {

NoiseEstimate estimate_noise(const std::vector<RgbImage>& pilots) {
    NoiseEstimate e;
    e.width = pilots.front().width;
    e.height = pilots.front().height;
    const size_t n = pilots.front().pixels();
    for (size_t c = 0; c < 3; ++c) {
        std::vector<double> sum_mean(n, 0.0), sum_var(n, 0.0);
        double samples = 0, dof = 0;
        for (size_t k = 0; k < pilots.size(); ++k) {
            const RgbImage& p = pilots[k];
            const double spp = double(p.spp.value_or(1)), d = std::max(spp - 1.0, 0.0);
            samples += spp;
            dof += d;
            if (k < 2) {
                e.pilot_variance[k][c].resize(n);
                e.pilot_dof[k] = d;
            }
            for (size_t i = 0; i < n; ++i) {
                sum_mean[i] += spp * p.mean[c][i];
                const double s2 = p.has_sample_variance() ? p.sample_var[c][i]
                                  : p.has_variance()      ? p.var[c][i] * spp
                                                          : 0.0;
                sum_var[i] += d * s2;
                if (k < 2) e.pilot_variance[k][c][i] = s2;
            }
        }
        e.mean[c].resize(n);
        e.sample_variance[c].resize(n);
        for (size_t i = 0; i < n; ++i) {
            e.mean[c][i] = sum_mean[i] / samples;
            e.sample_variance[c][i] = dof > 0 ? sum_var[i] / dof : 0.0;
        }
    }
    if (pilots.size() >= 2 && pilots[0].has_variance() && pilots[1].has_variance())
        e.correlation = compare_images(pilots[0], pilots[1], CompareOptions{}).global.correlation;
    return e;
}

PowerModel noise_power_model(const NoiseEstimate& noise) {
    const bool two = noise.pilot_dof[0] > 0.0 && noise.pilot_dof[1] > 0.0;
    const VarianceSplit split{&noise.pilot_variance[0], &noise.pilot_variance[1],
                              noise.pilot_dof[0], noise.pilot_dof[1]};
    return power_model(noise.width, noise.height, noise.mean, noise.sample_variance,
                       noise.correlation, kDefaultTile, two ? &split : nullptr)
        .lower_bound(kNoiseConfidenceZ);
}

EngineCost engine_cost(const EngineRun& pilot, int lane) {
    EngineCost c;
    c.lane = lane;
    c.kept_spp = pilot.kept_spp;
    // An engine that keeps its pilot (the window) is already set up.
    c.setup_s = pilot.kept_spp ? 0.0 : pilot.setup_s;
    const uint32_t spp = std::max(1u, pilot.result.stats.spp);
    c.seconds_per_spp = pilot.sampling_s / double(spp);
    return c;
}

} // namespace tp
