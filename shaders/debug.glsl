// The debug variant of the render shaders (compiled with -DTP_DEBUG_SHADER; the normal variant
// does not contain any of this, docs/debugging.md): the debug buffer that path logs are written
// to, the AOV buffer, and the debug views. Include it after the trace include and before
// integrator.glsl, whose PATH_LOG(...) statements it switches on.
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

#define PATH_LOG(x) x

void path_log_emit(PathVertex v, uint termination) {
    if (!g_path_log_on) return;
    v.termination = termination;
    uint i = atomicAdd(debug_header.count, 1u);
    if (i < debug_header.capacity) debug_records[i] = v;
}

// The camera ray's first hit as AOVs (cpu_ref/debug_views.cpp is the CPU's).
PixelAov primary_aov(Ray ray) {
    PixelAov a;
    a.albedo = vec3(0.0f);
    a.depth = FLOAT_MAX;
    a.normal = vec3(0.0f);
    a.instance = NO_INDEX;
    a.material = NO_INDEX;
    a.pad0 = 0u;
    a.pad1 = 0u;
    a.pad2 = 0u;
    TraceHit hit;
    if (!trace_closest(ray, hit)) return a;
    SurfacePoint sp = scene_surface(hit);
    Material m = scene_material(hit.instance, sp.uv);
    a.albedo = material_albedo(m);
    a.depth = hit.t;
    a.normal = sp.ns;
    a.instance = hit.instance;
    a.material = instances[hit.instance].material;
    return a;
}

// A debug view's value for sample `sample_index` of pixel (x, y): the camera ray jittered as
// the path loop jitters it, so the views are antialiased like the image.
vec3 debug_view_radiance(uint x, uint y, uint sample_index) {
    RngKey key = rng_key(params.seed, y * params.camera.width + x, sample_index);
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
    if (a.instance == NO_INDEX) return vec3(0.0f);
    if (integrator == INTEGRATOR_NORMALS) return 0.5f * a.normal + 0.5f;
    if (integrator == INTEGRATOR_ALBEDO) return a.albedo;
    return vec3(a.depth);
}

#endif // TP_SHADERS_DEBUG_GLSL
