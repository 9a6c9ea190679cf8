#include "bench/backends.h"

#include "bench/host_info.h"
#include "cpu_ref/cpu_renderer.h"
#include "util/error.h"
#include "vulkan_rt/vulkan_renderer.h"

#include <fmt/format.h>

#include <algorithm>

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
        const std::string mode = r == "vulkan"                ? ""
                                 : r.rfind("vulkan:", 0) == 0 ? r.substr(7)
                                                              : "-";
        if (mode == "-" ||
            (!mode.empty() && mode != "compute" && mode != "compute-wide" && mode != "pipeline"))
            input_error("--backends: unknown backend '{}' (expected cpu, vulkan, vulkan:compute, "
                        "vulkan:compute-wide or vulkan:pipeline)",
                        r);
        DeviceInfo device;
        try {
            device = select_device(list_vulkan_devices(), device_selector);
        } catch (const RuntimeError& e) {
            skipped.push_back({r, e.what()});
            continue;
        }
        const std::string where = fmt::format("{} ({})", device.name, device.driver);
        const std::vector<std::string> modes = device.modes();
        // compute-wide (compute mode over the wide BVH) only when asked for by name.
        const std::string device_mode = mode == "compute-wide" ? "compute" : mode;
        for (const std::string& m : modes)
            if (mode.empty() || m == device_mode) add({"vulkan", mode.empty() ? m : mode, where});
        if (!mode.empty() && std::find(modes.begin(), modes.end(), device_mode) == modes.end())
            skipped.push_back({r, fmt::format("{} does not offer {} mode", device.name, mode)});
    }
    return out;
}

RenderResult render_on(const Backend& backend, const FlatScene& scene, const RenderOptions& options,
                       const std::string& device_selector, bool pipeline_statistics) {
    if (backend.name == "cpu") return render_cpu(scene, options);
    VulkanOptions vk = backend_vulkan_options(backend.mode, device_selector);
    vk.pipeline_statistics = pipeline_statistics;
    return render_vulkan(scene, options, vk);
}

} // namespace tp::bench
