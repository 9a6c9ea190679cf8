// The glTF material's goodness-of-fit cases (MATERIAL_PBR, common/shared/pbr.h), shared by the CPU
// suite (pbr_chi2_test.cpp) and the GPU one (tests/gpu/chi2_gpu_test.cpp), so that both test the
// sampler on the same materials in the same frames.
//
// Each lobe alone (diffuse only: specular 0; metal; the dielectric's specular reflection alone:
// black base colour; the thin-walled and the volume transmission alone: specular 0, so that F = 0
// except under total internal reflection), their mixtures, a volume met from outside (eta 1.5) and
// from inside (1/1.5, total internal reflection beyond 41.8 degrees), grazing views (85
// degrees), roughness 0.02, 0.1, 0.5 and 1, and the smooth limit, whose Dirac samples count as
// draws that give no direction (the harness expects them at the rate 1 - integral of the pdf, so
// the Dirac lobe's probability is tested too).
//
// The chart: polar about the lobe whose shape is tested, rows geometric in 1 - cos from
// s0 = alpha^2 / 4 (GGX's lobe of directions is ~2 alpha wide, 1 - cos ~ 2 alpha^2 at its
// edge), so that a narrow lobe spans many cells while the grid still covers the whole sphere.
#pragma once

#include "chi2/direction_at.h"
#include "support/chi2.h"
#include "support/pbr_reference.h"

#include <glm/glm.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace tp::test::chi2 {

struct PbrCase {
    std::string name;
    tp::test::pbr::Params p;
    double theta_o_degrees;
    glm::dvec3 normal;
    bool chart_on_transmission; // the chart about the transmission lobe, not the reflection's
    bool on_gpu;                // also in the GPU suite (a subset: lavapipe draws slowly)

    tp::vec3 n() const { return tp::vec3(glm::normalize(normal)); }
    tp::vec3 wo() const { return direction_at(glm::normalize(normal), theta_o_degrees); }

    SphereChart chart() const {
        const glm::dvec3 nd(n()), v(wo());
        const double c = glm::dot(nd, v);
        glm::dvec3 axis = 2.0 * c * nd - v; // mirror
        if (chart_on_transmission) {
            if (!p.volume) {
                axis = -v;
            } else {
                const double eta = p.ior, s2 = (1.0 - c * c) / (eta * eta);
                axis = s2 >= 1.0 ? -nd : -v / eta + (c / eta - std::sqrt(1.0 - s2)) * nd;
            }
        }
        const double alpha = p.roughness * p.roughness;
        return SphereChart::lobe(glm::normalize(axis), std::clamp(0.25 * alpha * alpha, 1e-9, 0.05),
                                 48, 64);
    }
};

