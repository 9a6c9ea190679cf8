#include "vulkan_rt/compute_program.h"

#include "vulkan_rt/vk_error.h"

#include <vector>

namespace tp {
namespace {

std::vector<BindingSlot> storage_slots(uint32_t count) {
    std::vector<BindingSlot> slots;
    for (uint32_t i = 0; i < count; ++i) slots.push_back({i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    return slots;
}

} // namespace

ComputeProgram::ComputeProgram(const VulkanContext& ctx, const uint32_t* spirv, size_t spirv_bytes,
                               uint32_t binding_count, uint32_t push_bytes)
    : device_(ctx.device()),
      bindings_(ctx, storage_slots(binding_count), VK_SHADER_STAGE_COMPUTE_BIT, push_bytes) {
    VkShaderModuleCreateInfo mi{};
    mi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    mi.codeSize = spirv_bytes;
    mi.pCode = spirv;
    VkShaderModule module = VK_NULL_HANDLE;
    vk_check(vkCreateShaderModule(device_, &mi, nullptr, &module), "loading a shader");
    VkComputePipelineCreateInfo ci{};
    ci.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    ci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = module;
    ci.stage.pName = "main";
    ci.layout = bindings_.layout();
    const VkResult r = vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline_);
    vkDestroyShaderModule(device_, module, nullptr);
    vk_check(r, "compiling a compute pipeline");
}

ComputeProgram::~ComputeProgram() {
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
}

void ComputeProgram::record_dispatch(VkCommandBuffer cmd, const void* push, uint32_t groups_x,
                                     uint32_t groups_y, uint32_t groups_z) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    bindings_.record_bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, push);
    vkCmdDispatch(cmd, groups_x, groups_y, groups_z);
}

} // namespace tp
