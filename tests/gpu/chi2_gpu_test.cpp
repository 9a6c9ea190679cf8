// The chi-square sampling tests of tests/chi2/, repeated with the samples drawn on the GPU by
// the shared samplers in a compute shader (sample_draws.comp) from the renderer's own random
// numbers, and judged by the same harness (tests/support/chi2.h) at the same Sidak-corrected
// level (tests/chi2/suite.h; the same tests, the glTF material's on a subset of its cases).
#include "chi2/direction_at.h"
#include "chi2/lights.h"
#include "chi2/pbr_cases.h"
#include "chi2/suite.h"
#include "gpu_harness.h"
#include "shaders/draw_ids.h"

#include "sample_draws.spv.h"

#include "shared/brdf.h"
#include "shared/pbr.h"
#include "shared/sampling.h"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

using namespace tp::test::chi2;

namespace {

const glm::dvec3 kZ(0.0, 0.0, 1.0);

std::vector<glm::vec4> draw(uint32_t sampler, const tp::DrawParams& params,
                            const std::vector<tp::AliasEntry>& table, uint32_t seed) {
    const uint32_t n = uint32_t(kSamples);
    const tp::DrawPush push{sampler, seed, n, uint32_t(table.size())};
    const std::vector<tp::DrawParams> p = {params};
    const std::vector<tp::AliasEntry> t =
        table.empty() ? std::vector<tp::AliasEntry>(1, tp::AliasEntry{}) : table;
    const auto out =
        tp::test::run_shader(tp_spirv_sample_draws, sizeof(tp_spirv_sample_draws),
                             {tp::test::bytes_of(p), tp::test::bytes_of(t)},
                             {n * sizeof(glm::vec4)}, &push, sizeof(push), (n + 63) / 64);
    return tp::test::as_vector<glm::vec4>(out[0]);
}

DirectionSamples directions(const std::vector<glm::vec4>& draws) {
    DirectionSamples s;
    s.directions.reserve(draws.size());
    for (const glm::vec4& d : draws) {
        if (d.w == 0.0f)
            ++s.failed;
        else
            s.add(glm::vec3(d));
    }
    return s;
}

PointSamples points(const std::vector<glm::vec4>& draws) {
    PointSamples s;
    for (const glm::vec4& d : draws) s.points.emplace_back(d.x, d.y);
    return s;
}
} // namespace

TEST_CASE("GPU: cosine and Phong lobe and sphere and triangle samplers follow their pdfs",
          "[gpu]") {
    tp::DrawParams p{};
    {
        const Result r = test_directions(
            SphereChart::uniform(kZ, 64, 64), directions(draw(tp::DRAW_COSINE, p, {}, 101)),
            [](const glm::dvec3& w) { return double(tp::cosine_hemisphere_pdf(float(w.z))); });
        check_accepted("GPU cosine hemisphere", r);
    }
    for (const float n : {1.0f, 10.0f, 100.0f, 1000.0f, 10000.0f}) {
        p.f[0].x = n;
        const Result r = test_directions(
            SphereChart::lobe(kZ, 0.05 / (double(n) + 1.0), 48, 64),
            directions(draw(tp::DRAW_PHONG_LOBE, p, {}, 200 + uint32_t(n))),
            [n](const glm::dvec3& w) { return double(tp::phong_lobe_pdf(float(w.z), n)); });
        check_accepted(fmt::format("GPU Phong lobe n = {}", n).c_str(), r);
    }
    {
        const Result r =
            test_directions(SphereChart::uniform(glm::normalize(glm::dvec3(1, 2, 3)), 48, 96),
                            directions(draw(tp::DRAW_SPHERE, p, {}, 301)),
                            [](const glm::dvec3&) { return double(tp::INV_FOUR_PI); });
        check_accepted("GPU uniform sphere", r);
    }
    {
        const Result r = test_points(Grid::uniform(0.0, 1.0, 64, 0.0, 1.0, 64),
                                     points(draw(tp::DRAW_TRIANGLE, p, {}, 401)),
                                     [](double x, double y) { return x + y <= 1.0 ? 2.0 : 0.0; });
        check_accepted("GPU uniform triangle", r);
    }
    {
        const Result r = test_points(Grid::uniform(0.0, 1.0, 64, 0.0, 1.0, 64),
                                     points(draw(tp::DRAW_RNG_PAIR, p, {}, 0)),
                                     [](double, double) { return 1.0; });
        check_accepted("GPU rng pairs", r);
    }
    CHECK(tp::test::validation_messages() == 0);
}

