// Chi-square goodness-of-fit of the BSDF samplers of shared/brdf.h: the full modified Phong
// mixture against phong_pdf, and the dielectric's reflect/refract choice against Fresnel.
#include "chi2/direction_at.h"
#include "chi2/suite.h"
#include "support/fresnel_reference.h"

#include "shared/brdf.h"

#include <fmt/format.h>

#include <cmath>

using namespace tp::test::chi2;

namespace {

struct PhongCase {
    tp::vec3 kd, ks;
    float ns;
    double theta_o_degrees; // angle between wo and the normal
    glm::dvec3 normal;      // any direction: the samplers must work in every frame
};
} // namespace

TEST_CASE("Phong mixture sampling follows phong_pdf", "[chi2]") {
    // From mostly diffuse to a 10^4 lobe, from normal incidence to grazing; coloured kd/ks test
    // the lobe probability's channel average. At grazing angles much of the glossy lobe lies
    // below the horizon: those draws fail, and the harness expects them at the rate
    // 1 - integral of the pdf over the sphere.
    const PhongCase cases[] = {
        {tp::vec3(0.5f), tp::vec3(0.5f), 1.0f, 0.0, {0, 0, 1}},
        {tp::vec3(0.6f, 0.3f, 0.1f), tp::vec3(0.2f, 0.3f, 0.4f), 10.0f, 30.0, {0, 0, -1}},
        {tp::vec3(0.1f), tp::vec3(0.8f), 100.0f, 60.0, glm::normalize(glm::dvec3(0.3, -0.5, 0.8))},
        {tp::vec3(0.05f), tp::vec3(0.9f), 1000.0f, 80.0,
         glm::normalize(glm::dvec3(-0.6, 0.2, -0.77))},
        {tp::vec3(0.2f), tp::vec3(0.7f), 10000.0f, 45.0, {1, 0, 0}},
        {tp::vec3(0.0f), tp::vec3(0.9f), 20.0f, 85.0, glm::normalize(glm::dvec3(0.1, 0.9, 0.2))},
        {tp::vec3(0.7f), tp::vec3(0.0f), 50.0f, 70.0, glm::normalize(glm::dvec3(-1, -1, 1))},
        {tp::vec3(0.4f), tp::vec3(0.5f), 0.0f, 50.0, glm::normalize(glm::dvec3(0.5, 0.5, -0.5))},
    };
    int index = 0;
    for (const PhongCase& c : cases) {
        DYNAMIC_SECTION("case " << index) {
            const tp::vec3 n(c.normal);
            const tp::vec3 wo = direction_at(c.normal, c.theta_o_degrees);
            const glm::dvec3 dn(n), dwo(wo);
            const glm::dvec3 mirror = glm::normalize(2.0 * glm::dot(dn, dwo) * dn - dwo);
            const SphereChart chart =
                SphereChart::lobe(mirror, 0.05 / (double(c.ns) + 1.0), 48, 64);
            const DirectionSamples s = draw_directions(
                [&](const glm::vec4& u) -> std::optional<glm::vec3> {
                    const tp::BsdfSample b =
                        tp::phong_sample(c.kd, c.ks, c.ns, n, wo, u.x, tp::vec2(u.y, u.z));
                    if (b.lobe == tp::LOBE_NONE) return std::nullopt;
                    return b.wi;
                },
                kSamples, 500 + uint64_t(index));
            const Result r = test_directions(chart, s, [&](const glm::dvec3& w) {
                return tp::phong_pdf(c.kd, c.ks, c.ns, n, wo, tp::vec3(w));
            });
            check_accepted(fmt::format("Phong mixture case {} (n = {})", index, c.ns).c_str(), r);
        }
        ++index;
    }
}

TEST_CASE("dielectric chooses reflection with the Fresnel probability", "[chi2]") {
    // A binomial test per configuration: the number of reflections among 10^6 draws against
    // Fresnel's F. Light arriving from outside (wo on the normal's side) and from inside,
    // including just under the critical angle where F rises steeply.
    struct Case {
        double cos_o; // |cos| of wo against the normal
        float ior;
        bool inside; // wo inside the medium (cos_o negative against the outward normal)
    };
    const Case cases[] = {{1.0, 1.5f, false},  {0.7, 2.4f, false}, {0.3, 1.5f, false},
                          {0.05, 1.5f, false}, {0.9, 1.5f, true},  {0.76, 1.5f, true}};
    const tp::vec3 n(0.0f, 0.0f, 1.0f);
    int index = 0;
    for (const Case& c : cases) {
        DYNAMIC_SECTION("cos " << c.cos_o << " ior " << c.ior << (c.inside ? " inside" : "")) {
            const double sin_o = std::sqrt(1.0 - c.cos_o * c.cos_o);
            const tp::vec3 wo(float(sin_o), 0.0f, float(c.inside ? -c.cos_o : c.cos_o));
            const double eta = c.inside ? 1.0 / double(c.ior) : double(c.ior);
            const double F = tp::test::fresnel_reference(double(std::abs(wo.z)), eta);
            Uniform u(600 + uint64_t(index));
            uint64_t reflected = 0;
            for (uint64_t i = 0; i < kSamples; ++i) {
                const tp::BsdfSample b =
                    tp::dielectric_sample(tp::vec3(1.0f), c.ior, n, wo, u.next());
                if ((b.lobe & tp::LOBE_TRANSMISSION) == 0u) ++reflected;
            }
            const double p = binomial_p_value(reflected, kSamples, F);
            const std::string name = fmt::format("dielectric case {} (F = {:.5f})", index, F);
            std::printf("chi2 %-40s %llu of %llu reflected, binomial p = %.4g\n", name.c_str(),
                        (unsigned long long)reflected, (unsigned long long)kSamples, p);
            INFO(name << ": " << reflected << " reflected, p = " << p);
            CHECK(p >= alpha_per_test());
        }
        ++index;
    }
}
