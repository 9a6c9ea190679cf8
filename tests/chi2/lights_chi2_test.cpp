// Chi-square goodness-of-fit of light sampling (shared/lights.h) in solid angle: the directions
// next-event estimation draws must follow the pdfs that multiple importance sampling uses.
#include "chi2/lights.h"
#include "chi2/suite.h"

#include "shared/lights.h"

using namespace tp::test::chi2;
using namespace tp::test::lights;

TEST_CASE("triangle light sampling follows its solid-angle pdf", "[chi2]") {
    const tp::Light l = test_triangle_light();
    const tp::vec3 p = test_shading_point();
    const SphereChart chart = SphereChart::lobe(to_centroid(l, p), 0.01, 48, 64);
    const DirectionSamples s = draw_directions(
        [&](const glm::vec4& u) -> std::optional<glm::vec3> {
            const tp::LightSample ls = tp::sample_triangle_light(l, p, tp::vec2(u.x, u.y), false);
            if (ls.pdf <= 0.0f) return std::nullopt;
            return ls.wi;
        },
        kSamples, 701);
    const Result r = test_directions(chart, s, [&](const glm::dvec3& w) {
        const std::optional<TriangleHit> h = hit_triangle(l, p, w);
        return h ? double(tp::triangle_light_pdf(l.area, float(h->t), float(h->cos_light))) : 0.0;
    });
    check_accepted("triangle light", r);
    // The pdf jumps to 0 at the triangle's edges; the cubature locates a jump to 2^-7 of a
    // cell, which leaves ~2e-5 of the mass uncertain (a smooth pdf integrates to 1e-7).
    CHECK(r.mass == Approx(1.0).epsilon(1e-4));
}

TEST_CASE("environment map sampling follows environment_map_pdf", "[chi2]") {
    const EnvMap env = test_environment_map();
    const SphereChart chart = environment_chart(env);
    const DirectionSamples s = draw_directions(
        [&](const glm::vec4& u) -> std::optional<glm::vec3> {
            const tp::LightSample ls = sample_environment(env, u);
            if (ls.pdf <= 0.0f) return std::nullopt;
            return ls.wi;
        },
        kSamples, 702);
    const Result r = test_directions(
        chart, s, [&](const glm::dvec3& w) { return double(environment_pdf(env, tp::vec3(w))); });
    check_accepted("environment map", r);
    // Cells inside pixels: smooth, integrated to rounding.
    CHECK(r.mass == Approx(1.0).epsilon(1e-6));
}
