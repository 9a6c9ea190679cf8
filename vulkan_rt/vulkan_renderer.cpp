#include "vulkan_rt/vulkan_renderer.h"

#include "util/error.h"
#include "vulkan_rt/compute_renderer.h"
#include "vulkan_rt/context.h"

namespace tp {
namespace {

void check_validation(const VulkanInstance& instance) {
    if (instance.validation_messages() > 0)
        runtime_error("the Vulkan validation layer reported {} message(s) (printed above)",
                      instance.validation_messages());
}

} // namespace

std::string resolve_vk_mode(const std::string& requested, const DeviceInfo&) {
    if (requested == "auto" || requested == "compute") return "compute";
    if (requested == "pipeline")
        input_error("--vk-mode pipeline: the ray-tracing pipeline mode is not part of this build "
                    "yet; use --vk-mode compute");
    input_error("--vk-mode {}: expected auto, compute or pipeline", requested);
}

RenderResult render_vulkan(const FlatScene& scene, const RenderOptions& options,
                           const VulkanOptions& vk) {
    const VulkanContext ctx(vk.device);
    resolve_vk_mode(vk.mode, ctx.info());
    RenderResult r = render_compute(ctx, scene, options);
    r.stats.extra["vk_mode_requested"] = vk.mode;
    r.stats.extra["driver"] = ctx.info().driver;
    r.stats.extra["validation"] = ctx.instance().validation_enabled() ? "on" : "off";
    r.stats.extra["validation_messages"] = std::to_string(ctx.instance().validation_messages());
    check_validation(ctx.instance());
    return r;
}

std::vector<DeviceInfo> list_vulkan_devices() {
    const VulkanInstance instance;
    std::vector<DeviceInfo> devices = instance.devices();
    check_validation(instance);
    return devices;
}

} // namespace tp
