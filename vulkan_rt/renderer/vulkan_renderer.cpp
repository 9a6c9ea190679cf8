#include "vulkan_rt/renderer/vulkan_renderer.h"

#include "scene/features.h"
#include "util/error.h"
#include "vulkan_rt/compute_mode/compute_renderer.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/device/pipeline_report.h"
#include "vulkan_rt/pipeline_mode/pipeline_renderer.h"
#include "vulkan_rt/renderer/device_group.h"

#include <fmt/core.h>

#include <memory>

namespace tp {
namespace {

void check_validation(const VulkanInstance& instance) {
    if (instance.validation_messages() > 0)
        runtime_error("the Vulkan validation layer reported {} message(s) (printed above)",
                      instance.validation_messages());
}

// The device opened by the last render, kept for the next one with the same request. twinpath
// bench and the stress sweeps render dozens of times in one process; opening and closing an
// instance and a device for each render made vkCreateInstance fail with
// VK_ERROR_INCOMPATIBLE_DRIVER after about 30 renders on an H200 (driver 580.159.04).
// A render that failed closes it (the device may be lost).
std::unique_ptr<VulkanContext> open_device;
std::string open_request;

const VulkanContext& open_context(const VulkanOptions& vk) {
    const std::string request = vk.device + '\n' + vk_mode_request_name(vk.mode) + '\n' +
                                (vk.pipeline_statistics ? "statistics" : "");
    if (!open_device || open_request != request) {
        open_device.reset(); // one device at a time
        open_device = std::make_unique<VulkanContext>(vk.device, vk.mode, vk.pipeline_statistics);
        open_request = request;
        const std::string note = pipeline_statistics_note(*open_device);
        if (!note.empty()) fmt::print(stderr, "twinpath: note: {}\n", note);
    }
    return *open_device;
}

RenderResult render_on(const VulkanContext& ctx, const FlatScene& scene,
                       const RenderOptions& options, BvhLayout layout) {
    try {
        return ctx.mode() == VkMode::pipeline ? render_pipeline(ctx, scene, options)
                                              : render_compute(ctx, scene, options, layout);
    } catch (...) {
        open_device.reset();
        throw;
    }
}

} // namespace

std::string vk_backend_name(const VkBackend& b) {
    const std::string mode = vk_mode_name(b.mode);
    return b.mode == VkMode::compute && b.bvh != BvhLayout::binary
               ? mode + "-" + bvh_layout_name(b.bvh)
               : mode;
}

std::optional<VkBackend> parse_vk_backend(const std::string& word) {
    for (const VkBackend b : {VkBackend{VkMode::compute, BvhLayout::binary},
                              VkBackend{VkMode::compute, BvhLayout::wide},
                              VkBackend{VkMode::compute, BvhLayout::automatic},
                              VkBackend{VkMode::pipeline, BvhLayout::binary}})
        if (word == vk_backend_name(b)) return b;
    return std::nullopt;
}

VulkanOptions backend_vulkan_options(const VkBackend& backend, const std::string& device) {
    VulkanOptions vk;
    vk.device = device;
    vk.mode = backend.mode;
    vk.bvh = backend.bvh;
    return vk;
}

RenderResult render_vulkan(const FlatScene& scene, const RenderOptions& options,
                           const VulkanOptions& vk) {
    const bool several = selects_several(vk.device);
    if (several) open_device.reset(); // every device of the group opens its own
    RenderResult r = several ? render_on_devices(scene, options, vk)
                             : render_on(open_context(vk), scene, options, vk.bvh);
    r.stats.scene_features = analyze_features(scene).names();
    r.stats.feature_mask = render_feature_mask(scene, options.all_features);
    r.stats.feature_variant = options.all_features ? "all" : "scene";
    r.stats.extra["vk_mode_requested"] = vk_mode_request_name(vk.mode);
    if (several) return r;
    const VulkanContext& ctx = *open_device;
    r.stats.extra["driver"] = ctx.info().driver;
    r.stats.extra["validation"] = ctx.instance().validation_enabled() ? "on" : "off";
    r.stats.extra["validation_messages"] = std::to_string(ctx.instance().validation_messages());
    check_validation(ctx.instance());
    return r;
}

void close_vulkan_device() {
    open_device.reset();
}

std::vector<DeviceInfo> list_vulkan_devices() {
    const VulkanInstance instance;
    std::vector<DeviceInfo> devices = instance.devices();
    check_validation(instance);
    return devices;
}

} // namespace tp
