// The interface of the viewer's display pass (shaders/display.comp,
// vulkan_rt/present/progressive_renderer.h): its two storage buffers, its push constants and the
// byte order of a packed pixel. Shared-header dialect (common/shared/lang.h).
#ifndef TP_SHADERS_DISPLAY_INTERFACE_H
#define TP_SHADERS_DISPLAY_INTERFACE_H

#include "shared/lang.h"

TP_NAMESPACE_BEGIN

const uint DISPLAY_BINDING_ACCUM = 0u;  // PixelAccum[width * height * slots]
const uint DISPLAY_BINDING_PIXELS = 1u; // uint[width * height], packed 8-bit pixels
const uint DISPLAY_BINDING_COUNT = 2u;

// A dispatch tone-maps rows [row_begin, row_end) of the image.
struct DisplayParams {
    uint width;
    uint height;
    uint row_begin;
    uint row_end;
    uint slots;  // PixelAccum per pixel, consecutive (one per batch of the Sobol sampler)
    uint bgra;   // 1: the swapchain's format is B8G8R8A8, 0: R8G8B8A8
    float scale; // 2^exposure
};

// An opaque pixel's four bytes in memory order (little-endian words): B, G, R, A for a B8G8R8A8
// image, R, G, B, A for an R8G8B8A8 one.
inline uint display_pack(uvec3 rgb, uint bgra) {
    uvec3 c = bgra != 0u ? uvec3(rgb.b, rgb.g, rgb.r) : rgb;
    return c.x | (c.y << 8u) | (c.z << 16u) | (255u << 24u);
}

TP_NAMESPACE_END

#endif // TP_SHADERS_DISPLAY_INTERFACE_H
