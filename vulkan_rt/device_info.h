// What twinpath needs to know about a Vulkan device, and the decisions made from it: which
// modes it can run and which device a --device selector means. Filled from Vulkan queries by
// device_query.cpp; everything here is plain data and pure functions (unit tested).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

struct DeviceCaps {
    uint32_t api_version = 0;
    bool float64 = false;             // shaderFloat64: the film accumulators are double
    bool scalar_layout = false;       // scalarBlockLayout: buffers mirror the C++ structs
    bool subgroup_arithmetic = false; // in compute shaders: ray-counter reduction
    bool compute_queue = false;
    uint32_t max_storage_buffers = 0; // per shader stage
    std::vector<std::string> extensions;
};

struct DeviceInfo {
    uint32_t index = 0; // position in vkEnumeratePhysicalDevices order
    std::string name;
    std::string type; // discrete, integrated, virtual, cpu, other
    std::string api_version;
    std::string driver;
    uint64_t memory_bytes = 0; // device-local heaps
    DeviceCaps caps;
    std::string compute_missing; // what compute mode lacks on this device; empty: it runs
    bool pipeline = false;       // ray-tracing pipeline mode possible

    bool compute() const { return compute_missing.empty(); }
    std::vector<std::string> modes() const;
};

// "1.3.230" from a VK_MAKE_API_VERSION value.
std::string vk_version_string(uint32_t version);

// Empty when compute mode can run; otherwise the missing capabilities, comma-separated.
std::string compute_mode_missing(const DeviceCaps& caps);

// VK_KHR_ray_tracing_pipeline + VK_KHR_acceleration_structure + VK_KHR_buffer_device_address.
bool pipeline_mode_supported(const DeviceCaps& caps);

// The device a --device selector names: an index, or a case-insensitive substring of the
// name; empty picks the first compute-capable device of the best type (discrete, integrated,
// virtual, cpu). Throws InputError for a selector that matches nothing (listing the devices)
// and RuntimeError when there is no device at all or the chosen one cannot run compute mode.
const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices,
                                const std::string& selector);

} // namespace tp
