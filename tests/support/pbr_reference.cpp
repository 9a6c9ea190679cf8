#include "support/pbr_reference.h"

#include "scene/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>

namespace tp::test::pbr {
namespace {

constexpr double kPi = 3.14159265358979323846;

using glm::dvec3;

double max_value(const dvec3& c) {
    return std::max({c.x, c.y, c.z});
}

// ---- glTF 2.0, Appendix B ---------------------------------------------------------------------
// D = alpha^2 chi+(N.H) / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2), the denominator's
// (N.H)^2 (alpha^2 - 1) + 1 taken as H_x^2 + H_y^2 + alpha^2 (N.H)^2 (equal for a unit H):
// 1 - (N.H)^2 would cancel to ~1e-16 / alpha^2 of itself at the peak, and the quadrature
// resolves lobes down to alpha = 1e-4.
double D(const dvec3& H, double alpha) {
    const double nh = H.z;
    if (!(nh > 0.0)) return 0.0;
    const double a2 = alpha * alpha;
    const double k = H.x * H.x + H.y * H.y + a2 * nh * nh;
    return a2 / (kPi * k * k);
}

// sqrt(alpha^2 + (1 - alpha^2) (N.X)^2)
double root(double nx, double alpha) {
    const double a2 = alpha * alpha;
    return std::sqrt(a2 + (1.0 - a2) * nx * nx);
}

// The height-correlated visibility nu = G / (4 |N.L| |N.V|) (the chi+ of H are checked by the
// caller).
double nu(const dvec3& V, const dvec3& L, double alpha) {
    const double nv = std::abs(V.z), nl = std::abs(L.z);
    const double d = nv * root(nl, alpha) + nl * root(nv, alpha);
    return d > 0.0 ? 1.0 / (2.0 * d) : 0.0;
}

// Separable Smith: G1(X) = 2 |N.X| / (|N.X| + sqrt(alpha^2 + (1 - alpha^2)(N.X)^2)), and the
// thin-walled transmission's nu_T = G1(L) G1(V) / (4 |N.L| |N.V|).
double G1(const dvec3& X, double alpha) {
    const double nx = std::abs(X.z);
    return 2.0 * nx / (nx + root(nx, alpha));
}
double nu_T(const dvec3& V, const dvec3& L, double alpha) {
    const double nv = std::abs(V.z), nl = std::abs(L.z);
    return 1.0 / ((nl + root(nl, alpha)) * (nv + root(nv, alpha)));
}

double pow5(double x) {
    return x * x * x * x * x;
}

// What fresnel_mix (KHR_materials_specular) gives the layer and the base at microfacet normal H
// with vh = |V.H|. On a volume boundary Schlick's cosine is the one on the less dense side, and
// under total internal reflection F = 1 with F90 not scaled by specular (KHR_materials_volume).
struct FresnelMix {
    dvec3 layer; // weight fr
    double base; // 1 - weight max_value(fr)
};

FresnelMix fresnel_mix(const Params& p, double vh) {
    double c = vh;
    if (p.volume && p.ior < 1.0) {
        const double sin2_o = (1.0 - vh * vh) / (p.ior * p.ior);
        if (sin2_o >= 1.0) return {dvec3(1.0), 0.0};
        c = std::sqrt(1.0 - sin2_o);
    }
    // ((1 - ior) / (1 + ior))^2 is the same for the relative index and its inverse.
    const double r = (1.0 - p.ior) / (1.0 + p.ior);
    const dvec3 f0 = glm::min(r * r * p.specular_color, dvec3(1.0));
    const dvec3 fr = f0 + (dvec3(1.0) - f0) * pow5(1.0 - std::abs(c));
    return {p.specular * fr, 1.0 - p.specular * max_value(fr)};
}

dvec3 conductor_fresnel(const Params& p, double vh) {
    return p.base_color + (dvec3(1.0) - p.base_color) * pow5(1.0 - std::abs(vh));
}

bool is_smooth(const Params& p) {
    return p.roughness < kSmoothRoughness;
}

// ---- the tensor Gauss-Kronrod (7, 15) rule --------------------------------------------------
// QUADPACK's qk15 nodes on [-1, 1] (the positive half, the centre last) and weights.
const double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                        0.207784955007898467600689403773245, 0.0};
const double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// The 7-point Gauss rule's weights at the nodes kXgk[1], [3], [5], [7].
const double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                       0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Rule {
    double x[15], wk[15], wg[15]; // nodes on [-1, 1], Kronrod weights, Gauss weights (0 if none)
    Rule() {
        for (int i = 0; i < 15; ++i) {
            const int k = i < 8 ? i : 14 - i; // index into the positive half
            x[i] = i < 8 ? -kXgk[k] : kXgk[k];
            wk[i] = kWgk[k];
            wg[i] = (k % 2 == 1) ? kWg[k / 2] : 0.0;
        }
    }
};

struct Panel {
    double t0, t1, p0, p1;
    dvec3 value;
    double error;
    bool operator<(const Panel& o) const { return error < o.error; }
};

struct Chart {
    dvec3 axis, t, b;
    dvec3 direction(double theta, double phi) const {
        const double st = std::sin(theta);
        return st * std::cos(phi) * t + st * std::sin(phi) * b + std::cos(theta) * axis;
    }
};

Panel evaluate(const Rule& rule, const Chart& chart, const Integrand& g, double t0, double t1,
               double p0, double p1) {
    const double ct = 0.5 * (t0 + t1), ht = 0.5 * (t1 - t0);
    const double cp = 0.5 * (p0 + p1), hp = 0.5 * (p1 - p0);
    dvec3 k(0.0), gs(0.0);
    for (int i = 0; i < 15; ++i) {
        const double theta = ct + ht * rule.x[i];
        const double st = std::sin(theta);
        dvec3 row_k(0.0), row_g(0.0);
        for (int j = 0; j < 15; ++j) {
            const dvec3 v = g(chart.direction(theta, cp + hp * rule.x[j])) * st;
            row_k += rule.wk[j] * v;
            row_g += rule.wg[j] * v;
        }
        k += rule.wk[i] * row_k;
        gs += rule.wg[i] * row_g;
    }
    const double area = ht * hp;
    Panel p{t0, t1, p0, p1, k * area, max_value(glm::abs(k - gs)) * area};
    return p;
}

} // namespace

