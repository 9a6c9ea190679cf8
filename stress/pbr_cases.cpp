// The glTF material's extremes (MATERIAL_PBR, common/shared/pbr.h), in C++ and in GLSL on the
// device: roughness at and around the smooth limit (0.0101, 0.01, 0.0099 and 0: alpha = 1.02e-4,
// 1e-4, 9.8e-5 and 0, where D's peak is 1e7 high or a Dirac lobe), view directions from the
// normal down to cos = 1e-4, shading normals tilted to the view, and degenerate normal maps (a
// texel that decodes to the zero vector, texels that bend the normal below the surface, a
// tangent parallel to the normal). Grey materials: metal, plastic (diffuse and specular), a
// thin-walled transmitter, a volume boundary met from outside (eta 1.5) and from inside (1/1.5,
// total internal reflection beyond 41.8 degrees), and one from inside with half its base diffuse.
// The normal is bent (surface_apply_normal_map) and turned to the viewer (surface_face_viewer) as
// the path loop does, then pbr_sample, pbr_eval and pbr_pdf run at it. Checks per group:
//   - every output finite (no NaN/Inf), every shading normal unit and on the viewer's side;
//   - pbr_pdf > 0 wherever pbr_eval > 0 (else MIS and the sampler disagree on support);
//   - each sample's weight w <= C / P with C = max(1, 1 / eta^2) and P the smallest selection
//     probability among the lobes that can produce its direction (pbr_diffuse_probability,
//     (1 - p_d) pbr_reflect_probability at its microfacet normal, or (1 - p_d)(1 - that)): with
//     the mixture pdf, w <= max over lobes k of f_k |cos| / (P_k pdf_k), and for grey materials
//     each lobe's f_k |cos| / pdf_k is at most 1 (diffuse: (1 - F) kd; reflection: F G2 / G1;
//     thin transmission: (1 - F) G1(wi); the volume's: (1 - F) G1(wi) / eta^2) and its share of
//     the lobe choice at most 1 (docs/stress.md);
//   - the mean weight of the random draws (the directional albedo) <= C + (1 - metallic)
//     (1 - transmission) max(baseColor) + 4 SE: the microfacet lobes give at most C together,
//     and the diffuse lobe, which fresnel_mix weighs by 1 - F(V.H) whatever the specular lobe
//     took, at most its colour (glTF 2.0 Appendix B, "Coupling Diffuse and Specular Reflection":
//     the model is not energy conserving; a grey plastic seen at cos 1e-4 reflects ~1.6).
#include "stress/common.h"
#include "vulkan_rt/device/shader_dispatch.h"

#include "shared/pbr.h"
#include "shared/surface.h"
#include "stress_pbr_comp.spv.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <random>

