// BRDF extremes: the modified Phong (common/shared/brdf.h) over exponents 0..1e6 with
// kd + ks = 1, view directions down to 1e-6 rad above the horizon and shading normals nearly
// tangent to the view, in C++ and in GLSL on the device. Checks per configuration:
//   - every output finite (no NaN/Inf);
//   - pdf(wo, wi) > 0 wherever f(wo, wi) > 0 (else MIS and the sampler disagree on support);
//   - each sample weight w = f cos / p <= (kd + ks)(n + 2)/(n + 1) per channel: with the
//     mixture pdf, w <= max(kd / P_d, ks cos_i (n + 2) / ((1 - P_d)(n + 1))) and
//     kd / P_d = ks / (1 - P_d) = kd + ks for grey kd, ks (docs/stress.md). The factor
//     (n + 2)/(n + 1) is real: at n = 0 the lobe is ks/pi over a hemisphere sampled
//     uniformly, weight 2 ks cos_i. So the bound is the albedo times at most 2, and the
//     *mean* weight (the directional albedo) must stay <= kd + ks = 1 within 4 SE.
#include "stress/common.h"
#include "util/clock.h"
#include "vulkan_rt/device/shader_dispatch.h"

#include "shared/brdf.h"
#include "stress_brdf_comp.spv.h"

#include <fmt/format.h>

#include <cmath>
#include <random>

namespace tp::stress {
namespace {

struct BrdfInput {
    vec3 kd;
    float ns;
    vec3 ks;
    float u_lobe;
    vec3 n;
    float u_dir0;
    vec3 wo;
    float u_dir1;
    vec3 wi;
    float pad0;
};
struct BrdfOutput {
    vec3 sample_wi;
    float sample_pdf;
    vec3 sample_weight;
    uint32_t sample_lobe;
    vec3 f;
    float pdf;
};
static_assert(sizeof(BrdfInput) == 80 && sizeof(BrdfOutput) == 48, "scalar layout");

const float kExponents[] = {0.0f, 1e-3f, 0.5f, 1.0f, 10.0f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f};
const float kDiffuse[] = {1.0f, 0.999999f, 0.5f, 1e-6f, 0.0f}; // ks = 1 - kd
// Angles of wo above the horizon (rad).
const double kElevations[] = {1.5707963, 0.5, 1e-2, 1e-4, 1e-6};

struct Config {
    float kd, ns;
    double elevation;
    bool tilted; // the normal turned so that wo is nearly tangent to it
};

std::vector<Config> configs() {
    std::vector<Config> v;
    for (float ns : kExponents)
        for (float kd : kDiffuse)
            for (double el : kElevations)
                for (bool tilted : {false, true}) v.push_back({kd, ns, el, tilted});
    return v;
}

// wo at `elevation` above the plane of n. "Tilted": a random normal and wo built around it,
// so neither is axis-aligned.
void frame(const Config& c, std::mt19937& rng, vec3& n, vec3& wo) {
    std::normal_distribution<double> g;
    if (c.tilted) {
        n = vec3(glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))));
    } else {
        n = vec3(0.0f, 0.0f, 1.0f);
    }
    vec3 t, b;
    orthonormal_basis(n, t, b);
    const double ce = std::cos(c.elevation), se = std::sin(c.elevation);
    wo = vec3(glm::normalize(glm::dvec3(t) * ce + glm::dvec3(n) * se));
}

std::vector<BrdfInput> inputs(const Size& s) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<double> g;
    std::vector<BrdfInput> in;
    for (const Config& c : configs()) {
        vec3 n, wo;
        frame(c, rng, n, wo);
        for (uint32_t k = 0; k < s.brdf_samples; ++k) {
            BrdfInput a{};
            a.kd = vec3(c.kd);
            a.ks = vec3(1.0f - c.kd);
            a.ns = c.ns;
            a.n = n;
            a.wo = wo;
            // The extremes of u as well: 0 and the largest float below 1.
            const float lo = 0.0f, hi = 0.99999994f;
            a.u_lobe = k == 0 ? lo : k == 1 ? hi : u(rng);
            a.u_dir0 = k == 0 ? lo : k == 1 ? hi : k == 2 ? lo : u(rng);
            a.u_dir1 = k == 2 ? hi : u(rng);
            // Half the test directions uniform on the sphere, half near the mirror direction
            // (where the narrow lobes live).
            const vec3 r = mirror_direction(n, wo);
            const glm::dvec3 d(g(rng), g(rng), g(rng));
            a.wi = k % 2 ? vec3(glm::normalize(d))
                         : vec3(glm::normalize(glm::dvec3(r) +
                                               1e-3 * double(u(rng)) * glm::normalize(d)));
            in.push_back(a);
        }
    }
    return in;
}

