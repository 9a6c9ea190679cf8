#version 460
// Compute-mode entry point: one invocation per pixel of the batch's rows, each tracing the
// batch's samples of its pixel with the software-BVH trace include: the binary BVH's, or with
// TP_TRACE_WIDE the compressed 8-wide BVH's (vulkan_rt/CMakeLists.txt builds both modules).
#extension GL_GOOGLE_include_directive : require

#include "bindings.glsl"
#ifdef TP_TRACE_WIDE
#include "trace_cwbvh.glsl"
#else
#include "trace_bvh.glsl"
#endif
#ifdef TP_DEBUG_SHADER
#include "debug.glsl"
#endif
#include "integrator.glsl"
#include "accumulate.glsl"
#ifdef TP_DEBUG_SHADER
#include "debug_pass.glsl"
#endif

layout(local_size_x = RENDER_GROUP_X, local_size_y = RENDER_GROUP_Y) in;

void main() {
    uvec2 pixel = uvec2(gl_GlobalInvocationID.x, batch.row_begin + gl_GlobalInvocationID.y);
#ifdef TP_DEBUG_SHADER
    if (debug_header.pass != DEBUG_PASS_RENDER) { // uniform: the whole dispatch returns
        debug_pass(pixel);
        return;
    }
#endif
    PixelCounts c = pixel_counts_zero();
    if (pixel.x < params.camera.width && pixel.y < batch.row_end) c = render_pixel(pixel);
    counters_flush(c);
}
