#version 460
// Closest hit of trace_closest (trace_rtx.glsl): hands the hit back to the ray-generation
// shader, which does all the shading. The instance's custom index is its FlatScene index
// (vulkan_rt/pipeline_mode/accel_inputs.cpp); the primitive is the triangle's index in its mesh,
// because each BLAS holds exactly one mesh's triangles in order; the two attributes are the
// barycentric weights of vertices 1 and 2.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require

#include "rt_interface.h"
#include "trace_hit.glsl"

layout(location = RT_PAYLOAD_HIT) rayPayloadInEXT TraceHit hit;
hitAttributeEXT vec2 bary;

void main() {
    hit.t = gl_HitTEXT;
    hit.instance = uint(gl_InstanceCustomIndexEXT);
    hit.primitive = uint(gl_PrimitiveID);
    hit.bary = bary;
}