TEST_CASE("GPU: Phong mixture sampling follows phong_pdf", "[gpu]") {
    struct PhongCase {
        tp::vec3 kd, ks;
        float ns;
        double theta_o_degrees;
        glm::dvec3 normal;
    };
    const PhongCase cases[] = {
        {tp::vec3(0.5f), tp::vec3(0.5f), 1.0f, 0.0, {0, 0, 1}},
        {tp::vec3(0.6f, 0.3f, 0.1f), tp::vec3(0.2f, 0.3f, 0.4f), 10.0f, 30.0, {0, 0, -1}},
        {tp::vec3(0.1f), tp::vec3(0.8f), 100.0f, 60.0, glm::normalize(glm::dvec3(0.3, -0.5, 0.8))},
        {tp::vec3(0.05f), tp::vec3(0.9f), 1000.0f, 80.0,
         glm::normalize(glm::dvec3(-0.6, 0.2, -0.77))},
        {tp::vec3(0.2f), tp::vec3(0.7f), 10000.0f, 45.0, {1, 0, 0}},
        {tp::vec3(0.0f), tp::vec3(0.9f), 20.0f, 85.0, glm::normalize(glm::dvec3(0.1, 0.9, 0.2))},
        {tp::vec3(0.7f), tp::vec3(0.0f), 50.0f, 70.0, glm::normalize(glm::dvec3(-1, -1, 1))},
    };
    uint32_t index = 0;
    for (const PhongCase& c : cases) {
        const tp::vec3 n(c.normal), wo = direction_at(c.normal, c.theta_o_degrees);
        const glm::dvec3 dn(n), dwo(wo);
        const glm::dvec3 mirror = glm::normalize(2.0 * glm::dot(dn, dwo) * dn - dwo);
        tp::DrawParams p{};
        p.f[0] = tp::vec4(c.kd, c.ns);
        p.f[1] = tp::vec4(c.ks, 0.0f);
        p.f[2] = tp::vec4(n, 0.0f);
        p.f[3] = tp::vec4(wo, 0.0f);
        const Result r = test_directions(
            SphereChart::lobe(mirror, 0.05 / (double(c.ns) + 1.0), 48, 64),
            directions(draw(tp::DRAW_PHONG_MIXTURE, p, {}, 500 + index)), [&](const glm::dvec3& w) {
                return double(tp::phong_pdf(c.kd, c.ks, c.ns, n, wo, tp::vec3(w)));
            });
        check_accepted(fmt::format("GPU Phong mixture case {} (n = {})", index, c.ns).c_str(), r);
        ++index;
    }
    CHECK(tp::test::validation_messages() == 0);
}

TEST_CASE("GPU: dielectric chooses reflection with the Fresnel probability", "[gpu]") {
    struct Case {
        double cos_o;
        float ior;
        bool inside;
    };
    const Case cases[] = {{1.0, 1.5f, false},  {0.7, 2.4f, false}, {0.3, 1.5f, false},
                          {0.05, 1.5f, false}, {0.9, 1.5f, true},  {0.76, 1.5f, true}};
    uint32_t index = 0;
    for (const Case& c : cases) {
        const double sin_o = std::sqrt(1.0 - c.cos_o * c.cos_o);
        const tp::vec3 wo(float(sin_o), 0.0f, float(c.inside ? -c.cos_o : c.cos_o));
        // Fresnel from the textbook equations in double (Born & Wolf), independent of brdf.h.
        const double eta = c.inside ? 1.0 / double(c.ior) : double(c.ior);
        const double ci = std::abs(double(wo.z)), s2 = (1.0 - ci * ci) / (eta * eta);
        double F = 1.0;
        if (s2 < 1.0) {
            const double ct = std::sqrt(1.0 - s2);
            const double rs = (ci - eta * ct) / (ci + eta * ct);
            const double rp = (eta * ci - ct) / (eta * ci + ct);
            F = 0.5 * (rs * rs + rp * rp);
        }
        tp::DrawParams p{};
        p.f[0].w = c.ior;
        p.f[2] = tp::vec4(0.0f, 0.0f, 1.0f, 0.0f);
        p.f[3] = tp::vec4(wo, 0.0f);
        const std::vector<glm::vec4> d = draw(tp::DRAW_DIELECTRIC, p, {}, 600 + index);
        uint64_t reflected = 0;
        for (const glm::vec4& x : d) reflected += x.x == 1.0f;
        const double pv = binomial_p_value(reflected, kSamples, F);
        const std::string name = fmt::format("GPU dielectric case {} (F = {:.5f})", index, F);
        std::printf("chi2 %-40s %llu of %llu reflected, binomial p = %.4g\n", name.c_str(),
                    (unsigned long long)reflected, (unsigned long long)kSamples, pv);
        INFO(name << ": " << reflected << " reflected, p = " << pv);
        CHECK(pv >= alpha_per_test());
        ++index;
    }
    CHECK(tp::test::validation_messages() == 0);
}

