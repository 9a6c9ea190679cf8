// The Vulkan backend's entry points for the command line: render a scene, list the devices.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/device/device_info.h"
#include "vulkan_rt/device/vk_mode.h"

#include <optional>

#include <string>
#include <vector>

namespace tp {

struct VulkanOptions {
    // --device: index or name substring; empty: the best device; "all" or a comma-separated
    // list: several devices at once (device_group.h).
    std::string device;
    VkModeRequest mode; // --vk-mode; none: auto (resolve_vk_mode)
    // --bvh: compute mode's BVH layout (compute_mode/bvh_builder.h). The default, auto, keeps
    // the binary tree unless its expected traversal is long (docs/gpu.md, "Why --bvh defaults
    // to auto").
    BvhLayout bvh = BvhLayout::automatic;
    // --pipeline-stats: the driver's statistics of the render pipeline in RenderStats::pipeline
    // (pipeline_report.h); on a device without them a note on stderr, once per device opened.
    bool pipeline_statistics = false;
};

// A Vulkan backend as `twinpath bench --backends vulkan:WORD` and the stress suite name it: a mode
// and compute mode's BVH layout.
struct VkBackend {
    VkMode mode = VkMode::compute;
    BvhLayout bvh = BvhLayout::binary;
};
// Its word: compute, pipeline, compute-wide (compute mode over the compressed 8-wide BVH,
// `render --vk-mode compute --bvh wide`) or compute-auto (`--bvh auto`: the layout chosen per
// scene, bvh_estimate.h).
std::string vk_backend_name(const VkBackend& backend);
// The backend a word names; nullopt for any other word.
std::optional<VkBackend> parse_vk_backend(const std::string& word);
// The options that render on it.
VulkanOptions backend_vulkan_options(const VkBackend& backend, const std::string& device);

// Renders on the selected device in the mode the request resolves to there (RenderStats::mode
// says which ran). Throws RuntimeError (exit code 3) for Vulkan failures, for pipeline mode on a
// device without it, and when the validation layer reported anything (validation.h). The device
// stays open for the next render with the same device and mode in this process.
RenderResult render_vulkan(const FlatScene& scene, const RenderOptions& options,
                           const VulkanOptions& vk);

// Closes the device that render_vulkan keeps open. Call it before the process exits: the NVIDIA
// driver registers exit-time destructors while it works (its shader compiler is loaded at the
// first pipeline), and a device destroyed after them crashes at exit (H200, driver 580.159.04).
void close_vulkan_device();

// Every device the Vulkan loader reports; RuntimeError when there is no usable loader/driver.
std::vector<DeviceInfo> list_vulkan_devices();

} // namespace tp
