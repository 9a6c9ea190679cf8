// The Vulkan backend's entry points for the command line: render a scene, list the devices.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "vulkan_rt/device_info.h"

#include <string>
#include <vector>

namespace tp {

struct VulkanOptions {
    std::string device;        // --device: index or name substring; empty: the best device
    std::string mode = "auto"; // --vk-mode: auto, compute or pipeline
};

// The mode that runs for a --vk-mode request on a device: "compute" for auto and compute;
// pipeline mode is not part of this build yet (InputError).
std::string resolve_vk_mode(const std::string& requested, const DeviceInfo& device);

// Renders on the selected device. Throws RuntimeError (exit code 3) for Vulkan failures and
// when the validation layer reported anything (validation.h).
RenderResult render_vulkan(const FlatScene& scene, const RenderOptions& options,
                           const VulkanOptions& vk);

// Every device the Vulkan loader reports; RuntimeError when there is no usable loader/driver.
std::vector<DeviceInfo> list_vulkan_devices();

} // namespace tp