namespace tp::stress {
namespace {

struct PbrInput {
    Material m;
    vec3 ng;
    float u_lobe;
    vec3 wo;
    float u_dir0;
    vec3 wi;
    float u_dir1;
    vec3 tangent;
    float normal_scale;
    vec3 bitangent;
    uint32_t use_map;
    vec3 texel;
    float pad0;
};
struct PbrOutput {
    vec3 sample_wi;
    float sample_pdf;
    vec3 sample_weight;
    uint32_t sample_lobe;
    vec3 f;
    float pdf;
    vec3 ns;
    float pad0;
};
static_assert(sizeof(Material) == 128, "Material layout");
static_assert(sizeof(PbrInput) == 128 + 96 && sizeof(PbrOutput) == 64, "scalar layout");

// Roughness at and around the smooth limit, and an ordinary one for the normal maps.
const float kRoughness[] = {0.0101f, 0.01f, 0.0099f, 0.0f};
// cos(theta_o) of the view against the (unmapped) normal.
const double kViewCos[] = {1.0, 0.5, 1e-2, 1e-4};

enum class MapKind { none, zero_texel, below, far_below, parallel_tangent };

struct Config {
    int material; // index into materials()
    float roughness;
    double view_cos;
    bool tilted;
    MapKind map;
};

struct NamedMaterial {
    const char* name;
    Material m;
};

std::vector<NamedMaterial> materials() {
    const auto make = [](float metallic, float transmission, bool volume, float ior,
                         float diffuse_grey) {
        Material m = default_pbr_material();
        m.kd = vec3(diffuse_grey);
        m.metallic = metallic;
        m.transmission = transmission;
        m.flags = volume ? MATERIAL_FLAG_VOLUME : 0u;
        m.ior = ior;
        return m;
    };
    return {{"metal", make(1.0f, 0.0f, false, 1.5f, 0.8f)},
            {"plastic", make(0.0f, 0.0f, false, 1.5f, 0.8f)},
            {"thin glass", make(0.0f, 1.0f, false, 1.5f, 1.0f)},
            {"volume from outside", make(0.0f, 1.0f, true, 1.5f, 1.0f)},
            {"volume from inside", make(0.0f, 1.0f, true, 1.0f / 1.5f, 1.0f)},
            {"half-diffuse volume from inside", make(0.0f, 0.5f, true, 1.0f / 1.5f, 0.8f)}};
}

std::vector<Config> roughness_configs() {
    std::vector<Config> v;
    const int n = int(materials().size());
    for (float r : kRoughness)
        for (int mi = 0; mi < n; ++mi)
            for (double c : kViewCos)
                for (bool tilted : {false, true}) v.push_back({mi, r, c, tilted, MapKind::none});
    return v;
}

std::vector<Config> normal_map_configs() {
    std::vector<Config> v;
    const int n = int(materials().size());
    for (MapKind k :
         {MapKind::zero_texel, MapKind::below, MapKind::far_below, MapKind::parallel_tangent})
        for (float r : {0.3f, 0.0099f})
            for (int mi = 0; mi < n; ++mi)
                for (double c : {1.0, 0.3, 1e-4}) v.push_back({mi, r, c, true, k});
    return v;
}

const char* map_name(MapKind k) {
    switch (k) {
    case MapKind::zero_texel:
        return "a texel decoding to the zero vector";
    case MapKind::below:
        return "texels bending the normal 60 deg off";
    case MapKind::far_below:
        return "texels bending the normal below the surface";
    case MapKind::parallel_tangent:
        return "a tangent parallel to the normal";
    default:
        return "";
    }
}

std::vector<PbrInput> inputs(const std::vector<Config>& configs, const Size& s) {
    const std::vector<NamedMaterial> mats = materials();
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<double> g;
    std::vector<PbrInput> in;
    for (const Config& c : configs) {
        const glm::dvec3 n = c.tilted ? glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)))
                                      : glm::dvec3(0.0, 0.0, 1.0);
        vec3 t, b;
        orthonormal_basis(vec3(n), t, b);
        const double sc = std::sqrt(std::max(0.0, 1.0 - c.view_cos * c.view_cos));
        const vec3 wo = vec3(glm::normalize(glm::dvec3(t) * sc + n * c.view_cos));
        for (uint32_t k = 0; k < s.brdf_samples; ++k) {
            PbrInput a{};
            a.m = mats[size_t(c.material)].m;
            a.m.roughness = c.roughness;
            a.ng = vec3(n);
            a.wo = wo;
            // The extremes of u too: 0 and the largest float below 1.
            const float lo = 0.0f, hi = 0.99999994f;
            a.u_lobe = k == 0 ? lo : k == 1 ? hi : u(rng);
            a.u_dir0 = k == 0 ? lo : k == 1 ? hi : k == 2 ? lo : u(rng);
            a.u_dir1 = k == 2 ? hi : u(rng);
            // Probe directions: near the mirror direction, near the transmission lobe (-wo),
            // anywhere.
            const glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
            const glm::dvec3 mirror = 2.0 * c.view_cos * n - glm::dvec3(wo);
            const double spread = 1e-4 * std::pow(1e4, double(u(rng)));
            a.wi = k % 3 == 0   ? vec3(glm::normalize(mirror + spread * d))
                   : k % 3 == 1 ? vec3(glm::normalize(-glm::dvec3(wo) + spread * d))
                                : vec3(d);
            a.use_map = c.map == MapKind::none ? 0u : 1u;
            a.tangent = t;
            a.bitangent = b;
            a.normal_scale = 1.0f;
            switch (c.map) {
            case MapKind::zero_texel:
                a.texel = vec3(0.5f);
                break;
            case MapKind::below: // (2c - 1) = (0.87, 0, 0.5): 60 degrees off n
                a.texel = vec3(0.933f, 0.5f, 0.75f);
                break;
            case MapKind::far_below: // any texel with a negative z, scaled up to 2
                a.texel = vec3(u(rng), u(rng), 0.5f * u(rng));
                a.normal_scale = 2.0f * u(rng);
                break;
            case MapKind::parallel_tangent:
                a.tangent = vec3(n) * 2.0f;
                a.texel = vec3(u(rng), u(rng), u(rng));
                break;
            default:
                break;
            }
            in.push_back(a);
        }
    }
    return in;
}

