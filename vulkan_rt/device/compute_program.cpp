#include "vulkan_rt/device/compute_program.h"

#include "util/clock.h"
#include "util/fnv1a.h"
#include "vulkan_rt/device/pipeline_report.h"
#include "vulkan_rt/device/specialization.h"
#include "vulkan_rt/device/vk_error.h"

#include <chrono>
#include <memory>
#include <vector>

namespace tp {
ComputeProgram::ComputeProgram(const VulkanContext& ctx, const uint32_t* spirv, size_t spirv_bytes,
                               const std::vector<BindingSlot>& slots, uint32_t push_bytes,
                               const RenderConstants& constants, bool cached)
    : device_(ctx.device()), bindings_(ctx, slots, VK_SHADER_STAGE_COMPUTE_BIT, push_bytes) {
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
    const RenderSpecialization spec(constants);
    ci.stage.pSpecializationInfo = &spec.info;
    std::unique_ptr<PipelineCache> cache;
    try {
        if (cached) cache = std::make_unique<PipelineCache>(ctx, fnv1a64(spirv, spirv_bytes));
    } catch (...) {
        vkDestroyShaderModule(device_, module, nullptr);
        throw;
    }
    PipelineReporter reporter(ctx, {VK_SHADER_STAGE_COMPUTE_BIT});
    ci.pNext = reporter.chain(nullptr);
    ci.flags = reporter.flags();
    const auto t0 = std::chrono::steady_clock::now();
    const VkResult r = vkCreateComputePipelines(device_, cache ? cache->handle() : VK_NULL_HANDLE,
                                                1, &ci, nullptr, &pipeline_);
    vkDestroyShaderModule(device_, module, nullptr);
    vk_check(r, "compiling a compute pipeline");
    if (cache) {
        cache->use().create_s = seconds_since(t0);
        cache->save();
        cache_use_ = cache->use();
    }
    try {
        report_ = reporter.report(pipeline_);
    } catch (...) {
        vkDestroyPipeline(device_, pipeline_, nullptr);
        throw;
    }
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
