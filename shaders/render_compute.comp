#version 460
// Compute-mode entry point: one invocation per pixel of the batch's rows, each tracing the
// batch's samples of its pixel with the software-BVH trace include.
#extension GL_GOOGLE_include_directive : require

#include "bindings.glsl"
#include "trace_bvh.glsl"
#include "integrator.glsl"
#include "accumulate.glsl"

layout(local_size_x = RENDER_GROUP_X, local_size_y = RENDER_GROUP_Y) in;

void main() {
    uvec2 pixel = uvec2(gl_GlobalInvocationID.x, batch.row_begin + gl_GlobalInvocationID.y);
    PixelCounts c = pixel_counts_zero();
    if (pixel.x < params.camera.width && pixel.y < batch.row_end) c = render_pixel(pixel);
    counters_flush(c);
}