TEST_CASE("GPU: light sampling and alias tables follow their distributions", "[gpu]") {
    using namespace tp::test::lights;
    {
        const tp::Light l = test_triangle_light();
        const tp::vec3 pt = test_shading_point();
        tp::DrawParams p{};
        p.f[0] = tp::vec4(l.p0, l.area);
        p.f[1] = tp::vec4(l.p1, 0.0f);
        p.f[2] = tp::vec4(l.p2, 0.0f);
        p.f[3] = tp::vec4(pt, 0.0f);
        const Result r = test_directions(
            SphereChart::lobe(to_centroid(l, pt), 0.01, 48, 64),
            directions(draw(tp::DRAW_TRIANGLE_LIGHT, p, {}, 701)), [&](const glm::dvec3& w) {
                const std::optional<TriangleHit> h = hit_triangle(l, pt, w);
                return h ? double(tp::triangle_light_pdf(l.area, float(h->t), float(h->cos_light)))
                         : 0.0;
            });
        check_accepted("GPU triangle light", r);
    }
    {
        const EnvMap env = test_environment_map();
        tp::DrawParams p{};
        p.f[0].x = env.rotation;
        p.u = tp::uvec4(env.width, env.height, 0u, 0u);
        const Result r = test_directions(
            SphereChart::uniform(glm::dvec3(0, 1, 0), 48, 96),
            directions(draw(tp::DRAW_ENV_MAP, p, env.table, 702)),
            [&](const glm::dvec3& w) { return double(environment_pdf(env, tp::vec3(w))); });
        check_accepted("GPU environment map", r);
    }
    const auto alias_test = [](const char* name, const std::vector<double>& w, uint32_t seed) {
        const std::vector<tp::AliasEntry> table = tp::build_alias_table(w);
        std::vector<uint64_t> counts(w.size(), 0);
        for (const glm::vec4& d : draw(tp::DRAW_ALIAS, tp::DrawParams{}, table, seed))
            ++counts.at(size_t(d.x));
        const double sum = std::accumulate(w.begin(), w.end(), 0.0);
        std::vector<double> probs;
        for (double x : w) probs.push_back(x / sum);
        check_accepted(name, test_discrete(counts, probs));
    };
    alias_test("GPU alias table, 10 weights", {1.0, 0.0, 3.0, 0.5, 10.0, 2.0, 7.0, 0.01, 4.0, 0.0},
               801);
    std::vector<double> w(1000);
    for (size_t i = 0; i < w.size(); ++i)
        w[i] = std::pow(10.0, 4.0 * double((i * 389) % 1000) / 1000.0);
    alias_test("GPU alias table, 1000 weights", w, 802);
    CHECK(tp::test::validation_messages() == 0);
}

TEST_CASE("GPU: glTF material sampling follows pbr_pdf", "[gpu]") {
    // pbr_cases.h's cases marked on_gpu: a Dirac sample or no direction is a failed draw, as on
    // the CPU; the pdf is the C++ pbr_pdf.
    uint32_t seed = 1100;
    int ran = 0;
    for (const PbrCase& c : pbr_cases()) {
        ++seed;
        if (!c.on_gpu) continue;
        ++ran;
        const tp::Material m = tp::test::pbr::to_material(c.p);
        const tp::vec3 n = c.n(), wo = c.wo();
        tp::DrawParams p{};
        p.f[0] = tp::vec4(m.kd, m.metallic);
        p.f[1] = tp::vec4(m.ks, m.roughness);
        p.f[2] = tp::vec4(n, m.transmission);
        p.f[3] = tp::vec4(wo, m.specular);
        p.f[4] = tp::vec4(m.ior, 0.0f, 0.0f, 0.0f);
        p.u = tp::uvec4(m.flags, 0u, 0u, 0u);
        const Result r = test_directions(
            c.chart(), directions(draw(tp::DRAW_PBR, p, {}, seed)),
            [&](const glm::dvec3& w) { return double(tp::pbr_pdf(m, n, wo, tp::vec3(w))); });
        check_accepted(fmt::format("GPU glTF {}", c.name).c_str(), r);
    }
    CHECK(ran >= 10);
    CHECK(tp::test::validation_messages() == 0);
}
