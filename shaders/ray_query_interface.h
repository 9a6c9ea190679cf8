// One ray's answer from the ray-query shaders (closest_hits.comp, closest_hits.rgen) to
// vulkan_rt/renderer/gpu_ray_queries.cpp, which hands it on as render/closest_hits.h's ClosestHits.
// Shared-header dialect (common/shared/lang.h).
#ifndef TP_SHADERS_RAY_QUERY_INTERFACE_H
#define TP_SHADERS_RAY_QUERY_INTERFACE_H

#include "shared/lang.h"

TP_NAMESPACE_BEGIN

struct RayHit {
    float t;
    uint found;
    uint instance;  // where found: the closest hit's FlatScene instance,
    uint primitive; // its triangle within the instance's mesh,
    vec2 bary;      // and the weights of the triangle's vertices 1 and 2
    uint occluded;  // trace_occluded's answer for the same ray
    // Compute mode: the loop budget held (shaders/render_items.glsl), so the answers are final;
    // always 1 in pipeline mode.
    uint budget_held;
};

#ifdef __cplusplus
static_assert(sizeof(RayHit) == 32, "RayHit layout");
#endif

TP_NAMESPACE_END

#endif // TP_SHADERS_RAY_QUERY_INTERFACE_H
