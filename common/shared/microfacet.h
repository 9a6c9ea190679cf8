// The Trowbridge-Reitz (GGX) microfacet distribution with the Smith masking-shadowing model, in
// a local frame whose +z is the macro-surface normal: what glTF 2.0's specular BRDF
// (Appendix B, "Specular BRDF") and the transmission extensions' BTDFs are built from, and the
// sampling of its visible normals.
//
// Notation as in Heitz, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs",
// JCGT 3(2), 2014: alpha is the width (glTF: roughness^2), h a microfacet normal, v a direction.
// Every cosine-dependent term is written with sin^2 = x^2 + y^2 taken from the vector rather
// than as 1 - cos^2, which cancels near the pole: at alpha = 1e-4 the peak of D sits where
// 1 - cos^2 is below float's spacing near 1.
#ifndef TP_SHARED_MICROFACET_H
#define TP_SHARED_MICROFACET_H

#include "math.h"

TP_NAMESPACE_BEGIN

// D(h) = alpha^2 chi+(h.z) / (pi ((h.z)^2 (alpha^2 - 1) + 1)^2)        (glTF 2.0, Appendix B)
// with (h.z)^2 (alpha^2 - 1) + 1 = h.x^2 + h.y^2 + alpha^2 h.z^2 for a unit h.
inline float ggx_d(vec3 h, float alpha) {
    if (h.z <= 0.0f) return 0.0f;
    float a2 = alpha * alpha;
    float k = h.x * h.x + h.y * h.y + a2 * h.z * h.z;
    return a2 / (PI * k * k);
}

// sqrt(alpha^2 + (1 - alpha^2) cos^2) = sqrt(cos^2 + alpha^2 sin^2) of direction v: the root in
// both visibility terms and in G1.
inline float ggx_root(vec3 v, float alpha) {
    return sqrt(v.z * v.z + alpha * alpha * (v.x * v.x + v.y * v.y));
}

// Smith's masking term of GGX: G1(v) = 2 |cos| / (|cos| + sqrt(alpha^2 + (1 - alpha^2) cos^2))
// (Heitz 2014, eq. 72 written without tan).
inline float ggx_g1(vec3 v, float alpha) {
    float c = abs(v.z);
    float r = ggx_root(v, alpha);
    return r > 0.0f ? 2.0f * c / (c + r) : 0.0f;
}

// The visibility function nu = G / (4 |N.L| |N.V|) of glTF's specular BRDF, G the
// height-correlated Smith masking-shadowing function (Appendix B, "Specular BRDF"):
//   nu = 1 / (2 (|N.V| sqrt(a^2 + (1 - a^2)(N.L)^2) + |N.L| sqrt(a^2 + (1 - a^2)(N.V)^2))).
// The caller checks chi+(H.L) chi+(H.V).
inline float ggx_visibility_correlated(vec3 wo, vec3 wi, float alpha) {
    float d = abs(wo.z) * ggx_root(wi, alpha) + abs(wi.z) * ggx_root(wo, alpha);
    return d > 0.0f ? 0.5f / d : 0.0f;
}

// The visibility function of the transmission BTDFs, from the separable Smith form
// G_T = G1(L) G1(V) (KHR_materials_transmission, "Implementation Notes"):
//   nu_T = 1 / ((|N.L| + sqrt(a^2 + (1 - a^2)(N.L)^2)) (|N.V| + sqrt(a^2 + (1 - a^2)(N.V)^2))).
inline float ggx_visibility_separable(vec3 wo, vec3 wi, float alpha) {
    float d = (abs(wo.z) + ggx_root(wo, alpha)) * (abs(wi.z) + ggx_root(wi, alpha));
    return d > 0.0f ? 1.0f / d : 0.0f;
}

// A microfacet normal drawn from the distribution of normals visible from v (v.z > 0),
//   D_v(h) = G1(v) max(0, v.h) D(h) / v.z                                (Heitz 2014, eq. 38),
// by the spherical-cap construction of Dupuy & Benyoub, "Sampling Visible GGX Normals with
// Spherical Caps", Computer Graphics Forum 42(8), 2023, listing 3: in the configuration
// stretched to alpha = 1 the visible normals are h = c + v with c uniform on the spherical cap
// z >= -v.z; the result is unstretched and normalized.
inline vec3 ggx_sample_visible_normal(vec3 v, float alpha, vec2 u) {
    vec3 vs = normalize(vec3(alpha * v.x, alpha * v.y, v.z));
    float phi = TWO_PI * u.x;
    float z = (1.0f - u.y) * (1.0f + vs.z) - vs.z;
    float sin_theta = safe_sqrt(1.0f - z * z);
    vec3 hs = vec3(sin_theta * cos(phi), sin_theta * sin(phi), z) + vs;
    return normalize(vec3(alpha * hs.x, alpha * hs.y, max(hs.z, 0.0f)));
}

// The density of ggx_sample_visible_normal: D_v(h) for v.z > 0.
inline float ggx_visible_normal_pdf(vec3 v, vec3 h, float alpha) {
    float vh = dot(v, h);
    if (v.z <= 0.0f || vh <= 0.0f) return 0.0f;
    return ggx_g1(v, alpha) * vh * ggx_d(h, alpha) / v.z;
}

TP_NAMESPACE_END

#endif // TP_SHARED_MICROFACET_H
