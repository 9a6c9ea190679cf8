#include "gpu_harness.h"

namespace tp::test {

VulkanContext& gpu_context() {
    static VulkanContext ctx("");
    return ctx;
}

uint64_t validation_messages() {
    return gpu_context().instance().validation_messages();
}

std::vector<std::vector<uint8_t>>
run_shader(const uint32_t* spirv, size_t spirv_bytes, const std::vector<HostBytes>& inputs,
           const std::vector<size_t>& output_bytes, const void* push, uint32_t push_bytes,
           uint32_t groups, const std::vector<const Buffer*>& device, uint32_t features) {
    return run_compute_shader(gpu_context(), spirv, spirv_bytes, inputs, output_bytes, push,
                              push_bytes, groups, device, features);
}

} // namespace tp::test
