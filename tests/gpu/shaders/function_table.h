// Every function of common/shared/, callable by number: run_function(id, input) unpacks the
// arguments from a generic record, calls the function and packs what it returns. Written in
// the shared-header dialect, so the very same dispatch is compiled as C++ (the reference) and
// as GLSL (shared_functions.comp); tests/gpu/shared_functions_test.cpp compares the two.
#ifndef TP_TESTS_FUNCTION_TABLE_H
#define TP_TESTS_FUNCTION_TABLE_H

#include "shared/alpha.h"
#include "shared/brdf.h"
#include "shared/camera.h"
#include "shared/intersect.h"
#include "shared/lights.h"
#include "shared/math.h"
#include "shared/microfacet.h"
#include "shared/offset.h"
#include "shared/path.h"
#include "shared/pbr.h"
#include "shared/rng.h"
#include "shared/roulette.h"
#include "shared/sampling.h"
#include "shared/surface.h"
#include "shared/texture.h"
#include "shared/types.h"

TP_NAMESPACE_BEGIN

struct FnIn {
    vec4 f[12];
    uvec4 u;
};

struct FnOut {
    vec4 f[6];
    uvec4 u;
};

// ---- function ids ----------------------------------------------------------------------------
const uint FN_MAX3 = 0u;
const uint FN_AVERAGE = 1u;
const uint FN_LUMINANCE = 2u;
const uint FN_IS_FINITE = 3u;
const uint FN_IS_FINITE3 = 4u;
const uint FN_IS_BLACK = 5u;
const uint FN_SAFE_SQRT = 6u;
const uint FN_EXPM1_PRECISE = 7u;
const uint FN_ORTHONORMAL_BASIS = 8u;
const uint FN_FRAME_TO_WORLD = 9u;
const uint FN_PCG4D = 10u;
const uint FN_UINT_TO_UNIT_FLOAT = 11u;
const uint FN_RNG_KEY = 12u;
const uint FN_RNG_GET = 13u;
const uint FN_RNG_BOUNCE_DIM = 14u;
const uint FN_RNG_BOUNCE2 = 15u;
const uint FN_SAMPLE_COSINE_HEMISPHERE = 16u;
const uint FN_COSINE_HEMISPHERE_PDF = 17u;
const uint FN_PHONG_POWER = 18u;
const uint FN_SAMPLE_PHONG_LOBE = 19u;
const uint FN_PHONG_LOBE_PDF = 20u;
const uint FN_SAMPLE_UNIFORM_SPHERE = 21u;
const uint FN_SAMPLE_UNIFORM_TRIANGLE = 22u;
const uint FN_ALIAS_SLOT = 23u;
const uint FN_ALIAS_RESOLVE = 24u;
const uint FN_BSDF_SAMPLE_NONE = 25u;
const uint FN_MIRROR_DIRECTION = 26u;
const uint FN_PHONG_DIFFUSE_PROBABILITY = 27u;
const uint FN_PHONG_EVAL = 28u;
const uint FN_PHONG_PDF = 29u;
const uint FN_PHONG_SAMPLE = 30u;
const uint FN_MIRROR_SAMPLE = 31u;
const uint FN_FRESNEL_DIELECTRIC = 32u;
const uint FN_DIELECTRIC_SAMPLE = 33u;
const uint FN_MATERIAL_IS_DELTA = 34u;
const uint FN_BSDF_EVAL = 35u;
const uint FN_BSDF_PDF = 36u;
const uint FN_BSDF_SAMPLE = 37u;
const uint FN_LIGHT_SAMPLE_NONE = 38u;
const uint FN_SAMPLE_POINT_LIGHT = 39u;
const uint FN_SAMPLE_DIRECTIONAL_LIGHT = 40u;
const uint FN_TRIANGLE_LIGHT_NORMAL = 41u;
const uint FN_TRIANGLE_LIGHT_PDF = 42u;
const uint FN_SAMPLE_TRIANGLE_LIGHT = 43u;
const uint FN_SAMPLE_CONSTANT_ENVIRONMENT = 44u;
const uint FN_ENVIRONMENT_MAP_PDF = 45u;
const uint FN_ENVIRONMENT_MAP_PIXEL_POINT = 46u;
const uint FN_ENVIRONMENT_MAP_COORDS = 47u;
const uint FN_ENVIRONMENT_MAP_PIXEL = 48u;
const uint FN_SAMPLE_ENVIRONMENT_MAP = 49u;
const uint FN_SAMPLE_LIGHT = 50u;
const uint FN_UV_TO_IMAGE = 51u;
const uint FN_WRAP_TEXEL = 52u;
const uint FN_TEXTURE_FOOTPRINT = 53u;
const uint FN_TEXTURE_BILERP = 54u;
const uint FN_LATLONG_TO_DIRECTION = 55u;
const uint FN_DIRECTION_TO_LATLONG = 56u;
const uint FN_ROTATE_Y = 57u;
const uint FN_INSTANCE_POINT_TO_WORLD = 58u;
const uint FN_INSTANCE_VECTOR_TO_WORLD = 59u;
const uint FN_INSTANCE_POINT_TO_OBJECT = 60u;
const uint FN_INSTANCE_VECTOR_TO_OBJECT = 61u;
const uint FN_INSTANCE_NORMAL_TO_WORLD = 62u;
const uint FN_BARYCENTRIC_MIX3 = 63u;
const uint FN_BARYCENTRIC_MIX2 = 64u;
const uint FN_SURFACE_POINT = 65u;
const uint FN_SURFACE_SET_SHADING_NORMAL = 66u;
const uint FN_SURFACE_FACE_VIEWER = 67u;
const uint FN_POWER_HEURISTIC = 68u;
const uint FN_EMISSION_MIS_WEIGHT = 69u;
const uint FN_SCATTER_IS_CONSISTENT = 70u;
const uint FN_SPAWN_RAY = 71u;
const uint FN_SHADOW_RAY = 72u;
const uint FN_CAMERA_MAKE = 73u;
const uint FN_CAMERA_DIRECTION = 74u;
const uint FN_SURFACE_SNAP_TO_RAY = 75u;
const uint FN_OFFSET_RAY_ORIGIN = 76u;
const uint FN_ROULETTE_SURVIVAL = 77u;
const uint FN_ROULETTE_APPLY = 78u;
const uint FN_RAY_INVERSE_DIRECTION = 79u;
const uint FN_INTERSECT_AABB = 80u;
const uint FN_WATERTIGHT_RAY = 81u;
const uint FN_INTERSECT_TRIANGLE = 82u;
const uint FN_UMUL_HI = 83u;
const uint FN_RNG_GET_BITS = 84u;
const uint FN_RNG_BOUNCE2_BITS = 85u;
const uint FN_LAINE_KARRAS_PERMUTATION = 86u;
const uint FN_NESTED_UNIFORM_SCRAMBLE = 87u;
const uint FN_SOBOL_DIM1 = 88u;
const uint FN_RNG_GROUP_FIRST = 89u;
const uint FN_GGX_D = 90u;
const uint FN_GGX_G1 = 91u;
const uint FN_GGX_VISIBILITY_CORRELATED = 92u;
const uint FN_GGX_VISIBILITY_SEPARABLE = 93u;
const uint FN_GGX_SAMPLE_VISIBLE_NORMAL = 94u;
const uint FN_GGX_VISIBLE_NORMAL_PDF = 95u;
const uint FN_PBR_EVAL = 96u;
const uint FN_PBR_PDF = 97u;
const uint FN_PBR_SAMPLE = 98u;
const uint FN_PBR_DIELECTRIC_FRESNEL = 99u;
const uint FN_PBR_VOLUME_TRANSMITTANCE = 100u;
const uint FN_ALPHA_BLEND_THRESHOLD = 101u;
const uint FN_ALPHA_COVERS = 102u;
const uint FN_SRGB_TO_LINEAR = 103u;
const uint FN_UNPACK_RGBA8 = 104u;
const uint FN_UNPACK_RGBA16 = 105u;
const uint FN_SURFACE_APPLY_NORMAL_MAP = 106u;
const uint FN_SPOT_LIGHT_FALLOFF = 107u;
const uint FN_COUNT = 108u;

