// Chi-square goodness-of-fit of the glTF material's sampler (pbr_sample, common/shared/pbr.h)
// against its pdf (pbr_pdf), 10^6 draws per case, on the cases of pbr_cases.h. A draw that gives
// no direction (a reflection below the horizon, a refraction under total internal reflection) or a
// Dirac lobe (the smooth limit) is a failed draw, expected at the rate 1 - integral of pbr_pdf.
#include "chi2/pbr_cases.h"
#include "chi2/suite.h"

#include "shared/pbr.h"

#include <fmt/format.h>

using namespace tp::test::chi2;

TEST_CASE("glTF material sampling follows pbr_pdf", "[chi2]") {
    const std::vector<PbrCase> cases = pbr_cases();
    REQUIRE(cases.size() == kPbrCases);
    uint64_t seed = 1100;
    for (const PbrCase& c : cases) {
        DYNAMIC_SECTION(c.name) {
            const tp::Material m = tp::test::pbr::to_material(c.p);
            const tp::vec3 n = c.n(), wo = c.wo();
            const DirectionSamples s = draw_directions(
                [&](const glm::vec4& u) -> std::optional<glm::vec3> {
                    const tp::BsdfSample b = tp::pbr_sample(m, n, wo, u.x, tp::vec2(u.y, u.z));
                    if (b.lobe == tp::LOBE_NONE || (b.lobe & tp::LOBE_SPECULAR) != 0u)
                        return std::nullopt;
                    return b.wi;
                },
                kSamples, seed);
            const Result r = test_directions(c.chart(), s, [&](const glm::dvec3& w) {
                return double(tp::pbr_pdf(m, n, wo, tp::vec3(w)));
            });
            check_accepted(fmt::format("glTF {}", c.name).c_str(), r);
        }
        ++seed;
    }
}
