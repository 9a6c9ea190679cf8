// glTF 2.0's metallic-roughness material as a BSDF (MATERIAL_PBR): Appendix B of the
// specification as it writes it, with the f0 of KHR_materials_ior and KHR_materials_specular,
// and the transmission of KHR_materials_transmission (thin-walled) and KHR_materials_volume
// (a refracting boundary). No energy compensation: the BRDF loses the energy of multiple
// scattering between microfacets, as the specification's single-scattering model does.
//
// With V = wo, L = wi, H their half vector, w = (1 - |V.H|)^5 and alpha = roughness^2:
//   specular_brdf = D(H) nu(V, L)                        (microfacet.h: GGX, height-correlated)
//   metal_brdf = specular_brdf (baseColor + (1 - baseColor) w)            (conductor_fresnel)
//   F_d = f0 + (f90 - f0) w, f0 = min(((ior - 1) / (ior + 1))^2 specularColor, 1) specular,
//         f90 = specular                                 (KHR_materials_specular, fresnel_mix)
//   dielectric_brdf = F_d specular_brdf + (1 - max(F_d)) base
//   base = (1 - transmission) baseColor / pi + transmission baseColor specular_btdf
//   material = (1 - metallic) dielectric_brdf + metallic metal_brdf
// specular_btdf is the thin-walled BTDF of KHR_materials_transmission (the specular lobe
// mirrored through the surface, separable Smith visibility), or, on a volume boundary
// (KHR_materials_volume, thickness > 0), Walter et al.'s refracting BTDF ("Microfacet Models for
// Refraction through Rough Surfaces", EGSR 2007, eq. 21) with its Fresnel taken on the dense
// side of the boundary (1 under total internal reflection), as the volume extension's
// implementation notes give it. That BTDF is written for radiance: the factor eta_V^2 / (eta_V
// (V.H) + eta_L (L.H))^2 with eta_V the index on V's side (pbrt-v4, sec. 9.7.5: radiance
// crossing into a denser medium is compressed, the smooth dielectric's tf / eta^2 in brdf.h).
//
// Frame and sides: the functions take the shading normal n on wo's side (the path loop turns
// it there, surface.h) and work in the local frame with n as +z. A direction with wi.z > 0 is
// reflected, wi.z < 0 transmitted. Material::ior is the relative index eta = eta_L / eta_V of
// the boundary as the path crosses it: the path loop inverts it when a ray meets a volume
// boundary from inside (pbr_material_at_side).
//
// Roughness below PBR_SMOOTH_ROUGHNESS is the limit alpha -> 0 (the specification's note: never
// alpha = 0 in D): the specular reflection and transmission become Dirac lobes, sampled but
// never evaluated, and the diffuse lobe stays as it is.
//
// Sampling: one lobe per sample. Diffuse (cosine-weighted) with probability p_d, the ratio of its
// albedo estimate at wo to the sum of all parts' (pbr_diffuse_probability); otherwise a
// microfacet normal H from the distribution of visible normals (microfacet.h) and, with the
// probability pbr_reflect_probability(H) that weighs the Fresnel-weighted reflection against
// the transmission at that H, the reflection about H, else the transmission through H. The
// lobe choice u_lobe decides p_d first, and its remainder, rescaled to [0, 1), decides
// reflection against transmission. The pdf is that of the whole mixture, so a sample's weight
// f cos / pdf is bounded wherever the mixture covers f.
#ifndef TP_SHARED_PBR_H
#define TP_SHARED_PBR_H

#include "brdf.h"
#include "microfacet.h"

TP_NAMESPACE_BEGIN

// Roughness below this is rendered as the smooth limit: alpha = roughness^2 < 1e-4, where GGX's
// lobe is 1e-4 rad wide and a light sample of next-event estimation almost never falls in it.
const float PBR_SMOOTH_ROUGHNESS = 0.01f;

inline float pbr_alpha(Material m) {
    return m.roughness * m.roughness;
}

