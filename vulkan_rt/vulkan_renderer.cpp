#include "vulkan_rt/vulkan_renderer.h"

#include "scene/features.h"
#include "util/error.h"
#include "vulkan_rt/compute_renderer.h"
#include "vulkan_rt/context.h"
#include "vulkan_rt/pipeline_renderer.h"

namespace tp {
namespace {

void check_validation(const VulkanInstance& instance) {
    if (instance.validation_messages() > 0)
        runtime_error("the Vulkan validation layer reported {} message(s) (printed above)",
                      instance.validation_messages());
}

} // namespace

RenderResult render_vulkan(const FlatScene& scene, const RenderOptions& options,
                           const VulkanOptions& vk) {
    const VulkanContext ctx(vk.device, vk.mode);
    RenderResult r = ctx.mode() == "pipeline" ? render_pipeline(ctx, scene, options)
                                              : render_compute(ctx, scene, options);
    r.stats.scene_features = analyze_features(scene).names();
    r.stats.feature_mask = render_feature_mask(scene, options.all_features);
    r.stats.feature_variant = options.all_features ? "all" : "scene";
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
