// What the driver says about a pipeline it creates (RenderStats::pipeline, docs/gpu.md,
// "Pipeline statistics"): VK_EXT_pipeline_creation_feedback on every pipeline where the device has
// it (did the application's pipeline cache spare the compilation, how long did creation take),
// and on request (`--pipeline-stats`) VK_KHR_pipeline_executable_properties: each executable the
// pipeline was compiled into, with every statistic the driver keeps (register counts, ...).
#pragma once

#include "render/stats.h"
#include "vulkan_rt/device/context.h"

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace tp {

// "compute", "raygen", "miss", "closest_hit", ... for each bit of `stages`.
std::vector<std::string> shader_stage_names(VkShaderStageFlags stages);

// Why a context asked for pipeline statistics cannot give them ("" when it can, or when they
// were not asked for).
std::string pipeline_statistics_note(const VulkanContext& ctx);

// The requests for one vkCreate*Pipelines call of one pipeline, and its report afterwards.
class PipelineReporter {
  public:
    // `stages`: the pipeline's shader stages, in the order of its create info.
    PipelineReporter(const VulkanContext& ctx, std::vector<VkShaderStageFlagBits> stages);
    PipelineReporter(const PipelineReporter&) = delete;
    PipelineReporter& operator=(const PipelineReporter&) = delete;

    // The create info's pNext: `next` with the feedback request in front where the device has
    // the extension.
    const void* chain(const void* next);
    // Flags for the create info: statistics capture when asked for and available.
    VkPipelineCreateFlags flags() const;
    // After creation: the feedback, and the executables of `pipeline` when asked for.
    PipelineReport report(VkPipeline pipeline) const;

  private:
    const VulkanContext& ctx_;
    std::vector<VkShaderStageFlagBits> stages_;
    VkPipelineCreationFeedback pipeline_{};
    std::vector<VkPipelineCreationFeedback> stage_feedback_;
    VkPipelineCreationFeedbackCreateInfo info_{};
};

} // namespace tp
