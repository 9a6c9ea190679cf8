// Path logs (`render --debug-pixel X,Y --debug-log P.json`, docs/debugging.md): one record per
// path vertex, filled by the path loop of both engines (integrator.h) in the same order from
// the same values, so that `twinpath pathdiff` can hold a GPU path against
// the CPU reference field by field. The GPU writes the records into the debug buffer
// (shaders/debug.glsl); the CPU into a vector. Both go through common/render/path_log.cpp to
// the same JSON.
//
// Also the other debug outputs of the same shader variant: the per-pixel AOVs (`--aov`) and
// the debug views (`--integrator normals|albedo|depth|cost`).
//
// Recording costs nothing when it is off: the loops wrap every recording statement in
// PATH_LOG(...), which is empty in the normal shader (TP_DEBUG_SHADER undefined: the debug
// variant is a separate SPIR-V module) and `if constexpr` on a template parameter in C++.
#ifndef TP_SHARED_PATH_LOG_H
#define TP_SHARED_PATH_LOG_H

#include "camera.h"
#include "path.h"
#include "rng.h"

TP_NAMESPACE_BEGIN

// PathVertex::event
const uint VERTEX_HIT = 0u;  // the ray hit a surface: every field below is filled
const uint VERTEX_MISS = 1u; // the ray left the scene: ray, environment emission and L only

// PathVertex::termination: why the path ended at this vertex (TERM_CONTINUE: it did not).
const uint TERM_CONTINUE = 0u;
const uint TERM_ESCAPED = 1u;      // the ray left the scene
const uint TERM_MAX_DEPTH = 2u;    // max_depth scattering events reached
const uint TERM_NO_SCATTER = 3u;   // the BSDF gave no sample (LOBE_NONE)
const uint TERM_INCONSISTENT = 4u; // the sampled direction is on the wrong side of ng
const uint TERM_ROULETTE = 5u;     // Russian roulette ended it

// PathVertex::shadow
const uint SHADOW_NOT_TRACED = 0u;
const uint SHADOW_UNOCCLUDED = 1u;
const uint SHADOW_OCCLUDED = 2u;

// PathVertex::rng: the random numbers a vertex drew, by RNG_* index (rng.h) of its bounce, as
// floats in [0, 1) (the alias-table slots, drawn as 32-bit words, are shown by their top 24
// bits); -1 where the number was not drawn.
const uint PATH_LOG_RNG = 10u;
const float RNG_NOT_DRAWN = -1.0f;

struct PathVertex {
    uint sample_index;
    uint bounce; // 0: the camera ray's vertex
    uint event;  // VERTEX_*
    uint termination;
    vec3 ray_origin; // the ray that found this vertex
    float t;         // its hit distance (0 for a miss)
    vec3 ray_dir;
    uint instance; // NO_INDEX for a miss
    vec2 bary;     // barycentric weights of vertices 1 and 2 (as the trace returned them)
    uint primitive;
    uint material;
    vec3 position;
    float cos_emit; // dot(ng, wo) before ng is turned to the viewer
    vec3 ng;        // geometric normal (after surface_face_viewer)
    float mis_emission;
    vec3 ns;              // shading normal (after surface_face_viewer)
    uint light;           // light chosen for next-event estimation, NO_INDEX: none
    vec3 emitted;         // radiance added by emission at this vertex (T, MIS included)
    float light_pdf;      // selection x sampling pdf of the light sample (solid angle)
    vec3 light_wi;        // direction to the light sample
    float light_bsdf_pdf; // BSDF pdf of light_wi (the other MIS strategy)
    vec3 light_f;         // BRDF value towards the light sample
    float mis_light;      // MIS weight of the light sample (1 for delta lights)
    vec3 nee;             // next-event contribution (added when shadow is SHADOW_UNOCCLUDED)
    uint shadow;          // SHADOW_*
    float rng[PATH_LOG_RNG];
    vec3 wi;          // sampled direction
    float bsdf_pdf;   // its pdf (for delta lobes the lobe probability)
    vec3 bsdf_weight; // f |cos| / pdf
    uint lobe;        // LOBE_* flags
    vec3 throughput;  // after this vertex (scattering and roulette)
    float roulette_q; // survival probability (1: no roulette)
    vec3 radiance;    // L after this vertex
    float roughness;  // the material at the hit, textures applied: PBR roughness (0 otherwise)
    vec3 base_color;  // kd: Phong's diffuse reflectance, PBR's base colour
    float metallic;   // PBR metallic (0 otherwise)
    float transmission; // PBR transmission (0 otherwise)
    float alpha;        // coverage (1 for opaque materials)
};

