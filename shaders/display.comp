#version 460
// The viewer's display pass: every pixel's accumulated mean (PixelAccum, interface.h), through
// the display transform of --png (shared/tonemap.h), packed as the 8-bit pixel of the
// swapchain's format (display_interface.h).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require

#include "display_interface.h"
#include "interface.h"
#include "shared/tonemap.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(scalar, set = 0, binding = DISPLAY_BINDING_ACCUM) readonly buffer AccumBuffer {
    PixelAccum accum[];
};
layout(scalar, set = 0, binding = DISPLAY_BINDING_PIXELS) writeonly buffer PixelBuffer {
    uint pixels[];
};
layout(push_constant, scalar) uniform Push {
    DisplayParams display;
};

void main() {
    uvec2 p = gl_GlobalInvocationID.xy + uvec2(0u, display.row_begin);
    if (p.x >= display.width || p.y >= display.row_end) return;
    uint i = p.y * display.width + p.x;
    // The film's mean over the pixel's slots, sum / n in double, rounded to float as the EXR
    // stores it.
    dvec3 sum = dvec3(0.0);
    uint count = 0u;
    for (uint b = 0u; b < display.slots; ++b) {
        sum += accum[i * display.slots + b].sum;
        count += accum[i * display.slots + b].count;
    }
    vec3 mean = count > 0u ? vec3(sum / double(count)) : vec3(0.0f);
    pixels[i] = display_pack(display_srgb8(mean, display.scale), display.bgra);
}
