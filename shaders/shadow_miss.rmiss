#version 460
// Miss shader of trace_occluded (trace_rtx.glsl): nothing lies between the point and the light.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require

#include "rt_interface.h"
#include "trace_hit.glsl"

layout(location = RT_PAYLOAD_SHADOW) rayPayloadInEXT TraceHit shadow;

void main() {
    shadow.instance = TRACE_MISS;
}