// ---- argument unpacking ----------------------------------------------------------------------
inline vec3 fn3(FnIn x, uint i) {
    return vec3(x.f[i].x, x.f[i].y, x.f[i].z);
}

// seed u.x, pixel u.y, sample u.z; the sampler from f0.x, so that random inputs try both.
inline RngKey fn_rng_key(FnIn x) {
    return rng_key(x.f[0].x < 0.5f ? SAMPLER_RANDOM : SAMPLER_SOBOL, x.u.x, x.u.y, x.u.z);
}

// kd f0, ns f0.w, ks f1, ior f1.w, tf f6, type u.x; no emission, no texture.
inline Material fn_material(FnIn x) {
    Material m;
    m.kd = fn3(x, 0u);
    m.kd_texture = NO_TEXTURE;
    m.ks = fn3(x, 1u);
    m.ns = x.f[0].w;
    m.ke = vec3(0.0f);
    m.ior = x.f[1].w;
    m.tf = fn3(x, 6u);
    m.type = x.u.x;
    return m;
}

// A glTF material (MATERIAL_PBR, no textures): (base colour, metallic) f6, (specular colour,
// roughness) f7, (ior, transmission, specular, attenuation distance) f8, attenuation colour f9,
// flags u.x.
inline Material fn_pbr_material(FnIn x) {
    Material m;
    m.kd = fn3(x, 6u);
    m.kd_texture = NO_TEXTURE;
    m.ks = fn3(x, 7u);
    m.ns = 1.0f;
    m.ke = vec3(0.0f);
    m.ior = x.f[8].x;
    m.tf = fn3(x, 9u);
    m.type = MATERIAL_PBR;
    m.metallic = x.f[6].w;
    m.roughness = x.f[7].w;
    m.transmission = x.f[8].y;
    m.specular = x.f[8].z;
    m.alpha = 1.0f;
    m.alpha_cutoff = 0.5f;
    m.alpha_mode = ALPHA_OPAQUE;
    m.attenuation_distance = x.f[8].w;
    m.metallic_roughness_texture = NO_TEXTURE;
    m.normal_texture = NO_TEXTURE;
    m.emissive_texture = NO_TEXTURE;
    m.transmission_texture = NO_TEXTURE;
    m.specular_texture = NO_TEXTURE;
    m.specular_color_texture = NO_TEXTURE;
    m.normal_scale = 1.0f;
    m.flags = x.u.x;
    return m;
}

