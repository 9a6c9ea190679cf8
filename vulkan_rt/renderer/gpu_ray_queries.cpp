#include "vulkan_rt/renderer/gpu_ray_queries.h"

#include "closest_hits_comp.spv.h"
#include "closest_hits_rgen.spv.h"
#include "closest_hits_wide_comp.spv.h"
#include "shaders/interface.h"
#include "shaders/ray_query_interface.h"
#include "vulkan_rt/compute_mode/bvh_buffers.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/device/barriers.h"
#include "vulkan_rt/device/shader_dispatch.h"
#include "vulkan_rt/pipeline_mode/accel_structures.h"
#include "vulkan_rt/pipeline_mode/rt_functions.h"
#include "vulkan_rt/pipeline_mode/rt_program.h"
#include "vulkan_rt/render_loop/scene_buffers.h"

#include <algorithm>
#include <cstring>

namespace tp {
namespace {

void store(const RayHit& h, size_t i, ClosestHits& out) {
    out.t[i] = h.t;
    out.found[i] = uint8_t(h.found);
    out.instance[i] = h.instance;
    out.primitive[i] = h.primitive;
    out.bary[i] = h.bary;
    out.occluded[i] = uint8_t(h.occluded);
}

} // namespace

ClosestHits closest_hits_compute(const VulkanContext& ctx, const FlatScene& scene,
                                 const std::vector<Ray>& all_rays, BvhLayout layout,
                                 uint32_t features) {
    const BvhBuild bvh = build_bvh(scene, features, layout);
    const bool wide = bvh.layout == BvhLayout::wide;
    const SceneBuffers sb = upload_scene(ctx, scene, scene.params, bvh.mesh_roots, 0);
    const BvhBuffers bb = upload_bvh(ctx, bvh);
    const Buffer dummy(ctx, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    std::vector<const Buffer*> bound;
    for (const Buffer& b : sb.slots) bound.push_back(&b);
    bound.push_back(nullptr); // BINDING_IMAGES: `images`, for the alpha test's texture reads
    const ImageArrayBinding images{BINDING_IMAGES, sb.images.views, sb.images.count};
    static_assert(BINDING_SCENE_COUNT == BINDING_IMAGES && BINDING_IMAGES + 1 == BINDING_BVH_NODES,
                  "the slots below follow interface.h");
    bound.push_back(&bb.nodes);
    bound.push_back(&bb.triangles);
    bound.push_back(&dummy); // accumulators
    bound.push_back(&dummy); // counters
    // Whatever slots the render interface adds after these (debug buffers) get the placeholder
    // too: the rays and hits follow at BINDING_COUNT.
    while (bound.size() < BINDING_COUNT) bound.push_back(&dummy);
    ClosestHits out(all_rays.size());
    // Chunks of 2^18 rays: a few MB per dispatch, and a cut traversal is retried alone.
    const size_t chunk = size_t(1) << 18;
    for (size_t begin = 0; begin < all_rays.size(); begin += chunk) {
        std::vector<Ray> rays(all_rays.begin() + begin,
                              all_rays.begin() + std::min(all_rays.size(), begin + chunk));
        std::vector<size_t> index(rays.size());
        for (size_t i = 0; i < index.size(); ++i) index[i] = begin + i;
        for (int attempt = 0; attempt < 4 && !rays.empty(); ++attempt) {
            BatchParams bp{};
            bp.sample_count = uint32_t(rays.size());
            bp.bvh_top_root = bvh.top_root;
            bp.probe_iterations = LOOP_PROBE_ITERATIONS;
            const auto res = run_compute_shader(
                ctx, wide ? tp_spirv_closest_hits_wide_comp : tp_spirv_closest_hits_comp,
                wide ? sizeof(tp_spirv_closest_hits_wide_comp) : sizeof(tp_spirv_closest_hits_comp),
                {bytes_of(rays)}, {rays.size() * sizeof(RayHit)}, &bp, sizeof(bp),
                uint32_t(rays.size() + 63) / 64, bound, features, &images);
            const std::vector<RayHit> hits = as_vector<RayHit>(res[0]);
            std::vector<Ray> again;
            std::vector<size_t> again_index;
            for (size_t i = 0; i < rays.size(); ++i) {
                if (!hits[i].budget_held) {
                    again.push_back(rays[i]);
                    again_index.push_back(index[i]);
                    continue;
                }
                store(hits[i], index[i], out);
            }
            rays.swap(again);
            index.swap(again_index);
        }
        out.truncated += rays.size();
    }
    return out;
}

ClosestHits closest_hits_pipeline(const VulkanContext& ctx, const FlatScene& scene,
                                  const std::vector<Ray>& rays) {
    // The render's own acceleration structures and pipeline (pipeline_renderer.cpp), with
    // closest_hits.rgen as the ray-generation shader.
    const RtFunctions rt(ctx.device());
    const SceneBuffers sb = upload_scene(ctx, scene, scene.params, {}, kAccelInputUsage);
    const AccelStructures as(ctx, rt, scene, sb);
    RenderConstants constants;
    constants.image_count = sb.images.count;
    RtProgram program(ctx, rt, sizeof(BatchParams), tp_spirv_closest_hits_rgen,
                      sizeof(tp_spirv_closest_hits_rgen), constants, as.exact_count() > 0);
    program.bind_tlas(as.tlas());
    for (uint32_t b = 0; b < sb.slots.size(); ++b) program.bind(b, sb.slots[b]);
    program.bind_images(sb.images.views);
    const Buffer dummy(ctx, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    program.bind(BINDING_ACCUM, dummy);
    program.bind(BINDING_COUNTERS, dummy);

    Uploader up(ctx);
    const Buffer ray_buffer = up.add(rays, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    up.flush();
    const size_t hit_bytes = rays.size() * sizeof(RayHit);
    const Buffer hits(ctx, hit_bytes,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false);
    const Buffer readback(ctx, hit_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    program.bind(BINDING_DEBUG, ray_buffer);
    program.bind(BINDING_AOV, hits);
    BatchParams bp{};
    bp.sample_count = uint32_t(rays.size());
    // A 2D launch of rows of 4096 rays (4.4e6 rays: 1070 rows).
    const uint32_t width = 4096;
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        program.record_trace(cmd, &bp, width, (bp.sample_count + width - 1) / width);
        record_shader_barrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
        const VkBufferCopy region{0, 0, hit_bytes};
        vkCmdCopyBuffer(cmd, hits.handle(), readback.handle(), 1, &region);
        record_host_read_barrier(cmd);
    });
    std::vector<RayHit> h(rays.size());
    std::memcpy(h.data(), readback.mapped(), hit_bytes);
    ClosestHits out(h.size());
    for (size_t i = 0; i < h.size(); ++i) store(h[i], i, out);
    return out;
}

} // namespace tp