inline bool pbr_is_smooth(Material m) {
    return m.roughness < PBR_SMOOTH_ROUGHNESS;
}

inline bool pbr_is_volume(Material m) {
    return (m.flags & MATERIAL_FLAG_VOLUME) != 0u;
}

// Whether light can pass through the surface at all (the transmission lobe has weight).
inline bool pbr_transmits(Material m) {
    return m.transmission > 0.0f && m.metallic < 1.0f;
}

// The weight of the diffuse lobe: zero makes a smooth material a delta BSDF.
inline bool pbr_has_diffuse(Material m) {
    return m.metallic < 1.0f && m.transmission < 1.0f && !is_black(m.kd);
}

inline float pow5(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

// The dielectric's reflectance at normal incidence, f0 (KHR_materials_ior, _specular).
inline vec3 pbr_dielectric_f0(Material m) {
    float r = (m.ior - 1.0f) / (m.ior + 1.0f);
    return min(vec3(r * r) * m.ks, vec3(1.0f)) * m.specular;
}

// The cosine Schlick's approximation takes for microfacet normal H with c = |V.H|: c itself,
// except where V is on the dense side of a volume boundary (eta < 1): there the cosine of the
// refracted angle, or -1 under total internal reflection (KHR_materials_volume,
// "Implementation": three cases).
inline float pbr_fresnel_cosine(Material m, float c) {
    if (!pbr_is_volume(m) || m.ior >= 1.0f) return c;
    float sin2_t = (1.0f - c * c) / (m.ior * m.ior);
    return sin2_t >= 1.0f ? -1.0f : sqrt(1.0f - sin2_t);
}

// F_d = f0 + (f90 - f0)(1 - c)^5 for the cosine of pbr_fresnel_cosine; 1 under total internal
// reflection, where F90 is not scaled by the specular factor (KHR_materials_specular with
// KHR_materials_volume).
inline vec3 pbr_dielectric_fresnel(Material m, float c) {
    if (c < 0.0f) return vec3(1.0f);
    vec3 f0 = pbr_dielectric_f0(m);
    return f0 + (vec3(m.specular) - f0) * pow5(1.0f - c);
}

// conductor_fresnel: baseColor + (1 - baseColor)(1 - |V.H|)^5.
inline vec3 pbr_metal_fresnel(Material m, float vh) {
    return m.kd + (vec3(1.0f) - m.kd) * pow5(1.0f - vh);
}

// How much of the microfacet lobe's weight at H is reflection rather than transmission:
// R / (R + T) with R = (1 - metallic) max(F_d) + metallic avg(F_metal) and
// T = (1 - metallic)(1 - max(F_d)) transmission avg(baseColor).
inline float pbr_reflect_probability(Material m, float vh) {
    float fd = max3(pbr_dielectric_fresnel(m, pbr_fresnel_cosine(m, vh)));
    float r = (1.0f - m.metallic) * fd + m.metallic * average(pbr_metal_fresnel(m, vh));
    float t = (1.0f - m.metallic) * (1.0f - fd) * m.transmission * average(m.kd);
    return r + t > 0.0f ? r / (r + t) : 1.0f;
}

// The probability of the diffuse lobe: its albedo estimate at wo (the Fresnel weights at
// V.H = cos(theta_o)) against the microfacet lobes'. Under total internal reflection at N the
// estimate takes Schlick's cosine at cos_o itself: 1 - F(V.H) is not 0 for the other half
// vectors, so the diffuse lobe that f has must keep a probability.
inline float pbr_diffuse_probability(Material m, float cos_o) {
    float c = pbr_fresnel_cosine(m, cos_o);
    float fd = max3(pbr_dielectric_fresnel(m, c < 0.0f ? cos_o : c));
    float rest = (1.0f - m.metallic) * (1.0f - fd) * average(m.kd);
    float d = rest * (1.0f - m.transmission);
    float s = (1.0f - m.metallic) * fd + m.metallic * average(pbr_metal_fresnel(m, cos_o)) +
              rest * m.transmission;
    return d + s > 0.0f ? d / (d + s) : 1.0f;
}

// The microfacet normal of a transmitted pair: H = -(wo + eta wi), normalized and turned to
// +z (Walter et al. 2007, eq. 16); (0, 0, 0) where wo + eta wi vanishes (eta = 1, wi = -wo).
inline vec3 pbr_refraction_half_vector(vec3 wo, vec3 wi, float eta) {
    vec3 h = wo + eta * wi;
    float len2 = dot(h, h);
    if (!(len2 > 0.0f)) return vec3(0.0f);
    h = h * inversesqrt(len2);
    return h.z < 0.0f ? -h : h;
}

// The thin-walled transmission's microfacet normal: the half vector of wo and wi mirrored to
// wo's side (KHR_materials_transmission: H_T = normalize(V - 2 (N.L) N + L)).
inline vec3 pbr_thin_half_vector(vec3 wo, vec3 wi) {
    return normalize(wo + vec3(wi.x, wi.y, -wi.z));
}

// f(wo, wi) in the local frame (wo.z > 0).
inline vec3 pbr_eval_local(Material m, vec3 wo, vec3 wi) {
    float alpha = pbr_alpha(m);
    bool is_smooth = pbr_is_smooth(m);
    if (wi.z > 0.0f) {
        vec3 h = normalize(wo + wi);
        float vh = dot(wo, h);
        vec3 fd = pbr_dielectric_fresnel(m, pbr_fresnel_cosine(m, vh));
        vec3 f = ((1.0f - m.metallic) * (1.0f - max3(fd)) * (1.0f - m.transmission) * INV_PI) * m.kd;
        // chi+(H.V) of Appendix B's visibility: V.H > 0 for any two directions above the
        // surface, but not in floats where both graze it and wo + wi nearly cancels, and the pdf
        // (a visible normal) is 0 there.
        if (!is_smooth && vh > 0.0f) {
            float spec = ggx_d(h, alpha) * ggx_visibility_correlated(wo, wi, alpha);
            f += ((1.0f - m.metallic) * fd + m.metallic * pbr_metal_fresnel(m, vh)) * spec;
        }
        return f;
    }
    if (is_smooth || !pbr_transmits(m) || wi.z == 0.0f) return vec3(0.0f);
    float weight = (1.0f - m.metallic) * m.transmission;
    if (!pbr_is_volume(m)) {
        vec3 h = pbr_thin_half_vector(wo, wi);
        if (!(dot(wo, h) > 0.0f)) return vec3(0.0f); // chi+(H_T.V), as for the reflection
        float fd = max3(pbr_dielectric_fresnel(m, dot(wo, h)));
        float btdf = ggx_d(h, alpha) * ggx_visibility_separable(wo, wi, alpha);
        return (weight * (1.0f - fd) * btdf) * m.kd;
    }
    vec3 h = pbr_refraction_half_vector(wo, wi, m.ior);
    float vh = dot(wo, h);
    float lh = dot(wi, h);
    if (!(vh > 0.0f) || !(lh < 0.0f)) return vec3(0.0f);
    float c = pbr_fresnel_cosine(m, vh);
    if (c < 0.0f) return vec3(0.0f); // total internal reflection
    float fd = max3(pbr_dielectric_fresnel(m, c));
    float denom = vh + m.ior * lh;
    float btdf = ggx_d(h, alpha) * ggx_g1(wo, alpha) * ggx_g1(wi, alpha) * vh * (-lh) /
                 (wo.z * (-wi.z) * denom * denom);
    return (weight * (1.0f - fd) * btdf) * m.kd;
}

// The solid-angle density with which pbr_sample_local draws wi (wo.z > 0).
inline float pbr_pdf_local(Material m, vec3 wo, vec3 wi) {
    float alpha = pbr_alpha(m);
    bool is_smooth = pbr_is_smooth(m);
    float p_d = pbr_diffuse_probability(m, wo.z);
    if (wi.z > 0.0f) {
        float p = p_d * cosine_hemisphere_pdf(wi.z);
        if (!is_smooth) {
            vec3 h = normalize(wo + wi);
            float vh = dot(wo, h);
            // Reflection about H maps D_v(H) to D_v(H) / (4 |V.H|) (Walter et al. 2007, eq. 14).
            if (vh > 0.0f)
                p += (1.0f - p_d) * pbr_reflect_probability(m, vh) *
                     ggx_visible_normal_pdf(wo, h, alpha) / (4.0f * vh);
        }
        return p;
    }
    if (is_smooth || !pbr_transmits(m) || wi.z == 0.0f) return 0.0f;
    if (!pbr_is_volume(m)) {
        vec3 h = pbr_thin_half_vector(wo, wi);
        float vh = dot(wo, h);
        if (!(vh > 0.0f)) return 0.0f;
        return (1.0f - p_d) * (1.0f - pbr_reflect_probability(m, vh)) *
               ggx_visible_normal_pdf(wo, h, alpha) / (4.0f * vh);
    }
    vec3 h = pbr_refraction_half_vector(wo, wi, m.ior);
    float vh = dot(wo, h);
    float lh = dot(wi, h);
    if (!(vh > 0.0f) || !(lh < 0.0f)) return 0.0f;
    // Refraction through H: dH/dL = eta^2 |L.H| / (V.H + eta L.H)^2 (Walter et al., eq. 17).
    float denom = vh + m.ior * lh;
    return (1.0f - p_d) * (1.0f - pbr_reflect_probability(m, vh)) *
           ggx_visible_normal_pdf(wo, h, alpha) * m.ior * m.ior * (-lh) / (denom * denom);
}

// One sample of the mixture (module comment): wi, its pdf, f cos / pdf and the lobe.
inline BsdfSample pbr_sample_local(Material m, vec3 wo, float u_lobe, vec2 u_dir) {
    bool is_smooth = pbr_is_smooth(m);
    float p_d = pbr_diffuse_probability(m, wo.z);
    BsdfSample s;
    s.lobe = LOBE_NONE;
    if (u_lobe < p_d) {
        s.wi = sample_cosine_hemisphere(u_dir);
        s.lobe = LOBE_DIFFUSE;
    } else {
        float u = min((u_lobe - p_d) / (1.0f - p_d), ONE_MINUS_EPSILON);
        vec3 h = is_smooth ? vec3(0.0f, 0.0f, 1.0f)
                        : ggx_sample_visible_normal(wo, pbr_alpha(m), u_dir);
        float vh = dot(wo, h);
        float p_r = pbr_reflect_probability(m, vh);
        uint glossy = is_smooth ? LOBE_SPECULAR : LOBE_GLOSSY;
        vec3 r = 2.0f * vh * h - wo;
        if (u < p_r) {
            s.wi = r;
            s.lobe = glossy;
            if (is_smooth) {
                // Dirac lobe: f cos / pdf is the Fresnel-weighted reflectance over its
                // probability, F being exact at H = N.
                s.pdf = (1.0f - p_d) * p_r;
                vec3 fd = pbr_dielectric_fresnel(m, pbr_fresnel_cosine(m, vh));
                s.weight = ((1.0f - m.metallic) * fd + m.metallic * pbr_metal_fresnel(m, vh)) /
                           s.pdf;
                return s;
            }
        } else if (!pbr_is_volume(m)) {
            s.wi = vec3(r.x, r.y, -r.z);
            s.lobe = glossy | LOBE_TRANSMISSION;
        } else {
            // Snell's law about H: wt = -wo / eta + (cos_i / eta - cos_t) H.
            float eta = m.ior;
            float sin2_t = (1.0f - vh * vh) / (eta * eta);
            if (sin2_t >= 1.0f) return bsdf_sample_none(); // total internal reflection
            s.wi = normalize(-wo / eta + (vh / eta - sqrt(1.0f - sin2_t)) * h);
            s.lobe = glossy | LOBE_TRANSMISSION;
        }
        if (is_smooth) {
            // The smooth transmission: tinted by baseColor, (1 - F) of the base's transmission
            // part, and compressed by 1 / eta^2 on a volume boundary (brdf.h, dielectric).
            s.pdf = (1.0f - p_d) * (1.0f - p_r);
            float fd = max3(pbr_dielectric_fresnel(m, pbr_fresnel_cosine(m, vh)));
            float scale = pbr_is_volume(m) ? 1.0f / (m.ior * m.ior) : 1.0f;
            s.weight = ((1.0f - m.metallic) * m.transmission * (1.0f - fd) * scale / s.pdf) * m.kd;
            return s;
        }
    }
    // The side decides the lobe that evaluates the direction; a sample on the wrong one is none.
    bool transmitted = (s.lobe & LOBE_TRANSMISSION) != 0u;
    if (transmitted ? !(s.wi.z < 0.0f) : !(s.wi.z > 0.0f)) return bsdf_sample_none();
    s.pdf = pbr_pdf_local(m, wo, s.wi);
    if (!(s.pdf > 0.0f)) return bsdf_sample_none();
    s.weight = pbr_eval_local(m, wo, s.wi) * (abs(s.wi.z) / s.pdf);
    return s;
}

// ---- world space: n is the shading normal on wo's side --------------------------------------
inline vec3 pbr_to_local(vec3 v, vec3 t, vec3 b, vec3 n) {
    return vec3(dot(v, t), dot(v, b), dot(v, n));
}

inline vec3 pbr_eval(Material m, vec3 n, vec3 wo, vec3 wi) {
    vec3 t;
    vec3 b;
    orthonormal_basis(n, t, b);
    vec3 lo = pbr_to_local(wo, t, b, n);
    if (lo.z <= 0.0f) return vec3(0.0f);
    return pbr_eval_local(m, lo, pbr_to_local(wi, t, b, n));
}

inline float pbr_pdf(Material m, vec3 n, vec3 wo, vec3 wi) {
    vec3 t;
    vec3 b;
    orthonormal_basis(n, t, b);
    vec3 lo = pbr_to_local(wo, t, b, n);
    if (lo.z <= 0.0f) return 0.0f;
    return pbr_pdf_local(m, lo, pbr_to_local(wi, t, b, n));
}

inline BsdfSample pbr_sample(Material m, vec3 n, vec3 wo, float u_lobe, vec2 u_dir) {
    vec3 t;
    vec3 b;
    orthonormal_basis(n, t, b);
    vec3 lo = pbr_to_local(wo, t, b, n);
    if (lo.z <= 0.0f) return bsdf_sample_none();
    BsdfSample s = pbr_sample_local(m, lo, u_lobe, u_dir);
    if (s.lobe != LOBE_NONE) s.wi = normalize(frame_to_world(s.wi, t, b, n));
    return s;
}

// A PBR material as a path meets it: a volume boundary met from inside (the ray arrived at the
// back of the geometric normal) has the reciprocal relative index.
inline Material pbr_material_at_side(Material m, bool from_back) {
    if (from_back && pbr_is_volume(m)) m.ior = 1.0f / m.ior;
    return m;
}

// Beer-Lambert attenuation over a segment of length d inside a volume:
// T = attenuationColor^(d / attenuationDistance) (KHR_materials_volume, "Attenuation"), with
// attenuationColor in Material::tf. An infinite attenuation distance attenuates nothing.
inline vec3 pbr_volume_transmittance(Material m, float d) {
    if (!(m.attenuation_distance < FLOAT_MAX)) return vec3(1.0f);
    float k = d / m.attenuation_distance;
    if (!(k > 0.0f)) return vec3(1.0f); // pow(0, 0) is undefined in GLSL
    return vec3(pow(m.tf.x, k), pow(m.tf.y, k), pow(m.tf.z, k));
}

TP_NAMESPACE_END

#endif // TP_SHARED_PBR_H