BrdfOutput eval_cpp(const BrdfInput& a) {
    const BsdfSample s =
        phong_sample(a.kd, a.ks, a.ns, a.n, a.wo, a.u_lobe, vec2(a.u_dir0, a.u_dir1));
    BrdfOutput o;
    o.sample_wi = s.wi;
    o.sample_pdf = s.pdf;
    o.sample_weight = s.weight;
    o.sample_lobe = s.lobe;
    o.f = phong_eval(a.kd, a.ks, a.ns, a.n, a.wo, a.wi);
    o.pdf = phong_pdf(a.kd, a.ks, a.ns, a.n, a.wo, a.wi);
    return o;
}

// The checks, grouped by exponent so that a failure names it.
std::vector<CaseResult> check(const std::vector<BrdfInput>& in, const std::vector<BrdfOutput>& out,
                              const std::string& backend, const Size& s) {
    std::vector<CaseResult> results;
    const std::vector<Config> cfg = configs();
    for (float ns : kExponents) {
        CaseResult c;
        c.group = "brdf";
        c.name = fmt::format("Phong n = {:g}, kd + ks = 1, elevations down to 1e-6 rad", ns);
        c.backend = backend;
        c.mode = "-";
        c.expected = "no NaN/Inf; pdf > 0 wherever f > 0; weight <= (kd+ks)(n+2)/(n+1); mean "
                     "weight <= kd+ks + 4 SE";
        uint64_t support = 0, over = 0, albedo_over = 0, valid = 0;
        double worst_ratio = 0.0, worst_albedo = 0.0;
        for (size_t ci = 0; ci < cfg.size(); ++ci) {
            if (cfg[ci].ns != ns) continue;
            double sum = 0.0, sum_sq = 0.0;
            for (uint32_t k = 0; k < s.brdf_samples; ++k) {
                const size_t i = ci * s.brdf_samples + k;
                const BrdfInput& a = in[i];
                const BrdfOutput& o = out[i];
                count_nonfinite(c, o);
                if (cmax(o.f) > 0.0f && !(o.pdf > 0.0f)) ++support;
                const double bound =
                    double(a.kd.x + a.ks.x) * (double(ns) + 2.0) / (double(ns) + 1.0);
                const double w = o.sample_lobe == LOBE_NONE ? 0.0 : double(cmax(o.sample_weight));
                if (o.sample_lobe != LOBE_NONE) ++valid;
                worst_ratio = std::max(worst_ratio, w / bound);
                if (w > bound * (1.0 + 1e-4)) ++over;
                sum += w;
                sum_sq += w * w;
            }
            const double n = s.brdf_samples, mean = sum / n;
            const double se = std::sqrt(std::max(sum_sq / n - mean * mean, 0.0) / (n - 1.0));
            worst_albedo = std::max(worst_albedo, mean);
            if (mean > 1.0 + 4.0 * se + 1e-6) ++albedo_over;
        }
        c.pass =
            c.nan == 0 && c.inf == 0 && support == 0 && over == 0 && albedo_over == 0 && valid > 0;
        c.measured = fmt::format("f > 0 with pdf = 0: {}; weights over the bound: {} (largest "
                                 "weight / bound {:.4g}); largest mean weight {:.4g} ({} over); "
                                 "{} valid samples",
                                 support, over, worst_ratio, worst_albedo, albedo_over, valid);
        results.push_back(c);
    }
    return results;
}

} // namespace

std::vector<CaseResult> brdf_cases_cpp(const Size& s) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<BrdfInput> in = inputs(s);
    std::vector<BrdfOutput> out(in.size());
    for (size_t i = 0; i < in.size(); ++i) out[i] = eval_cpp(in[i]);
    std::vector<CaseResult> r = check(in, out, "c++", s);
    const double dt = seconds_since(t0);
    for (CaseResult& c : r) c.seconds = dt / double(r.size());
    return r;
}

std::vector<CaseResult> brdf_cases_glsl(const VulkanContext& ctx, const Size& s) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<BrdfInput> in = inputs(s);
    const uint32_t count = uint32_t(in.size());
    const auto bytes = run_compute_shader(
        ctx, tp_spirv_stress_brdf_comp, sizeof(tp_spirv_stress_brdf_comp), {bytes_of(in)},
        {in.size() * sizeof(BrdfOutput)}, &count, sizeof(count), (count + 63) / 64);
    std::vector<CaseResult> r = check(in, as_vector<BrdfOutput>(bytes[0]), "glsl", s);
    const double dt = seconds_since(t0);
    for (CaseResult& c : r) {
        c.mode = ctx.info().name;
        c.seconds = dt / double(r.size());
    }
    return r;
}

} // namespace tp::stress
