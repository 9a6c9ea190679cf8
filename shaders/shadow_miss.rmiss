#version 460
// Miss shader of trace_occluded (trace_rtx.glsl): nothing lies between the point and the light.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require

#include "rt_interface.h"

layout(location = RT_PAYLOAD_SHADOW) rayPayloadInEXT uint occluded;

void main() {
    occluded = 0u;
}
