// The backends and modes a benchmark runs: `cpu` (Embree), and `vulkan`, which stands for
// every mode the selected device offers (compute everywhere; pipeline where the device has
// the ray-tracing extensions), or one Vulkan backend as `vulkan:compute`, `vulkan:pipeline` or
// `vulkan:compute-wide` (vulkan_renderer.h, VkBackend).
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <string>
#include <vector>

namespace tp::bench {

struct Backend {
    std::string name;   // cpu, vulkan
    std::string mode;   // embree, or the Vulkan backend's word (vk_backend_name)
    std::string device; // what it runs on, in words (CPU model and threads, or GPU and driver)
    VkBackend vulkan{}; // the Vulkan backend that `mode` names
    std::string label() const { return name + "/" + mode; }
};

struct Skip {
    std::string what;
    std::string reason;
};

// Expands the --backends list. A backend that cannot run here (no Vulkan driver, a mode the
// device lacks) is left out and reported in `skipped`; an unknown name is an InputError.
std::vector<Backend> expand_backends(const std::vector<std::string>& requested,
                                     const std::string& device_selector, uint32_t cpu_threads,
                                     std::vector<Skip>& skipped);

// Renders on a backend (RenderOptions::threads applies to the CPU only;
// `pipeline_statistics` to Vulkan only: VulkanOptions::pipeline_statistics).
RenderResult render_on(const Backend& backend, const FlatScene& scene, const RenderOptions& options,
                       const std::string& device_selector, bool pipeline_statistics = false);

} // namespace tp::bench