tp::Material to_material(const Params& p) {
    tp::Material m = tp::default_pbr_material();
    m.kd = vec3(p.base_color);
    m.ks = vec3(p.specular_color);
    m.metallic = float(p.metallic);
    m.roughness = float(p.roughness);
    m.ior = float(p.ior);
    m.transmission = float(p.transmission);
    m.specular = float(p.specular);
    m.flags = p.volume ? MATERIAL_FLAG_VOLUME : 0u;
    return m;
}

dvec3 bsdf(const Params& p, const dvec3& V, const dvec3& L) {
    const double alpha = p.roughness * p.roughness;
    const bool smooth = is_smooth(p);
    if (L.z > 0.0) {
        const dvec3 H = glm::normalize(V + L);
        const double vh = std::abs(glm::dot(V, H));
        // chi+(H.L) chi+(H.V) hold for the half vector of two directions above the surface.
        const double specular_brdf = smooth ? 0.0 : D(H, alpha) * nu(V, L, alpha);
        const FresnelMix fm = fresnel_mix(p, vh);
        const dvec3 base = (1.0 - p.transmission) * p.base_color / kPi; // L above: no btdf
        const dvec3 dielectric = fm.base * base + fm.layer * specular_brdf;
        const dvec3 metal = specular_brdf * conductor_fresnel(p, vh);
        return (1.0 - p.metallic) * dielectric + p.metallic * metal;
    }
    if (!(L.z < 0.0) || smooth || p.transmission == 0.0) return dvec3(0.0);
    double btdf = 0.0, vh = 0.0;
    if (!p.volume) {
        const dvec3 H = glm::normalize(V + dvec3(L.x, L.y, -L.z)); // V - 2 (N.L) N + L
        vh = std::abs(glm::dot(V, H));
        btdf = D(H, alpha) * nu_T(V, L, alpha);
    } else {
        dvec3 H = V + p.ior * L; // eta_V V + eta_L L with eta_V = 1
        const double len = glm::length(H);
        if (!(len > 0.0)) return dvec3(0.0);
        H /= len;
        if (H.z < 0.0) H = -H;
        vh = glm::dot(V, H);
        const double lh = glm::dot(L, H);
        // chi+(H.V / N.V) and chi+(H.L / N.L) with N.V > 0 > N.L.
        if (!(vh > 0.0) || !(lh < 0.0)) return dvec3(0.0);
        const double denom = vh + p.ior * lh;
        btdf = std::abs(lh) * vh / (std::abs(L.z) * V.z) * G1(V, alpha) * G1(L, alpha) *
               D(H, alpha) / (denom * denom);
    }
    const FresnelMix fm = fresnel_mix(p, vh);
    return (1.0 - p.metallic) * fm.base * p.transmission * btdf * p.base_color;
}

DiracLobes dirac_lobes(const Params& p, const dvec3& V) {
    DiracLobes d;
    if (!is_smooth(p)) return d;
    const FresnelMix fm = fresnel_mix(p, V.z);
    d.reflection = (1.0 - p.metallic) * fm.layer + p.metallic * conductor_fresnel(p, V.z);
    const double compression = p.volume ? 1.0 / (p.ior * p.ior) : 1.0;
    d.transmission = (1.0 - p.metallic) * fm.base * p.transmission * compression * p.base_color;
    return d;
}

