// Every function of common/shared/ run in a compute shader and in C++ on the same random
// inputs (function_table.h holds the one dispatch both compile), compared per function:
// bit-exact where the function is integer or built only from correctly rounded operations,
// otherwise within a tolerance derived from the Vulkan precision requirements (tolerance.h)
// for that function's operations, justified next to each case.
#include "function_inputs.h"
#include "gpu_harness.h"
#include "tolerance.h"

#include "shared_functions.spv.h"

#include <catch2/catch.hpp>

#include <functional>
#include <tuple>

namespace tp::test {
namespace {

constexpr uint32_t kInputsPerFunction = 10000;

using Check = std::function<void(const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker&)>;

struct Case {
    uint32_t id;
    const char* name;
    Check check;
    // Fraction of inputs that may disagree because a branch on a float comparison went the
    // other way (operands within the tolerances of each other); 0 for branch-free functions.
    double outliers = 0.0;
};

vec3 v3(const vec4& v) {
    return vec3(v);
}
glm::dvec3 d3(const vec4& v) {
    return glm::dvec3(v3(v));
}
double sum_abs(glm::dvec3 v) {
    return std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
}

// Whole outputs bit-identical.
void same_all(const FnOut& c, const FnOut& g, Checker& k) {
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 4; ++j) k.same("f", g.f[i][j], c.f[i][j]);
    for (int j = 0; j < 4; ++j) k.exact("u", g.u[j], c.u[j]);
}

// ---- shared error models ---------------------------------------------------------------------
// A unit vector put together from at most ~10 correctly rounded or contracted operations on
// magnitudes <= 2 and normalized (inversesqrt 2 ulp): each component within 32 u.
constexpr double kUnitAbs = 32.0 * kU;

// offset.h's error-bound factors, in double.
const double kGammaM = double(OFFSET_GAMMA_M);
const double kGammaP = double(OFFSET_GAMMA_P);

// Relative error of phong_power(c, n) = exp2(n log2 c) when c itself is uncertain by dc:
// log2 c errs by log2_abs(c) plus dc / (c ln 2), multiplied by n, plus the
// product's rounding; exp2 turns an absolute error dx of its argument into a relative error
// ln 2 dx and adds its own 3 + 2|x| ulp.
double phong_power_rel(double c, double n, double dc) {
    if (n == 0.0 || c <= 0.0) return 0.0;
    const double x = n * std::log2(c);
    const double dx = n * (log2_abs(c) + dc / (c * std::log(2.0))) + kU * std::abs(x);
    return std::log(2.0) * dx + exp_rel(x) + 2.0 * kU;
}

// A direction from sample_cosine_hemisphere / sample_uniform_sphere / sample_phong_lobe:
// (cos(phi) s, sin(phi) s, z) with sin/cos off by 2^-11 and s, z off by ds, dz.
void check_lobe_direction(Checker& k, vec3 gpu, vec3 cpu, double s, double ds, double dz) {
    k.close("x", gpu.x, cpu.x, kSinCosAbs * s + ds + kU, 0);
    k.close("y", gpu.y, cpu.y, kSinCosAbs * s + ds + kU, 0);
    k.close("z", gpu.z, cpu.z, dz + kU, 0);
}

// Uncertainty of sqrt(y) when y is uncertain by dy: dy / (2 sqrt y), but never more than
// sqrt(dy) (sqrt is not Lipschitz at 0), plus sqrt's own error.
double sqrt_err(double y, double dy) {
    const double r = std::sqrt(std::max(y, 0.0));
    const double prop = r > 0.0 ? std::min(dy / (2.0 * r), std::sqrt(dy)) : std::sqrt(dy);
    return prop + kSqrtRel * r;
}

// sample_phong_lobe's error chain in double: t = log(1 - u)/(n + 1), omc = -expm1(t),
// sin = sqrt(omc (2 - omc)); returns (sin alpha, its error, error of cos alpha = 1 - omc, which
// includes the roundings of 1 - omc on both sides: up to one ulp of [0.5, 1) = 2 u).
glm::dvec3 phong_lobe_errors(double u1, double n) {
    const double one_minus_u = double(1.0f - float(u1));
    const double L = std::log(one_minus_u);
    const double dL = log_abs(one_minus_u) + kU;
    const double t = L / (n + 1.0);
    const double dt = dL / (n + 1.0) + kDivRel * std::abs(t) + kU * std::abs(t);
    const double omc = -std::expm1(t);
    const double domc =
        std::exp(t) * dt + (std::abs(t) < 1e-3 ? 8.0 * kU * omc : exp_rel(t) * std::exp(t) + kU);
    const double s2 = omc * (2.0 - omc);
    return {std::sqrt(std::max(s2, 0.0)), sqrt_err(s2, 2.0 * domc + kU), domc + 2.0 * kU};
}

// Fresnel reflectance in double with cos_t perturbed by +-dct, and the spread that causes.
double fresnel_d(double ci, double eta, double ct) {
    const double rp = (eta * ci - ct) / (eta * ci + ct), rs = (ci - eta * ct) / (ci + eta * ct);
    return 0.5 * (rp * rp + rs * rs);
}
double fresnel_tol(double ci, double eta) {
    const double s = (1.0 - ci * ci) / (eta * eta);
    if (s >= 1.0) return 0.0;
    const double ds = 8.0 * kU * std::max(s, 1.0 / (eta * eta)) + kDivRel * s;
    const double ct = std::sqrt(1.0 - s), dct = sqrt_err(1.0 - s, ds);
    const double f = fresnel_d(ci, eta, ct);
    const double spread = std::max(std::abs(fresnel_d(ci, eta, ct + dct) - f),
                                   std::abs(fresnel_d(ci, eta, std::max(ct - dct, 0.0)) - f));
    return spread + 16.0 * kU * f;
}

// The Phong pdf's value in double (for scale) and its tolerance given an uncertainty dc of
// cos(alpha).
void phong_pdf_tol(const vec3& kd, const vec3& ks, double ns, const glm::dvec3& n,
                   const glm::dvec3& wo, const glm::dvec3& wi, double dc, double& pdf,
                   double& tol) {
    const double d = double(kd.x + kd.y + kd.z) / 3.0, s = double(ks.x + ks.y + ks.z) / 3.0;
    const double pd = d + s > 0 ? d / (d + s) : 1.0;
    const glm::dvec3 r = glm::normalize(2.0 * glm::dot(n, wo) * n - wo);
    const double ca = glm::dot(r, wi), ci = glm::dot(n, wi);
    const double pp = ca <= 0 ? 0.0 : std::pow(ca, ns);
    const double diffuse = std::max(ci, 0.0) / M_PI, glossy = (ns + 1) / (2 * M_PI) * pp;
    pdf = pd * diffuse + (1 - pd) * glossy;
    const double dpd = 16.0 * kU * pd;
    tol = pd * diffuse * 16.0 * kU + dpd * (diffuse + glossy) +
          (1 - pd) * glossy * (phong_power_rel(ca, ns, dc) + 8.0 * kU) + 8.0 * kU * diffuse +
          (ns + 1) * kFlushAbs;
}

// ---- the glTF material ------------------------------------------------------------------------
// GGX's terms on identical inputs (microfacet.h): k = h.x^2 + h.y^2 + alpha^2 h.z^2 is a
// contractible sum of three non-negative products, within 4u of itself; D = a2 / (pi k k) adds
// a2's rounding, two products and the quotient. root = sqrt(v.z^2 + alpha^2 (v.x^2 + v.y^2)):
// 4u under the sqrt, half of it and sqrt's own outside. G1 = 2c / (c + root), the visibilities
// 0.5 / (c_o root_i + c_i root_o) and 1 / ((c_o + root_o)(c_i + root_i)): a sum or product of
// those and a quotient.
constexpr double kGgxDRel = 16.0 * kU + kDivRel;
constexpr double kRootRel = kSqrtRel + 3.0 * kU;
constexpr double kG1Rel = kRootRel + 4.0 * kU + kDivRel;
constexpr double kVisCorrelatedRel = kRootRel + 4.0 * kU + kDivRel;
constexpr double kVisSeparableRel = 2.0 * kRootRel + 6.0 * kU + kDivRel;

// ggx_sample_visible_normal(v, alpha, u) in double with its error chain, the microfacet normal
// and the tolerance of each of its components: vs = normalize(alpha v.x, alpha v.y, v.z)
// (kUnitAbs), z = (1 - u.y)(1 + vs.z) - vs.z (a few u and vs.z's error twice), sin(theta) =
// sqrt(1 - z^2) (not Lipschitz at z = +-1: sqrt_err), the cap point's x and y through cos and
// sin of 2 pi u.x (2^-11 absolute each), hs = that + vs; the result normalizes
// w = (alpha hs.x, alpha hs.y, max(hs.z, 0)), which moves by at most |dw| / |w|.
glm::dvec2 ggx_sample_errors(const glm::dvec3& v, double alpha, double u0, double u1,
                             glm::dvec3& h) {
    const glm::dvec3 vs = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, v.z));
    const double z = (1.0 - u1) * (1.0 + vs.z) - vs.z;
    const double dz = 6.0 * kU + 2.0 * kUnitAbs;
    const double s2 = std::max(0.0, 1.0 - z * z);
    const double sin_t = std::sqrt(s2);
    const double dsin = sqrt_err(s2, 2.0 * std::abs(z) * dz + 2.0 * kU);
    const double phi = 2.0 * M_PI * u0;
    const glm::dvec3 hs = glm::dvec3(sin_t * std::cos(phi), sin_t * std::sin(phi), z) + vs;
    const glm::dvec3 w(alpha * hs.x, alpha * hs.y, std::max(hs.z, 0.0));
    const double len = glm::length(w);
    h = len > 0.0 ? w / len : glm::dvec3(0.0);
    const double dxy = kSinCosAbs * sin_t + dsin + kUnitAbs + 2.0 * kU;
    const double dw = alpha * 2.0 * dxy + dz + kUnitAbs + 2.0 * kU;
    return {len, len > 0.0 ? dw / len + kUnitAbs : 1.0};
}

