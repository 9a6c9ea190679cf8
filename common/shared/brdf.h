// Scattering functions: the modified Phong BRDF of Lafortune & Willems (1994) with its
// importance sampling, the perfect mirror and the smooth dielectric.
//
// Conventions: all vectors are unit and in world space; wo points from the surface towards
// the previous vertex (the viewer), wi towards the next one (the light); n is the shading
// normal. Phong and mirror are one-sided here: the caller turns n to wo's side first
// (surface.h). The dielectric takes the outward normal and works out the side itself.
#ifndef TP_SHARED_BRDF_H
#define TP_SHARED_BRDF_H

#include "sampling.h"
#include "types.h"

TP_NAMESPACE_BEGIN

const uint LOBE_NONE = 0u; // no valid sample: the path ends
const uint LOBE_DIFFUSE = 1u;
const uint LOBE_GLOSSY = 2u;
const uint LOBE_SPECULAR = 4u; // Dirac delta: eval() and pdf() are 0 for it
const uint LOBE_TRANSMISSION = 8u;

struct BsdfSample {
    vec3 wi;
    float pdf;   // solid-angle pdf of the whole mixture; for delta lobes the lobe's probability
    vec3 weight; // f |cos theta_i| / pdf: what the path throughput is multiplied by
    uint lobe;   // LOBE_* flags of the sampled lobe
};

inline BsdfSample bsdf_sample_none() {
    BsdfSample s;
    s.wi = vec3(0.0f);
    s.pdf = 0.0f;
    s.weight = vec3(0.0f);
    s.lobe = LOBE_NONE;
    return s;
}

// ---- modified Phong ------------------------------------------------------------------------
// f(wo, wi) = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha)                       (thesis eq. 2.28)
// with alpha the angle between wi and the mirror direction of wo. kd + ks <= 1 per channel
// keeps the directional albedo <= 1 (Lafortune & Willems 1994, sec. 3); at normal incidence it
// equals kd + ks exactly.
//
// Sampling: the mixture pdf
//   p(wi) = P_d cos(theta_i) / pi + (1 - P_d) (n + 1) / (2 pi) cos^n(alpha)
// with P_d = avg(kd) / (avg(kd) + avg(ks)), the lobes' albedos at normal incidence. Unlike the
// thesis's one-lobe estimator (eq. 2.32-2.33), the weight f cos / p always uses both lobes, so
// it stays bounded when one lobe is tiny, and no sample is spent on absorption.

inline vec3 mirror_direction(vec3 n, vec3 wo) {
    return normalize(2.0f * dot(n, wo) * n - wo);
}

inline float phong_diffuse_probability(vec3 kd, vec3 ks) {
    float d = average(kd);
    float s = average(ks);
    return d + s > 0.0f ? d / (d + s) : 1.0f;
}

inline vec3 phong_eval(vec3 kd, vec3 ks, float ns, vec3 n, vec3 wo, vec3 wi) {
    if (dot(n, wi) <= 0.0f || dot(n, wo) <= 0.0f) return vec3(0.0f);
    float cos_alpha = dot(mirror_direction(n, wo), wi);
    return kd * INV_PI + ks * ((ns + 2.0f) * INV_TWO_PI * phong_power(cos_alpha, ns));
}

inline float phong_pdf(vec3 kd, vec3 ks, float ns, vec3 n, vec3 wo, vec3 wi) {
    float cos_i = dot(n, wi);
    if (cos_i <= 0.0f || dot(n, wo) <= 0.0f) return 0.0f;
    float p_d = phong_diffuse_probability(kd, ks);
    float cos_alpha = dot(mirror_direction(n, wo), wi);
    return p_d * cosine_hemisphere_pdf(cos_i) + (1.0f - p_d) * phong_lobe_pdf(cos_alpha, ns);
}

