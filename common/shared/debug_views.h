// The debug outputs of both engines besides path logs (docs/debugging.md): the AOVs of the
// camera ray's first hit and the debug views drawn from them (`--integrator
// normals|albedo|depth`). Written against the hooks of integrator.h and scene_access.h
// (trace_closest, scene_surface, scene_material, instances[]); each engine includes it where it
// includes those. The cost view measures the engine's own traversal and stays with each engine.
#ifndef TP_SHARED_DEBUG_VIEWS_H
#define TP_SHARED_DEBUG_VIEWS_H

// AOVs of the ray's first hit (PixelAov, path_log.h); instance NO_INDEX where it hits nothing.
PixelAov primary_aov(Ray ray) {
    PixelAov a;
    a.albedo = vec3(0.0f);
    a.depth = FLOAT_MAX;
    a.normal = vec3(0.0f);
    a.instance = NO_INDEX;
    a.material = NO_INDEX;
    a.roughness = 0.0f;
    a.metallic = 0.0f;
    a.pad0 = 0u;
    TraceHit hit;
    if (!trace_closest(ray, hit)) return a;
    SurfacePoint sp = scene_surface(hit);
    Material m = scene_material(hit.instance, sp);
    a.albedo = material_albedo(m);
    if (m.type == MATERIAL_PBR) {
        a.roughness = m.roughness;
        a.metallic = m.metallic;
    }
    a.depth = hit.t;
    a.normal = sp.ns;
    a.instance = hit.instance;
    a.material = instances[hit.instance].material;
    return a;
}

// The value of debug view `integrator` (INTEGRATOR_NORMALS, _ALBEDO or _DEPTH) for a camera
// ray whose first hit gave the AOVs a: black where the ray hits nothing.
vec3 debug_view_value(PixelAov a, uint integrator) {
    if (a.instance == NO_INDEX) return vec3(0.0f);
    if (integrator == INTEGRATOR_NORMALS) return 0.5f * a.normal + 0.5f;
    if (integrator == INTEGRATOR_ALBEDO) return a.albedo;
    return vec3(a.depth);
}

#endif // TP_SHARED_DEBUG_VIEWS_H
