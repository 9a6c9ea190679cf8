#include "vulkan_rt/pipeline_mode/rt_program.h"

#include "shaders/interface.h"
#include "shaders/rt_interface.h"
#include "util/clock.h"
#include "util/fnv1a.h"
#include "vulkan_rt/device/pipeline_report.h"
#include "vulkan_rt/device/specialization.h"
#include "vulkan_rt/device/vk_error.h"
#include "vulkan_rt/pipeline_mode/sbt_layout.h"
#include "vulkan_rt/render_loop/scene_buffers.h"

#include <chrono>
#include <vector>

// Generated from shaders/*.rgen, *.rmiss, *.rchit (shaders/spirv.cmake).
#include "closest_hit.spv.h"
#include "alpha_test.spv.h"
#include "exact_triangle.spv.h"
#include "miss.spv.h"
#include "render_pipeline.spv.h"
#include "shadow_miss.spv.h"

namespace tp {
namespace {

// Every interface slot but BINDING_BVH_TRIS, with the TLAS in BINDING_TLAS and the scene's
// images in BINDING_IMAGES. The ray-generation shader reads them, the any-hit alpha test the
// scene's (its texture reads among them) and the intersection shader its triangles; the closest
// hit and miss shaders touch only their payloads.
std::vector<BindingSlot> pipeline_slots() {
    std::vector<BindingSlot> slots;
    for (const BindingSlot& s : interface_slots(BINDING_COUNT, true, true))
        if (s.binding != BINDING_BVH_TRIS) slots.push_back(s);
    return slots;
}

struct Stage {
    VkShaderStageFlagBits stage;
    const uint32_t* spirv;
    size_t bytes;
};

// Shader stages, and groups, in the order of shaders/rt_interface.h: ray generation, the miss
// shaders, the triangle hit group's closest hit; the procedural hit group adds the intersection
// shader (kExactStage) and shares the closest hit.
static_assert(RT_MISS_CLOSEST == 0 && RT_MISS_SHADOW == 1 && RT_MISS_COUNT == 2 &&
                  RT_HIT_GROUP_TRIANGLES == 0 && RT_HIT_GROUP_EXACT == 1 && RT_HIT_GROUP_COUNT == 2,
              "the stages below follow rt_interface.h");
const Stage kStages[] = {
    {VK_SHADER_STAGE_RAYGEN_BIT_KHR, tp_spirv_render_pipeline, sizeof(tp_spirv_render_pipeline)},
    {VK_SHADER_STAGE_MISS_BIT_KHR, tp_spirv_miss, sizeof(tp_spirv_miss)},
    {VK_SHADER_STAGE_MISS_BIT_KHR, tp_spirv_shadow_miss, sizeof(tp_spirv_shadow_miss)},
    {VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, tp_spirv_closest_hit, sizeof(tp_spirv_closest_hit)},
    {VK_SHADER_STAGE_INTERSECTION_BIT_KHR, tp_spirv_exact_triangle,
     sizeof(tp_spirv_exact_triangle)},
    {VK_SHADER_STAGE_ANY_HIT_BIT_KHR, tp_spirv_alpha_test, sizeof(tp_spirv_alpha_test)},
};
constexpr uint32_t kClosestHitStage = 3;
constexpr uint32_t kExactStage = 4;
constexpr uint32_t kAlphaStage = 5;

VkRayTracingShaderGroupCreateInfoKHR shader_group(VkRayTracingShaderGroupTypeKHR type,
                                                  uint32_t general, uint32_t closest_hit,
                                                  uint32_t intersection, uint32_t any_hit) {
    VkRayTracingShaderGroupCreateInfoKHR g{};
    g.sType = VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR;
    g.type = type;
    g.generalShader = general;
    g.closestHitShader = closest_hit;
    g.anyHitShader = any_hit;
    g.intersectionShader = intersection;
    return g;
}

VkStridedDeviceAddressRegionKHR region(VkDeviceAddress table, const SbtRegion& r) {
    return {table + r.offset, r.stride, r.size};
}

} // namespace

RtProgram::RtProgram(const VulkanContext& ctx, const RtFunctions& rt, uint32_t push_bytes,
                     const uint32_t* raygen, size_t raygen_bytes, const RenderConstants& constants,
                     bool exact)
    : ctx_(ctx), rt_(rt), raygen_spirv_(raygen), raygen_bytes_(raygen_bytes), constants_(constants),
      hit_groups_(exact ? 2u : 1u), alpha_(feature_on(constants.features, FEATURE_ALPHA)),
      bindings_(ctx, pipeline_slots(),
                VK_SHADER_STAGE_RAYGEN_BIT_KHR |
                    (exact ? VK_SHADER_STAGE_INTERSECTION_BIT_KHR : VkShaderStageFlagBits(0)) |
                    (alpha_ ? VK_SHADER_STAGE_ANY_HIT_BIT_KHR : VkShaderStageFlagBits(0)),
                push_bytes) {
    create_pipeline();
    try {
        create_binding_table();
    } catch (...) {
        vkDestroyPipeline(ctx.device(), pipeline_, nullptr);
        throw;
    }
}

RtProgram::~RtProgram() {
    vkDestroyPipeline(ctx_.device(), pipeline_, nullptr);
}

void RtProgram::create_pipeline() {
    const VkDevice device = ctx_.device();
    std::vector<VkShaderModule> modules;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
    std::vector<VkShaderStageFlagBits> stage_bits;
    struct ModuleGuard {
        VkDevice d;
        std::vector<VkShaderModule>& m;
        ~ModuleGuard() {
            for (VkShaderModule x : m) vkDestroyShaderModule(d, x, nullptr);
        }
    } guard{device, modules};
    // The path loop lives in the ray-generation shader: it alone is specialized (to the scene's
    // features and the item schedule). One closest-hit shader serves every material (it only
    // reports the hit), so there is no per-material hit group to leave out (docs/gpu.md).
    const RenderSpecialization spec(constants_);
    uint64_t shader_hash = fnv1a64(nullptr, 0);
    // The stages in kStages order: the intersection shader only with the procedural group, the
    // any-hit shader only for a scene with alpha.
    std::vector<uint32_t> used;
    for (uint32_t i = 0; i <= kClosestHitStage; ++i) used.push_back(i);
    if (hit_groups_ == 2) used.push_back(kExactStage);
    if (alpha_) used.push_back(kAlphaStage);
    for (uint32_t i : used) {
        VkShaderModuleCreateInfo mi{};
        mi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
        const bool own_raygen = i == 0 && raygen_spirv_;
        mi.codeSize = own_raygen ? raygen_bytes_ : kStages[i].bytes;
        mi.pCode = own_raygen ? raygen_spirv_ : kStages[i].spirv;
        VkShaderModule module = VK_NULL_HANDLE;
        vk_check(vkCreateShaderModule(device, &mi, nullptr, &module), "loading a shader");
        modules.push_back(module);
        shader_hash = fnv1a64(mi.pCode, mi.codeSize, shader_hash);

        VkPipelineShaderStageCreateInfo st{};
        st.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        st.stage = kStages[i].stage;
        st.module = module;
        st.pName = "main";
        if (kStages[i].stage == VK_SHADER_STAGE_RAYGEN_BIT_KHR ||
            kStages[i].stage == VK_SHADER_STAGE_ANY_HIT_BIT_KHR)
            st.pSpecializationInfo = &spec.info;
        stages.push_back(st);
        stage_bits.push_back(st.stage);
    }
    // Ray generation and miss shaders are "general" groups; the built-in triangles' hit group
    // has the closest hit, and the alpha test as its any-hit shader in a scene with alpha (only
    // the instances not forced opaque run it). Group entries index `stages`, in `used` order.
    const uint32_t exact_stage = kExactStage;
    const uint32_t any_hit = alpha_ ? uint32_t(used.size() - 1) : VK_SHADER_UNUSED_KHR;
    for (uint32_t i = 0; i < kClosestHitStage; ++i)
        groups.push_back(shader_group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, i,
                                      VK_SHADER_UNUSED_KHR, VK_SHADER_UNUSED_KHR,
                                      VK_SHADER_UNUSED_KHR));
    groups.push_back(shader_group(VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR,
                                  VK_SHADER_UNUSED_KHR, kClosestHitStage, VK_SHADER_UNUSED_KHR,
                                  any_hit));
    if (hit_groups_ == 2)
        groups.push_back(shader_group(VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR,
                                      VK_SHADER_UNUSED_KHR, kClosestHitStage, exact_stage,
                                      any_hit));
    VkRayTracingPipelineCreateInfoKHR ci{};
    ci.sType = VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR;
    ci.stageCount = uint32_t(stages.size());
    ci.pStages = stages.data();
    ci.groupCount = uint32_t(groups.size());
    ci.pGroups = groups.data();
    // Only the ray-generation shader traces rays; hit and miss shaders never do.
    ci.maxPipelineRayRecursionDepth = 1;
    ci.layout = bindings_.layout();
    PipelineReporter reporter(ctx_, stage_bits);
    ci.pNext = reporter.chain(nullptr);
    // (VK_PIPELINE_CREATE_RAY_TRACING_SKIP_AABBS_BIT_KHR for pipelines without the procedural
    // group would need the rayTraversalPrimitiveCulling feature, and measured no faster on the
    // H200: docs/gpu.md, "Exact meshes".)
    ci.flags = reporter.flags();
    PipelineCache cache(ctx_, shader_hash);
    const auto t0 = std::chrono::steady_clock::now();
    vk_check(rt_.vkCreateRayTracingPipelinesKHR(device, VK_NULL_HANDLE, cache.handle(), 1, &ci,
                                                nullptr, &pipeline_),
             "compiling the ray-tracing pipeline");
    cache.use().create_s = seconds_since(t0);
    try {
        report_ = reporter.report(pipeline_);
    } catch (...) {
        vkDestroyPipeline(device, pipeline_, nullptr);
        pipeline_ = VK_NULL_HANDLE;
        throw;
    }
    cache.save();
    cache_use_ = cache.use();
}

