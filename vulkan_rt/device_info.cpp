#include "vulkan_rt/device_info.h"

#include "shaders/interface.h"
#include "util/error.h"

#include <fmt/format.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cctype>

namespace tp {

std::vector<std::string> DeviceInfo::modes() const {
    std::vector<std::string> m;
    if (compute()) m.push_back("compute");
    if (pipeline) m.push_back("pipeline");
    return m;
}

std::string vk_version_string(uint32_t v) {
    return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(v), VK_API_VERSION_MINOR(v),
                       VK_API_VERSION_PATCH(v));
}

namespace {

bool has_extension(const DeviceCaps& caps, const char* name) {
    return std::find(caps.extensions.begin(), caps.extensions.end(), name) != caps.extensions.end();
}

int type_rank(const std::string& type) {
    static const char* order[] = {"discrete", "integrated", "virtual", "cpu"};
    for (int i = 0; i < 4; ++i)
        if (type == order[i]) return i;
    return 4;
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string device_list(const std::vector<DeviceInfo>& devices) {
    std::string s;
    for (const DeviceInfo& d : devices)
        s += fmt::format("{}{}: {} ({})", s.empty() ? "" : ", ", d.index, d.name, d.type);
    return s;
}

const DeviceInfo& require_compute(const DeviceInfo& d) {
    if (!d.compute())
        runtime_error("Vulkan device {} ({}) cannot run compute mode: it lacks {}", d.index, d.name,
                      d.compute_missing);
    return d;
}

} // namespace

std::string compute_mode_missing(const DeviceCaps& caps) {
    std::vector<std::string> missing;
    if (caps.api_version < VK_API_VERSION_1_2) missing.push_back("Vulkan 1.2");
    if (!caps.compute_queue) missing.push_back("a compute queue");
    if (!caps.float64) missing.push_back("shaderFloat64");
    if (!caps.scalar_layout) missing.push_back("scalarBlockLayout");
    if (!caps.subgroup_arithmetic) missing.push_back("subgroup arithmetic in compute shaders");
    if (caps.max_storage_buffers < BINDING_COUNT)
        missing.push_back(fmt::format("{} storage buffers per stage", BINDING_COUNT));
    std::string s;
    for (const std::string& m : missing) s += (s.empty() ? "" : ", ") + m;
    return s;
}

bool pipeline_mode_supported(const DeviceCaps& caps) {
    return has_extension(caps, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME) &&
           has_extension(caps, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) &&
           has_extension(caps, VK_KHR_BUFFER_DEVICE_ADDRESS_EXTENSION_NAME);
}

const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices,
                                const std::string& selector) {
    if (devices.empty()) runtime_error("no Vulkan device found (is a Vulkan driver installed?)");
    if (selector.empty()) {
        const DeviceInfo* best = nullptr;
        for (const DeviceInfo& d : devices)
            if (d.compute() && (!best || type_rank(d.type) < type_rank(best->type))) best = &d;
        if (!best) return require_compute(devices.front());
        return *best;
    }
    if (std::all_of(selector.begin(), selector.end(),
                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
        const unsigned long index = selector.size() > 9 ? ~0ul : std::stoul(selector);
        for (const DeviceInfo& d : devices)
            if (d.index == index) return require_compute(d);
        input_error("--device {}: there is no Vulkan device with that index (devices: {})",
                    selector, device_list(devices));
    }
    for (const DeviceInfo& d : devices)
        if (lower(d.name).find(lower(selector)) != std::string::npos) return require_compute(d);
    input_error("--device {}: no Vulkan device name contains it (devices: {})", selector,
                device_list(devices));
}

} // namespace tp
