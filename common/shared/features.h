// Scene features: which materials, lights, textures and environment a scene uses, as bits of
// one mask, and the integrator's dispatch over materials and lights restricted to that mask.
// common/scene/features.h computes the mask of a FlatScene. Each engine compiles its path loop
// for a mask: the CPU engine instantiates a template on some bits (cpu_ref/integrator.cpp), the
// Vulkan engine passes the mask as a specialization constant (shaders/features.glsl), so the
// compiler removes what the scene cannot reach. FEATURES_ALL is the variant that can render
// every scene (`--features all`); a mask with a bit cleared must only ever be used for a scene
// that lacks that feature, because the code for it is gone, not merely skipped.
//
// Every function here gives the result of the unrestricted one (brdf.h, lights.h) for every
// input the mask admits: a restricted variant is the same estimator, with the same random
// numbers, and renders the same image up to float rounding.
#ifndef TP_SHARED_FEATURES_H
#define TP_SHARED_FEATURES_H

#include "brdf.h"
#include "lights.h"
#include "pbr.h"

TP_NAMESPACE_BEGIN

const uint FEATURE_TEXTURES = 1u;            // a material with a texture (map_Kd, glTF's slots)
const uint FEATURE_PHONG_SPECULAR = 2u;      // a Phong material with ks > 0: the glossy lobe
const uint FEATURE_MIRROR = 4u;              // a perfect mirror
const uint FEATURE_DIELECTRIC = 8u;          // a smooth dielectric
const uint FEATURE_EMISSIVE_TRIANGLES = 16u; // a material with ke > 0 on some instance
const uint FEATURE_POINT_LIGHTS = 32u;
const uint FEATURE_DIRECTIONAL_LIGHTS = 64u;
const uint FEATURE_ENV_CONSTANT = 128u; // a constant environment
const uint FEATURE_ENV_MAP = 256u;      // a lat-long environment map
// A mesh with more than one instance. Without it compute mode traverses a one-level BVH of
// world-space triangles (vulkan_rt/compute_mode/bvh_builder.h, shaders/trace_bvh.glsl); the CPU
// engine places every mesh that one instance uses in world space whatever the mask, and pipeline
// mode always has its TLAS and BLASes.
const uint FEATURE_INSTANCING = 512u;
const uint FEATURE_PBR = 1024u;         // glTF's metallic-roughness material (pbr.h)
const uint FEATURE_NORMAL_MAPS = 2048u; // a material with a normal map (and its tangent frames)
const uint FEATURE_ALPHA = 4096u;       // a material with alpha MASK or BLEND (alpha.h)
const uint FEATURE_COUNT = 13u;
const uint FEATURES_ALL = 8191u;

inline bool feature_on(uint features, uint f) {
    return (features & f) != 0u;
}

// A light that next-event estimation can choose; without one there are no shadow rays.
inline bool features_sample_lights(uint features) {
    return feature_on(features, FEATURE_EMISSIVE_TRIANGLES | FEATURE_POINT_LIGHTS |
                                    FEATURE_DIRECTIONAL_LIGHTS | FEATURE_ENV_CONSTANT |
                                    FEATURE_ENV_MAP);
}

// A light that BSDF sampling can also hit (area lights, the environment): the only case in
// which multiple importance sampling has two strategies to weigh. Without one every light is
// a delta light and no MIS weight is computed.
inline bool features_mis(uint features) {
    return feature_on(features,
                      FEATURE_EMISSIVE_TRIANGLES | FEATURE_ENV_CONSTANT | FEATURE_ENV_MAP);
}

inline bool features_environment(uint features) {
    return feature_on(features, FEATURE_ENV_CONSTANT | FEATURE_ENV_MAP);
}

inline bool features_delta_materials(uint features) {
    return feature_on(features, FEATURE_MIRROR | FEATURE_DIELECTRIC);
}

// A material kind other than Phong: brdf_*_in dispatch on Material::type only where one is on.
inline bool features_other_materials(uint features) {
    return feature_on(features, FEATURE_MIRROR | FEATURE_DIELECTRIC | FEATURE_PBR);
}

// ---- Lambert: the modified Phong BRDF with ks = 0 -------------------------------------------
// phong_* with ks = 0 reduce to these (p_d = 1: the diffuse lobe is always chosen, and
// f cos / p = kd); without FEATURE_PHONG_SPECULAR every Phong material is one of them.
inline vec3 lambert_eval(vec3 kd, vec3 n, vec3 wo, vec3 wi) {
    if (dot(n, wi) <= 0.0f || dot(n, wo) <= 0.0f) return vec3(0.0f);
    return kd * INV_PI;
}

inline float lambert_pdf(vec3 n, vec3 wo, vec3 wi) {
    float cos_i = dot(n, wi);
    if (cos_i <= 0.0f || dot(n, wo) <= 0.0f) return 0.0f;
    return cosine_hemisphere_pdf(cos_i);
}

