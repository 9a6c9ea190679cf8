#include "verify/render_engines.h"

#include "cpu_ref/cpu_renderer.h"
#include "render/render_header.h"
#include "render/sampler.h"
#include "util/clock.h"
#include "util/error.h"
#include "vulkan_rt/device/device_info.h"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <mutex>

namespace tp {
namespace {

// Renders `scene` at the request's spp and seed through `render` (render_cpu or render_vulkan),
// timing the set-up (up to the first pass) apart from the sampling, and the `render` flags that
// give the same image.
template <typename Render>
EngineRun timed_render(FlatScene& scene, const EngineSetup& setup, const EngineRequest& rq,
                       std::vector<std::string> backend_args, Render&& render) {
    scene.spp = rq.spp;
    RenderOptions opt;
    opt.seed = rq.seed;
    opt.sampler = setup.sampler;
    opt.threads = setup.threads;
    opt.debug = rq.debug;
    opt.stop = rq.stop;
    opt.progress = rq.progress;
    const auto t0 = std::chrono::steady_clock::now();
    std::mutex first_mutex;
    std::optional<double> first_pass; // several devices each call on_first_pass
    opt.on_first_pass = [&] {
        const std::lock_guard<std::mutex> lock(first_mutex);
        if (!first_pass) first_pass = seconds_since(t0);
    };
    EngineRun run;
    run.result = render(scene, opt);
    const double total = seconds_since(t0);
    run.setup_s = first_pass.value_or(total);
    run.sampling_s = total - run.setup_s;
    run.result.stats.scene = setup.scene_path;
    run.image = render_exr(run.result, scene, opt);
    run.device = run.result.stats.device;
    if (rq.debug.log)
        run.path_log = path_log_json(path_log_info(run.result, scene, setup.scene_path, rq.debug),
                                     run.result.debug.records);
    run.command = setup.scene_args;
    for (const std::string& a : backend_args) run.command.push_back(a);
    for (const std::string& a :
         {std::string("--sampler"), std::string(sampler_name(opt.sampler)), std::string("--spp"),
          std::to_string(rq.spp), std::string("--seed"), std::to_string(rq.seed)})
        run.command.push_back(a);
    if (rq.debug.aov) {
        run.command.push_back("--aov");
        run.command.push_back("all");
    }
    if (rq.debug.log) {
        run.command.push_back("--debug-pixel");
        run.command.push_back(fmt::format("{},{}", rq.debug.pixel_x, rq.debug.pixel_y));
        if (rq.debug.sample) {
            run.command.push_back("--debug-sample");
            run.command.push_back(std::to_string(*rq.debug.sample));
        }
    }
    return run;
}

} // namespace

EngineRun CpuEngine::render(const EngineRequest& request) {
    return timed_render(
        scene_, setup_, request, {},
        [](const FlatScene& s, const RenderOptions& o) { return render_cpu(s, o); });
}

std::string VulkanEngine::label() const {
    return std::string("vulkan ") + vk_mode_name(vk_.mode.value_or(VkMode::compute));
}

EngineRun VulkanEngine::render(const EngineRequest& request) {
    std::vector<std::string> args = {"--backend", "vulkan", "--vk-mode",
                                     vk_mode_name(vk_.mode.value_or(VkMode::compute))};
    if (!vk_.device.empty()) {
        args.push_back("--device");
        args.push_back(vk_.device);
    }
    if (vk_.bvh != VulkanOptions{}.bvh) {
        args.push_back("--bvh");
        args.push_back(bvh_layout_name(vk_.bvh));
    }
    EngineRun run = timed_render(
        scene_, setup_, request, args,
        [&](const FlatScene& s, const RenderOptions& o) { return render_vulkan(s, o, vk_); });
    // The test hook that replaces the shader (docs/debugging.md, "Planted bugs and the test
    // hook") changes the image: the commands must set it too.
    if (const char* spirv = std::getenv("TWINPATH_DEBUG_SPIRV"); spirv && *spirv)
        run.environment.push_back(std::string("TWINPATH_DEBUG_SPIRV=") + spirv);
    return run;
}

std::vector<VkMode> vulkan_engine_modes(const std::string& word, const std::string& device) {
    if (word != "auto" && word != "compute" && word != "pipeline" && word != "both")
        input_error("--vk-mode {}: expected auto, compute, pipeline or both", word);
    const std::vector<DeviceInfo> devices = list_vulkan_devices();
    const std::vector<DeviceInfo> chosen =
        selects_several(device) ? select_devices(devices, device)
                                : std::vector<DeviceInfo>{select_device(devices, device)};
    if (word == "both")
        return {resolve_common_mode(VkMode::compute, chosen),
                resolve_common_mode(VkMode::pipeline, chosen)};
    return {resolve_common_mode(parse_vk_mode_request(word), chosen)};
}

std::vector<std::unique_ptr<Engine>>
make_engines(const EngineSetup& setup, const std::vector<VkMode>& modes, const VulkanOptions& vk) {
    std::vector<std::unique_ptr<Engine>> engines;
    engines.push_back(std::make_unique<CpuEngine>(setup));
    for (VkMode m : modes) {
        VulkanOptions o = vk;
        o.mode = m;
        engines.push_back(std::make_unique<VulkanEngine>(setup, o));
    }
    return engines;
}

} // namespace tp