PbrOutput eval_cpp(const PbrInput& a) {
    SurfacePoint sp;
    sp.p = vec3(0.0f);
    sp.p_error = vec3(0.0f);
    sp.ng = a.ng;
    sp.ns = a.ng;
    sp.uv = vec2(0.0f);
    sp.uv1 = vec2(0.0f);
    sp.tangent = a.tangent;
    sp.bitangent = a.bitangent;
    if (a.use_map != 0u) surface_apply_normal_map(sp, a.texel, a.normal_scale);
    surface_face_viewer(sp, a.wo);
    const BsdfSample s = pbr_sample(a.m, sp.ns, a.wo, a.u_lobe, vec2(a.u_dir0, a.u_dir1));
    PbrOutput o{};
    o.sample_wi = s.wi;
    o.sample_pdf = s.pdf;
    o.sample_weight = s.weight;
    o.sample_lobe = s.lobe;
    o.f = pbr_eval(a.m, sp.ns, a.wo, a.wi);
    o.pdf = pbr_pdf(a.m, sp.ns, a.wo, a.wi);
    o.ns = sp.ns;
    return o;
}

// The weight bound C / P of a sample (module comment), from the lobe probabilities at the
// shading normal the functions saw.
double weight_bound(const Material& m, const glm::dvec3& ns, const glm::dvec3& wo,
                    const glm::dvec3& wi, uint32_t lobe) {
    const double c = std::max(1.0, 1.0 / (double(m.ior) * double(m.ior)));
    const double cos_o = glm::dot(ns, wo), cos_i = glm::dot(ns, wi);
    const double p_d = double(pbr_diffuse_probability(m, float(cos_o)));
    const bool dirac = (lobe & LOBE_SPECULAR) != 0u;
    double vh = cos_o;
    if (!dirac) {
        glm::dvec3 h;
        if (cos_i > 0.0)
            h = wo + wi;
        else if ((m.flags & MATERIAL_FLAG_VOLUME) == 0u)
            h = wo + (wi - 2.0 * cos_i * ns); // the transmitted direction mirrored
        else
            h = wo + double(m.ior) * wi;
        h = glm::normalize(h);
        if (glm::dot(h, ns) < 0.0) h = -h;
        vh = glm::dot(wo, h);
    }
    const double p_r = double(pbr_reflect_probability(m, float(vh)));
    double p = 1.0;
    if (cos_i > 0.0) {
        // Upper hemisphere: the diffuse lobe (where it has weight and a probability) and the
        // reflection.
        if (p_d > 0.0 && !dirac) p = std::min(p, p_d);
        if (!pbr_is_smooth(m) || dirac) p = std::min(p, (1.0 - p_d) * p_r);
    } else {
        p = (1.0 - p_d) * (1.0 - p_r);
    }
    return p > 0.0 ? c / p : std::numeric_limits<double>::infinity();
}