namespace {

// Edges on [lo, hi] that grow geometrically away from `centre` on both sides: the first cell
// `first` wide, `n` cells to each side (fewer where the side is short), lo and hi included.
std::vector<double> focused_edges(double lo, double hi, double centre, double first, int n) {
    centre = std::clamp(centre, lo, hi);
    std::vector<double> e = {lo, hi, centre};
    for (const double sign : {-1.0, 1.0}) {
        const double side = sign < 0.0 ? centre - lo : hi - centre;
        if (!(side > first)) continue;
        const double ratio = side / first + 1.0;
        for (int k = 1; k < n; ++k)
            e.push_back(centre + sign * first * (std::pow(ratio, double(k) / n) - 1.0));
    }
    std::sort(e.begin(), e.end());
    std::vector<double> out;
    for (double x : e)
        if (out.empty() || x - out.back() > 1e-12 * (hi - lo)) out.push_back(x);
    if (out.back() != hi) out.back() = hi;
    return out;
}

} // namespace

QuadratureResult integrate_hemisphere(const Integrand& g, bool upper, const dvec3& lobe,
                                      double width, double abs_tol) {
    static const Rule rule;
    // The hemisphere's own polar chart: theta from its pole (+z above, -z below), so that the
    // horizon, where the integrands have their kink, is the edge theta = pi / 2.
    Chart chart;
    chart.axis = dvec3(0.0, 0.0, upper ? 1.0 : -1.0);
    chart.t = dvec3(1.0, 0.0, 0.0);
    chart.b = dvec3(0.0, upper ? 1.0 : -1.0, 0.0);
    const dvec3 l = glm::normalize(lobe);
    const double lz = upper ? l.z : -l.z;
    const double theta_l = std::acos(std::clamp(lz, -1.0, 1.0));
    const double phi_l = std::atan2(glm::dot(l, chart.b), glm::dot(l, chart.t));
    const std::vector<double> thetas = focused_edges(0.0, 0.5 * kPi, theta_l, 0.25 * width, 12);
    // Around the pole a lobe covers every azimuth: uniform columns there.
    const double sin_l = std::sin(theta_l);
    const std::vector<double> phis =
        sin_l > 2.0 * width
            ? focused_edges(phi_l - kPi, phi_l + kPi, phi_l, 0.25 * width / sin_l, 8)
            : focused_edges(-kPi, kPi, 0.0, kPi / 6.0, 6);
    constexpr size_t kMaxPanels = 6000;
    std::priority_queue<Panel> queue;
    double total_error = 0.0;
    for (size_t i = 0; i + 1 < thetas.size(); ++i)
        for (size_t j = 0; j + 1 < phis.size(); ++j) {
            const Panel p =
                evaluate(rule, chart, g, thetas[i], thetas[i + 1], phis[j], phis[j + 1]);
            total_error += p.error;
            queue.push(p);
        }
    while (total_error > abs_tol && queue.size() < kMaxPanels) {
        const Panel worst = queue.top();
        queue.pop();
        total_error -= worst.error;
        const double tm = 0.5 * (worst.t0 + worst.t1), pm = 0.5 * (worst.p0 + worst.p1);
        for (const auto& [a0, a1, b0, b1] : {std::array<double, 4>{worst.t0, tm, worst.p0, pm},
                                             {tm, worst.t1, worst.p0, pm},
                                             {worst.t0, tm, pm, worst.p1},
                                             {tm, worst.t1, pm, worst.p1}}) {
            const Panel p = evaluate(rule, chart, g, a0, a1, b0, b1);
            total_error += p.error;
            queue.push(p);
        }
    }
    QuadratureResult r;
    r.panels = queue.size();
    while (!queue.empty()) {
        r.value += queue.top().value;
        r.error += queue.top().error;
        queue.pop();
    }
    return r;
}

QuadratureResult integrate_lobes(const Integrand& g, const dvec3& reflect, const dvec3& transmit,
                                 double width, double abs_tol) {
    const QuadratureResult up = integrate_hemisphere(g, true, reflect, width, 0.5 * abs_tol);
    const QuadratureResult down = integrate_hemisphere(g, false, transmit, width, 0.5 * abs_tol);
    QuadratureResult r;
    r.value = up.value + down.value;
    r.error = up.error + down.error;
    r.panels = up.panels + down.panels;
    return r;
}

dvec3 reflect_axis(const dvec3& V) {
    return dvec3(-V.x, -V.y, V.z);
}

dvec3 transmit_axis(const Params& p, const dvec3& V) {
    if (!p.volume) return -V;
    const double c = V.z, sin2_t = (1.0 - c * c) / (p.ior * p.ior);
    if (sin2_t >= 1.0) return dvec3(0.0, 0.0, -1.0);
    return glm::normalize(-V / p.ior + (c / p.ior - std::sqrt(1.0 - sin2_t)) * dvec3(0, 0, 1));
}

double lobe_width(const Params& p) {
    return std::clamp(p.roughness * p.roughness, 1e-4, 0.5);
}

QuadratureResult albedo(const Params& p, const dvec3& V, double abs_tol) {
    QuadratureResult r =
        integrate_lobes([&](const dvec3& L) { return bsdf(p, V, L) * std::abs(L.z); },
                        reflect_axis(V), transmit_axis(p, V), lobe_width(p), abs_tol);
    const DiracLobes d = dirac_lobes(p, V);
    r.value += d.reflection + d.transmission;
    return r;
}

} // namespace tp::test::pbr