// How far a function of (n, wo, wi) moves when every coordinate of the three directions moves on
// its own: the sum over the nine coordinates of the larger change of the two signs. The glTF
// material's chains (the frame from n, local coordinates, a half vector, D's peak of width
// alpha = roughness^2 down to 1e-4, Schlick's cosine on the dense side up to total internal
// reflection) are too long to bound by hand, so they are bounded by backward error: each of the
// GPU and C++ results is the function's value at directions a few dozen u from the given ones
// (orthonormal_basis within 16u, the local coordinates' contractible dot products within 3u
// more, the half vector's normalization within 32u of unit, which for a refraction half vector
// normalize(wo + eta wi) is a move of wi by up to 32u (1 + eta) / eta <= 128u for eta >= 1/3),
// times a relative rounding of the rest. So n moves by 32u and wo and wi by 128u here, the
// function evaluated in C++ at each; the relative part is 128u (some 30 operations, two
// quotients and two sqrt). A branch (a direction on the horizon, the boundary of total internal
// reflection, V.H or L.H through 0) is crossed by these moves and so counted in the tolerance.
template <class F>
glm::dvec3 direction_sensitivity(const F& f, const vec3& n, const vec3& wo, const vec3& wi) {
    const glm::dvec3 base = f(n, wo, wi);
    glm::dvec3 sum(0.0);
    for (int which = 0; which < 3; ++which)
        for (int c = 0; c < 3; ++c) {
            const float delta = float(which == 0 ? 32.0 * kU : 128.0 * kU);
            glm::dvec3 worst(0.0);
            for (const float sign : {-1.0f, 1.0f}) {
                vec3 v[3] = {n, wo, wi};
                v[which][c] += sign * delta;
                worst = glm::max(worst, glm::abs(f(v[0], v[1], v[2]) - base));
            }
            sum += worst;
        }
    return sum;
}

constexpr double kPbrRel = 128.0 * kU;

glm::dvec3 pbr_eval_tol(const Material& m, const vec3& n, const vec3& wo, const vec3& wi) {
    const auto f = [&m](const vec3& a, const vec3& b, const vec3& c) {
        return glm::dvec3(pbr_eval(m, a, b, c));
    };
    return direction_sensitivity(f, n, wo, wi) + kPbrRel * glm::abs(f(n, wo, wi));
}

double pbr_pdf_tol(const Material& m, const vec3& n, const vec3& wo, const vec3& wi) {
    const auto f = [&m](const vec3& a, const vec3& b, const vec3& c) {
        return glm::dvec3(double(pbr_pdf(m, a, b, c)), 0.0, 0.0);
    };
    return direction_sensitivity(f, n, wo, wi).x + kPbrRel * std::abs(f(n, wo, wi).x);
}