CaseResult check_group(const std::vector<Config>& cfg, const std::vector<size_t>& members,
                       const std::vector<PbrInput>& in, const std::vector<PbrOutput>& out,
                       const std::string& name, const std::string& backend, const Size& s) {
    CaseResult c;
    c.group = "pbr";
    c.name = name;
    c.backend = backend;
    c.mode = "-";
    c.expected = "no NaN/Inf; ns unit, facing wo; pdf > 0 wherever f > 0; weight <= max(1, "
                 "1/eta^2) / P(lobe); mean weight <= max(1, 1/eta^2) + (1 - metallic)(1 - "
                 "transmission) max(baseColor) + 4 SE";
    uint64_t support = 0, over = 0, albedo_over = 0, valid = 0, bad_normal = 0;
    double worst_ratio = 0.0, worst_weight = 0.0, worst_albedo = 0.0;
    std::string first;
    for (size_t ci : members) {
        double sum = 0.0, sum_sq = 0.0;
        const Material& m0 = in[ci * s.brdf_samples].m;
        // The microfacet lobes reflect and transmit at most max(1, 1/eta^2) together (F + (1 - F)
        // at each microfacet, G <= 1), the diffuse lobe at most (1 - metallic)(1 -
        // transmission) max(baseColor): fresnel_mix weighs it by 1 - F(V.H), not by what the
        // specular lobe left, so the sum may exceed 1 (glTF 2.0, Appendix B, "Coupling Diffuse and
        // Specular Reflection": at a grazing view the specular lobe reflects F(cos_o) ~ 1 and the
        // diffuse lobe still ~0.6 of a grey plastic's 0.8).
        const double bound_albedo =
            std::max(1.0, 1.0 / (double(m0.ior) * double(m0.ior))) +
            double((1.0f - m0.metallic) * (1.0f - m0.transmission) * max3(m0.kd));
        for (uint32_t k = 0; k < s.brdf_samples; ++k) {
            const size_t i = ci * s.brdf_samples + k;
            const PbrInput& a = in[i];
            const PbrOutput& o = out[i];
            count_nonfinite(c, o);
            for (int ch = 0; ch < 3; ++ch) {
                c.nan += std::isnan(o.ns[ch]);
                c.inf += std::isinf(o.ns[ch]);
            }
            const glm::dvec3 ns(o.ns), wo(a.wo);
            if (!(std::abs(glm::length(ns) - 1.0) < 1e-5) || !(glm::dot(ns, wo) > 0.0)) {
                if (bad_normal++ == 0)
                    first = fmt::format("shading normal ({}, {}, {}), dot with wo {}", ns.x, ns.y,
                                        ns.z, glm::dot(ns, wo));
            }
            if (cmax(glm::dvec3(o.f)) > 0.0 && !(o.pdf > 0.0f) && support++ == 0 && first.empty())
                first = fmt::format("f = {} with pdf 0 ({}, roughness {}, cos_o {}, cos_i {})",
                                    cmax(glm::dvec3(o.f)), cfg[ci].material, a.m.roughness,
                                    glm::dot(ns, wo), glm::dot(ns, glm::dvec3(a.wi)));
            double w = 0.0;
            if (o.sample_lobe != LOBE_NONE) {
                ++valid;
                w = cmax(glm::dvec3(o.sample_weight));
                const double bound =
                    weight_bound(a.m, ns, wo, glm::dvec3(o.sample_wi), o.sample_lobe);
                worst_ratio = std::max(worst_ratio, w / bound);
                worst_weight = std::max(worst_weight, w);
                if (!(w <= bound * (1.0 + 1e-3)) && over++ == 0 && first.empty())
                    first = fmt::format("weight {} over {} (lobe {}, roughness {}, cos_o {}, "
                                        "cos_i {})",
                                        w, bound, o.sample_lobe, a.m.roughness, glm::dot(ns, wo),
                                        glm::dot(ns, glm::dvec3(o.sample_wi)));
            }
            // The mean over the random draws only: the first three take u at 0 and just below
            // 1, which picks the lobe of the smallest probability and its heaviest weight on
            // purpose (a plastic seen at cos 1e-4: the diffuse lobe, weight ~2000).
            if (k >= 3) {
                sum += w;
                sum_sq += w * w;
            }
        }
        const double n = s.brdf_samples - 3.0, mean = sum / n;
        const double se = std::sqrt(std::max(sum_sq / n - mean * mean, 0.0) / (n - 1.0));
        worst_albedo = std::max(worst_albedo, mean / bound_albedo);
        if (mean > bound_albedo + 4.0 * se + 1e-6) ++albedo_over;
    }
    c.pass = c.nan == 0 && c.inf == 0 && support == 0 && over == 0 && albedo_over == 0 &&
             bad_normal == 0 && valid > 0;
    c.measured = fmt::format("f > 0 with pdf = 0: {}; weights over the bound: {} (largest weight "
                             "{:.4g}, largest weight / bound {:.4g}); largest mean weight / bound "
                             "{:.4g} ({} over); bad shading normals: {}; {} valid samples{}",
                             support, over, worst_weight, worst_ratio, worst_albedo, albedo_over,
                             bad_normal, valid, first.empty() ? "" : "; first: " + first);
    return c;
}