// p0 f6, area f6.w, p1 f7, p2 f8, value f9, type u.y.
inline Light fn_light(FnIn x) {
    Light l;
    l.p0 = fn3(x, 6u);
    l.type = x.u.y;
    l.p1 = fn3(x, 7u);
    l.area = x.f[6].w;
    l.p2 = fn3(x, 8u);
    l.instance = 0u;
    l.value = fn3(x, 9u);
    l.primitive = 0u;
    l.normal = triangle_light_normal(l.p0, l.p1, l.p2);
    l.pad0 = 0u;
    return l;
}

// Rows of the object-to-world matrix f0..f2 and of its inverse f3..f5.
inline Instance fn_instance(FnIn x) {
    Instance t;
    t.to_world0 = x.f[0];
    t.to_world1 = x.f[1];
    t.to_world2 = x.f[2];
    t.to_object0 = x.f[3];
    t.to_object1 = x.f[4];
    t.to_object2 = x.f[5];
    t.mesh = 0u;
    t.material = 0u;
    t.light_offset = NO_INDEX;
    t.pad0 = 0u;
    return t;
}

// (eye, tan_half_fov_y) f0, (forward, aspect) f1, right f2, up f3, width u.x, height u.y.
inline Camera fn_camera(FnIn x) {
    Camera c;
    c.eye = fn3(x, 0u);
    c.tan_half_fov_y = x.f[0].w;
    c.forward = fn3(x, 1u);
    c.aspect = x.f[1].w;
    c.right = fn3(x, 2u);
    c.width = x.u.x;
    c.up = fn3(x, 3u);
    c.height = x.u.y;
    return c;
}

// ---- result packing --------------------------------------------------------------------------
inline FnOut fn_out_zero() {
    FnOut o;
    for (uint i = 0u; i < 6u; ++i) o.f[i] = vec4(0.0f);
    o.u = uvec4(0u);
    return o;
}

inline uint fn_bool(bool b) {
    return b ? 1u : 0u;
}

// (wi, pdf) f0, weight f1, lobe u.x
inline void fn_put_bsdf(INOUT(FnOut) o, BsdfSample s) {
    o.f[0] = vec4(s.wi.x, s.wi.y, s.wi.z, s.pdf);
    o.f[1] = vec4(s.weight.x, s.weight.y, s.weight.z, 0.0f);
    o.u.x = s.lobe;
}