inline PathVertex path_vertex_begin(uint sample_index, uint bounce, Ray ray) {
    PathVertex v;
    v.sample_index = sample_index;
    v.bounce = bounce;
    v.event = VERTEX_MISS;
    v.termination = TERM_CONTINUE;
    v.ray_origin = ray.origin;
    v.t = 0.0f;
    v.ray_dir = ray.dir;
    v.instance = NO_INDEX;
    v.bary = vec2(0.0f);
    v.primitive = NO_INDEX;
    v.material = NO_INDEX;
    v.position = vec3(0.0f);
    v.cos_emit = 0.0f;
    v.ng = vec3(0.0f);
    v.mis_emission = 0.0f;
    v.ns = vec3(0.0f);
    v.light = NO_INDEX;
    v.emitted = vec3(0.0f);
    v.light_pdf = 0.0f;
    v.light_wi = vec3(0.0f);
    v.light_bsdf_pdf = 0.0f;
    v.light_f = vec3(0.0f);
    v.mis_light = 0.0f;
    v.nee = vec3(0.0f);
    v.shadow = SHADOW_NOT_TRACED;
    for (uint k = 0u; k < PATH_LOG_RNG; ++k) v.rng[k] = RNG_NOT_DRAWN;
    v.wi = vec3(0.0f);
    v.bsdf_pdf = 0.0f;
    v.bsdf_weight = vec3(0.0f);
    v.lobe = LOBE_NONE;
    v.throughput = vec3(0.0f);
    v.roulette_q = 1.0f;
    v.radiance = vec3(0.0f);
    v.roughness = 0.0f;
    v.base_color = vec3(0.0f);
    v.metallic = 0.0f;
    v.transmission = 0.0f;
    v.alpha = 1.0f;
    return v;
}

// ---- the debug buffer (Vulkan: BINDING_DEBUG, shaders/debug.glsl) ---------------------------
const uint DEBUG_PASS_RENDER = 0u; // render the image with `integrator`
const uint DEBUG_PASS_LOG = 1u;    // trace the debug pixel's samples, recording every vertex
const uint DEBUG_PASS_AOV = 2u;    // write every pixel's AOVs (BINDING_AOV)

const uint INTEGRATOR_PATH = 0u;
const uint INTEGRATOR_NORMALS = 1u; // 0.5 ns + 0.5 of the camera ray's hit
const uint INTEGRATOR_ALBEDO = 2u;  // material_albedo of the camera ray's hit
const uint INTEGRATOR_DEPTH = 3u;   // hit distance of the camera ray (0: miss)
const uint INTEGRATOR_COST = 4u;    // traversal cost of the camera ray (docs/debugging.md)

// The header of the debug buffer; PathVertex records follow it.
struct DebugHeader {
    uint pass;       // DEBUG_PASS_*
    uint integrator; // INTEGRATOR_*
    uint pixel_x;    // DEBUG_PASS_LOG: the pixel
    uint pixel_y;
    uint capacity; // records the buffer holds
    uint count;    // records written (may exceed capacity: the excess was dropped)
    uint pad0;
    uint pad1;
};

// ---- AOVs (`--aov`): the camera ray through the pixel centre, no jitter, so deterministic ----
struct PixelAov {
    vec3 albedo;   // material_albedo (0 for a miss)
    float depth;   // hit distance along the centre ray; FLOAT_MAX for a miss
    vec3 normal;   // shading normal as interpolated (not turned to the viewer); 0 for a miss
    uint instance; // NO_INDEX for a miss
    uint material; // NO_INDEX for a miss
    float roughness; // PBR roughness and metallic with textures applied (0 otherwise)
    float metallic;
    uint pad0;
};

// What an albedo AOV shows: the reflectance at normal incidence (Phong kd + ks, the mirror's
// tint, the dielectric's transmission filter, a PBR material's base colour), emission not
// included.
inline vec3 material_albedo(Material m) {
    if (m.type == MATERIAL_MIRROR) return m.ks;
    if (m.type == MATERIAL_DIELECTRIC) return m.tf;
    if (m.type == MATERIAL_PBR) return m.kd;
    return m.kd + m.ks;
}

// The material fields a path log records at a hit (the PBR ones are 0 for other kinds).
inline void path_vertex_set_material(INOUT(PathVertex) v, Material m) {
    bool pbr = m.type == MATERIAL_PBR;
    v.base_color = m.kd;
    v.roughness = pbr ? m.roughness : 0.0f;
    v.metallic = pbr ? m.metallic : 0.0f;
    v.transmission = pbr ? m.transmission : 0.0f;
    v.alpha = m.alpha_mode == ALPHA_OPAQUE ? 1.0f : m.alpha;
}

// The camera ray through the centre of pixel (x, y).
inline Ray camera_center_ray(Camera c, uint x, uint y) {
    Ray r;
    r.origin = c.eye;
    r.dir = camera_direction(c, float(x) + 0.5f, float(y) + 0.5f);
    r.tmax = FLOAT_MAX;
    r.tag = 0u;
    return r;
}

#ifdef __cplusplus
static_assert(sizeof(PathVertex) == 304, "PathVertex layout");
static_assert(offsetof(PathVertex, rng) == 176 && offsetof(PathVertex, radiance) == 264 &&
                  offsetof(PathVertex, alpha) == 300,
              "PathVertex layout");
static_assert(sizeof(DebugHeader) == 32, "DebugHeader layout");
static_assert(sizeof(PixelAov) == 48, "PixelAov layout");
#endif

TP_NAMESPACE_END

#endif // TP_SHARED_PATH_LOG_H
