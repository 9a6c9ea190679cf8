// What twinpath needs to know about a Vulkan device, and the decisions made from it: which
// modes it can run and which device a --device selector means. Filled from Vulkan queries by
// device_query.cpp; everything here is plain data and pure functions (unit tested).
#pragma once

#include "vulkan_rt/device/vk_mode.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

struct DeviceCaps {
    uint32_t api_version = 0;
    bool float64 = false;             // shaderFloat64: the film accumulators are double
    bool scalar_layout = false;       // scalarBlockLayout: buffers mirror the C++ structs
    bool subgroup_arithmetic = false; // in compute shaders: ray-counter reduction
    bool subgroup_ballot = false;     // in compute shaders: work items taken together
    bool compute_queue = false;
    uint32_t max_storage_buffers = 0; // per shader stage
    // Sampled images per shader stage and per descriptor set (the lesser), and resources of
    // every kind per stage: the render shaders bind IMAGE_SLOTS images (shaders/interface.h).
    uint32_t max_sampled_images = 0;
    uint32_t max_stage_resources = 0;
    std::vector<std::string> extensions;
    // Invocations the device keeps resident at once, where it says so (VK_NV_shader_sm_builtins:
    // multiprocessors x warps per multiprocessor x 32); 0: unknown. Render launches need no more
    // (shaders/render_items.glsl: each invocation takes work items until none is left).
    uint64_t resident_invocations = 0;
    // Pipeline mode: the features of its extensions, and the ray-counter reduction and item
    // fetch of shaders/counters.glsl and render_items.glsl in the ray-generation shader.
    bool acceleration_structure = false; // VkPhysicalDeviceAccelerationStructureFeaturesKHR
    bool ray_tracing_pipeline = false;   // VkPhysicalDeviceRayTracingPipelineFeaturesKHR
    bool buffer_device_address = false;  // Vulkan 1.2: SBT, geometry and instance addresses
    bool subgroup_arithmetic_raygen = false;
    bool subgroup_ballot_raygen = false;
    // VK_KHR_pipeline_executable_properties with its pipelineExecutableInfo feature: the
    // driver's statistics of compiled pipelines (`--pipeline-stats`).
    bool pipeline_executable_info = false;

    bool has(const char* extension) const;
};

struct DeviceInfo {
    uint32_t index = 0; // position in vkEnumeratePhysicalDevices order
    std::string name;
    std::string type; // discrete, integrated, virtual, cpu, other
    std::string api_version;
    std::string driver;
    uint64_t memory_bytes = 0; // device-local heaps
    DeviceCaps caps;
    std::string compute_missing;  // what compute mode lacks on this device; empty: it runs
    std::string pipeline_missing; // the same for the ray-tracing pipeline mode

    bool compute() const { return compute_missing.empty(); }
    bool pipeline() const { return pipeline_missing.empty(); }
    std::vector<VkMode> modes() const;
};

// "1.3.230" from a VK_MAKE_API_VERSION value.
std::string vk_version_string(uint32_t version);

// Empty when compute mode can run; otherwise the missing capabilities, comma-separated.
std::string compute_mode_missing(const DeviceCaps& caps);

// The device extensions pipeline mode enables. Their other dependencies (buffer device address,
// descriptor indexing, SPIR-V 1.4, float controls) are Vulkan 1.2 core, which compute mode
// already requires.
const std::vector<const char*>& pipeline_extensions();

// Empty when pipeline mode can run: its extensions and their features, subgroup arithmetic in
// ray-generation shaders, and everything compute mode needs (the same shading code runs).
std::string pipeline_mode_missing(const DeviceCaps& caps);

// The mode that runs for a --vk-mode request on a device: auto is pipeline where the device
// supports it, else compute. Throws RuntimeError (exit code 3) for pipeline on a device without
// it, naming what is missing.
VkMode resolve_vk_mode(VkModeRequest requested, const DeviceInfo& device);

// The device a --device selector names: an index, or a case-insensitive substring of the
// name; empty picks the first compute-capable device of the best type (discrete, integrated,
// virtual, cpu). Throws InputError for a selector that matches nothing (listing the devices)
// and RuntimeError when there is no device at all or the chosen one cannot run compute mode.
const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices,
                                const std::string& selector);

// Whether a --device selector names several devices: "all" or a comma-separated list.
bool selects_several(const std::string& selector);
// The devices such a selector names. "all": every compute-capable device, without the CPU
// devices (lavapipe) when there is another kind: a rasterizer on the host's cores would take
// them from the threads that drive the GPUs. A list: each item as select_device reads it, no
// device twice (InputError).
std::vector<DeviceInfo> select_devices(const std::vector<DeviceInfo>& devices,
                                       const std::string& selector);
// The mode that every one of `devices` runs for a --vk-mode request, so that their samples are
// of one estimator: auto is pipeline when every device supports it, else compute.
VkMode resolve_common_mode(VkModeRequest requested, const std::vector<DeviceInfo>& devices);

} // namespace tp
