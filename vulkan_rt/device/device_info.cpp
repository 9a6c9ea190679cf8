#include "vulkan_rt/device/device_info.h"

#include "shaders/interface.h"
#include "util/error.h"

#include <fmt/format.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cctype>

namespace tp {

bool DeviceCaps::has(const char* extension) const {
    return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

std::vector<VkMode> DeviceInfo::modes() const {
    std::vector<VkMode> m;
    if (compute()) m.push_back(VkMode::compute);
    if (pipeline()) m.push_back(VkMode::pipeline);
    return m;
}

std::string vk_version_string(uint32_t v) {
    return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(v), VK_API_VERSION_MINOR(v),
                       VK_API_VERSION_PATCH(v));
}

namespace {

std::string join(const std::vector<std::string>& items) {
    std::string s;
    for (const std::string& m : items) s += (s.empty() ? "" : ", ") + m;
    return s;
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
    if (!caps.subgroup_ballot) missing.push_back("subgroup ballots in compute shaders");
    if (caps.max_storage_buffers < BINDING_COUNT)
        missing.push_back(fmt::format("{} storage buffers per stage", BINDING_COUNT));
    if (caps.max_sampled_images < IMAGE_SLOTS)
        missing.push_back(fmt::format("{} sampled images per stage and set", IMAGE_SLOTS));
    // Every slot but the images is one resource (a storage buffer, or the TLAS).
    if (caps.max_stage_resources < BINDING_COUNT - 1 + IMAGE_SLOTS)
        missing.push_back(fmt::format("{} resources per stage", BINDING_COUNT - 1 + IMAGE_SLOTS));
    return join(missing);
}

const std::vector<const char*>& pipeline_extensions() {
    static const std::vector<const char*> names = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                                   VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                                                   VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
    return names;
}

std::string pipeline_mode_missing(const DeviceCaps& caps) {
    std::vector<std::string> missing;
    for (const char* ext : pipeline_extensions())
        if (!caps.has(ext)) missing.push_back(ext);
    // The features matter only where the extensions exist.
    if (missing.empty()) {
        if (!caps.acceleration_structure) missing.push_back("accelerationStructure");
        if (!caps.ray_tracing_pipeline) missing.push_back("rayTracingPipeline");
        if (!caps.buffer_device_address) missing.push_back("bufferDeviceAddress");
        if (!caps.subgroup_arithmetic_raygen)
            missing.push_back("subgroup arithmetic in ray-generation shaders");
        if (!caps.subgroup_ballot_raygen)
            missing.push_back("subgroup ballots in ray-generation shaders");
    }
    const std::string compute = compute_mode_missing(caps);
    if (!compute.empty()) missing.push_back(compute);
    return join(missing);
}

VkMode resolve_vk_mode(VkModeRequest requested, const DeviceInfo& d) {
    if (!requested) return d.pipeline() ? VkMode::pipeline : VkMode::compute;
    if (*requested == VkMode::compute) return VkMode::compute;
    if (!d.pipeline())
        runtime_error("--vk-mode pipeline: Vulkan device {} ({}) cannot run the ray-tracing "
                      "pipeline mode: it lacks {}; use --vk-mode compute (auto picks it there)",
                      d.index, d.name, d.pipeline_missing);
    return VkMode::pipeline;
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

bool selects_several(const std::string& selector) {
    return selector == "all" || selector.find(',') != std::string::npos;
}

std::vector<DeviceInfo> select_devices(const std::vector<DeviceInfo>& devices,
                                       const std::string& selector) {
    if (devices.empty()) runtime_error("no Vulkan device found (is a Vulkan driver installed?)");
    std::vector<DeviceInfo> chosen;
    if (selector == "all") {
        const bool other_than_cpu = std::any_of(devices.begin(), devices.end(), [](const auto& d) {
            return d.compute() && d.type != "cpu";
        });
        for (const DeviceInfo& d : devices)
            if (d.compute() && (d.type != "cpu" || !other_than_cpu)) chosen.push_back(d);
        if (chosen.empty()) return {require_compute(devices.front())};
        return chosen;
    }
    size_t start = 0;
    while (start <= selector.size()) {
        const size_t end = std::min(selector.find(',', start), selector.size());
        const DeviceInfo& d = select_device(devices, selector.substr(start, end - start));
        for (const DeviceInfo& c : chosen)
            if (c.index == d.index)
                input_error("--device {}: device {} ({}) is named twice", selector, d.index,
                            d.name);
        chosen.push_back(d);
        start = end + 1;
    }
    return chosen;
}

VkMode resolve_common_mode(VkModeRequest requested, const std::vector<DeviceInfo>& devices) {
    const bool all_pipeline = std::all_of(devices.begin(), devices.end(),
                                          [](const DeviceInfo& d) { return d.pipeline(); });
    const VkMode mode = requested ? *requested : all_pipeline ? VkMode::pipeline : VkMode::compute;
    for (const DeviceInfo& d : devices) resolve_vk_mode(mode, d); // throws for what cannot run
    return mode;
}

} // namespace tp
