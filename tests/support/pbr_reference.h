// glTF 2.0's metallic-roughness BSDF written again, in double precision, from the specification's
// text and not from common/shared/pbr.h: the reference that the PBR tests hold pbr.h to. The
// formulas, each where the specification writes it:
//   - glTF 2.0, Appendix B ("Specular BRDF", "Fresnel", "Metal BRDF and Dielectric BRDF"): the
//     GGX distribution D, the height-correlated visibility nu, Schlick's Fresnel in |V.H|,
//     metal_brdf = specular_brdf (baseColor + (1 - baseColor)(1 - |V.H|)^5),
//     material = mix(dielectric_brdf, metal_brdf, metallic);
//   - KHR_materials_specular and _ior ("Implementation"): fresnel_mix(f0_color, ior, weight,
//     base, layer) = (1 - weight max_value(fr)) base + weight fr layer with
//     f0 = min(((1 - ior)/(1 + ior))^2 f0_color, 1), fr = f0 + (1 - f0)(1 - |V.H|)^5;
//   - KHR_materials_transmission: base = mix(diffuse_brdf(baseColor), specular_btdf baseColor,
//     transmission), the thin-walled specular_btdf = D_T nu_T at H_T = normalize(V - 2 (N.L) N +
//     L) with the separable visibility nu_T; fresnel_mix's |V.H| of the transmitted part is
//     taken at H_T, the microfacet the light crosses;
//   - KHR_materials_volume ("Implementation"): the refracting BTDF of Walter et al. 2007 at
//     H_TR = normalize(eta_V V + eta_L L), with Schlick's cosine on the less dense side (the
//     extension's three cases: |V.H|, cos theta_o, or total internal reflection with F = 1 and
//     F90 not scaled by specular). The extension writes the factor eta_o^2 with eta_o the index
//     on L's side, which is the BTDF for importance; a path tracer gathering radiance needs
//     eta_V^2 (Walter et al. 2007, eq. 21 with o the viewer's side; pbrt-v4 sec. 9.7.5), which
//     is what pbr.h's header promises, so this reference uses eta_V^2. The two differ by
//     (eta_L / eta_V)^2 and agree in a closed volume's furnace.
// In the smooth limit (roughness below pbr.h's 0.01) the microfacet lobes become Dirac lobes
// whose weights are the limits alpha -> 0 of their integrals: G -> 1 and H -> N, so the
// reflection weighs the Fresnel terms at cos(theta_V) and the transmission (1 - max F) times
// the transmitted share (and (eta_V / eta_L)^2 on a volume boundary).
//
// Directions are in the local frame with N = +z; V.z > 0. The index `ior` is the relative index
// eta = eta_L / eta_V of the boundary as the path crosses it, as pbr.h takes it (a volume met
// from inside has 1 / ior).
#pragma once

#include "shared/types.h"

#include <glm/glm.hpp>

#include <functional>

namespace tp::test::pbr {

struct Params {
    glm::dvec3 base_color{1.0};
    double metallic = 1.0;
    double roughness = 1.0;
    double ior = 1.5;
    double transmission = 0.0;
    double specular = 1.0;
    glm::dvec3 specular_color{1.0};
    bool volume = false; // KHR_materials_volume: a refracting boundary, not thin-walled
};

// The roughness below which pbr.h renders the smooth limit (PBR_SMOOTH_ROUGHNESS).
constexpr double kSmoothRoughness = 0.01;

// The material as pbr.h takes it (MATERIAL_PBR, no textures).
tp::Material to_material(const Params& p);

// f(V, L), the non-Dirac part (in the smooth limit only the diffuse lobe).
glm::dvec3 bsdf(const Params& p, const glm::dvec3& V, const glm::dvec3& L);

// The smooth limit's Dirac lobes at V: the weights (integrals of f |cos|) of the reflection
// about N and of the transmission; zero unless roughness < kSmoothRoughness.
struct DiracLobes {
    glm::dvec3 reflection{0.0};
    glm::dvec3 transmission{0.0};
};
DiracLobes dirac_lobes(const Params& p, const glm::dvec3& V);

// ---- quadrature over the sphere ---------------------------------------------------------------
using Integrand = std::function<glm::dvec3(const glm::dvec3& w)>;

struct QuadratureResult {
    glm::dvec3 value{0.0};
    double error = 0.0; // the sum of the panels' error estimates (largest channel)
    size_t panels = 0;
};

// Integral of g over the hemisphere above the surface (`upper`) or below it. The hemisphere is
// charted in polar coordinates about its pole, so that the horizon, where f |cos| has a kink, is
// a panel edge; the initial panels' edges grow geometrically in theta and phi away from `lobe`,
// the direction a lobe of angular width `width` is centred on, so that the lobe and the broad
// parts elsewhere start out with panels of their own size. Each panel is integrated by the
// tensor 15-point Gauss-Kronrod rule, whose difference from the embedded 7-point Gauss rule is
// its error estimate (an overestimate for the 15-point value returned, exact for polynomials of
// degree 22 in each variable); the panel with the largest estimate is quartered until the
// estimates add up to abs_tol or 6000 panels (globally adaptive, as QUADPACK's and cubature's
// integrators).
QuadratureResult integrate_hemisphere(const Integrand& g, bool upper, const glm::dvec3& lobe,
                                      double width, double abs_tol);

// Integral of g over the sphere: the hemisphere above (lobe about `reflect_axis`) plus the one
// below (about `transmit_axis`).
QuadratureResult integrate_lobes(const Integrand& g, const glm::dvec3& reflect_axis,
                                 const glm::dvec3& transmit_axis, double width, double abs_tol);

// Where a material's lobes are at V: the mirror direction, and below the surface the direction
// the transmission lobe is centred on (-V thin-walled, the refracted direction on a volume
// boundary, -N under total internal reflection); and the angular width of the lobes.
glm::dvec3 reflect_axis(const glm::dvec3& V);
glm::dvec3 transmit_axis(const Params& p, const glm::dvec3& V);
double lobe_width(const Params& p);

// The directional albedo at V: the integral of f |cos| over the sphere by the quadrature above,
// plus the Dirac lobes' weights in the smooth limit.
QuadratureResult albedo(const Params& p, const glm::dvec3& V, double abs_tol = 1e-7);

} // namespace tp::test::pbr