inline BsdfSample phong_sample(vec3 kd, vec3 ks, float ns, vec3 n, vec3 wo, float u_lobe,
                               vec2 u_dir) {
    if (dot(n, wo) <= 0.0f) return bsdf_sample_none();
    float p_d = phong_diffuse_probability(kd, ks);
    bool diffuse = u_lobe < p_d;
    vec3 axis = diffuse ? n : mirror_direction(n, wo);
    vec3 local = diffuse ? sample_cosine_hemisphere(u_dir) : sample_phong_lobe(u_dir, ns);
    vec3 t;
    vec3 b;
    orthonormal_basis(axis, t, b);
    vec3 wi = normalize(frame_to_world(local, t, b, axis));
    float pdf = phong_pdf(kd, ks, ns, n, wo, wi);
    if (pdf <= 0.0f) return bsdf_sample_none(); // a glossy sample below the horizon
    BsdfSample s;
    s.wi = wi;
    s.pdf = pdf;
    s.weight = phong_eval(kd, ks, ns, n, wo, wi) * (dot(n, wi) / pdf);
    s.lobe = diffuse ? LOBE_DIFFUSE : LOBE_GLOSSY;
    return s;
}

// ---- perfect mirror ----------------------------------------------------------------------
// f = ks delta(wi - R(wo)) / cos(theta_i), so the sample weight is ks.
inline BsdfSample mirror_sample(vec3 ks, vec3 n, vec3 wo) {
    if (dot(n, wo) <= 0.0f) return bsdf_sample_none();
    BsdfSample s;
    s.wi = mirror_direction(n, wo);
    s.pdf = 1.0f;
    s.weight = ks;
    s.lobe = LOBE_SPECULAR;
    return s;
}

// ---- smooth dielectric -------------------------------------------------------------------
// Fresnel reflectance for unpolarized light at a smooth interface, eta = n_t / n_i and
// cos_i >= 0 the cosine on the incident side (pbrt-v4, sec. 9.3.5, FrDielectric). 1 under total
// internal reflection.
inline float fresnel_dielectric(float cos_i, float eta) {
    float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) return 1.0f;
    float cos_t = safe_sqrt(1.0f - sin2_t);
    float r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_parl * r_parl + r_perp * r_perp);
}

// Chooses reflection with probability F and refraction with 1 - F, so the weights are 1 and
// tf / eta^2: radiance crossing into a denser medium is compressed into a smaller solid angle
// (Veach 1997, sec. 5.2; pbrt-v4 sec. 9.5.2). n is the outward normal; ior = n_inside/n_outside.
inline BsdfSample dielectric_sample(vec3 tf, float ior, vec3 n, vec3 wo, float u_lobe) {
    float cos_o = dot(n, wo);
    bool entering = cos_o > 0.0f;
    float eta = entering ? ior : 1.0f / ior;
    vec3 nw = entering ? n : -n; // the normal on wo's side
    float cos_i = abs(cos_o);
    float f = fresnel_dielectric(cos_i, eta);
    BsdfSample s;
    if (u_lobe < f) {
        s.wi = normalize(2.0f * cos_i * nw - wo);
        s.pdf = f;
        s.weight = vec3(1.0f);
        s.lobe = LOBE_SPECULAR;
    } else {
        // Snell's law in vector form: wt = -wo / eta + (cos_i / eta - cos_t) nw.
        float cos_t = safe_sqrt(1.0f - (1.0f - cos_i * cos_i) / (eta * eta));
        s.wi = normalize(-wo / eta + (cos_i / eta - cos_t) * nw);
        s.pdf = 1.0f - f;
        s.weight = tf / (eta * eta);
        s.lobe = LOBE_SPECULAR | LOBE_TRANSMISSION;
    }
    return s;
}

// ---- dispatch over Material::type --------------------------------------------------------
inline bool material_is_delta(Material m) {
    return m.type != MATERIAL_PHONG;
}

inline vec3 bsdf_eval(Material m, vec3 n, vec3 wo, vec3 wi) {
    if (m.type != MATERIAL_PHONG) return vec3(0.0f);
    return phong_eval(m.kd, m.ks, m.ns, n, wo, wi);
}

inline float bsdf_pdf(Material m, vec3 n, vec3 wo, vec3 wi) {
    if (m.type != MATERIAL_PHONG) return 0.0f;
    return phong_pdf(m.kd, m.ks, m.ns, n, wo, wi);
}

inline BsdfSample bsdf_sample(Material m, vec3 n, vec3 wo, float u_lobe, vec2 u_dir) {
    if (m.type == MATERIAL_MIRROR) return mirror_sample(m.ks, n, wo);
    if (m.type == MATERIAL_DIELECTRIC) return dielectric_sample(m.tf, m.ior, n, wo, u_lobe);
    return phong_sample(m.kd, m.ks, m.ns, n, wo, u_lobe, u_dir);
}

TP_NAMESPACE_END

#endif // TP_SHARED_BRDF_H
