#include "bench/frame_loop.h"

#include "bench/result_json.h"
#include "util/clock.h"
#include "vulkan_rt/present/progressive_renderer.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <vector>

using nlohmann::json;

namespace tp::bench {
namespace {

// Frames before the timed ones: the first pays for growing the sample buffer and cold caches.
constexpr uint32_t kWarmFrames = 2;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

} // namespace

json run_frame_loop(const FlatScene& scene, const Backend& backend, const BenchOptions& o,
                    const std::function<void(double)>& progress) {
    const VulkanContext ctx(o.device, backend.vulkan.mode);
    json run = {{"backend", backend.name},
                {"mode", backend.mode},
                {"device", backend.device},
                {"width", scene.params.camera.width},
                {"height", scene.params.camera.height},
                {"points", json::array()}};
    const uint32_t frames = std::max<uint32_t>(o.frame_loop_frames, 1);
    for (size_t k = 0; k < o.frame_loop_spp.size(); ++k) {
        ProgressiveOptions po;
        po.seed = o.seed;
        po.bvh = backend.vulkan.bvh;
        po.samples_per_frame = o.frame_loop_spp[k];
        ProgressiveRenderer renderer(ctx, scene, po);
        renderer.set_display(false, 0.0f);
        for (uint32_t i = 0; i < kWarmFrames; ++i) renderer.frame();
        std::vector<double> wall;
        BatchSplit gpu;
        const uint64_t rays_before = renderer.rays();
        for (uint32_t i = 0; i < frames; ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            renderer.frame();
            wall.push_back(seconds_since(t0));
            const BatchSplit& s = renderer.frame_split();
            gpu.trace += s.trace;
            gpu.resolve += s.resolve;
            gpu.after += s.after;
        }
        const double total = std::accumulate(wall.begin(), wall.end(), 0.0);
        const double n = double(frames);
        const double gpu_total = gpu.trace + gpu.resolve + gpu.after;
        run["points"].push_back(
            {{"spp_per_frame", po.samples_per_frame},
             {"frames", frames},
             {"ms_mean", 1e3 * total / n},
             {"ms_median", 1e3 * median(wall)},
             {"gpu_ms", gpu_total > 0 ? json{{"trace", 1e3 * gpu.trace / n},
                                             {"resolve", 1e3 * gpu.resolve / n},
                                             {"display", 1e3 * gpu.after / n}}
                                      : json(nullptr)},
             {"host_ms", gpu_total > 0 ? json(1e3 * (total - gpu_total) / n) : json(nullptr)},
             {"mrays_s",
              number_or_null(total > 0 ? 1e-6 * double(renderer.rays() - rays_before) / total
                                       : 0.0)}});
        if (progress) progress(double(k + 1) / double(o.frame_loop_spp.size()));
    }
    return run;
}

} // namespace tp::bench
