#include "vulkan_rt/pipeline_mode/rt_functions.h"

#include "util/error.h"

namespace tp {
namespace {

template <typename Fn>
void load(VkDevice device, const char* name, Fn& fn) {
    fn = reinterpret_cast<Fn>(vkGetDeviceProcAddr(device, name));
    if (!fn) runtime_error("the Vulkan driver does not provide {} (pipeline mode)", name);
}

} // namespace

#define TP_LOAD(name) load(device, #name, name)

RtFunctions::RtFunctions(VkDevice device) {
    TP_LOAD(vkGetAccelerationStructureBuildSizesKHR);
    TP_LOAD(vkCreateAccelerationStructureKHR);
    TP_LOAD(vkDestroyAccelerationStructureKHR);
    TP_LOAD(vkGetAccelerationStructureDeviceAddressKHR);
    TP_LOAD(vkCmdBuildAccelerationStructuresKHR);
    TP_LOAD(vkCmdWriteAccelerationStructuresPropertiesKHR);
    TP_LOAD(vkCmdCopyAccelerationStructureKHR);
    TP_LOAD(vkCreateRayTracingPipelinesKHR);
    TP_LOAD(vkGetRayTracingShaderGroupHandlesKHR);
    TP_LOAD(vkCmdTraceRaysKHR);
}

#undef TP_LOAD

} // namespace tp
