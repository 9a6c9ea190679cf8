// Ray queries through the render shaders' own trace code, for checks that aim rays at a scene
// directly: the closest hit and the occlusion answer of each ray (render/closest_hits.h), from
// compute mode's BVH traversal (shaders/trace_bvh.glsl or trace_cwbvh.glsl, via
// shaders/closest_hits.comp) or pipeline mode's traceRayEXT on the render's TLAS
// (shaders/trace_rtx.glsl, via shaders/closest_hits.rgen).
#pragma once

#include "render/closest_hits.h"
#include "scene/flatten.h"
#include "shared/features.h"
#include "shared/path.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"

#include <cstdint>
#include <vector>

namespace tp {

class VulkanContext;

// Compute mode on `ctx`, over the BVH in `layout`, in the shape that the feature mask `features`
// gives it (bvh_builder.h: one level without FEATURE_INSTANCING), with the traversal specialized
// to that mask as the render's is. On lavapipe a traversal can be cut by the loop budget
// (shaders/render_items.glsl): such rays are retried alone, and those still cut are counted in
// ClosestHits::truncated.
ClosestHits closest_hits_compute(const VulkanContext& ctx, const FlatScene& scene,
                                 const std::vector<Ray>& rays, BvhLayout layout = BvhLayout::binary,
                                 uint32_t features = FEATURES_ALL);
// Pipeline mode on `ctx`, a context made for pipeline mode. The driver's traversal has no loop
// budget: every answer is final.
ClosestHits closest_hits_pipeline(const VulkanContext& ctx, const FlatScene& scene,
                                  const std::vector<Ray>& rays);

} // namespace tp