// ---- the cases -------------------------------------------------------------------------------
std::vector<Case> cases() {
    std::vector<Case> c;
    const Check exact = [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
        same_all(cpu, gpu, k);
    };

    // min/max, comparisons, integer arithmetic and bit operations are exact in both.
    c.push_back({FN_MAX3, "max3", exact});
    // (x + y + z) * (1/3): three correctly rounded operations, none contractible.
    c.push_back({FN_AVERAGE, "average", exact});
    // Two contractible products: 2 u times the sum of the terms' magnitudes.
    c.push_back({FN_LUMINANCE, "luminance",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const glm::dvec3 v = glm::abs(d3(x.f[0]));
                     const double m = 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z;
                     k.close("luminance", gpu.f[0].x, cpu.f[0].x, 2.0 * kU * m, 0);
                 }});
    c.push_back({FN_IS_FINITE, "is_finite", exact}); // a bit test on the pattern
    c.push_back({FN_IS_FINITE3, "is_finite3", exact});
    c.push_back({FN_IS_BLACK, "is_black", exact});
    // sqrt inherited from 1/inversesqrt.
    c.push_back({FN_SAFE_SQRT, "safe_sqrt",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("sqrt", gpu.f[0].x, cpu.f[0].x, 0, kSqrtRel);
                 }});
    // |x| < 1e-3: a contractible cubic (4 u); else exp(x) - 1 with exp's 3 + 2|x| ulp.
    c.push_back({FN_EXPM1_PRECISE, "expm1_precise",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double v = x.f[0].x;
                     const double abs = std::abs(v) < 1e-3 ? 0.0 : exp_rel(v) * std::exp(v);
                     k.close("expm1", gpu.f[0].x, cpu.f[0].x, abs + kU, 4.0 * kU);
                 }});
    // One division (|1/(s + n.z)| <= 1) and a few contractible products of magnitude <= 1.
    c.push_back({FN_ORTHONORMAL_BASIS, "orthonormal_basis",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("t", v3(gpu.f[0]), v3(cpu.f[0]), 16.0 * kU, 0);
                     k.close3("b", v3(gpu.f[1]), v3(cpu.f[1]), 16.0 * kU, 0);
                 }});
    // Two contractible sums of products per component.
    c.push_back({FN_FRAME_TO_WORLD, "frame_to_world",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("v", v3(gpu.f[0]), v3(cpu.f[0]), 6.0 * kU, 0);
                 }});
    c.push_back({FN_PCG4D, "pcg4d", exact});
    c.push_back({FN_UINT_TO_UNIT_FLOAT, "uint_to_unit_float", exact}); // exact conversion, 2^-24
    c.push_back({FN_RNG_KEY, "rng_key", exact});
    c.push_back({FN_RNG_GET, "rng_get", exact});
    c.push_back({FN_RNG_BOUNCE_DIM, "rng_bounce_dim", exact});
    c.push_back({FN_RNG_BOUNCE2, "rng_bounce2", exact});
    c.push_back({FN_UMUL_HI, "umul_hi", exact});
    c.push_back({FN_RNG_GET_BITS, "rng_get_bits", exact});
    c.push_back({FN_RNG_BOUNCE2_BITS, "rng_bounce2_bits", exact});
    c.push_back({FN_LAINE_KARRAS_PERMUTATION, "laine_karras_permutation", exact});
    c.push_back({FN_NESTED_UNIFORM_SCRAMBLE, "nested_uniform_scramble", exact}); // bitfieldReverse
    c.push_back({FN_SOBOL_DIM1, "sobol_dim1", exact});
    c.push_back({FN_RNG_GROUP_FIRST, "rng_group_first and rng_group_second", exact});
    // cos/sin(2 pi u2) (2^-11) times sin(theta) = sqrt(u1); cos(theta) = sqrt(1 - u1).
    c.push_back({FN_SAMPLE_COSINE_HEMISPHERE, "sample_cosine_hemisphere",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double s = std::sqrt(double(x.f[0].x));
                     check_lobe_direction(k, v3(gpu.f[0]), v3(cpu.f[0]), s, kSqrtRel * s, kSqrtRel);
                 }});
    // One product by a constant after max(): correctly rounded.
    c.push_back({FN_COSINE_HEMISPHERE_PDF, "cosine_hemisphere_pdf", exact});
    c.push_back({FN_PHONG_POWER, "phong_power",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("pow", gpu.f[0].x, cpu.f[0].x, 0,
                             phong_power_rel(x.f[0].x, x.f[0].y, 0.0));
                 }});
    c.push_back({FN_SAMPLE_PHONG_LOBE, "sample_phong_lobe",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const glm::dvec3 e = phong_lobe_errors(x.f[0].x, x.f[0].z);
                     check_lobe_direction(k, v3(gpu.f[0]), v3(cpu.f[0]), e.x, e.y, e.z);
                 }});
    // (n + 1) / (2 pi) times phong_power: two more roundings; a cos^n that underflowed to a
    // flushed denormal is scaled by up to n + 1.
    c.push_back({FN_PHONG_LOBE_PDF, "phong_lobe_pdf",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("pdf", gpu.f[0].x, cpu.f[0].x, double(x.f[0].y + 1) * kFlushAbs,
                             phong_power_rel(x.f[0].x, x.f[0].y, 0.0) + 4.0 * kU);
                 }});
    // z = 1 - 2 u1 exact; r = sqrt(1 - z^2) with a contractible z^2 (u) under the sqrt.
    c.push_back({FN_SAMPLE_UNIFORM_SPHERE, "sample_uniform_sphere",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double z = 1.0 - 2.0 * double(x.f[0].x), r2 = 1.0 - z * z;
                     check_lobe_direction(k, v3(gpu.f[0]), v3(cpu.f[0]), std::sqrt(r2),
                                          sqrt_err(r2, 2.0 * kU), 0.0);
                 }});
    // sqrt(u1) times correctly rounded factors.
    c.push_back({FN_SAMPLE_UNIFORM_TRIANGLE, "sample_uniform_triangle",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("b1", gpu.f[0].x, cpu.f[0].x, 0, kSqrtRel + 2.0 * kU);
                     k.close("b2", gpu.f[0].y, cpu.f[0].y, 0, kSqrtRel + 2.0 * kU);
                 }});
    // Integer arithmetic only (the high word of a 32 x 32 -> 64-bit product).
    c.push_back({FN_ALIAS_SLOT, "alias_slot_from_bits", exact});
    c.push_back({FN_ALIAS_RESOLVE, "alias_resolve", exact});
    c.push_back({FN_BSDF_SAMPLE_NONE, "bsdf_sample_none", exact});
    c.push_back({FN_MIRROR_DIRECTION, "mirror_direction",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("r", v3(gpu.f[0]), v3(cpu.f[0]), kUnitAbs, 0);
                 }});
    // Two averages (exact as above) and one division.
    c.push_back({FN_PHONG_DIFFUSE_PROBABILITY, "phong_diffuse_probability",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("p", gpu.f[0].x, cpu.f[0].x, 0, kDivRel + 2.0 * kU);
                 }});
    // kd / pi plus the lobe: cos(alpha) = dot(mirror, wi) carries ~40 u, then phong_power.
    const auto phong_eval_check = [](const FnIn& x, const FnOut& cpu, const FnOut& gpu,
                                     Checker& k) {
        const glm::dvec3 n = d3(x.f[2]), wo = d3(x.f[3]), wi = d3(x.f[4]);
        const glm::dvec3 r = glm::normalize(2.0 * glm::dot(n, wo) * n - wo);
        const double ca = glm::dot(r, wi), ns = x.f[0].w;
        const double pp = ca <= 0 ? 0.0 : std::pow(ca, ns);
        const double lobe = (ns + 2) / (2 * M_PI) * pp;
        for (int i = 0; i < 3; ++i) {
            const double tol =
                double(x.f[0][i]) / M_PI * 4.0 * kU + (ns + 2) * kFlushAbs +
                double(x.f[1][i]) * lobe * (phong_power_rel(ca, ns, 40.0 * kU) + 8.0 * kU);
            k.close("f", gpu.f[0][i], cpu.f[0][i], tol, 0);
        }
    };
    const auto phong_pdf_check = [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
        double pdf, tol;
        phong_pdf_tol(v3(x.f[0]), v3(x.f[1]), x.f[0].w, d3(x.f[2]), d3(x.f[3]), d3(x.f[4]),
                      40.0 * kU, pdf, tol);
        k.close("pdf", gpu.f[0].x, cpu.f[0].x, tol, 0);
    };
    // Branches: wi or wo on the horizon of n.
    c.push_back({FN_PHONG_EVAL, "phong_eval", phong_eval_check, 1e-3});
    c.push_back({FN_PHONG_PDF, "phong_pdf", phong_pdf_check, 1e-3});
    // The sample's direction carries the sampler's error (cosine or Phong lobe) rotated into
    // the frame (kUnitAbs more); pdf and weight are checked as functions of the GPU's own
    // direction, so their tolerance does not have to absorb the 2^-11 of sin/cos. Branches:
    // the lobe choice u_lobe < P_d and a glossy sample at the horizon.
    const auto phong_sample_check = [](const vec3& kd, const vec3& ks, float ns, const FnIn& x,
                                       const FnOut& cpu, const FnOut& gpu, Checker& k) {
        k.exact("lobe", gpu.u.x, cpu.u.x);
        if (cpu.u.x == LOBE_NONE || gpu.u.x != cpu.u.x) return;
        double dir_tol;
        if (cpu.u.x == LOBE_DIFFUSE) {
            dir_tol = kSinCosAbs + 2.0 * kSqrtRel;
        } else {
            const glm::dvec3 e = phong_lobe_errors(x.f[5].y, ns);
            dir_tol = kSinCosAbs * e.x + e.y + e.z;
        }
        k.close3("wi", v3(gpu.f[0]), v3(cpu.f[0]), dir_tol + 2.0 * kUnitAbs, 0);
        const glm::dvec3 n = d3(x.f[2]), wo = d3(x.f[3]), wi = d3(gpu.f[0]);
        double pdf, tol;
        phong_pdf_tol(kd, ks, ns, n, wo, wi, 40.0 * kU, pdf, tol);
        const float pdf_cpu = phong_pdf(kd, ks, ns, vec3(n), vec3(wo), vec3(wi));
        k.close("pdf", gpu.f[0].w, pdf_cpu, tol + 4.0 * kU * pdf, 0);
        const vec3 f = phong_eval(kd, ks, ns, vec3(n), vec3(wo), vec3(wi));
        for (int i = 0; i < 3; ++i) {
            const double w = double(f[i]) * glm::dot(n, wi) / double(gpu.f[0].w);
            k.close("weight", gpu.f[1][i], w, 0, tol / pdf + phong_power_rel(1, ns, 0) + 1e-4);
        }
    };
    c.push_back(
        {FN_PHONG_SAMPLE, "phong_sample",
         [phong_sample_check](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
             phong_sample_check(v3(x.f[0]), v3(x.f[1]), x.f[0].w, x, cpu, gpu, k);
         },
         1e-3});
    const auto mirror_sample_check = [](const FnOut& cpu, const FnOut& gpu, Checker& k) {
        k.exact("lobe", gpu.u.x, cpu.u.x);
        k.close3("wi", v3(gpu.f[0]), v3(cpu.f[0]), kUnitAbs, 0);
        k.same("pdf", gpu.f[0].w, cpu.f[0].w);
        k.same3("weight", v3(gpu.f[1]), v3(cpu.f[1]));
    };
    c.push_back({FN_MIRROR_SAMPLE, "mirror_sample",
                 [mirror_sample_check](const FnIn&, const FnOut& cpu, const FnOut& gpu,
                                       Checker& k) { mirror_sample_check(cpu, gpu, k); },
                 1e-3});
    // One division by eta^2, a sqrt with cancellation near total internal reflection (the
    // tolerance propagates it through the formula in double), two quotients.
    c.push_back({FN_FRESNEL_DIELECTRIC, "fresnel_dielectric",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("F", gpu.f[0].x, cpu.f[0].x,
                             fresnel_tol(x.f[0].x, x.f[0].y) + 8.0 * kDivRel, 0);
                 },
                 1e-3});
    // Reflect/refract chosen by u_lobe < F (branch); the direction is a normalized sum with
    // cos_t's error (as in fresnel) scaled by |nw| = 1.
    const auto dielectric_check = [](const FnIn& x, const FnOut& cpu, const FnOut& gpu,
                                     Checker& k) {
        k.exact("lobe", gpu.u.x, cpu.u.x);
        if (gpu.u.x != cpu.u.x) return;
        const double ior = x.f[1].w, co = glm::dot(d3(x.f[2]), d3(x.f[3]));
        const double eta = co > 0 ? ior : 1.0 / ior, ci = std::abs(co);
        const double s = (1.0 - ci * ci) / (eta * eta);
        const double dct = s < 1.0 ? sqrt_err(1.0 - s, 8.0 * kU + kDivRel * s) : 0.0;
        k.close3("wi", v3(gpu.f[0]), v3(cpu.f[0]), kUnitAbs + 2.0 * dct, 0);
        const double ftol = fresnel_tol(ci, eta) + 8.0 * kDivRel + 4.0 * kU;
        k.close("pdf", gpu.f[0].w, cpu.f[0].w, ftol, 0);
        k.close3("weight", v3(gpu.f[1]), v3(cpu.f[1]), 0, 2.0 * kDivRel);
    };
    c.push_back({FN_DIELECTRIC_SAMPLE, "dielectric_sample", dielectric_check, 1e-3});
    c.push_back({FN_MATERIAL_IS_DELTA, "material_is_delta", exact});
    c.push_back({FN_BSDF_EVAL, "bsdf_eval", phong_eval_check, 1e-3}); // 0 unless Phong
    c.push_back({FN_BSDF_PDF, "bsdf_pdf", phong_pdf_check, 1e-3});
    c.push_back({FN_BSDF_SAMPLE, "bsdf_sample",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     if (x.u.x == MATERIAL_PHONG)
                         phong_sample_check(v3(x.f[0]), v3(x.f[1]), x.f[0].w, x, cpu, gpu, k);
                     else if (x.u.x == MATERIAL_MIRROR)
                         mirror_sample_check(cpu, gpu, k);
                     else
                         dielectric_check(x, cpu, gpu, k);
                 },
                 1e-3});
    c.push_back({FN_LIGHT_SAMPLE_NONE, "light_sample_none", exact});
    // d = p0 - p exact; dist = sqrt(contractible dot) (sqrt + u); wi = d / dist (3 ulp + that);
    // I / dist^2 one division.
    const auto point_check = [](const FnOut& cpu, const FnOut& gpu, Checker& k) {
        k.close3("wi", v3(gpu.f[0]), v3(cpu.f[0]), 0, kSqrtRel + kDivRel + 2.0 * kU);
        k.close("dist", gpu.f[0].w, cpu.f[0].w, 0, kSqrtRel + 2.0 * kU);
        k.close3("radiance", v3(gpu.f[1]), v3(cpu.f[1]), 0, kDivRel + 4.0 * kU);
        k.same("pdf", gpu.f[1].w, cpu.f[1].w);
        k.same3("point", v3(gpu.f[2]), v3(cpu.f[2]));
        k.exact("delta", gpu.u.x, cpu.u.x);
    };
    c.push_back({FN_SAMPLE_POINT_LIGHT, "sample_point_light",
                 [=](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     point_check(cpu, gpu, k);
                 }});
    c.push_back({FN_SAMPLE_DIRECTIONAL_LIGHT, "sample_directional_light", exact});
    // normalize(cross(e1, e2)): each cross component is a contractible difference of products
    // (u times their magnitudes), relative to the cross product's length, then normalize.
    const auto normal_tol = [](const FnIn& x) {
        const glm::dvec3 e1 = d3(x.f[7]) - d3(x.f[6]), e2 = d3(x.f[8]) - d3(x.f[6]);
        const double mag = (std::abs(e1.y * e2.z) + std::abs(e1.z * e2.y) + std::abs(e1.z * e2.x) +
                            std::abs(e1.x * e2.z) + std::abs(e1.x * e2.y) + std::abs(e1.y * e2.x));
        return 2.0 * kU * mag / glm::length(glm::cross(e1, e2)) + kUnitAbs;
    };
    c.push_back({FN_TRIANGLE_LIGHT_NORMAL, "triangle_light_normal",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("n", v3(gpu.f[0]), v3(cpu.f[0]), normal_tol(x), 0);
                 }});
    c.push_back({FN_TRIANGLE_LIGHT_PDF, "triangle_light_pdf",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("pdf", gpu.f[0].x, cpu.f[0].x, 0, kDivRel + 2.0 * kU);
                 }});
    // The point q = p0 + b1 e1 + b2 e2 (b from sqrt, contractible sums); the rest is checked
    // against C++ evaluated at the GPU's q, like the point light; the pdf divides by
    // cos_light, whose error relative to itself is the normal's error over cos_light.
    const auto triangle_check = [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
        const glm::dvec3 p0 = d3(x.f[6]), e1 = d3(x.f[7]) - p0, e2 = d3(x.f[8]) - p0;
        const double q_tol =
            (kSqrtRel + 4.0 * kU) * (sum_abs(e1) + sum_abs(e2)) + 4.0 * kU * sum_abs(p0);
        k.close3("point", v3(gpu.f[2]), v3(cpu.f[2]), q_tol, 0);
        const glm::dvec3 d = d3(gpu.f[2]) - d3(x.f[0]);
        const double dist = glm::length(d);
        k.close3("wi", v3(gpu.f[0]), vec3(d / dist), 0, kSqrtRel + kDivRel + 4.0 * kU);
        k.close("dist", gpu.f[0].w, dist, 0, kSqrtRel + 4.0 * kU);
        const double cos_l = -glm::dot(glm::normalize(glm::cross(e1, e2)), d / dist);
        const double pdf = cos_l > 0 ? dist * dist / (cos_l * double(x.f[6].w)) : 0.0;
        const double rel = kDivRel + 2.0 * kSqrtRel + (normal_tol(x) + kUnitAbs) / cos_l;
        k.close("pdf", gpu.f[1].w, pdf, 0, rel);
        k.same3("radiance", v3(gpu.f[1]), v3(cpu.f[1]));
        k.exact("delta", gpu.u.x, cpu.u.x);
    };
    c.push_back({FN_SAMPLE_TRIANGLE_LIGHT, "sample_triangle_light", triangle_check, 1e-3});
    const auto sphere_check = [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
        const double z = 1.0 - 2.0 * double(x.f[1].x), r2 = 1.0 - z * z;
        check_lobe_direction(k, v3(gpu.f[0]), v3(cpu.f[0]), std::sqrt(r2), sqrt_err(r2, 2.0 * kU),
                             0.0);
        k.same("dist", gpu.f[0].w, cpu.f[0].w);
        k.same3("radiance", v3(gpu.f[1]), v3(cpu.f[1]));
        k.same("pdf", gpu.f[1].w, cpu.f[1].w);
        k.exact("delta", gpu.u.x, cpu.u.x);
    };
    c.push_back({FN_SAMPLE_CONSTANT_ENVIRONMENT, "sample_constant_environment", sphere_check});
    // Products (exact) and one division.
    c.push_back({FN_ENVIRONMENT_MAP_PDF, "environment_map_pdf",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("pdf", gpu.f[0].x, cpu.f[0].x, 0, kDivRel);
                 }});
    c.push_back({FN_ENVIRONMENT_MAP_PIXEL_POINT, "environment_map_pixel_point",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("s", gpu.f[0].x, cpu.f[0].x, 0, kDivRel);
                     k.close("t", gpu.f[0].y, cpu.f[0].y, 0, kDivRel);
                 }});
    // rotate_y (sin/cos: 2^-11 per term), then phi = atan2 (4096 ulp plus the input error
    // over the horizontal radius) and theta = acos (through atan2, plus the input error over
    // sin theta, bounded near the poles by sqrt). Branch: the seam phi = +-pi.
    const auto latlong_check = [](const glm::dvec3& d, double in_err, const FnOut& cpu,
                                  const FnOut& gpu, Checker& k) {
        const double rh = std::sqrt(d.x * d.x + d.z * d.z);
        const double phi = std::atan2(d.x, -d.z);
        k.close("s", gpu.f[0].x, cpu.f[0].x,
                (kAtanRel * std::abs(phi) + std::min(2.0 * in_err / rh, M_PI)) / (2 * M_PI) +
                    2.0 * kU,
                0);
        const double theta = std::acos(std::clamp(d.y, -1.0, 1.0));
        const double dtheta = std::min(in_err / std::max(rh, 1e-30), std::sqrt(2.0 * in_err)) +
                              sqrt_err(rh * rh, 4.0 * kU) + kAtanRel * theta;
        k.close("t", gpu.f[0].y, cpu.f[0].y, dtheta / M_PI + 2.0 * kU, 0);
    };
    c.push_back({FN_ENVIRONMENT_MAP_COORDS, "environment_map_coords",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     latlong_check(d3(x.f[0]), 2.0 * kSinCosAbs + 4.0 * kU, cpu, gpu, k);
                 },
                 1e-3});
    c.push_back({FN_ENVIRONMENT_MAP_PIXEL, "environment_map_pixel", exact});
    // latlong_to_direction then rotate_y: sin/cos errors of up to four factors; the pdf
    // divides by sin(pi t) (2^-11 absolute).
    c.push_back({FN_SAMPLE_ENVIRONMENT_MAP, "sample_environment_map",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("wi", v3(gpu.f[0]), v3(cpu.f[0]), 6.0 * kSinCosAbs, 0);
                     const double st =
                         std::sqrt(std::max(0.0, 1.0 - double(cpu.f[0].y) * double(cpu.f[0].y)));
                     k.close("pdf", gpu.f[1].w, cpu.f[1].w, 0,
                             4.0 * kSinCosAbs / std::max(st, 1e-3) + kDivRel);
                     k.same("dist", gpu.f[0].w, cpu.f[0].w);
                 },
                 1e-3});
    c.push_back({FN_SAMPLE_LIGHT, "sample_light",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     if (x.u.y == LIGHT_POINT)
                         point_check(cpu, gpu, k);
                     else if (x.u.y == LIGHT_DIRECTIONAL)
                         same_all(cpu, gpu, k);
                     else if (x.u.y == LIGHT_TRIANGLE)
                         triangle_check(x, cpu, gpu, k);
                     else
                         sphere_check(x, cpu, gpu, k);
                 },
                 1e-3});
    c.push_back({FN_UV_TO_IMAGE, "uv_to_image", exact});
    // Exact after folding the quotient's error back (texture.h).
    c.push_back({FN_WRAP_TEXEL, "wrap_texel", exact});
    // x = s w - 0.5 is contractible (u |s w|): the blend weights carry that, and floor() may
    // flip at an integer (branch).
    c.push_back({FN_TEXTURE_FOOTPRINT, "texture_footprint",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     for (int i = 0; i < 4; ++i) k.exact("index", gpu.u[i], cpu.u[i]);
                     k.close("fx", gpu.f[0].x, cpu.f[0].x,
                             2.0 * kU * std::abs(double(x.f[0].x) * x.u.x), 0);
                     k.close("fy", gpu.f[0].y, cpu.f[0].y,
                             2.0 * kU * std::abs(double(x.f[0].y) * x.u.y), 0);
                 },
                 1e-3});
    // Three contractible mixes a (1 - t) + b t.
    c.push_back({FN_TEXTURE_BILERP, "texture_bilerp",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     double m = 0;
                     for (int i = 0; i < 4; ++i) m = std::max(m, sum_abs(d3(x.f[i])));
                     k.close3("c", v3(gpu.f[0]), v3(cpu.f[0]), 8.0 * kU * m, 0);
                     k.close("alpha", gpu.f[0].w, cpu.f[0].w, 8.0 * kU, 0);
                 }});
    // Products of two sin/cos values.
    c.push_back({FN_LATLONG_TO_DIRECTION, "latlong_to_direction",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("d", v3(gpu.f[0]), v3(cpu.f[0]), 2.0 * kSinCosAbs + 4.0 * kU, 0);
                 }});
    c.push_back({FN_DIRECTION_TO_LATLONG, "direction_to_latlong",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     latlong_check(d3(x.f[0]), 0.0, cpu, gpu, k);
                 },
                 1e-3});
    c.push_back({FN_ROTATE_Y, "rotate_y",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double m = std::abs(x.f[0].x) + std::abs(x.f[0].z);
                     k.close3("d", v3(gpu.f[0]), v3(cpu.f[0]), kSinCosAbs * m + 4.0 * kU * m, 0);
                 }});
    // Affine maps: contractible dot products, u times the sum of the terms' magnitudes.
    const auto affine_check = [](int row0, bool point) {
        return [row0, point](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
            const glm::dvec3 v = d3(x.f[6]);
            for (int r = 0; r < 3; ++r) {
                const glm::dvec4 m(x.f[row0 + r]);
                const double mag = std::abs(m.x * v.x) + std::abs(m.y * v.y) + std::abs(m.z * v.z) +
                                   (point ? std::abs(m.w) : 0.0);
                k.close("v", gpu.f[0][r], cpu.f[0][r], 4.0 * kU * mag, 0);
            }
        };
    };
    c.push_back({FN_INSTANCE_POINT_TO_WORLD, "instance_point_to_world", affine_check(0, true)});
    c.push_back({FN_INSTANCE_VECTOR_TO_WORLD, "instance_vector_to_world", affine_check(0, false)});
    c.push_back({FN_INSTANCE_POINT_TO_OBJECT, "instance_point_to_object", affine_check(3, true)});
    c.push_back(
        {FN_INSTANCE_VECTOR_TO_OBJECT, "instance_vector_to_object", affine_check(3, false)});
    // Columns of the inverse weighted by n: the same contractible sums, transposed.
    c.push_back({FN_INSTANCE_NORMAL_TO_WORLD, "instance_normal_to_world",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const glm::dvec3 v = d3(x.f[6]);
                     for (int r = 0; r < 3; ++r) {
                         const double mag = std::abs(double(x.f[3][r]) * v.x) +
                                            std::abs(double(x.f[4][r]) * v.y) +
                                            std::abs(double(x.f[5][r]) * v.z);
                         k.close("n", gpu.f[0][r], cpu.f[0][r], 4.0 * kU * mag, 0);
                     }
                 }});
    const auto bary_tol = [](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& cc,
                             double u, double v) {
        return 4.0 * kU * (sum_abs(a) + u * sum_abs(b) + v * sum_abs(cc));
    };
    c.push_back({FN_BARYCENTRIC_MIX3, "barycentric_mix3",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("p", v3(gpu.f[0]), v3(cpu.f[0]),
                              bary_tol(d3(x.f[0]), d3(x.f[1]), d3(x.f[2]), x.f[3].x, x.f[3].y), 0);
                 }});
    c.push_back({FN_BARYCENTRIC_MIX2, "barycentric_mix2",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double m = 4.0 * kU * (sum_abs(d3(x.f[0])) + sum_abs(d3(x.f[1])));
                     k.close("u", gpu.f[0].x, cpu.f[0].x, m, 0);
                     k.close("v", gpu.f[0].y, cpu.f[0].y, m, 0);
                 }});
    // p: the barycentric mix's error through the matrix plus the affine map's own; ng: the
    // cross product's error (as for triangle_light_normal) through the normal matrix,
    // relative to the result's length, then normalize.
    const auto surface_check = [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k,
                                   bool shading) {
        const glm::dvec3 v0 = d3(x.f[6]), v1 = d3(x.f[7]), v2 = d3(x.f[8]);
        const double u = x.f[9].x, v = x.f[9].y;
        double mrow = 0, mag = 0;
        for (int r = 0; r < 3; ++r)
            mrow = std::max(mrow, sum_abs(d3(x.f[r])) + std::abs(double(x.f[r].w)));
        const glm::dvec3 pm = (1 - u - v) * v0 + u * v1 + v * v2;
        mag = mrow * (sum_abs(pm) + 1.0);
        k.close3("p", v3(gpu.f[0]), v3(cpu.f[0]),
                 4.0 * kU * mag + mrow * bary_tol(v0, v1, v2, u, v), 0);
        const glm::dvec3 e1 = v1 - v0, e2 = v2 - v0, cr = glm::cross(e1, e2);
        const glm::dmat3 nm(d3(x.f[3]), d3(x.f[4]), d3(x.f[5])); // rows as columns: M^-T
        const glm::dvec3 nw = nm * cr;
        double mi = 0;
        for (int r = 3; r < 6; ++r) mi = std::max(mi, sum_abs(d3(x.f[r])));
        const double cross_err = 2.0 * kU * (sum_abs(e1) * sum_abs(e2));
        const double ng_tol =
            (mi * cross_err + 4.0 * kU * mi * sum_abs(cr)) / glm::length(nw) + kUnitAbs;
        k.close3("ng", v3(gpu.f[1]), v3(cpu.f[1]), ng_tol, 0);
        // p_error: nonnegative sums (contractible dots), within 4u of themselves; its |p| term,
        // (OFFSET_GAMMA_P + u mix) |p| with mix <= 9 (surface.h), follows p's own difference.
        k.close3("p_error", v3(gpu.f[4]), v3(cpu.f[4]),
                 (kGammaP + 9.0 * kU) * (4.0 * kU * mag + mrow * bary_tol(v0, v1, v2, u, v)),
                 4.0 * kU);
        if (!shading) {
            k.close3("ns", v3(gpu.f[2]), v3(cpu.f[2]), ng_tol, 0);
        } else {
            const glm::dvec3 n0 = d3(x.f[10]), n1 = d3(x.f[11]), n2(x.f[6].w, x.f[7].w, x.f[8].w);
            const glm::dvec3 nmix = (1 - u - v) * n0 + u * n1 + v * n2;
            const double tol = (mi * (4.0 * kU * (sum_abs(n0) + sum_abs(n1) + sum_abs(n2))) +
                                4.0 * kU * mi * sum_abs(nmix)) /
                                   glm::length(nm * nmix) +
                               kUnitAbs;
            k.close3("ns", v3(gpu.f[2]), v3(cpu.f[2]), tol, 0);
        }
        k.same("u", gpu.f[3].x, cpu.f[3].x);
        k.same("v", gpu.f[3].y, cpu.f[3].y);
    };
    c.push_back({FN_SURFACE_POINT, "surface_point",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     surface_check(x, cpu, gpu, k, false);
                 }});
    // Branch: the interpolated normal's side of ng.
    c.push_back({FN_SURFACE_SET_SHADING_NORMAL, "surface_set_shading_normal",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     surface_check(x, cpu, gpu, k, true);
                 },
                 1e-3});
    // Negations and copies chosen by the signs of two contractible dot products (branches).
    c.push_back({FN_SURFACE_FACE_VIEWER, "surface_face_viewer", exact, 1e-3});
    // Products exact, one division.
    c.push_back({FN_POWER_HEURISTIC, "power_heuristic",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("w", gpu.f[0].x, cpu.f[0].x, 0, kDivRel);
                 }});
    c.push_back({FN_EMISSION_MIS_WEIGHT, "emission_mis_weight",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("w", gpu.f[0].x, cpu.f[0].x, 0, kDivRel);
                 }});
    // Signs of contractible dot products (branches).
    c.push_back({FN_SCATTER_IS_CONSISTENT, "scatter_is_consistent", exact, 1e-3});
    // p + dot(|n|, e) n: the dot (contractible) within 3u of itself, the sum (contractible
    // with the product) one rounding of |origin|: per coordinate 4u (|p| + |dot(|n|, e)|).
    const auto origin_tol = [](glm::dvec3 p, glm::dvec3 n, glm::dvec3 e) {
        const double off = glm::dot(glm::abs(n), e);
        return 4.0 * kU * (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) + off);
    };
    // Branch: the side, the sign of a contractible dot(d, ng).
    c.push_back({FN_SPAWN_RAY, "spawn_ray",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("origin", v3(gpu.f[0]), v3(cpu.f[0]),
                              origin_tol(d3(x.f[0]), d3(x.f[1]), d3(x.f[3])), 0);
                     k.same("tmax", gpu.f[0].w, cpu.f[0].w);
                     k.same3("dir", v3(gpu.f[1]), v3(cpu.f[1]));
                 },
                 1e-3});
    // spawn_ray, then the direction to the offset target (offset the same way): length (sqrt
    // of a contractible dot) and a division, relative to the length, whose ends each carry
    // origin_tol.
    c.push_back(
        {FN_SHADOW_RAY, "shadow_ray",
         [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
             // The target moves by at most |p_error|_1 <= 3 (OFFSET_GAMMA_M m +
             // OFFSET_GAMMA_P |t|) along a unit normal that agrees to kUnitAbs.
             const glm::dvec3 p = d3(x.f[0]), n = d3(x.f[1]), t = d3(x.f[4]);
             const glm::dvec3 m = glm::max(glm::max(glm::abs(d3(x.f[6])), glm::abs(d3(x.f[7]))),
                                           glm::abs(d3(x.f[8])));
             const double t_max = std::max({std::abs(t.x), std::abs(t.y), std::abs(t.z)});
             const double t_off = 3.0 * (kGammaM * std::max({m.x, m.y, m.z}) + kGammaP * t_max);
             const double ends =
                 origin_tol(p, n, d3(x.f[5])) + 4.0 * kU * (t_max + t_off) + kUnitAbs * t_off;
             const double len = std::max(double(cpu.f[0].w), 1e-30);
             k.close3("origin", v3(gpu.f[0]), v3(cpu.f[0]), origin_tol(p, n, d3(x.f[5])), 0);
             k.close("tmax", gpu.f[0].w, cpu.f[0].w, 2.0 * ends, kSqrtRel + 2.0 * kU);
             k.close3("dir", v3(gpu.f[1]), v3(cpu.f[1]), 4.0 * ends / len,
                      kSqrtRel + kDivRel + 4.0 * kU);
         },
         1e-3});
    // normalize/cross as above; tan(theta) inherited from sin/cos: 2^-11 each, relative to
    // sin and cos of the half angle; the aspect ratio one division.
    c.push_back({FN_CAMERA_MAKE, "camera_make",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double h = 0.5 * double(x.f[0].w) * M_PI / 180.0;
                     const double tan_rel = kSinCosAbs / std::sin(h) + kSinCosAbs / std::cos(h);
                     k.same3("eye", v3(gpu.f[0]), v3(cpu.f[0]));
                     k.close("tan", gpu.f[0].w, cpu.f[0].w, 0, tan_rel + kDivRel);
                     const glm::dvec3 f = glm::normalize(d3(x.f[1]) - d3(x.f[0]));
                     const double s = glm::length(glm::cross(f, d3(x.f[2])));
                     const double dir_tol = kUnitAbs + (2.0 * kU * 2.0 + kUnitAbs * 3.0) / s;
                     k.close3("forward", v3(gpu.f[1]), v3(cpu.f[1]), kUnitAbs, 0);
                     k.close("aspect", gpu.f[1].w, cpu.f[1].w, 0, kDivRel);
                     k.close3("right", v3(gpu.f[2]), v3(cpu.f[2]), dir_tol, 0);
                     k.close3("up", v3(gpu.f[3]), v3(cpu.f[3]), 2.0 * dir_tol, 0);
                     k.exact("width", gpu.u.x, cpu.u.x);
                     k.exact("height", gpu.u.y, cpu.u.y);
                 }});
    // u, v: one division each; the ray: contractible sum of three scaled unit vectors,
    // normalized (errors relative to the unnormalized length).
    c.push_back({FN_CAMERA_DIRECTION, "camera_direction",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double t = x.f[0].w, a = x.f[1].w;
                     const double u = 2.0 * double(x.f[4].x) / x.u.x - 1.0,
                                  v = 1.0 - 2.0 * double(x.f[4].y) / x.u.y;
                     const double mag = 1.0 + std::abs(u * t * a) + std::abs(v * t);
                     const double len = std::sqrt(1.0 + u * t * a * u * t * a + v * t * v * t);
                     const double tol = (4.0 * kU * mag + 2.0 * kDivRel * mag) / len + kUnitAbs;
                     k.close3("d", v3(gpu.f[0]), v3(cpu.f[0]), tol, 0);
                 }});
    c.push_back({FN_OFFSET_RAY_ORIGIN, "offset_ray_origin",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("origin", v3(gpu.f[0]), v3(cpu.f[0]),
                              origin_tol(d3(x.f[0]), d3(x.f[2]), d3(x.f[1])), 0);
                 }});
    // t = dot(p - o, ng) / dot(d, ng): the dots contractible, each within 4u of the sum of
    // its terms' magnitudes (|p| + |o| for the first, 1 for the second), the division one
    // more rounding; o + t d and the step back onto the plane add a few u of |o| + |t|.
    // Together below 16u (|p| + |o| + |t|) / |dot(d, ng)| per coordinate; p_error follows
    // with SNAP_GAMMA of that and 2u of itself.
    c.push_back(
        {FN_SURFACE_SNAP_TO_RAY, "surface_snap_to_ray",
         [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
             const glm::dvec3 p = d3(x.f[0]), n = d3(x.f[2]), o = d3(x.f[3]), d = d3(x.f[4]);
             const double cos = std::abs(glm::dot(d, n));
             const double t = glm::dot(p - o, n) / glm::dot(d, n);
             const double mag = sum_abs(p) + sum_abs(o) + std::abs(t);
             const double tol = 16.0 * kU * mag / cos;
             k.close3("p", v3(gpu.f[0]), v3(cpu.f[0]), tol, 0);
             k.close3("p_error", v3(gpu.f[4]), v3(cpu.f[4]), double(SNAP_GAMMA) * tol, 2.0 * kU);
             k.same3("ng", v3(gpu.f[1]), v3(cpu.f[1]));
         }});
    c.push_back({FN_ROULETTE_SURVIVAL, "roulette_survival", exact});
    // The decision compares exact values; the survivor's throughput is one division.
    c.push_back({FN_ROULETTE_APPLY, "roulette_apply",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.exact("survived", gpu.u.x, cpu.u.x);
                     k.close3("T", v3(gpu.f[0]), v3(cpu.f[0]), 0, kDivRel);
                 }});
    c.push_back({FN_RAY_INVERSE_DIRECTION, "ray_inverse_direction",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("inv", v3(gpu.f[0]), v3(cpu.f[0]), 0, kDivRel);
                 }});
    // Differences, products by 1/d, min/max, one product by a constant: no contractible
    // pattern, so bit-exact.
    c.push_back({FN_INTERSECT_AABB, "intersect_aabb", exact});
    c.push_back({FN_WATERTIGHT_RAY, "watertight_ray",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     for (int i = 0; i < 3; ++i) k.exact("k", gpu.u[i], cpu.u[i]);
                     k.close3("shear", v3(gpu.f[0]), v3(cpu.f[0]), 0, kDivRel);
                 }});
    // The shear's divisions (3 ulp) move the projected vertices by ~3 ulp of their largest
    // coordinate; edge functions and T are contractible sums of products; barycentrics and t
    // are quotients by det. The tolerance is that perturbation relative to |det|: the
    // condition of the hit. Branch: rays through an edge.
    c.push_back({FN_INTERSECT_TRIANGLE, "intersect_triangle",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.exact("hit", gpu.u.x, cpu.u.x);
                     if (!cpu.u.x || !gpu.u.x) return;
                     const glm::dvec3 o = d3(x.f[0]), dir = d3(x.f[1]);
                     const glm::dvec3 a = d3(x.f[2]) - o, b = d3(x.f[3]) - o, cc = d3(x.f[4]) - o;
                     const double scale = std::max({sum_abs(a), sum_abs(b), sum_abs(cc)});
                     const glm::dvec3 cr = glm::cross(b - a, cc - a);
                     const double det =
                         std::abs(glm::dot(cr, dir)) /
                         std::max({std::abs(dir.x), std::abs(dir.y), std::abs(dir.z)});
                     const double cond = scale * scale / det;
                     const double tol = 64.0 * kU * cond;
                     k.close("t", gpu.f[0].x, cpu.f[0].x, tol * scale, 0);
                     k.close("u", gpu.f[0].y, cpu.f[0].y, tol, 0);
                     k.close("v", gpu.f[0].z, cpu.f[0].z, tol, 0);
                 },
                 1e-3});

    // ---- the glTF material (microfacet.h, pbr.h) ------------------------------------------
    c.push_back(
        {FN_GGX_D, "ggx_d", [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
             k.close("D", gpu.f[0].x, cpu.f[0].x, 0, kGgxDRel);
         }});
    c.push_back(
        {FN_GGX_G1, "ggx_g1", [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
             k.close("G1", gpu.f[0].x, cpu.f[0].x, 0, kG1Rel);
         }});
    c.push_back({FN_GGX_VISIBILITY_CORRELATED, "ggx_visibility_correlated",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("V", gpu.f[0].x, cpu.f[0].x, 0, kVisCorrelatedRel);
                 }});
    c.push_back({FN_GGX_VISIBILITY_SEPARABLE, "ggx_visibility_separable",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close("V", gpu.f[0].x, cpu.f[0].x, 0, kVisSeparableRel);
                 }});
    c.push_back({FN_GGX_SAMPLE_VISIBLE_NORMAL, "ggx_sample_visible_normal",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     glm::dvec3 h;
                     const glm::dvec2 e =
                         ggx_sample_errors(d3(x.f[0]), x.f[0].w, x.f[1].x, x.f[1].y, h);
                     k.close3("h", v3(gpu.f[0]), v3(cpu.f[0]), 2.0 * e.y, 0);
                 }});
    // vh = dot(v, h) contractible, within 3u of the sum of its terms' magnitudes (relative to
    // vh itself that is large where vh is near 0); then G1, D and a quotient by v.z. Branch:
    // vh <= 0.
    c.push_back({FN_GGX_VISIBLE_NORMAL_PDF, "ggx_visible_normal_pdf",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const glm::dvec3 v = d3(x.f[0]), h = d3(x.f[1]);
                     const double vh = glm::dot(v, h);
                     const double mag =
                         std::abs(v.x * h.x) + std::abs(v.y * h.y) + std::abs(v.z * h.z);
                     const double vh_rel = vh > 0.0 ? 3.0 * kU * mag / vh : 0.0;
                     k.close("pdf", gpu.f[0].x, cpu.f[0].x, 0,
                             vh_rel + kG1Rel + kGgxDRel + kDivRel + 2.0 * kU);
                 },
                 1e-3});
    const auto pbr_at = [](const FnIn& x) {
        return std::make_tuple(fn_pbr_material(x), vec3(v3(x.f[2])), vec3(v3(x.f[3])),
                               vec3(v3(x.f[4])));
    };
    c.push_back({FN_PBR_EVAL, "pbr_eval",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const auto [m, n, wo, wi] = pbr_at(x);
                     const glm::dvec3 tol = pbr_eval_tol(m, n, wo, wi);
                     for (int i = 0; i < 3; ++i) k.close("f", gpu.f[0][i], cpu.f[0][i], tol[i], 0);
                 },
                 1e-3});
    c.push_back({FN_PBR_PDF, "pbr_pdf",
                 [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const auto [m, n, wo, wi] = pbr_at(x);
                     k.close("pdf", gpu.f[0].x, cpu.f[0].x, pbr_pdf_tol(m, n, wo, wi), 0);
                 },
                 1e-3});
    // The lobe must agree (branches: the lobe choice, the horizon, total internal reflection).
    // The direction: a Dirac lobe's is a reflection or refraction about n (the frame's kUnitAbs,
    // and for a refraction the sqrt's error as in dielectric_sample); the diffuse lobe's the
    // cosine sampler's (as for Phong); a microfacet lobe's the visible normal's error
    // (ggx_sample_errors) carried through the reflection 2 (V.H) H - V or the refraction, which
    // move by at most 2 |dH| and (1 + 1/eta) |dH|. Pdf and weight of a non-Dirac sample are
    // checked as functions of the GPU's own direction, with pbr_pdf's and pbr_eval's
    // tolerances; a Dirac sample's are Fresnel terms and their probabilities, within 64u plus
    // their sensitivity to wo (direction_sensitivity of the C++ sample at fixed random numbers).
    c.push_back(
        {FN_PBR_SAMPLE, "pbr_sample",
         [=](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
             k.exact("lobe", gpu.u.x, cpu.u.x);
             if (cpu.u.x == LOBE_NONE || gpu.u.x != cpu.u.x) return;
             const auto [m, n, wo, wi_in] = pbr_at(x);
             (void)wi_in;
             const float ul = x.f[5].x, u0 = x.f[5].y, u1 = x.f[5].z;
             const double eta = std::min(double(m.ior), 1.0);
             if ((cpu.u.x & LOBE_SPECULAR) != 0u) {
                 const auto sample = [&](const vec3& a, const vec3& b, const vec3&) {
                     const BsdfSample s = pbr_sample(m, a, b, ul, vec2(u0, u1));
                     return glm::dvec3(s.pdf, glm::length(glm::dvec3(s.weight)), 0.0);
                 };
                 const glm::dvec3 sens = direction_sensitivity(sample, n, wo, vec3(0.0f));
                 k.close3("wi", v3(gpu.f[0]), v3(cpu.f[0]), 4.0 * kUnitAbs + 1e-5 / eta, 0);
                 k.close("pdf", gpu.f[0].w, cpu.f[0].w, sens.x, 64.0 * kU);
                 k.close3("weight", v3(gpu.f[1]), v3(cpu.f[1]), sens.y, 64.0 * kU);
                 return;
             }
             double dir_tol;
             if (cpu.u.x == LOBE_DIFFUSE) {
                 dir_tol = kSinCosAbs + 2.0 * kSqrtRel;
             } else {
                 // wo in pbr.h's local frame, where u picks the microfacet normal.
                 vec3 t, b;
                 orthonormal_basis(n, t, b);
                 const glm::dvec3 wod(wo);
                 const glm::dvec3 local(glm::dot(wod, glm::dvec3(t)), glm::dot(wod, glm::dvec3(b)),
                                        glm::dot(wod, glm::dvec3(n)));
                 glm::dvec3 h;
                 const glm::dvec2 e = ggx_sample_errors(
                     glm::normalize(local), double(m.roughness) * double(m.roughness), u0, u1, h);
                 dir_tol = 2.0 * e.y * (1.0 + 1.0 / eta);
             }
             k.close3("wi", v3(gpu.f[0]), v3(cpu.f[0]), dir_tol + 4.0 * kUnitAbs, 0);
             const vec3 wi = v3(gpu.f[0]);
             const float pdf = pbr_pdf(m, n, wo, wi);
             const double pdf_tol = pbr_pdf_tol(m, n, wo, wi);
             k.close("pdf", gpu.f[0].w, pdf, pdf_tol, 0);
             const vec3 f = pbr_eval(m, n, wo, wi);
             const glm::dvec3 f_tol = pbr_eval_tol(m, n, wo, wi);
             const double cos_i = std::abs(glm::dot(glm::dvec3(n), glm::dvec3(wi)));
             const double p = double(gpu.f[0].w);
             for (int i = 0; i < 3; ++i) {
                 const double w = double(f[i]) * cos_i / p;
                 k.close("weight", gpu.f[1][i], w, f_tol[i] * cos_i / p + 4.0 * kU * w,
                         pdf_tol / p);
             }
         },
         1e-3});
    // f0 = min(((ior - 1) / (ior + 1))^2 ks, 1) specular: a quotient, a square and two products;
    // (1 - c)^5 four products; F = f0 + (f90 - f0) w contractible. Every term is within [0, 1]:
    // absolute 2 kDivRel + 16u.
    c.push_back({FN_PBR_DIELECTRIC_FRESNEL, "pbr_dielectric_fresnel",
                 [](const FnIn&, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     k.close3("F", v3(gpu.f[0]), v3(cpu.f[0]), 2.0 * kDivRel + 16.0 * kU, 0);
                 }});
    // T = tf^(d / distance): pow inherited from exp2(k log2 tf) with k = d / distance one
    // quotient (kDivRel), whose error moves the exponent by |ln tf| k kDivRel.
    c.push_back({FN_PBR_VOLUME_TRANSMITTANCE, "pbr_volume_transmittance",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double kk = double(x.f[0].x) / double(x.f[8].w);
                     for (int i = 0; i < 3; ++i) {
                         const double t = x.f[9][i];
                         const double rel = t > 0.0 ? phong_power_rel(t, kk, 0.0) +
                                                          std::abs(std::log(t)) * kk * kDivRel
                                                    : 0.0;
                         k.close("T", gpu.f[0][i], cpu.f[0][i], 0, rel);
                     }
                 }});
    // A hash of the floats' bits and a conversion by 2^-24: integer operations.
    c.push_back({FN_ALPHA_BLEND_THRESHOLD, "alpha_blend_threshold", exact});
    c.push_back({FN_ALPHA_COVERS, "alpha_covers", exact});
    // Below 0.04045 a product by a constant (correctly rounded); above, pow((c + 0.055) x
    // (1 / 1.055), 2.4), its base from two correctly rounded operations (a sum, then a product:
    // not contractible), pow inherited from exp2(2.4 log2 base).
    c.push_back({FN_SRGB_TO_LINEAR, "srgb_to_linear",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double c = x.f[0].x;
                     const double rel =
                         c <= 0.04045 ? 0.0 : phong_power_rel((c + 0.055) / 1.055, 2.4, 2.0 * kU);
                     k.close("linear", gpu.f[0].x, cpu.f[0].x, 0, rel);
                 }});
    // Exact integer-to-float conversions times a constant, correctly rounded.
    c.push_back({FN_UNPACK_RGBA8, "unpack_rgba8", exact});
    c.push_back({FN_UNPACK_RGBA16, "unpack_rgba16", exact});
    // t = tangent - n dot(n, tangent) (contractible: 4u of |tangent|_1 + |dot|), normalized
    // (errors over its length lt, plus sqrt's and a quotient's); b = cross(n, t) (2u, and t's
    // error twice); m = (2c - 1) (s, s, 1) in the frame (contractible: 8u of the terms), and m
    // normalized, whose error is m's over |m|. Branches: the bitangent's side (dot near 0), a
    // tangent parallel to n, a texel that decodes to the zero vector.
    c.push_back({FN_SURFACE_APPLY_NORMAL_MAP, "surface_apply_normal_map",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const glm::dvec3 n = d3(x.f[0]), tg = d3(x.f[1]), c = d3(x.f[3]);
                     const double s = x.f[3].w;
                     const glm::dvec3 t = tg - n * glm::dot(n, tg);
                     const double lt = glm::length(t);
                     const glm::dvec3 v = 2.0 * c - 1.0;
                     const double lm_terms = std::abs(v.x * s) + std::abs(v.y * s) + std::abs(v.z);
                     if (!(lt > 0.0)) {
                         same_all(cpu, gpu, k);
                         return;
                     }
                     const glm::dvec3 tn = t / lt, b = glm::cross(n, tn);
                     const glm::dvec3 m = v.x * s * tn + v.y * s * b + v.z * n;
                     const double lm = glm::length(m);
                     const double dt =
                         4.0 * kU * (sum_abs(tg) + std::abs(glm::dot(n, tg))) * 3.0 / lt +
                         kSqrtRel + kDivRel + 2.0 * kU;
                     const double db = 2.0 * dt + 4.0 * kU;
                     const double dm = std::abs(v.x * s) * dt + std::abs(v.y * s) * db +
                                       8.0 * kU * lm_terms + 4.0 * kU * (std::abs(s) + 1.0);
                     const double tol = lm > 0.0 ? dm / lm + kSqrtRel + kDivRel + kUnitAbs : 0.0;
                     k.close3("ns", v3(gpu.f[0]), v3(cpu.f[0]), tol, 0);
                 },
                 1e-3});
    // clamp(-dot(wi, axis) scale + offset, 0, 1)^2: the dot within 3u, times the scale (up to
    // 1000) and plus the offset (contractible: 4u of both terms), then squared.
    c.push_back({FN_SPOT_LIGHT_FALLOFF, "spot_light_falloff",
                 [](const FnIn& x, const FnOut& cpu, const FnOut& gpu, Checker& k) {
                     const double sc = x.f[8].x, off = x.f[8].y;
                     const double cosv = -glm::dot(d3(x.f[0]), d3(x.f[7]));
                     const double lin = cosv * sc + off;
                     const double dlin =
                         3.0 * kU * std::abs(sc) + 4.0 * kU * (std::abs(cosv * sc) + std::abs(off));
                     const double f = std::clamp(lin, 0.0, 1.0);
                     k.close("falloff", gpu.f[0].x, cpu.f[0].x,
                             2.0 * f * dlin + dlin * dlin + 2.0 * kU, 0);
                 }});
    return c;
}

} // namespace

