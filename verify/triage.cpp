#include "verify/triage.h"

#include "compare/significance_map.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tp {
namespace {

// A log render's film and image are not needed once its log is read: only its command and log
// stay (for the report).
EngineRun log_only(EngineRun run) {
    run.result = RenderResult{};
    run.image = ExrImage{};
    return run;
}

} // namespace

std::vector<PixelPick> pick_pixels(const CompareResult& r, const ExactResult& aov) {
    const int w = r.diff.width, h = r.diff.height;
    std::vector<PixelPick> picks;
    auto taken = [&](uint32_t x, uint32_t y) {
        return std::any_of(picks.begin(), picks.end(),
                           [&](const PixelPick& p) { return p.x == x && p.y == y; });
    };
    auto z_at = [&](size_t i) {
        return signed_max(r.local.z[0][i], r.local.z[1][i], r.local.z[2][i]);
    };
    if (!aov.identical() && !aov.mismatch_examples.empty()) {
        const auto [x, y] = aov.mismatch_examples.front();
        picks.push_back(
            {uint32_t(x), uint32_t(y), z_at(size_t(y) * size_t(w) + size_t(x)), "AOVs differ"});
    }
    std::vector<size_t> order(size_t(w) * size_t(h));
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t i, size_t j) { return std::fabs(z_at(i)) > std::fabs(z_at(j)); });
    for (size_t i : order) {
        if (picks.size() >= kTriagePixels) break;
        const uint32_t x = uint32_t(i % size_t(w)), y = uint32_t(i / size_t(w));
        if (!taken(x, y)) picks.push_back({x, y, z_at(i), "most significant"});
    }
    return picks;
}

Triage triage(Engine& a, Engine& b, const CompareResult& r, uint32_t seed, uint32_t max_depth) {
    Triage t;
    EngineRequest aov;
    aov.spp = 1;
    aov.seed = seed;
    aov.debug.aov = true;
    t.aov_a = a.render(aov);
    t.aov_b = b.render(aov);
    t.aov =
        exact_compare(a.label() + " AOVs", t.aov_a.image, b.label() + " AOVs", t.aov_b.image, 0.0);
    // A log holds at most 2^16 records on the GPU (docs/debugging.md, "GPU side").
    const uint32_t samples = std::clamp<uint32_t>(
        (1u << 16) / path_log_records_per_sample(max_depth), 1u, kTriageSamples);
    for (const PixelPick& p : pick_pixels(r, t.aov)) {
        EngineRequest log;
        log.spp = samples;
        log.seed = seed;
        log.debug.log = true;
        log.debug.pixel_x = p.x;
        log.debug.pixel_y = p.y;
        PixelPaths pp;
        pp.pixel = p;
        pp.samples = samples;
        pp.run_a = log_only(a.render(log));
        pp.run_b = log_only(b.render(log));
        pp.diff = pathdiff(a.label(), pp.run_a.path_log, b.label(), pp.run_b.path_log,
                           PathDiffTolerances{});
        t.paths.push_back(std::move(pp));
        // No pixel can diverge before the camera ray's vertex: the rest would add nothing.
        if (t.paths.back().diff.diverged && t.paths.back().diff.vertex == 0) break;
    }
    for (size_t i = 0; i < t.paths.size(); ++i)
        if (t.paths[i].diff.diverged &&
            (!t.first || t.paths[i].diff.vertex < t.paths[*t.first].diff.vertex))
            t.first = i;
    return t;
}

} // namespace tp