std::vector<CaseResult> check(const std::vector<Config>& cfg, const std::vector<PbrInput>& in,
                              const std::vector<PbrOutput>& out, const std::string& backend,
                              const Size& s, bool maps) {
    std::vector<CaseResult> results;
    const std::vector<NamedMaterial> mats = materials();
    if (!maps) {
        for (float r : kRoughness)
            for (size_t mi = 0; mi < mats.size(); ++mi) {
                std::vector<size_t> members;
                for (size_t ci = 0; ci < cfg.size(); ++ci)
                    if (cfg[ci].roughness == r && cfg[ci].material == int(mi))
                        members.push_back(ci);
                results.push_back(check_group(
                    cfg, members, in, out,
                    fmt::format("glTF {}, roughness {:g}, cos(view) 1 to 1e-4", mats[mi].name, r),
                    backend, s));
            }
    } else {
        for (MapKind k :
             {MapKind::zero_texel, MapKind::below, MapKind::far_below, MapKind::parallel_tangent}) {
            std::vector<size_t> members;
            for (size_t ci = 0; ci < cfg.size(); ++ci)
                if (cfg[ci].map == k) members.push_back(ci);
            results.push_back(check_group(cfg, members, in, out,
                                          fmt::format("glTF normal map: {}", map_name(k)), backend,
                                          s));
        }
    }
    return results;
}

std::vector<CaseResult> run_cpp(const Size& s, bool maps) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<Config> cfg = maps ? normal_map_configs() : roughness_configs();
    const std::vector<PbrInput> in = inputs(cfg, s);
    std::vector<PbrOutput> out(in.size());
    for (size_t i = 0; i < in.size(); ++i) out[i] = eval_cpp(in[i]);
    std::vector<CaseResult> r = check(cfg, in, out, "c++", s, maps);
    const double dt = seconds_since(t0);
    for (CaseResult& c : r) c.seconds = dt / double(r.size());
    return r;
}

std::vector<CaseResult> run_glsl(const VulkanContext& ctx, const Size& s, bool maps) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<Config> cfg = maps ? normal_map_configs() : roughness_configs();
    const std::vector<PbrInput> in = inputs(cfg, s);
    const uint32_t count = uint32_t(in.size());
    const auto bytes = run_compute_shader(
        ctx, tp_spirv_stress_pbr_comp, sizeof(tp_spirv_stress_pbr_comp), {bytes_of(in)},
        {in.size() * sizeof(PbrOutput)}, &count, sizeof(count), (count + 63) / 64);
    std::vector<CaseResult> r = check(cfg, in, as_vector<PbrOutput>(bytes[0]), "glsl", s, maps);
    const double dt = seconds_since(t0);
    for (CaseResult& c : r) {
        c.mode = ctx.info().name;
        c.seconds = dt / double(r.size());
    }
    return r;
}

} // namespace

std::vector<CaseResult> pbr_cases_cpp(const Size& s) {
    std::vector<CaseResult> r = run_cpp(s, false);
    for (CaseResult& c : run_cpp(s, true)) r.push_back(c);
    return r;
}

std::vector<CaseResult> pbr_cases_glsl(const VulkanContext& ctx, const Size& s) {
    std::vector<CaseResult> r = run_glsl(ctx, s, false);
    for (CaseResult& c : run_glsl(ctx, s, true)) r.push_back(c);
    return r;
}

} // namespace tp::stress
