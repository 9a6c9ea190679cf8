#include "view/cpu_jobs.h"

#include "compare/pathdiff.h"
#include "compare/significance_map.h"
#include "cpu_ref/cpu_renderer.h"
#include "render/render_header.h"
#include "verify/render_engines.h"
#include "verify/summary.h"
#include "verify/verify.h"

#include <fmt/core.h>

#include <chrono>
#include <sstream>

namespace tp {
namespace {

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

std::string CpuJob::activity() const {
    const std::lock_guard<std::mutex> lock(activity_mutex_);
    return activity_;
}

std::unique_ptr<CpuJob> CpuJob::live_compare(FlatScene scene, std::shared_ptr<WindowEngine> window,
                                             uint32_t seed, uint32_t sampler, uint32_t threads,
                                             PlanRequest plan, std::atomic<bool>* stop) {
    auto job = std::make_unique<CpuJob>();
    CpuJob* self = job.get();
    job->result_ = std::async(std::launch::async, [=, scene = std::move(scene)]() {
        EngineSetup setup;
        setup.scene = &scene;
        setup.scene_path = scene.name;
        setup.sampler = sampler;
        setup.threads = threads;
        CpuEngine cpu(setup);
        VerifyOptions o;
        o.plan = plan;
        o.seed = seed;
        o.triage = false;
        o.stop = stop;
        VerifyObserver observer;
        observer.progress = [self](const std::string& phase, const std::vector<double>& f) {
            const std::lock_guard<std::mutex> lock(self->activity_mutex_);
            self->activity_ = fmt::format("verify, {}: window {:.0f}%, CPU reference {:.0f}%",
                                          phase, 100.0 * f[0], 100.0 * f[1]);
        };
        // The window first: compare's A, so that the map is red where the window is brighter.
        const VerifyResult v = verify({window.get(), &cpu}, o, observer);
        const PairVerdict& pv = v.verdicts.front();
        CpuJobOutcome out;
        out.lines.push_back(
            fmt::format("compare, window {} spp against CPU {} spp: {} (p = {:.3g}, "
                        "alpha {})",
                        v.rgb[0].spp.value_or(0), v.rgb[1].spp.value_or(0),
                        pv.compare.different ? "DIFFERENT" : "consistent", pv.compare.p_value,
                        pv.compare.alpha));
        out.lines.push_back(fmt::format("a uniform bias of {} is found with probability {:.2g} at "
                                        "these spp; significant pixels: {} of {}; Esc leaves the "
                                        "map",
                                        percent(pv.detectable), v.request.power,
                                        pv.compare.local.significant_pixels, v.rgb[0].pixels()));
        out.picture_rgb = significance_map(pv.compare);
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
