#include "vulkan_rt/device/device_query.h"

#include "vulkan_rt/device/vk_error.h"

#include <fmt/format.h>

#include <algorithm>

namespace tp {
namespace {

const char* type_name(VkPhysicalDeviceType t) {
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "cpu";
    default:
        return "other";
    }
}

std::vector<std::string> device_extensions(VkPhysicalDevice device) {
    uint32_t n = 0;
    vk_check(vkEnumerateDeviceExtensionProperties(device, nullptr, &n, nullptr),
             "listing device extensions");
    std::vector<VkExtensionProperties> props(n);
    vk_check(vkEnumerateDeviceExtensionProperties(device, nullptr, &n, props.data()),
             "listing device extensions");
    std::vector<std::string> names;
    for (uint32_t i = 0; i < n; ++i) names.emplace_back(props[i].extensionName);
    return names;
}

} // namespace

DeviceInfo query_device(VkPhysicalDevice device, uint32_t index) {
    DeviceInfo info;
    info.index = index;

    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device, &props);
    info.name = props.deviceName;
    info.type = type_name(props.deviceType);
    info.api_version = vk_version_string(props.apiVersion);
    info.driver = fmt::format("driver version {:#x}", props.driverVersion);
    DeviceCaps& caps = info.caps;
    caps.api_version = props.apiVersion;
    caps.max_storage_buffers = props.limits.maxPerStageDescriptorStorageBuffers;
    caps.max_sampled_images = std::min(props.limits.maxPerStageDescriptorSampledImages,
                                       props.limits.maxDescriptorSetSampledImages);
    caps.max_stage_resources = props.limits.maxPerStageResources;
    caps.extensions = device_extensions(device);

    // Vulkan 1.1/1.2 structures may only be chained for devices that have them.
    if (props.apiVersion >= VK_API_VERSION_1_2) {
        VkPhysicalDeviceDriverProperties driver{};
        driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
        VkPhysicalDeviceSubgroupProperties subgroup{};
        subgroup.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES;
        subgroup.pNext = &driver;
        VkPhysicalDeviceShaderSMBuiltinsPropertiesNV sm{};
        sm.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_SM_BUILTINS_PROPERTIES_NV;
        if (caps.has(VK_NV_SHADER_SM_BUILTINS_EXTENSION_NAME)) {
            sm.pNext = subgroup.pNext;
            subgroup.pNext = &sm;
        }
        VkPhysicalDeviceProperties2 props2{};
        props2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
        props2.pNext = &subgroup;
        vkGetPhysicalDeviceProperties2(device, &props2);
        caps.resident_invocations = uint64_t(sm.shaderSMCount) * sm.shaderWarpsPerSM * 32;
        info.driver = fmt::format("{} {}", driver.driverName, driver.driverInfo);
        const bool arithmetic = subgroup.supportedOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
        caps.subgroup_arithmetic =
            arithmetic && (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT);
        caps.subgroup_arithmetic_raygen =
            arithmetic && (subgroup.supportedStages & VK_SHADER_STAGE_RAYGEN_BIT_KHR);
        const bool ballot = subgroup.supportedOperations & VK_SUBGROUP_FEATURE_BALLOT_BIT;
        caps.subgroup_ballot = ballot && (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT);
        caps.subgroup_ballot_raygen =
            ballot && (subgroup.supportedStages & VK_SHADER_STAGE_RAYGEN_BIT_KHR);

        // Extension feature structures may only be chained where the extension exists.
        VkPhysicalDeviceAccelerationStructureFeaturesKHR as{};
        as.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR;
        VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{};
        rt.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR;
        VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR exec{};
        exec.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR;
        VkPhysicalDeviceVulkan12Features f12{};
        f12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
        if (caps.has(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME)) {
            exec.pNext = f12.pNext;
            f12.pNext = &exec;
        }
        if (caps.has(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME)) {
            as.pNext = f12.pNext;
            f12.pNext = &as;
        }
        if (caps.has(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME)) {
            rt.pNext = f12.pNext;
            f12.pNext = &rt;
        }
        VkPhysicalDeviceFeatures2 features{};
        features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
        features.pNext = &f12;
        vkGetPhysicalDeviceFeatures2(device, &features);
        caps.float64 = features.features.shaderFloat64 == VK_TRUE;
        caps.scalar_layout = f12.scalarBlockLayout == VK_TRUE;
        caps.buffer_device_address = f12.bufferDeviceAddress == VK_TRUE;
        caps.acceleration_structure = as.accelerationStructure == VK_TRUE;
        caps.ray_tracing_pipeline = rt.rayTracingPipeline == VK_TRUE;
        caps.pipeline_executable_info = exec.pipelineExecutableInfo == VK_TRUE;
    }

    uint32_t nq = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &nq, nullptr);
    std::vector<VkQueueFamilyProperties> queues(nq);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &nq, queues.data());
    for (const VkQueueFamilyProperties& q : queues)
        if (q.queueFlags & VK_QUEUE_COMPUTE_BIT) caps.compute_queue = true;

    VkPhysicalDeviceMemoryProperties mem;
    vkGetPhysicalDeviceMemoryProperties(device, &mem);
    for (uint32_t i = 0; i < mem.memoryHeapCount; ++i)
        if (mem.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            info.memory_bytes += mem.memoryHeaps[i].size;

    info.compute_missing = compute_mode_missing(caps);
    info.pipeline_missing = pipeline_mode_missing(caps);
    return info;
}

} // namespace tp