inline std::vector<PbrCase> pbr_cases() {
    using glm::dvec3;
    const auto params = [](dvec3 base, double metallic, double roughness) {
        tp::test::pbr::Params p;
        p.base_color = base;
        p.metallic = metallic;
        p.roughness = roughness;
        return p;
    };
    const dvec3 tilt1 = glm::normalize(dvec3(0.3, -0.5, 0.8));
    const dvec3 tilt2 = glm::normalize(dvec3(-0.6, 0.2, -0.77));
    const dvec3 tilt3 = glm::normalize(dvec3(0.1, 0.9, 0.2));
    std::vector<PbrCase> v;
    {
        auto p = params({0.8, 0.5, 0.2}, 0.0, 0.5);
        p.specular = 0.0;
        v.push_back({"diffuse alone", p, 30.0, tilt1, false, true});
    }
    v.push_back(
        {"metal, roughness 0.02", params({0.9, 0.6, 0.3}, 1.0, 0.02), 0.0, {0, 0, 1}, false, true});
    v.push_back(
        {"metal, roughness 0.1", params({0.9, 0.6, 0.3}, 1.0, 0.1), 45.0, tilt2, false, false});
    v.push_back(
        {"metal, roughness 0.5", params({0.9, 0.6, 0.3}, 1.0, 0.5), 60.0, tilt3, false, true});
    v.push_back({"metal, roughness 1, 85 deg", params({0.5, 0.5, 0.5}, 1.0, 1.0), 85.0, tilt1,
                 false, false});
    v.push_back({"metal, roughness 0.02, 85 deg",
                 params({1.0, 0.8, 0.4}, 1.0, 0.02),
                 85.0,
                 {1, 0, 0},
                 false,
                 true});
    v.push_back({"dielectric specular alone, roughness 0.1", params({0, 0, 0}, 0.0, 0.1), 30.0,
                 tilt2, false, false});
    v.push_back({"dielectric specular alone, roughness 0.5, 85 deg", params({0, 0, 0}, 0.0, 0.5),
                 85.0, tilt3, false, true});
    v.push_back(
        {"plastic, roughness 0.1", params({0.7, 0.2, 0.1}, 0.0, 0.1), 45.0, tilt1, false, true});
    v.push_back({"plastic, roughness 0.02, 70 deg", params({0.3, 0.3, 0.3}, 0.0, 0.02), 70.0, tilt2,
                 false, false});
    v.push_back({"plastic, roughness 0.1, 85 deg",
                 params({0.3, 0.6, 0.3}, 0.0, 0.1),
                 85.0,
                 {0, 0, -1},
                 false,
                 false});
    v.push_back({"half metallic, roughness 0.35", params({0.5, 0.6, 0.7}, 0.5, 0.35), 60.0, tilt3,
                 false, true});
    {
        // A coloured, clamped f0: the lobe probabilities take max3 and averages of it.
        auto p = params({0.3, 0.4, 0.2}, 0.0, 0.3);
        p.ior = 2.0;
        p.specular = 0.7;
        p.specular_color = {1.0, 0.5, 20.0};
        v.push_back({"coloured specular, roughness 0.3", p, 45.0, tilt1, false, false});
    }
    {
        auto p = params({0.9, 0.8, 0.7}, 0.0, 0.1);
        p.transmission = 1.0;
        p.specular = 0.0;
        v.push_back({"thin transmission alone, roughness 0.1", p, 30.0, tilt2, true, true});
    }
    {
        auto p = params({0.9, 0.8, 0.7}, 0.0, 0.5);
        p.transmission = 1.0;
        v.push_back(
            {"thin transmission and reflection, roughness 0.5", p, 60.0, tilt3, true, false});
    }
    {
        auto p = params({0.6, 0.9, 0.5}, 0.2, 1.0);
        p.transmission = 0.5;
        v.push_back({"thin transmission 0.5, diffuse, metal 0.2, roughness 1", p, 0.0, tilt1, false,
                     false});
    }
    {
        auto p = params({1, 1, 1}, 0.0, 0.1);
        p.transmission = 1.0;
        p.specular = 0.0;
        p.volume = true;
        v.push_back(
            {"volume eta 1.5 alone from outside, roughness 0.1", p, 45.0, tilt2, true, true});
    }
    {
        auto p = params({1, 1, 1}, 0.0, 0.5);
        p.transmission = 1.0;
        p.volume = true;
        v.push_back({"volume eta 1.5 from outside, roughness 0.5", p, 0.0, {0, 1, 0}, true, false});
    }
    {
        auto p = params({1, 1, 1}, 0.0, 0.5);
        p.transmission = 1.0;
        p.volume = true;
        v.push_back(
            {"volume eta 1.5 from outside, roughness 0.5, 85 deg", p, 85.0, tilt1, false, false});
    }
    {
        auto p = params({1, 0.9, 0.8}, 0.0, 0.1);
        p.transmission = 1.0;
        p.volume = true;
        p.ior = 1.0 / 1.5;
        v.push_back({"volume from inside, roughness 0.1, 30 deg", p, 30.0, tilt3, true, true});
    }
    {
        auto p = params({1, 0.9, 0.8}, 0.0, 0.5);
        p.transmission = 1.0;
        p.volume = true;
        p.ior = 1.0 / 1.5;
        v.push_back(
            {"volume from inside, roughness 0.5, 60 deg (TIR)", p, 60.0, tilt2, false, true});
    }
    {
        auto p = params({1, 1, 1}, 0.0, 0.02);
        p.transmission = 1.0;
        p.volume = true;
        p.ior = 1.0 / 1.5;
        v.push_back(
            {"volume from inside, roughness 0.02, 45 deg (TIR)", p, 45.0, tilt1, false, false});
    }
    v.push_back({"smooth plastic (Dirac as no direction)", params({0.5, 0.5, 0.5}, 0.0, 0.005),
                 45.0, tilt3, false, true});
    return v;
}

} // namespace tp::test::chi2
