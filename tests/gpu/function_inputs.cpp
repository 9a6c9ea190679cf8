#include "function_inputs.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstring>

namespace tp::test {

float InputGen::any_bits() {
    const uint32_t bits = u32();
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
}

vec3 InputGen::unit() {
    std::normal_distribution<double> n;
    glm::dvec3 v(n(rng_), n(rng_), n(rng_));
    return vec3(glm::normalize(v));
}

vec3 InputGen::towards(vec3 n) {
    const vec3 v = unit();
    return glm::dot(v, n) < 0.0f ? -v : v;
}

void InputGen::phong(vec3& kd, vec3& ks, float& ns) {
    for (int c = 0; c < 3; ++c) {
        const float total = uni();
        const float split = uni();
        kd[c] = total * split;
        ks[c] = total * (1.0f - split);
    }
    if (chance(0.2f)) ks = vec3(0.0f);
    ns = chance(0.1f) ? 0.0f : log_uniform(1.0f, 1e4f);
}

void InputGen::transform(vec4 rows[3], vec4 inverse_rows[3]) {
    const glm::dquat q =
        glm::normalize(glm::dquat(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
    const glm::dmat3 s(glm::dvec3(log_uniform(0.2f, 5.0f), 0, 0),
                       glm::dvec3(0, log_uniform(0.2f, 5.0f), 0),
                       glm::dvec3(0, 0, log_uniform(0.2f, 5.0f)));
    glm::dmat4 m(glm::mat3_cast(q) * s);
    m[3] = glm::dvec4(glm::dvec3(box(10.0f)), 1.0);
    const glm::dmat4 inv = glm::inverse(m);
    for (int r = 0; r < 3; ++r) {
        rows[r] = vec4(float(m[0][r]), float(m[1][r]), float(m[2][r]), float(m[3][r]));
        inverse_rows[r] =
            vec4(float(inv[0][r]), float(inv[1][r]), float(inv[2][r]), float(inv[3][r]));
    }
}

namespace {

void set3(FnIn& x, int i, vec3 v, float w = 0.0f) {
    x.f[i] = vec4(v, w);
}

// An intersector's factor on the ray-offset bound (shared/offset.h): the engines' 1 and 4.
float slack(InputGen& g) {
    return g.chance(0.5f) ? 1.0f : 4.0f;
}

void light(InputGen& g, FnIn& x, uint32_t type) {
    x.u.y = type;
    if (type == LIGHT_DIRECTIONAL) {
        set3(x, 6, g.unit());
    } else if (type == LIGHT_TRIANGLE) {
        const vec3 a = g.box(5.0f), b = g.box(5.0f), c = g.box(5.0f);
        const float area =
            float(0.5 * glm::length(glm::cross(glm::dvec3(b - a), glm::dvec3(c - a))));
        set3(x, 6, a, area);
        set3(x, 7, b);
        set3(x, 8, c);
    } else {
        set3(x, 6, g.box(10.0f));
    }
    set3(x, 9, g.color(100.0f));
}

void material(InputGen& g, FnIn& x) {
    vec3 kd, ks;
    float ns;
    g.phong(kd, ks, ns);
    x.u.x = g.below(3);
    set3(x, 0, kd, ns);
    set3(x, 1, ks, g.uniform(1.01f, 3.0f));
    set3(x, 6, g.color(1.0f));
}

// Surface frame and directions for the BSDF functions: n f2, wo f3, wi f4 (near the mirror
// direction half of the time, where the Phong lobe is), u_lobe f5.x, u_dir f5.yz.
void bsdf_directions(InputGen& g, FnIn& x) {
    const vec3 n = g.unit();
    const vec3 wo = g.chance(0.9f) ? g.towards(n) : g.unit();
    vec3 wi = g.towards(n);
    if (g.chance(0.5f)) {
        const vec3 r = glm::normalize(2.0f * glm::dot(n, wo) * n - wo);
        wi = glm::normalize(r + g.box(g.log_uniform(1e-4f, 0.3f)));
    }
    set3(x, 2, n);
    set3(x, 3, wo);
    set3(x, 4, wi);
    x.f[5] = vec4(g.uni(), g.uni(), g.uni(), 0.0f);
}

// A GGX width: the smooth limit's 1e-4 up to 1, log-uniform, with both ends.
float ggx_alpha(InputGen& g) {
    const float r = g.uni();
    return r < 0.05f ? 1e-4f : r < 0.1f ? 1.0f : g.log_uniform(1e-4f, 1.0f);
}

// A glTF material (fn_pbr_material): roughness 0, around the smooth limit 0.01 and up to 1,
// metallic and transmission at 0, 1 and between, a clamped coloured f0, volumes met from
// outside and inside, attenuation or none.
void pbr_material(InputGen& g, FnIn& x) {
    const float r = g.uni();
    const float roughness = r < 0.1f    ? 0.0f
                            : r < 0.15f ? 0.0099f
                            : r < 0.2f  ? 0.0101f
                            : r < 0.25f ? 1.0f
                                        : g.log_uniform(0.01f, 1.0f);
    const float m = g.uni();
    const float metallic = m < 0.3f ? 0.0f : m < 0.45f ? 1.0f : g.uni();
    const float t = g.uni();
    const float transmission = t < 0.4f ? 0.0f : t < 0.7f ? 1.0f : g.uni();
    const bool volume = g.chance(0.4f);
    float ior = g.uniform(1.0f, 3.0f);
    if (volume && g.chance(0.5f)) ior = 1.0f / ior;
    set3(x, 6, g.color(1.0f), metallic);
    set3(x, 7, g.chance(0.7f) ? vec3(1.0f) : g.color(4.0f), roughness);
    x.f[8] = vec4(ior, transmission, g.chance(0.7f) ? 1.0f : g.uni(),
                  g.chance(0.3f) ? FLOAT_MAX : g.log_uniform(1e-3f, 1e3f));
    set3(x, 9, g.color(1.0f));
    x.u.x = volume ? MATERIAL_FLAG_VOLUME : 0u;
}

// n f2, wo f3, wi f4, u f5 as for the Phong functions, with wi also near the thin-walled
// transmission's lobe (-wo) and wo down to 1e-4 of the horizon.
void pbr_directions(InputGen& g, FnIn& x) {
    bsdf_directions(g, x);
    const vec3 n = vec3(x.f[2]);
    if (g.chance(0.2f)) {
        const vec3 t = glm::normalize(g.unit() - n * glm::dot(g.unit(), n));
        const float c = g.log_uniform(1e-4f, 0.1f);
        if (std::isfinite(t.x)) set3(x, 3, glm::normalize(c * n + std::sqrt(1.0f - c * c) * t));
    }
    if (g.chance(0.25f))
        set3(x, 4, glm::normalize(-vec3(x.f[3]) + g.box(g.log_uniform(1e-4f, 0.5f))));
}

} // namespace

void make_input(uint32_t id, InputGen& g, FnIn& x) {
    x = FnIn{};
    const vec3 n = g.unit();
    switch (id) {
    case FN_MAX3:
    case FN_AVERAGE:
        set3(x, 0, g.box(10.0f));
        break;
    case FN_LUMINANCE:
        set3(x, 0, g.color(10.0f));
        break;
    case FN_IS_FINITE:
    case FN_IS_FINITE3:
        set3(x, 0, vec3(g.any_bits(), g.chance(0.5f) ? g.any_bits() : 1.0f, g.any_bits()));
        if (g.chance(0.2f)) x.f[0].x = g.chance(0.5f) ? INFINITY : NAN;
        break;
    case FN_IS_BLACK:
        for (int c = 0; c < 3; ++c) x.f[0][c] = g.chance(0.6f) ? 0.0f : g.uniform(-1, 1);
        break;
    case FN_SAFE_SQRT:
        x.f[0].x = g.chance(0.1f) ? -g.uni() : g.log_uniform(1e-20f, 1e20f);
        break;
    case FN_EXPM1_PRECISE:
        x.f[0].x = g.chance(0.3f) ? g.uniform(-1e-3f, 1e-3f) : g.uniform(-20.0f, 2.0f);
        break;
    case FN_ORTHONORMAL_BASIS:
        set3(x, 0, n);
        break;
    case FN_FRAME_TO_WORLD: {
        vec3 t, b;
        orthonormal_basis(n, t, b);
        set3(x, 0, g.unit());
        set3(x, 1, t);
        set3(x, 2, b);
        set3(x, 3, n);
        break;
    }
    case FN_PCG4D:
    case FN_UINT_TO_UNIT_FLOAT:
    case FN_RNG_KEY:
    case FN_RNG_GET:
    case FN_RNG_BOUNCE2:
    case FN_UMUL_HI:
    case FN_RNG_GET_BITS:
    case FN_RNG_BOUNCE2_BITS:
    case FN_LAINE_KARRAS_PERMUTATION:
    case FN_NESTED_UNIFORM_SCRAMBLE:
    case FN_SOBOL_DIM1:
    case FN_ALIAS_RESOLVE:
        x.u = uvec4(g.u32(), g.u32(), g.u32(), g.u32());
        x.f[0] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        break;
    case FN_RNG_BOUNCE_DIM:
        x.u = uvec4(g.below(1000), g.below(10), 0u, 0u);
        break;
    case FN_RNG_GROUP_FIRST:
        x.u = uvec4(g.below(1000), 0u, 0u, 0u);
        break;
    case FN_SAMPLE_COSINE_HEMISPHERE:
    case FN_SAMPLE_UNIFORM_SPHERE:
    case FN_SAMPLE_UNIFORM_TRIANGLE:
        x.f[0] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        break;
    case FN_COSINE_HEMISPHERE_PDF:
        x.f[0].x = g.uniform(-1.0f, 1.0f);
        break;
    case FN_PHONG_POWER:
    case FN_PHONG_LOBE_PDF:
        x.f[0].x = g.chance(0.1f) ? g.uniform(-1.0f, 0.0f) : 1.0f - g.uni();
        if (g.chance(0.5f)) x.f[0].x = 1.0f - g.log_uniform(1e-7f, 1.0f); // near the lobe axis
        x.f[0].y = g.chance(0.1f) ? 0.0f : g.log_uniform(0.5f, 1e4f);
        break;
    case FN_SAMPLE_PHONG_LOBE:
        x.f[0] = vec4(g.uni(), g.uni(), g.chance(0.1f) ? 0.0f : g.log_uniform(0.5f, 1e5f), 0.0f);
        break;
    case FN_ALIAS_SLOT:
        x.u.x = 1 + g.below(1000000);
        x.u.y = g.u32();
        break;
    case FN_BSDF_SAMPLE_NONE:
    case FN_LIGHT_SAMPLE_NONE:
        break;
    case FN_MIRROR_DIRECTION:
    case FN_MIRROR_SAMPLE:
        set3(x, 1, g.color(1.0f));
        set3(x, 2, n);
        set3(x, 3, id == FN_MIRROR_DIRECTION ? g.towards(n) : g.unit());
        break;
    case FN_PHONG_DIFFUSE_PROBABILITY:
    case FN_PHONG_EVAL:
    case FN_PHONG_PDF:
    case FN_PHONG_SAMPLE: {
        vec3 kd, ks;
        float ns;
        g.phong(kd, ks, ns);
        set3(x, 0, kd, ns);
        set3(x, 1, ks);
        if (id == FN_PHONG_DIFFUSE_PROBABILITY && g.chance(0.1f)) {
            set3(x, 0, vec3(0.0f));
            set3(x, 1, vec3(0.0f));
        }
        bsdf_directions(g, x);
        break;
    }
    case FN_FRESNEL_DIELECTRIC:
        x.f[0] = vec4(g.uni(), g.uniform(0.3f, 3.0f), 0.0f, 0.0f);
        break;
    case FN_DIELECTRIC_SAMPLE:
        set3(x, 1, vec3(0.0f), g.uniform(1.01f, 3.0f));
        set3(x, 6, g.color(1.0f));
        set3(x, 2, n);
        set3(x, 3, g.unit());
        x.f[5].x = g.uni();
        break;
    case FN_MATERIAL_IS_DELTA:
    case FN_BSDF_EVAL:
    case FN_BSDF_PDF:
    case FN_BSDF_SAMPLE:
        material(g, x);
        bsdf_directions(g, x);
        break;
    case FN_SAMPLE_POINT_LIGHT:
        light(g, x, LIGHT_POINT);
        set3(x, 0, g.box(10.0f));
        break;
    case FN_SAMPLE_DIRECTIONAL_LIGHT:
        light(g, x, LIGHT_DIRECTIONAL);
        break;
    case FN_TRIANGLE_LIGHT_NORMAL:
        light(g, x, LIGHT_TRIANGLE);
        break;
    case FN_TRIANGLE_LIGHT_PDF:
        x.f[0] = vec4(g.chance(0.1f) ? 0.0f : g.uniform(0.0f, 10.0f), g.log_uniform(0.01f, 100.0f),
                      g.uniform(-0.5f, 1.0f), 0.0f);
        break;
    case FN_SAMPLE_TRIANGLE_LIGHT:
        light(g, x, LIGHT_TRIANGLE);
        set3(x, 0, g.box(10.0f));
        // z: the normal from the vertices (1) or as stored (0).
        x.f[1] = vec4(g.uni(), g.uni(), float(g.below(2)), 0.0f);
        break;
    case FN_SAMPLE_CONSTANT_ENVIRONMENT:
        light(g, x, LIGHT_ENVIRONMENT);
        x.f[1] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        break;
    case FN_ENVIRONMENT_MAP_PDF:
        x.f[0] = vec4(g.uniform(0.0f, 1e-3f), g.uniform(-0.1f, 1.0f), 0.0f, 0.0f);
        x.u = uvec4(1 + g.below(4096), 1 + g.below(4096), 0u, 0u);
        break;
    case FN_ENVIRONMENT_MAP_PIXEL_POINT:
    case FN_SAMPLE_ENVIRONMENT_MAP:
        x.u = uvec4(1 + g.below(2048), 1 + g.below(2048), 0u, 0u);
        x.u.z = g.below(x.u.x * x.u.y);
        x.f[0] = vec4(g.log_uniform(1e-9f, 1e-2f), g.uniform(-3.14159f, 3.14159f), 0.0f, 0.0f);
        if (id == FN_ENVIRONMENT_MAP_PIXEL_POINT) x.f[0] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        x.f[1] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        break;
    case FN_ENVIRONMENT_MAP_COORDS:
    case FN_ROTATE_Y:
        set3(x, 0, n, g.uniform(-3.14159f, 3.14159f));
        break;
    case FN_ENVIRONMENT_MAP_PIXEL:
        x.f[0] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        if (g.chance(0.1f)) x.f[0].x = 1.0f;
        x.u = uvec4(1 + g.below(4096), 1 + g.below(4096), 0u, 0u);
        break;
    case FN_SAMPLE_LIGHT: {
        const uint32_t type = g.below(4);
        light(g, x, type);
        set3(x, 0, g.box(10.0f));
        x.f[1] = vec4(g.uni(), g.uni(), float(g.below(2)), 0.0f);
        break;
    }
    case FN_UV_TO_IMAGE:
        x.f[0] = vec4(g.uniform(-2.0f, 2.0f), g.uniform(-2.0f, 2.0f), 0.0f, 0.0f);
        break;
    case FN_WRAP_TEXEL: {
        x.u.x = 1 + g.below(4096);
        const int n_i = int(x.u.x);
        const int k = int(g.below(9)) - 4;
        x.f[0].x = float(g.chance(0.3f) ? k * n_i : k * n_i + int(g.below(uint32_t(n_i))));
        break;
    }
    case FN_TEXTURE_FOOTPRINT:
        x.f[0] = vec4(g.uniform(-2.0f, 3.0f), g.uniform(-2.0f, 3.0f), 0.0f, 0.0f);
        // Wrap modes of t and s (SLOT_WRAP_*: repeat, clamp, mirror).
        x.u = uvec4(1 + g.below(2048), 1 + g.below(2048), g.below(3), g.below(3));
        break;
    case FN_TEXTURE_BILERP:
        for (int i = 0; i < 4; ++i) {
            set3(x, i, g.color(10.0f));
            x.f[i].w = g.uni();
        }
        x.f[4] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        break;
    case FN_LATLONG_TO_DIRECTION:
        x.f[0] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        break;
    case FN_DIRECTION_TO_LATLONG:
        set3(x, 0, n);
        break;
    case FN_INSTANCE_POINT_TO_WORLD:
    case FN_INSTANCE_VECTOR_TO_WORLD:
    case FN_INSTANCE_POINT_TO_OBJECT:
    case FN_INSTANCE_VECTOR_TO_OBJECT:
    case FN_INSTANCE_NORMAL_TO_WORLD:
    case FN_SURFACE_POINT:
    case FN_SURFACE_SET_SHADING_NORMAL: {
        vec4 rows[3], inv[3];
        g.transform(rows, inv);
        for (int r = 0; r < 3; ++r) {
            x.f[r] = rows[r];
            x.f[3 + r] = inv[r];
        }
        const vec3 n2 = g.unit();
        set3(x, 6, g.box(5.0f), n2.x);
        set3(x, 7, g.box(5.0f), n2.y);
        set3(x, 8, g.box(5.0f), n2.z);
        const float u = g.uni(), v = g.uni();
        x.f[9] = u + v <= 1.0f ? vec4(u, v, 0.0f, 0.0f) : vec4(1.0f - u, 1.0f - v, 0.0f, 0.0f);
        set3(x, 10, g.unit());
        set3(x, 11, g.unit());
        break;
    }
    case FN_BARYCENTRIC_MIX3:
    case FN_BARYCENTRIC_MIX2: {
        set3(x, 0, g.box(10.0f));
        set3(x, 1, g.box(10.0f));
        set3(x, 2, g.box(10.0f));
        const float u = g.uni(), v = g.uni();
        x.f[id == FN_BARYCENTRIC_MIX3 ? 3 : 2] =
            u + v <= 1.0f ? vec4(u, v, 0.0f, 0.0f) : vec4(1.0f - u, 1.0f - v, 0.0f, 0.0f);
        break;
    }
    case FN_SURFACE_FACE_VIEWER:
        set3(x, 6, g.box(10.0f));
        set3(x, 7, n);
        set3(x, 8, g.chance(0.5f) ? g.towards(n) : g.unit());
        x.f[9] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        set3(x, 10, g.unit());
        break;
    case FN_POWER_HEURISTIC:
    case FN_EMISSION_MIS_WEIGHT:
        x.f[0] = vec4(g.log_uniform(1e-10f, 1e10f), g.log_uniform(1e-10f, 1e10f), 0.0f, 0.0f);
        if (g.chance(0.05f)) x.f[0].x = 0.0f;
        if (g.chance(0.05f)) x.f[0].y = 0.0f;
        if (g.chance(0.05f)) x.f[0].x = INFINITY;
        x.u.x = g.below(2);
        break;
    case FN_SCATTER_IS_CONSISTENT: {
        static const uint32_t lobes[4] = {LOBE_DIFFUSE, LOBE_GLOSSY, LOBE_SPECULAR,
                                          LOBE_SPECULAR | LOBE_TRANSMISSION};
        set3(x, 0, n);
        set3(x, 1, g.unit());
        set3(x, 2, g.unit());
        x.u.x = lobes[g.below(4)];
        break;
    }
    case FN_SPAWN_RAY: {
        const vec3 p = g.box(g.log_uniform(1e-4f, 1e5f));
        set3(x, 0, p, slack(g));
        set3(x, 1, n);
        set3(x, 2, g.unit());
        set3(x, 3, point_error_bound(glm::abs(p) + g.box(1.0f), p));
        break;
    }
    case FN_OFFSET_RAY_ORIGIN: {
        const vec3 p = g.box(g.log_uniform(1e-4f, 1e5f));
        set3(x, 0, p, slack(g));
        set3(x, 1, point_error_bound(glm::abs(p) + g.box(1.0f), p));
        set3(x, 2, n);
        break;
    }
    case FN_SURFACE_SNAP_TO_RAY: {
        // A point of a plane, a ray that meets the plane near it at |cos| >= 0.05.
        const vec3 p = g.box(10.0f);
        vec3 d = g.unit();
        while (std::abs(glm::dot(d, n)) < 0.05f) d = g.unit();
        set3(x, 0, p);
        set3(x, 1, point_error_bound(glm::abs(p), p));
        set3(x, 2, n);
        set3(x, 3, p + g.box(1e-3f) - g.log_uniform(0.01f, 100.0f) * d);
        set3(x, 4, d);
        break;
    }
    case FN_SHADOW_RAY: {
        const vec3 p = g.box(10.0f), wi = g.unit();
        set3(x, 5, point_error_bound(glm::abs(p), p));
        const float dist = g.chance(0.3f) ? FLOAT_MAX : g.log_uniform(0.1f, 100.0f);
        set3(x, 0, p, slack(g));
        set3(x, 1, n, float(g.below(2))); // w: the light's normal from its vertices
        set3(x, 2, wi, dist);
        set3(x, 3, g.color(10.0f), g.uni());
        set3(x, 4, dist >= FLOAT_MAX ? vec3(0.0f) : p + dist * wi);
        light(g, x, g.below(3));
        x.u.x = g.below(2);
        break;
    }
    case FN_CAMERA_MAKE:
    case FN_CAMERA_DIRECTION: {
        const vec3 eye = g.box(10.0f), target = eye + g.unit() * g.log_uniform(0.1f, 10.0f);
        vec3 up = g.unit();
        while (glm::length(glm::cross(glm::normalize(target - eye), up)) < 1e-3f) up = g.unit();
        const float fov = g.uniform(1.0f, 170.0f);
        const uint32_t w = 1 + g.below(4096), h = 1 + g.below(4096);
        if (id == FN_CAMERA_MAKE) {
            set3(x, 0, eye, fov);
            set3(x, 1, target);
            set3(x, 2, up);
            x.u = uvec4(w, h, 0u, 0u);
        } else {
            const Camera c = camera_make(eye, target, up, fov, w, h);
            set3(x, 0, c.eye, c.tan_half_fov_y);
            set3(x, 1, c.forward, c.aspect);
            set3(x, 2, c.right);
            set3(x, 3, c.up);
            x.u = uvec4(w, h, 0u, 0u);
            x.f[4] = vec4(g.uniform(0.0f, float(w)), g.uniform(0.0f, float(h)), 0.0f, 0.0f);
        }
        break;
    }
    case FN_ROULETTE_SURVIVAL:
    case FN_ROULETTE_APPLY:
        set3(x, 0, g.color(2.0f), g.uni());
        x.u = uvec4(g.below(10), g.below(10), 0u, 0u);
        break;
    case FN_RAY_INVERSE_DIRECTION:
    case FN_WATERTIGHT_RAY: {
        vec3 d = n;
        for (int c = 0; c < 3; ++c) {
            if (g.chance(0.1f)) d[c] = 0.0f;
            if (g.chance(0.05f)) d[c] = 1e-25f;
        }
        if (d == vec3(0.0f)) d.x = 1.0f;
        set3(x, 0, d);
        break;
    }
    case FN_INTERSECT_AABB: {
        vec3 d = n;
        if (g.chance(0.2f)) d[g.below(3)] = 0.0f;
        const vec3 a = g.box(5.0f), b = g.box(5.0f);
        set3(x, 0, g.box(10.0f), g.chance(0.5f) ? FLOAT_MAX : g.uniform(0.0f, 20.0f));
        set3(x, 1, ray_inverse_direction(d));
        set3(x, 2, glm::min(a, b));
        set3(x, 3, glm::max(a, b));
        break;
    }
    case FN_INTERSECT_TRIANGLE: {
        const vec3 a = g.box(5.0f), b = g.box(5.0f), c = g.box(5.0f), org = g.box(10.0f);
        vec3 d = g.unit();
        if (g.chance(0.7f)) { // aimed at a point of the triangle's plane near it
            const float u = g.uniform(-0.2f, 1.2f), v = g.uniform(-0.2f, 1.2f);
            d = vec3(glm::normalize(glm::dvec3(a + u * (b - a) + v * (c - a) - org)));
        }
        set3(x, 0, org, g.chance(0.5f) ? FLOAT_MAX : g.uniform(0.0f, 20.0f));
        set3(x, 1, d);
        set3(x, 2, a);
        set3(x, 3, b);
        set3(x, 4, c);
        break;
    }
    case FN_GGX_D:
        // Microfacet normals around the pole, where D's peak is, and anywhere.
        set3(x, 0,
             g.chance(0.5f)
                 ? glm::normalize(vec3(0.0f, 0.0f, 1.0f) + g.box(g.log_uniform(1e-5f, 1.0f)))
                 : n,
             ggx_alpha(g));
        break;
    case FN_GGX_G1:
    case FN_GGX_VISIBILITY_CORRELATED:
    case FN_GGX_VISIBILITY_SEPARABLE:
        set3(x, 0, g.chance(0.2f) ? glm::normalize(vec3(n.x, n.y, g.uniform(-1e-3f, 1e-3f))) : n,
             ggx_alpha(g));
        set3(x, 1, g.unit());
        break;
    case FN_GGX_SAMPLE_VISIBLE_NORMAL:
    case FN_GGX_VISIBLE_NORMAL_PDF: {
        // v above the surface, down to 1e-4 of the horizon; h from the sampler or anywhere.
        vec3 v = g.towards(vec3(0.0f, 0.0f, 1.0f));
        if (g.chance(0.2f)) v = glm::normalize(vec3(v.x, v.y, g.log_uniform(1e-4f, 1e-2f)));
        const float alpha = ggx_alpha(g);
        set3(x, 0, v, alpha);
        if (id == FN_GGX_SAMPLE_VISIBLE_NORMAL)
            x.f[1] = vec4(g.uni(), g.uni(), 0.0f, 0.0f);
        else
            set3(x, 1,
                 g.chance(0.7f) ? ggx_sample_visible_normal(v, alpha, vec2(g.uni(), g.uni()))
                                : g.unit());
        break;
    }
    case FN_PBR_EVAL:
    case FN_PBR_PDF:
    case FN_PBR_SAMPLE:
        pbr_material(g, x);
        pbr_directions(g, x);
        break;
    case FN_PBR_DIELECTRIC_FRESNEL:
        pbr_material(g, x);
        x.f[0].x = g.chance(0.1f) ? -1.0f : g.chance(0.1f) ? 1.0f : g.uni();
        break;
    case FN_PBR_VOLUME_TRANSMITTANCE:
        pbr_material(g, x);
        if (g.chance(0.1f)) x.f[9].x = 0.0f;
        x.f[0].x = g.chance(0.1f) ? 0.0f : g.log_uniform(1e-4f, 1e3f);
        break;
    case FN_ALPHA_BLEND_THRESHOLD:
    case FN_ALPHA_COVERS:
        // instance, primitive, alpha mode, the ray's tag
        x.u = uvec4(g.below(1000), g.u32(), g.below(3), g.u32());
        x.f[2] = vec4(g.chance(0.2f) ? float(g.below(2)) : g.uni(), g.uni(), 0.0f, 0.0f);
        break;
    case FN_SRGB_TO_LINEAR:
        x.f[0].x = g.chance(0.2f) ? float(g.below(256)) / 255.0f : g.uni();
        if (g.chance(0.05f)) x.f[0].x = 0.04045f;
        break;
    case FN_UNPACK_RGBA8:
    case FN_UNPACK_RGBA16:
        x.u = uvec4(g.u32(), g.u32(), 0u, 0u);
        break;
    case FN_SURFACE_APPLY_NORMAL_MAP: {
        // A shading normal, a tangent (unit, scaled, nearly parallel to the normal, or zero), a
        // bitangent on either side, and a texel: any, the flat (0.5, 0.5, 1), the zero vector's
        // (0.5, 0.5, 0.5), or bent below the surface; scale 0 to 2.
        set3(x, 0, n);
        const float k = g.uni();
        const vec3 t = k < 0.05f  ? vec3(0.0f)
                       : k < 0.1f ? n * g.uniform(0.5f, 2.0f) + g.box(1e-4f)
                                  : g.unit() * g.log_uniform(0.1f, 10.0f);
        set3(x, 1, t);
        set3(x, 2, glm::cross(n, t) * (g.chance(0.5f) ? 1.0f : -1.0f) + g.box(0.1f));
        const float c = g.uni();
        const vec3 texel = c < 0.1f    ? vec3(0.5f, 0.5f, 1.0f)
                           : c < 0.2f  ? vec3(0.5f)
                           : c < 0.35f ? vec3(g.uni(), g.uni(), g.uniform(0.0f, 0.5f))
                                       : g.color(1.0f);
        set3(x, 3, texel, g.uniform(0.0f, 2.0f));
        break;
    }
    case FN_SPOT_LIGHT_FALLOFF: {
        // KHR_lights_punctual's cone angles: 0 <= inner < outer <= pi / 2.
        const float outer = g.uniform(1e-3f, 1.5707963f);
        const float inner = g.chance(0.2f) ? outer * (1.0f - 1e-4f) : g.uniform(0.0f, outer);
        const float scale = 1.0f / std::max(1e-3f, std::cos(inner) - std::cos(outer));
        set3(x, 7, n);
        set3(x, 8, vec3(scale, -std::cos(outer) * scale, 0.0f));
        x.u.y = LIGHT_SPOT;
        // wi from the light's position to the point: -wi near the axis half of the time.
        const float spread = g.log_uniform(1e-3f, 2.0f * outer + 1e-3f);
        set3(x, 0, glm::normalize(-(n + g.box(spread))));
        break;
    }
    default:
        break;
    }
}

} // namespace tp::test
