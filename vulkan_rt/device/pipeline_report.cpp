#include "vulkan_rt/device/pipeline_report.h"

#include "util/error.h"
#include "vulkan_rt/device/vk_error.h"

#include <fmt/format.h>

#include <utility>
#include <vector>

namespace tp {
namespace {

PipelineFeedback feedback(const std::string& stage, const VkPipelineCreationFeedback& f) {
    PipelineFeedback out;
    out.stage = stage;
    out.valid = f.flags & VK_PIPELINE_CREATION_FEEDBACK_VALID_BIT;
    out.cache_hit = f.flags & VK_PIPELINE_CREATION_FEEDBACK_APPLICATION_PIPELINE_CACHE_HIT_BIT;
    out.base_pipeline_acceleration =
        f.flags & VK_PIPELINE_CREATION_FEEDBACK_BASE_PIPELINE_ACCELERATION_BIT;
    out.duration_ms = double(f.duration) * 1e-6;
    return out;
}

template <typename Fn>
Fn device_function(VkDevice device, const char* name) {
    const auto fn = reinterpret_cast<Fn>(vkGetDeviceProcAddr(device, name));
    if (!fn) runtime_error("the Vulkan driver does not provide {} (--pipeline-stats)", name);
    return fn;
}

PipelineStatistic statistic(const VkPipelineExecutableStatisticKHR& s) {
    PipelineStatistic out;
    out.name = s.name;
    out.description = s.description;
    switch (s.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
        out.value = s.value.b32 == VK_TRUE;
        break;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
        out.value = s.value.i64;
        break;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
        out.value = s.value.u64;
        break;
    default: // VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR
        out.value = s.value.f64;
        break;
    }
    return out;
}

// Vulkan's two-call enumeration of output structures, whose sType must be set before the fill.
template <typename T, typename Call>
std::vector<T> enumerate(VkStructureType type, const char* what, Call call) {
    uint32_t n = 0;
    vk_check(call(&n, nullptr), what);
    std::vector<T> items(n);
    for (T& item : items) item.sType = type;
    vk_check(call(&n, items.data()), what);
    items.resize(n);
    return items;
}

// Every executable of `pipeline` with every statistic (VK_KHR_pipeline_executable_properties).
std::vector<PipelineExecutable> executables(VkDevice device, VkPipeline pipeline) {
    const auto get_properties = device_function<PFN_vkGetPipelineExecutablePropertiesKHR>(
        device, "vkGetPipelineExecutablePropertiesKHR");
    const auto get_statistics = device_function<PFN_vkGetPipelineExecutableStatisticsKHR>(
        device, "vkGetPipelineExecutableStatisticsKHR");
    VkPipelineInfoKHR pi{};
    pi.sType = VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR;
    pi.pipeline = pipeline;
    const auto props = enumerate<VkPipelineExecutablePropertiesKHR>(
        VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR, "listing pipeline executables",
        [&](uint32_t* n, VkPipelineExecutablePropertiesKHR* p) {
            return get_properties(device, &pi, n, p);
        });
    std::vector<PipelineExecutable> out;
    for (uint32_t i = 0; i < uint32_t(props.size()); ++i) {
        PipelineExecutable e;
        e.stages = shader_stage_names(props[i].stages);
        e.name = props[i].name;
        e.description = props[i].description;
        e.subgroup_size = props[i].subgroupSize;
        VkPipelineExecutableInfoKHR ei{};
        ei.sType = VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR;
        ei.pipeline = pipeline;
        ei.executableIndex = i;
        const auto stats = enumerate<VkPipelineExecutableStatisticKHR>(
            VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR, "reading pipeline statistics",
            [&](uint32_t* m, VkPipelineExecutableStatisticKHR* st) {
                return get_statistics(device, &ei, m, st);
            });
        for (const VkPipelineExecutableStatisticKHR& s : stats)
            e.statistics.push_back(statistic(s));
        out.push_back(std::move(e));
    }
    return out;
}

} // namespace

std::vector<std::string> shader_stage_names(VkShaderStageFlags stages) {
    static const std::pair<VkShaderStageFlagBits, const char*> kNames[] = {
        {VK_SHADER_STAGE_VERTEX_BIT, "vertex"},
        {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, "tessellation_control"},
        {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, "tessellation_evaluation"},
        {VK_SHADER_STAGE_GEOMETRY_BIT, "geometry"},
        {VK_SHADER_STAGE_FRAGMENT_BIT, "fragment"},
        {VK_SHADER_STAGE_COMPUTE_BIT, "compute"},
        {VK_SHADER_STAGE_RAYGEN_BIT_KHR, "raygen"},
        {VK_SHADER_STAGE_ANY_HIT_BIT_KHR, "any_hit"},
        {VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, "closest_hit"},
        {VK_SHADER_STAGE_MISS_BIT_KHR, "miss"},
        {VK_SHADER_STAGE_INTERSECTION_BIT_KHR, "intersection"},
        {VK_SHADER_STAGE_CALLABLE_BIT_KHR, "callable"}};
    std::vector<std::string> names;
    for (const auto& [bit, name] : kNames)
        if (stages & bit) {
            names.emplace_back(name);
            stages &= ~VkShaderStageFlags(bit);
        }
    if (stages) names.push_back(fmt::format("{:#x}", stages));
    return names;
}

std::string pipeline_statistics_note(const VulkanContext& ctx) {
    if (!ctx.statistics_requested() || ctx.pipeline_statistics()) return "";
    return fmt::format("{} does not offer {} (with its pipelineExecutableInfo feature): no "
                       "pipeline statistics",
                       ctx.info().name, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
}

PipelineReporter::PipelineReporter(const VulkanContext& ctx,
                                   std::vector<VkShaderStageFlagBits> stages)
    : ctx_(ctx), stages_(std::move(stages)), stage_feedback_(stages_.size()) {
    info_.sType = VK_STRUCTURE_TYPE_PIPELINE_CREATION_FEEDBACK_CREATE_INFO;
    info_.pPipelineCreationFeedback = &pipeline_;
    info_.pipelineStageCreationFeedbackCount = uint32_t(stage_feedback_.size());
    info_.pPipelineStageCreationFeedbacks = stage_feedback_.data();
}

const void* PipelineReporter::chain(const void* next) {
    if (!ctx_.creation_feedback()) return next;
    info_.pNext = next;
    return &info_;
}

VkPipelineCreateFlags PipelineReporter::flags() const {
    return ctx_.pipeline_statistics() ? VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR : 0;
}

PipelineReport PipelineReporter::report(VkPipeline pipeline) const {
    PipelineReport r;
    if (ctx_.creation_feedback()) {
        r.feedback.push_back(feedback("pipeline", pipeline_));
        for (size_t i = 0; i < stages_.size(); ++i)
            r.feedback.push_back(
                feedback(shader_stage_names(stages_[i]).front(), stage_feedback_[i]));
    }
    r.statistics_requested = ctx_.statistics_requested();
    r.statistics_available = ctx_.pipeline_statistics();
    r.statistics_note = pipeline_statistics_note(ctx_);
    if (r.statistics_available) r.executables = executables(ctx_.device(), pipeline);
    return r;
}

} // namespace tp
