#include "bench/backends.h"

#include "bench/host_info.h"
#include "cpu_ref/cpu_renderer.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace tp::bench {
namespace {

std::string cpu_device(uint32_t threads) {
    const unsigned n = threads > 0 ? std::min<unsigned>(threads, cpu_cores()) : cpu_cores();
    return fmt::format("{} ({} thread{}, Embree + TBB)", cpu_model(), n, n == 1 ? "" : "s");
}

} // namespace

std::vector<Backend> expand_backends(const std::vector<std::string>& requested,
                                     const std::string& device_selector, uint32_t cpu_threads,
                                     std::vector<Skip>& skipped) {
    std::vector<Backend> out;
    const auto add = [&](const Backend& b) {
        for (const Backend& o : out)
            if (o.label() == b.label()) return;
        out.push_back(b);
    };
    for (const std::string& r : requested) {
        if (r == "cpu") {
            add({"cpu", "embree", cpu_device(cpu_threads)});
            continue;
        }
        const std::optional<VkBackend> one =
            r.rfind("vulkan:", 0) == 0 ? parse_vk_backend(r.substr(7)) : std::nullopt;
        if (r != "vulkan" && !one)
            input_error("--backends: unknown backend '{}' (expected cpu, vulkan, vulkan:compute, "
                        "vulkan:compute-wide, vulkan:compute-auto or vulkan:pipeline)",
                        r);
        DeviceInfo device;
        try {
            device = select_device(list_vulkan_devices(), device_selector);
        } catch (const RuntimeError& e) {
            skipped.push_back({r, e.what()});
            continue;
        }
        const std::string where = fmt::format("{} ({})", device.name, device.driver);
        const std::vector<VkMode> modes = device.modes();
        const auto add_vulkan = [&](const VkBackend& b) {
            add({"vulkan", vk_backend_name(b), where, b});
        };
        if (!one) {
            // compute-wide and compute-auto (compute mode's other BVH layouts) only when asked for
            // by name.
            for (const VkMode m : modes) add_vulkan({m, BvhLayout::binary});
        } else if (std::find(modes.begin(), modes.end(), one->mode) != modes.end()) {
            add_vulkan(*one);
        } else {
            skipped.push_back(
                {r, fmt::format("{} does not offer {} mode", device.name, vk_backend_name(*one))});
        }
    }
    return out;
}

RenderResult render_on(const Backend& backend, const FlatScene& scene, const RenderOptions& options,
                       const std::string& device_selector, bool pipeline_statistics) {
    if (backend.name == "cpu") return render_cpu(scene, options);
    VulkanOptions vk = backend_vulkan_options(backend.vulkan, device_selector);
    vk.pipeline_statistics = pipeline_statistics;
    return render_vulkan(scene, options, vk);
}

} // namespace tp::bench
