// The debug variant of the render shaders (compiled with -DTP_DEBUG_SHADER; the normal variant
// does not contain any of this, docs/debugging.md): the debug buffer that path logs are written
// to, the AOV buffer, and the debug views. Include it after the trace include and before
// integrator.glsl, whose path log (shared/integrator.h, PATH_LOG) it switches on.
//
// Why a separate SPIR-V module and not a branch on a push constant: a path record is 70 words
// that the loop keeps live from the hit to the end of the bounce; even behind a branch that is
// never taken, the compiler must keep registers (or scratch) for them and the loop grows, so
// the normal render would pay for the debug feature. A compile-time variant costs nothing when
// off, and the debug module is only built into a pipeline when a debug output is requested.
#ifndef TP_SHADERS_DEBUG_GLSL
#define TP_SHADERS_DEBUG_GLSL

#include "bindings.glsl"
#include "scene_access.glsl"
#include "shared/path_log.h"

layout(scalar, set = 0, binding = BINDING_DEBUG) buffer DebugBuffer {
    DebugHeader debug_header;
    PathVertex debug_records[];
};
layout(scalar, set = 0, binding = BINDING_AOV) buffer AovBuffer {
    PixelAov aovs[];
};

// Set by the log pass for the debug pixel only: path_log_emit writes nothing otherwise.
bool g_path_log_on = false;

const bool path_log_recording = true;

void path_log_emit(PathVertex v, uint termination) {
    if (!g_path_log_on) return;
    v.termination = termination;
    uint i = atomicAdd(debug_header.count, 1u);
    if (i < debug_header.capacity) debug_records[i] = v;
}

#include "shared/debug_views.h"

// A debug view's value for sample `sample_index` of pixel (x, y): the camera ray jittered as
// the path loop jitters it, so the views are antialiased like the image.
vec3 debug_view_radiance(uint x, uint y, uint sample_index) {
    RngKey key = rng_key(params.sampler_id, params.seed, y * params.camera.width + x, sample_index);
    Ray ray = camera_ray(params.camera, key, x, y);
#ifdef TP_TRACE_COUNTS
    g_trace_nodes = 0u;
    g_trace_triangles = 0u;
#endif
    PixelAov a = primary_aov(ray);
    uint integrator = debug_header.integrator;
    if (integrator == INTEGRATOR_COST) {
#ifdef TP_TRACE_COUNTS
        return vec3(float(g_trace_nodes), float(g_trace_triangles),
                    float(g_trace_nodes + g_trace_triangles));
#else
        return vec3(0.0f);
#endif
    }
    return debug_view_value(a, integrator);
}

#endif // TP_SHADERS_DEBUG_GLSL