void RtProgram::create_binding_table() {
    VkPhysicalDeviceRayTracingPipelinePropertiesKHR props{};
    props.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR;
    VkPhysicalDeviceProperties2 p2{};
    p2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    p2.pNext = &props;
    vkGetPhysicalDeviceProperties2(ctx_.physical(), &p2);
    const SbtProperties sp{props.shaderGroupHandleSize, props.shaderGroupHandleAlignment,
                           props.shaderGroupBaseAlignment, props.maxShaderGroupStride};
    const SbtLayout layout = sbt_layout(sp, RT_MISS_COUNT, hit_groups_);

    const uint32_t group_count = 1 + RT_MISS_COUNT + hit_groups_;
    std::vector<uint8_t> handles(size_t(group_count) * sp.handle_size);
    vk_check(rt_.vkGetRayTracingShaderGroupHandlesKHR(ctx_.device(), pipeline_, 0, group_count,
                                                      handles.size(), handles.data()),
             "reading shader group handles");
    const std::vector<uint8_t> table = sbt_table(layout, handles);

    // The table starts at the buffer's first multiple of the base alignment.
    sbt_ = Buffer(ctx_, layout.bytes + sp.base_alignment - 1,
                  VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR |
                      VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  false);
    const VkDeviceAddress base = sbt_.device_address();
    const uint64_t start = sbt_placement(base, sp.base_alignment);
    Uploader up(ctx_);
    up.add_to(sbt_, start, table.data(), table.size());
    up.flush();
    raygen_ = region(base + start, layout.raygen);
    miss_ = region(base + start, layout.miss);
    hit_ = region(base + start, layout.hit);
}

void RtProgram::bind_tlas(VkAccelerationStructureKHR tlas) {
    bindings_.write_acceleration_structure(BINDING_TLAS, tlas);
}

void RtProgram::record_trace(VkCommandBuffer cmd, const void* push, uint32_t width,
                             uint32_t height) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_);
    bindings_.record_bind(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, push);
    // At most 16384 x 16384 = 2^28 invocations (the CLI's size limit), below every device's
    // maxRayDispatchInvocationCount (at least 2^30).
    rt_.vkCmdTraceRaysKHR(cmd, &raygen_, &miss_, &hit_, &callable_, width, height, 1);
}

} // namespace tp