// (wi, dist) f0, (radiance, pdf) f1, point f2, delta u.x
inline void fn_put_light(INOUT(FnOut) o, LightSample s) {
    o.f[0] = vec4(s.wi.x, s.wi.y, s.wi.z, s.dist);
    o.f[1] = vec4(s.radiance.x, s.radiance.y, s.radiance.z, s.pdf);
    o.f[2] = vec4(s.point.x, s.point.y, s.point.z, 0.0f);
    o.u.x = fn_bool(s.delta);
}

// (origin, tmax) f0, dir f1
inline void fn_put_ray(INOUT(FnOut) o, Ray r) {
    o.f[0] = vec4(r.origin.x, r.origin.y, r.origin.z, r.tmax);
    o.f[1] = vec4(r.dir.x, r.dir.y, r.dir.z, 0.0f);
}

// p f0, ng f1, ns f2, uv f3, p_error f4
inline void fn_put_surface(INOUT(FnOut) o, SurfacePoint s) {
    o.f[0] = vec4(s.p.x, s.p.y, s.p.z, 0.0f);
    o.f[1] = vec4(s.ng.x, s.ng.y, s.ng.z, 0.0f);
    o.f[2] = vec4(s.ns.x, s.ns.y, s.ns.z, 0.0f);
    o.f[3] = vec4(s.uv.x, s.uv.y, 0.0f, 0.0f);
    o.f[4] = vec4(s.p_error.x, s.p_error.y, s.p_error.z, 0.0f);
}

inline void fn_put3(INOUT(FnOut) o, uint i, vec3 v) {
    o.f[i] = vec4(v.x, v.y, v.z, 0.0f);
}

