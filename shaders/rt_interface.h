// The ray-tracing pipeline's wiring that the host (vulkan_rt/pipeline_mode/rt_program.cpp, which
// lays out the shader binding table) and the shaders (trace_rtx.glsl and the hit and miss shaders)
// must agree on: which miss shader a traceRayEXT selects and where each payload lives.
//
// Shader groups, in pipeline and binding-table order: ray generation; the miss shaders in
// RT_MISS_* order; the triangle hit group (closest hit only); and, in a pipeline for a scene
// with exact meshes (vulkan_rt/pipeline_mode/accel_inputs.h), the procedural hit group
// (exact_triangle.rint and the same closest hit). Rays add no SBT record offset and stride 0, so an
// instance's own record offset picks its group: RT_HIT_GROUP_TRIANGLES or RT_HIT_GROUP_EXACT.
// Shadow rays skip the closest-hit shader, so they need no group of their own.
#ifndef TP_SHADERS_RT_INTERFACE_H
#define TP_SHADERS_RT_INTERFACE_H

#include "shared/lang.h"

TP_NAMESPACE_BEGIN

const uint RT_MISS_CLOSEST = 0u; // miss.rmiss: closest-hit rays that leave the scene
const uint RT_MISS_SHADOW = 1u;  // shadow_miss.rmiss: unoccluded shadow rays
const uint RT_MISS_COUNT = 2u;
const uint RT_HIT_GROUP_TRIANGLES = 0u; // built-in triangles
const uint RT_HIT_GROUP_EXACT = 1u;     // boxes around triangles, exact_triangle.rint
const uint RT_HIT_GROUP_COUNT = 2u;     // at most; 1 without exact meshes

// Payload locations (traceRayEXT takes an int constant).
const int RT_PAYLOAD_HIT = 0;    // TraceHit (trace_hit.glsl)
const int RT_PAYLOAD_SHADOW = 1; // TraceHit: instance TRACE_MISS free, else occluded

TP_NAMESPACE_END

#endif // TP_SHADERS_RT_INTERFACE_H
