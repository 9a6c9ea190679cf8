#include "view/cpu_jobs.h"

#include "compare/compare.h"
#include "compare/pathdiff.h"
#include "compare/rgb_image.h"
#include "compare/significance_map.h"
#include "cpu_ref/cpu_renderer.h"
#include "render/render_header.h"

#include <fmt/core.h>

#include <chrono>
#include <sstream>

namespace tp {
namespace {

// The live compare's CPU seed: any other seed gives independent random numbers
// (shared/rng.h hashes the seed with pixel, sample and dimension).
constexpr uint32_t kIndependentSeed = 0x9e3779b9u;

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    return lines;
}

} // namespace

std::optional<CpuJobOutcome> CpuJob::poll() {
    if (!result_.valid() || result_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return std::nullopt;
    try {
        return result_.get();
    } catch (const std::exception& e) {
        return CpuJobOutcome{{fmt::format("failed: {}", e.what())}, {}};
    }
}

std::unique_ptr<CpuJob> CpuJob::live_compare(FlatScene scene, RenderResult gpu, uint32_t seed,
                                             uint32_t sampler, uint32_t threads) {
    auto job = std::make_unique<CpuJob>();
    std::atomic<double>* progress = &job->progress_;
    job->result_ = std::async(
        std::launch::async, [=, scene = std::move(scene), gpu = std::move(gpu)]() mutable {
            scene.spp = std::max(1u, gpu.stats.spp);
            RenderOptions opt;
            opt.seed = seed ^ kIndependentSeed;
            opt.sampler = sampler;
            opt.threads = threads;
            opt.progress = [progress](double f) { progress->store(f); };
            RenderResult cpu = render_cpu(scene, opt);
            RenderOptions gpu_opt;
            gpu_opt.sampler = sampler;
            const RgbImage a = rgb_image_from_exr(render_exr(gpu, scene, gpu_opt), "window");
            const RgbImage b = rgb_image_from_exr(render_exr(cpu, scene, opt), "CPU reference");
            const CompareResult r = compare_images(a, b, CompareOptions{});
            CpuJobOutcome out;
            out.lines.push_back(fmt::format("compare, {} spp each: {} (p = {:.3g}, alpha {})",
                                            scene.spp, r.different ? "DIFFERENT" : "consistent",
                                            r.p_value, r.alpha));
            out.lines.push_back(fmt::format("significant pixels: {} of {}; Esc leaves the map",
                                            r.local.significant_pixels, a.pixels()));
            out.picture_rgb = significance_map(r);
            return out;
        });
    return job;
}

std::unique_ptr<CpuJob> CpuJob::pathdiff(FlatScene scene, uint32_t x, uint32_t y, uint32_t seed,
                                         uint32_t sampler, uint32_t threads, VulkanOptions vk,
                                         std::string scene_path, std::string log_prefix) {
    auto job = std::make_unique<CpuJob>();
    job->result_ = std::async(std::launch::async, [=, scene = std::move(scene)]() mutable {
        scene.spp = 1;
        RenderOptions opt;
        opt.seed = seed;
        opt.sampler = sampler;
        opt.threads = threads;
        opt.debug.log = true;
        opt.debug.pixel_x = x;
        opt.debug.pixel_y = y;
        opt.debug.sample = 0;
        RenderResult gpu = render_vulkan(scene, opt, vk);
        close_vulkan_device();
        RenderResult cpu = render_cpu(scene, opt);
        const std::string gpu_log = log_prefix + "_gpu.json", cpu_log = log_prefix + "_cpu.json";
        write_path_log(gpu_log, path_log_info(gpu, scene, scene_path, opt.debug),
                       gpu.debug.records);
        write_path_log(cpu_log, path_log_info(cpu, scene, scene_path, opt.debug),
                       cpu.debug.records);
        const PathDiffResult r = tp::pathdiff(gpu_log, read_path_log(gpu_log), cpu_log,
                                              read_path_log(cpu_log), PathDiffTolerances{});
        CpuJobOutcome out;
        out.lines.push_back(fmt::format("pixel {},{} sample 0: {}", x, y,
                                        r.diverged ? "the engines DIVERGE" : "same paths"));
        for (const std::string& l : split_lines(r.report)) out.lines.push_back(l);
        return out;
    });
    return job;
}

} // namespace tp