inline BsdfSample lambert_sample(vec3 kd, vec3 n, vec3 wo, vec2 u_dir) {
    if (dot(n, wo) <= 0.0f) return bsdf_sample_none();
    vec3 t;
    vec3 b;
    orthonormal_basis(n, t, b);
    vec3 wi = normalize(frame_to_world(sample_cosine_hemisphere(u_dir), t, b, n));
    float pdf = lambert_pdf(n, wo, wi);
    if (pdf <= 0.0f) return bsdf_sample_none();
    BsdfSample s;
    s.wi = wi;
    s.pdf = pdf;
    s.weight = lambert_eval(kd, n, wo, wi) * (dot(n, wi) / pdf);
    s.lobe = LOBE_DIFFUSE;
    return s;
}

// ---- brdf.h's dispatch, restricted to a feature mask -----------------------------------------
// Whether next-event estimation can skip the material: every lobe is a Dirac delta (mirror,
// smooth dielectric, a smooth PBR material without a diffuse part).
inline bool material_is_delta_in(uint features, Material m) {
    if (feature_on(features, FEATURE_PBR) && m.type == MATERIAL_PBR)
        return pbr_is_smooth(m) && !pbr_has_diffuse(m);
    return features_delta_materials(features) && material_is_delta(m);
}

// Whether the material scatters light through the surface into non-delta directions, so that
// next-event estimation also samples lights on the far side.
inline bool material_transmits_in(uint features, Material m) {
    return feature_on(features, FEATURE_PBR) && m.type == MATERIAL_PBR && pbr_transmits(m) &&
           !pbr_is_smooth(m);
}

inline vec3 bsdf_eval_in(uint features, Material m, vec3 n, vec3 wo, vec3 wi) {
    if (feature_on(features, FEATURE_PBR) && m.type == MATERIAL_PBR) return pbr_eval(m, n, wo, wi);
    if (features_delta_materials(features) && m.type != MATERIAL_PHONG) return vec3(0.0f);
    if (!feature_on(features, FEATURE_PHONG_SPECULAR)) return lambert_eval(m.kd, n, wo, wi);
    return phong_eval(m.kd, m.ks, m.ns, n, wo, wi);
}

inline float bsdf_pdf_in(uint features, Material m, vec3 n, vec3 wo, vec3 wi) {
    if (feature_on(features, FEATURE_PBR) && m.type == MATERIAL_PBR) return pbr_pdf(m, n, wo, wi);
    if (features_delta_materials(features) && m.type != MATERIAL_PHONG) return 0.0f;
    if (!feature_on(features, FEATURE_PHONG_SPECULAR)) return lambert_pdf(n, wo, wi);
    return phong_pdf(m.kd, m.ks, m.ns, n, wo, wi);
}

inline BsdfSample bsdf_sample_in(uint features, Material m, vec3 n, vec3 wo, float u_lobe,
                                 vec2 u_dir) {
    if (feature_on(features, FEATURE_PBR) && m.type == MATERIAL_PBR)
        return pbr_sample(m, n, wo, u_lobe, u_dir);
    if (feature_on(features, FEATURE_MIRROR) && m.type == MATERIAL_MIRROR)
        return mirror_sample(m.ks, n, wo);
    if (feature_on(features, FEATURE_DIELECTRIC) && m.type == MATERIAL_DIELECTRIC)
        return dielectric_sample(m.tf, m.ior, n, wo, u_lobe);
    if (!feature_on(features, FEATURE_PHONG_SPECULAR)) return lambert_sample(m.kd, n, wo, u_dir);
    return phong_sample(m.kd, m.ks, m.ns, n, wo, u_lobe, u_dir);
}

// Whether bsdf_sample_in's result depends on u_lobe: a dielectric chooses reflection or
// refraction with it, a PBR material its lobe; a Phong material only where both lobes have
// weight, since u_lobe < p_d holds for every u_lobe in [0, 1) when p_d >= 1 and for none when
// p_d <= 0.
inline bool bsdf_reads_lobe_choice_in(uint features, Material m) {
    if (feature_on(features, FEATURE_PBR) && m.type == MATERIAL_PBR) return true;
    if (feature_on(features, FEATURE_MIRROR) && m.type == MATERIAL_MIRROR) return false;
    if (feature_on(features, FEATURE_DIELECTRIC) && m.type == MATERIAL_DIELECTRIC) return true;
    if (!feature_on(features, FEATURE_PHONG_SPECULAR)) return false;
    float p_d = phong_diffuse_probability(m.kd, m.ks);
    return p_d > 0.0f && p_d < 1.0f;
}

// lights.h's sample_light (every light but the environment map), restricted to a mask.
inline LightSample sample_light_in(uint features, Light l, vec3 p, vec2 u,
                                   bool normal_from_vertices) {
    if (feature_on(features, FEATURE_POINT_LIGHTS) && l.type == LIGHT_POINT)
        return sample_point_light(l, p);
    if (feature_on(features, FEATURE_POINT_LIGHTS) && l.type == LIGHT_SPOT)
        return sample_spot_light(l, p);
    if (feature_on(features, FEATURE_DIRECTIONAL_LIGHTS) && l.type == LIGHT_DIRECTIONAL)
        return sample_directional_light(l);
    if (feature_on(features, FEATURE_EMISSIVE_TRIANGLES) && l.type == LIGHT_TRIANGLE)
        return sample_triangle_light(l, p, u, normal_from_vertices);
    if (feature_on(features, FEATURE_ENV_CONSTANT)) return sample_constant_environment(l, u);
    return light_sample_none();
}

TP_NAMESPACE_END

#endif // TP_SHARED_FEATURES_H
