#version 460
// Compute-mode entry point: the render invocations (render_items.glsl) with the software-BVH
// trace include: the binary BVH's, or with TP_TRACE_WIDE the compressed 8-wide BVH's
// (vulkan_rt/CMakeLists.txt builds both modules). The debug variant's other passes take one
// invocation per pixel of the batch's rows.
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
#include "render_items.glsl"
#ifdef TP_DEBUG_SHADER
#include "debug_pass.glsl"
#endif

layout(local_size_x = RENDER_GROUP_SIZE) in;

void main() {
#ifdef TP_DEBUG_SHADER
    if (debug_header.pass != DEBUG_PASS_RENDER) { // uniform: the whole dispatch returns
        uint i = gl_GlobalInvocationID.x;
        debug_pass(uvec2(i % params.camera.width, batch.row_begin + i / params.camera.width));
        return;
    }
#endif
    render_items(gl_GlobalInvocationID.x, gl_NumWorkGroups.x * gl_WorkGroupSize.x);
}
