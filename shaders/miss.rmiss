#version 460
// Miss shader of trace_closest (trace_rtx.glsl): the ray left the scene.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require

#include "rt_interface.h"
#include "trace_hit.glsl"

layout(location = RT_PAYLOAD_HIT) rayPayloadInEXT TraceHit hit;

void main() {
    hit.instance = TRACE_MISS;
}