TEST_CASE("every shared-header function agrees between C++ and the GPU", "[gpu]") {
    const std::vector<Case> all = cases();
    REQUIRE(all.size() == FN_COUNT);
    // Many functions per dispatch (their inputs in contiguous blocks, so that a workgroup runs
    // one function): each dispatch builds a pipeline for the whole dispatch table, which on
    // lavapipe costs far more than running it.
    constexpr size_t kFunctionsPerDispatch = 28;
    const uint32_t n = kInputsPerFunction;
    for (size_t first_fn = 0; first_fn < all.size(); first_fn += kFunctionsPerDispatch) {
        const size_t fns = std::min(kFunctionsPerDispatch, all.size() - first_fn);
        const uint32_t count = uint32_t(fns) * n;
        std::vector<uint32_t> ids(count);
        std::vector<FnIn> inputs(count);
        for (size_t f = 0; f < fns; ++f) {
            const Case& fc = all[first_fn + f];
            InputGen gen(0x5eed0000u + fc.id);
            for (uint32_t i = 0; i < n; ++i) {
                ids[f * n + i] = fc.id;
                make_input(fc.id, gen, inputs[f * n + i]);
            }
        }
        const auto out = run_shader(tp_spirv_shared_functions, sizeof(tp_spirv_shared_functions),
                                    {bytes_of(ids), bytes_of(inputs)}, {count * sizeof(FnOut)},
                                    &count, sizeof(count), (count + 63) / 64);
        const std::vector<FnOut> gpu = as_vector<FnOut>(out[0]);
        for (size_t f = 0; f < fns; ++f) {
            const Case& fc = all[first_fn + f];
            Checker k;
            double worst = 0.0;
            uint32_t failures = 0;
            std::string first;
            for (uint32_t i = 0; i < n; ++i) {
                const FnIn& x = inputs[f * n + i];
                const FnOut cpu = run_function(fc.id, x);
                k.reset_input();
                fc.check(x, cpu, gpu[f * n + i], k);
                if (!k.failed()) worst = std::max(worst, k.input_worst());
                if (k.failed() && failures++ == 0)
                    first = fmt::format("input {}: {}", i, k.message());
            }
            const uint32_t allowed = uint32_t(fc.outliers * n);
            INFO(fc.name << ": " << failures << " of " << n << " inputs disagree (allowed "
                         << allowed << "); first: " << first);
            CHECK(failures <= allowed);
            fmt::print("{:<28} worst |gpu - cpu| / tolerance {:.3g}, outliers {}\n", fc.name, worst,
                       failures);
        }
    }
    CHECK(validation_messages() == 0);
}

} // namespace tp::test