// ---- the dispatch ----------------------------------------------------------------------------
inline FnOut run_function(uint id, FnIn x) {
    FnOut o = fn_out_zero();
    vec3 a = fn3(x, 0u);
    vec3 b = fn3(x, 1u);
    vec3 c = fn3(x, 2u);
    vec3 d = fn3(x, 3u);
    vec3 e = fn3(x, 4u);
    switch (id) {
    case FN_MAX3:
        o.f[0].x = max3(a);
        break;
    case FN_AVERAGE:
        o.f[0].x = average(a);
        break;
    case FN_LUMINANCE:
        o.f[0].x = luminance(a);
        break;
    case FN_IS_FINITE:
        o.u.x = fn_bool(is_finite(a.x));
        break;
    case FN_IS_FINITE3:
        o.u.x = fn_bool(is_finite3(a));
        break;
    case FN_IS_BLACK:
        o.u.x = fn_bool(is_black(a));
        break;
    case FN_SAFE_SQRT:
        o.f[0].x = safe_sqrt(a.x);
        break;
    case FN_EXPM1_PRECISE:
        o.f[0].x = expm1_precise(a.x);
        break;
    case FN_ORTHONORMAL_BASIS: {
        vec3 t;
        vec3 bt;
        orthonormal_basis(a, t, bt);
        fn_put3(o, 0u, t);
        fn_put3(o, 1u, bt);
        break;
    }
    case FN_FRAME_TO_WORLD:
        fn_put3(o, 0u, frame_to_world(a, b, c, d));
        break;
    case FN_PCG4D:
        o.u = pcg4d(x.u);
        break;
    case FN_UINT_TO_UNIT_FLOAT:
        o.f[0].x = uint_to_unit_float(x.u.x);
        break;
    case FN_RNG_KEY: {
        RngKey k = fn_rng_key(x);
        o.u = uvec4(k.seed, k.pixel, k.sample_index, k.sampler_id);
        break;
    }
    case FN_RNG_GET:
        o.f[0].x = rng_get(fn_rng_key(x), x.u.w);
        break;
    case FN_UMUL_HI:
        o.u.x = umul_hi(x.u.x, x.u.y);
        break;
    case FN_RNG_GET_BITS:
        o.u.x = rng_get_bits(fn_rng_key(x), x.u.w);
        break;
    case FN_RNG_BOUNCE2_BITS: {
        uvec2 r = rng_bounce2_bits(fn_rng_key(x), x.u.w & 0xFFu, (x.u.w >> 8u) % 10u);
        o.u.x = r.x;
        o.u.y = r.y;
        break;
    }
    case FN_RNG_BOUNCE_DIM:
        o.u.x = rng_bounce_dim(x.u.x, x.u.y);
        break;
    case FN_RNG_BOUNCE2: {
        vec2 r = rng_bounce2(fn_rng_key(x), x.u.w & 0xFFu, (x.u.w >> 8u) % 10u);
        o.f[0].x = r.x;
        o.f[0].y = r.y;
        break;
    }
    case FN_LAINE_KARRAS_PERMUTATION:
        o.u.x = laine_karras_permutation(x.u.x, x.u.y);
        break;
    case FN_NESTED_UNIFORM_SCRAMBLE:
        o.u.x = nested_uniform_scramble(x.u.x, x.u.y);
        break;
    case FN_SOBOL_DIM1:
        o.u.x = sobol_dim1(x.u.x);
        break;
    case FN_RNG_GROUP_FIRST:
        o.u.x = rng_group_first(x.u.x);
        o.u.y = rng_group_second(o.u.x);
        break;
    case FN_SAMPLE_COSINE_HEMISPHERE:
        fn_put3(o, 0u, sample_cosine_hemisphere(vec2(a.x, a.y)));
        break;
    case FN_COSINE_HEMISPHERE_PDF:
        o.f[0].x = cosine_hemisphere_pdf(a.x);
        break;
    case FN_PHONG_POWER:
        o.f[0].x = phong_power(a.x, a.y);
        break;
    case FN_SAMPLE_PHONG_LOBE:
        fn_put3(o, 0u, sample_phong_lobe(vec2(a.x, a.y), a.z));
        break;
    case FN_PHONG_LOBE_PDF:
        o.f[0].x = phong_lobe_pdf(a.x, a.y);
        break;
    case FN_SAMPLE_UNIFORM_SPHERE:
        fn_put3(o, 0u, sample_uniform_sphere(vec2(a.x, a.y)));
        break;
    case FN_SAMPLE_UNIFORM_TRIANGLE: {
        vec2 bc = sample_uniform_triangle(vec2(a.x, a.y));
        o.f[0] = vec4(bc.x, bc.y, 0.0f, 0.0f);
        break;
    }
    case FN_ALIAS_SLOT:
        o.u.x = alias_slot_from_bits(x.u.y, x.u.x);
        break;
    case FN_ALIAS_RESOLVE:
        o.u.x = alias_resolve(x.u.x, a.x, x.u.y, a.y);
        break;
    case FN_BSDF_SAMPLE_NONE:
        fn_put_bsdf(o, bsdf_sample_none());
        break;
    case FN_MIRROR_DIRECTION:
        fn_put3(o, 0u, mirror_direction(c, d));
        break;
    case FN_PHONG_DIFFUSE_PROBABILITY:
        o.f[0].x = phong_diffuse_probability(a, b);
        break;
    case FN_PHONG_EVAL:
        fn_put3(o, 0u, phong_eval(a, b, x.f[0].w, c, d, e));
        break;
    case FN_PHONG_PDF:
        o.f[0].x = phong_pdf(a, b, x.f[0].w, c, d, e);
        break;
    case FN_PHONG_SAMPLE:
        fn_put_bsdf(o, phong_sample(a, b, x.f[0].w, c, d, x.f[5].x, vec2(x.f[5].y, x.f[5].z)));
        break;
    case FN_MIRROR_SAMPLE:
        fn_put_bsdf(o, mirror_sample(b, c, d));
        break;
    case FN_FRESNEL_DIELECTRIC:
        o.f[0].x = fresnel_dielectric(a.x, a.y);
        break;
    case FN_DIELECTRIC_SAMPLE:
        fn_put_bsdf(o, dielectric_sample(fn3(x, 6u), x.f[1].w, c, d, x.f[5].x));
        break;
    case FN_MATERIAL_IS_DELTA:
        o.u.x = fn_bool(material_is_delta(fn_material(x)));
        break;
    case FN_BSDF_EVAL:
        fn_put3(o, 0u, bsdf_eval(fn_material(x), c, d, e));
        break;
    case FN_BSDF_PDF:
        o.f[0].x = bsdf_pdf(fn_material(x), c, d, e);
        break;
    case FN_BSDF_SAMPLE:
        fn_put_bsdf(o, bsdf_sample(fn_material(x), c, d, x.f[5].x, vec2(x.f[5].y, x.f[5].z)));
        break;
    case FN_LIGHT_SAMPLE_NONE:
        fn_put_light(o, light_sample_none());
        break;
    case FN_SAMPLE_POINT_LIGHT:
        fn_put_light(o, sample_point_light(fn_light(x), a));
        break;
    case FN_SAMPLE_DIRECTIONAL_LIGHT:
        fn_put_light(o, sample_directional_light(fn_light(x)));
        break;
    case FN_TRIANGLE_LIGHT_NORMAL:
        fn_put3(o, 0u, triangle_light_normal(fn3(x, 6u), fn3(x, 7u), fn3(x, 8u)));
        break;
    case FN_TRIANGLE_LIGHT_PDF:
        o.f[0].x = triangle_light_pdf(a.x, a.y, a.z);
        break;
    case FN_SAMPLE_TRIANGLE_LIGHT:
        fn_put_light(o, sample_triangle_light(fn_light(x), a, vec2(b.x, b.y), b.z != 0.0f));
        break;
    case FN_SAMPLE_CONSTANT_ENVIRONMENT:
        fn_put_light(o, sample_constant_environment(fn_light(x), vec2(b.x, b.y)));
        break;
    case FN_ENVIRONMENT_MAP_PDF:
        o.f[0].x = environment_map_pdf(a.x, x.u.x, x.u.y, a.y);
        break;
    case FN_ENVIRONMENT_MAP_PIXEL_POINT: {
        vec2 st = environment_map_pixel_point(x.u.z, x.u.x, x.u.y, vec2(a.x, a.y));
        o.f[0] = vec4(st.x, st.y, 0.0f, 0.0f);
        break;
    }
    case FN_ENVIRONMENT_MAP_COORDS: {
        vec2 st = environment_map_coords(a, x.f[0].w);
        o.f[0] = vec4(st.x, st.y, 0.0f, 0.0f);
        break;
    }
    case FN_ENVIRONMENT_MAP_PIXEL:
        o.u.x = environment_map_pixel(vec2(a.x, a.y), x.u.x, x.u.y);
        break;
    case FN_SAMPLE_ENVIRONMENT_MAP:
        fn_put_light(o, sample_environment_map(x.u.z, a.x, x.u.x, x.u.y, a.y, vec2(b.x, b.y)));
        break;
    case FN_SAMPLE_LIGHT:
        fn_put_light(o, sample_light(fn_light(x), a, vec2(b.x, b.y), b.z != 0.0f));
        break;
    case FN_UV_TO_IMAGE: {
        vec2 st = uv_to_image(vec2(a.x, a.y));
        o.f[0] = vec4(st.x, st.y, 0.0f, 0.0f);
        break;
    }
    case FN_WRAP_TEXEL:
        o.u.x = wrap_texel(a.x, x.u.x);
        break;
    case FN_TEXTURE_FOOTPRINT: {
        TexelFootprint fp = texture_footprint(vec2(a.x, a.y), x.u.x, x.u.y, x.u.w, x.u.z);
        o.u = uvec4(fp.i00, fp.i10, fp.i01, fp.i11);
        o.f[0] = vec4(fp.f.x, fp.f.y, 0.0f, 0.0f);
        break;
    }
    case FN_TEXTURE_BILERP:
        o.f[0] = texture_bilerp(x.f[0], x.f[1], x.f[2], x.f[3], vec2(e.x, e.y));
        break;
    case FN_LATLONG_TO_DIRECTION:
        fn_put3(o, 0u, latlong_to_direction(vec2(a.x, a.y)));
        break;
    case FN_DIRECTION_TO_LATLONG: {
        vec2 st = direction_to_latlong(a);
        o.f[0] = vec4(st.x, st.y, 0.0f, 0.0f);
        break;
    }
    case FN_ROTATE_Y:
        fn_put3(o, 0u, rotate_y(a, x.f[0].w));
        break;
    case FN_INSTANCE_POINT_TO_WORLD:
        fn_put3(o, 0u, instance_point_to_world(fn_instance(x), fn3(x, 6u)));
        break;
    case FN_INSTANCE_VECTOR_TO_WORLD:
        fn_put3(o, 0u, instance_vector_to_world(fn_instance(x), fn3(x, 6u)));
        break;
    case FN_INSTANCE_POINT_TO_OBJECT:
        fn_put3(o, 0u, instance_point_to_object(fn_instance(x), fn3(x, 6u)));
        break;
    case FN_INSTANCE_VECTOR_TO_OBJECT:
        fn_put3(o, 0u, instance_vector_to_object(fn_instance(x), fn3(x, 6u)));
        break;
    case FN_INSTANCE_NORMAL_TO_WORLD:
        fn_put3(o, 0u, instance_normal_to_world(fn_instance(x), fn3(x, 6u)));
        break;
    case FN_BARYCENTRIC_MIX3:
        fn_put3(o, 0u, barycentric_mix3(a, b, c, vec2(d.x, d.y)));
        break;
    case FN_BARYCENTRIC_MIX2: {
        vec2 m = barycentric_mix2(vec2(a.x, a.y), vec2(a.z, b.x), vec2(b.y, b.z), vec2(c.x, c.y));
        o.f[0] = vec4(m.x, m.y, 0.0f, 0.0f);
        break;
    }
    case FN_SURFACE_POINT:
        fn_put_surface(o, surface_point(fn_instance(x), fn3(x, 6u), fn3(x, 7u), fn3(x, 8u),
                                        vec2(x.f[9].x, x.f[9].y)));
        break;
    case FN_SURFACE_SET_SHADING_NORMAL: {
        Instance t = fn_instance(x);
        vec2 bary = vec2(x.f[9].x, x.f[9].y);
        SurfacePoint s = surface_point(t, fn3(x, 6u), fn3(x, 7u), fn3(x, 8u), bary);
        surface_set_shading_normal(s, t, fn3(x, 10u), fn3(x, 11u),
                                   vec3(x.f[6].w, x.f[7].w, x.f[8].w), bary);
        fn_put_surface(o, s);
        break;
    }
    case FN_SURFACE_FACE_VIEWER: {
        SurfacePoint s;
        s.p = fn3(x, 6u);
        s.p_error = vec3(0.0f);
        s.ng = fn3(x, 7u);
        s.ns = fn3(x, 8u);
        s.uv = vec2(x.f[9].x, x.f[9].y);
        surface_face_viewer(s, fn3(x, 10u));
        fn_put_surface(o, s);
        break;
    }
    case FN_POWER_HEURISTIC:
        o.f[0].x = power_heuristic(a.x, a.y);
        break;
    case FN_EMISSION_MIS_WEIGHT:
        o.f[0].x = emission_mis_weight(x.u.x != 0u, a.x, a.y);
        break;
    case FN_SCATTER_IS_CONSISTENT:
        o.u.x = fn_bool(scatter_is_consistent(a, b, c, x.u.x));
        break;
    case FN_SPAWN_RAY:
        fn_put_ray(o, spawn_ray(a, d, b, c, x.f[0].w));
        break;
    case FN_SHADOW_RAY: {
        LightSample ls;
        ls.wi = c;
        ls.dist = x.f[2].w;
        ls.radiance = d;
        ls.pdf = x.f[3].w;
        ls.point = e;
        ls.delta = x.u.x != 0u;
        fn_put_ray(o, shadow_ray(a, fn3(x, 5u), b, ls, fn_light(x), x.f[0].w, x.f[1].w != 0.0f));
        break;
    }
    case FN_CAMERA_MAKE: {
        Camera cam = camera_make(a, b, c, x.f[0].w, x.u.x, x.u.y);
        o.f[0] = vec4(cam.eye.x, cam.eye.y, cam.eye.z, cam.tan_half_fov_y);
        o.f[1] = vec4(cam.forward.x, cam.forward.y, cam.forward.z, cam.aspect);
        fn_put3(o, 2u, cam.right);
        fn_put3(o, 3u, cam.up);
        o.u = uvec4(cam.width, cam.height, 0u, 0u);
        break;
    }
    case FN_CAMERA_DIRECTION:
        fn_put3(o, 0u, camera_direction(fn_camera(x), e.x, e.y));
        break;
    case FN_SURFACE_SNAP_TO_RAY: {
        SurfacePoint s;
        s.p = a;
        s.p_error = b;
        s.ng = c;
        s.ns = c;
        s.uv = vec2(0.0f);
        surface_snap_to_ray(s, d, e);
        fn_put_surface(o, s);
        break;
    }
    case FN_OFFSET_RAY_ORIGIN:
        fn_put3(o, 0u, offset_ray_origin(a, b, c, x.f[0].w));
        break;
    case FN_ROULETTE_SURVIVAL:
        o.f[0].x = roulette_survival(a, x.u.x, x.u.y);
        break;
    case FN_ROULETTE_APPLY: {
        vec3 t = a;
        o.u.x = fn_bool(roulette_apply(t, x.u.x, x.u.y, x.f[0].w));
        fn_put3(o, 0u, t);
        break;
    }
    case FN_RAY_INVERSE_DIRECTION:
        fn_put3(o, 0u, ray_inverse_direction(a));
        break;
    case FN_INTERSECT_AABB: {
        float t_enter = 0.0f;
        o.u.x = fn_bool(intersect_aabb(a, b, c, d, x.f[0].w, t_enter));
        o.f[0].x = o.u.x != 0u ? t_enter : 0.0f;
        break;
    }
    case FN_WATERTIGHT_RAY: {
        WatertightRay r = watertight_ray(a);
        o.u = uvec4(r.k.x, r.k.y, r.k.z, 0u);
        fn_put3(o, 0u, r.shear);
        break;
    }
    case FN_INTERSECT_TRIANGLE: {
        vec3 tuv = vec3(0.0f);
        o.u.x = fn_bool(intersect_triangle(a, watertight_ray(b), c, d, e, x.f[0].w, tuv));
        fn_put3(o, 0u, tuv);
        break;
    }
    case FN_GGX_D:
        o.f[0].x = ggx_d(a, x.f[0].w);
        break;
    case FN_GGX_G1:
        o.f[0].x = ggx_g1(a, x.f[0].w);
        break;
    case FN_GGX_VISIBILITY_CORRELATED:
        o.f[0].x = ggx_visibility_correlated(a, b, x.f[0].w);
        break;
    case FN_GGX_VISIBILITY_SEPARABLE:
        o.f[0].x = ggx_visibility_separable(a, b, x.f[0].w);
        break;
    case FN_GGX_SAMPLE_VISIBLE_NORMAL:
        fn_put3(o, 0u, ggx_sample_visible_normal(a, x.f[0].w, vec2(b.x, b.y)));
        break;
    case FN_GGX_VISIBLE_NORMAL_PDF:
        o.f[0].x = ggx_visible_normal_pdf(a, b, x.f[0].w);
        break;
    case FN_PBR_EVAL:
        fn_put3(o, 0u, pbr_eval(fn_pbr_material(x), c, d, e));
        break;
    case FN_PBR_PDF:
        o.f[0].x = pbr_pdf(fn_pbr_material(x), c, d, e);
        break;
    case FN_PBR_SAMPLE:
        fn_put_bsdf(o, pbr_sample(fn_pbr_material(x), c, d, x.f[5].x, vec2(x.f[5].y, x.f[5].z)));
        break;
    case FN_PBR_DIELECTRIC_FRESNEL:
        fn_put3(o, 0u, pbr_dielectric_fresnel(fn_pbr_material(x), a.x));
        break;
    case FN_PBR_VOLUME_TRANSMITTANCE:
        fn_put3(o, 0u, pbr_volume_transmittance(fn_pbr_material(x), a.x));
        break;
    case FN_ALPHA_BLEND_THRESHOLD:
        o.f[0].x = alpha_blend_threshold(x.u.w, x.u.x, x.u.y);
        break;
    case FN_ALPHA_COVERS:
        o.u.x = fn_bool(alpha_covers(x.u.z, c.x, c.y, x.u.w, x.u.x, x.u.y));
        break;
    case FN_SRGB_TO_LINEAR:
        o.f[0].x = srgb_to_linear(a.x);
        break;
    case FN_UNPACK_RGBA8:
        o.f[0] = unpack_rgba8(x.u.x);
        break;
    case FN_UNPACK_RGBA16:
        o.f[0] = unpack_rgba16(x.u.x, x.u.y);
        break;
    case FN_SURFACE_APPLY_NORMAL_MAP: {
        SurfacePoint s;
        s.p = vec3(0.0f);
        s.p_error = vec3(0.0f);
        s.ng = a;
        s.ns = a;
        s.uv = vec2(0.0f);
        s.uv1 = vec2(0.0f);
        s.tangent = b;
        s.bitangent = c;
        surface_apply_normal_map(s, d, x.f[3].w);
        fn_put3(o, 0u, s.ns);
        break;
    }
    case FN_SPOT_LIGHT_FALLOFF:
        o.f[0].x = spot_light_falloff(fn_light(x), a);
        break;
    default:
        o.u = uvec4(0xFFFFFFFFu);
        break;
    }
    return o;
}

TP_NAMESPACE_END

#endif // TP_TESTS_FUNCTION_TABLE_H
