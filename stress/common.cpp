#include "stress/common.h"

#include "compare/compare.h"
#include "compare/rgb_image.h"
#include "cpu_ref/cpu_renderer.h"
#include "scene/generators.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace tp::stress {

std::string describe(const CaseResult& r) {
    return fmt::format(
        "[{}] {} / {} on {}/{}: {} (NaN {}, Inf {}, {} checked, {:.2f} s); expected: "
        "{}; measured: {}",
        r.skipped ? "SKIP"
        : r.pass  ? "PASS"
                  : "FAIL",
        r.group, r.name, r.backend, r.mode,
        r.skipped ? "skipped"
        : r.pass  ? "pass"
                  : "fail",
        r.nan, r.inf, r.checked, r.seconds, r.expected, r.measured);
}

Engine cpu_engine(uint32_t threads) {
    return {"cpu", "embree", [threads](const FlatScene& f, const RenderOptions& o) {
                RenderOptions opt = o;
                opt.threads = threads;
                return render_cpu(f, opt);
            }};
}

Engine vulkan_engine(const VkBackend& backend, const std::string& device) {
    const VulkanOptions vk = backend_vulkan_options(backend, device);
    return {"vulkan", vk_backend_name(backend),
            [vk](const FlatScene& f, const RenderOptions& o) { return render_vulkan(f, o, vk); }};
}

Size small_size() {
    return Size{};
}

Size large_size() {
    Size s;
    s.image = 64;
    s.spp = 512;
    s.furnace_spp = 256;
    s.watertight_rays = 4000000;
    s.brdf_samples = 20000;
    s.accumulation_spp = 4000000;
    s.point_lights = 100000;
    s.rare_spp = 8192;
    return s;
}

uint32_t add_material(Scene& s, const std::string& name, const Material& m) {
    s.materials.push_back(m);
    s.material_names.push_back(name);
    return uint32_t(s.materials.size() - 1);
}

Material phong(vec3 kd, vec3 ks, float ns) {
    Material m = default_material();
    m.type = MATERIAL_PHONG;
    m.kd = kd;
    m.ks = ks;
    m.ns = ns;
    return m;
}

Material glass(float ior, vec3 tf) {
    Material m = default_material();
    m.type = MATERIAL_DIELECTRIC;
    m.ior = ior;
    m.tf = tf;
    return m;
}

Material emitter(vec3 ke) {
    Material m = default_material();
    m.ke = ke;
    return m;
}

uint32_t add_mesh(Scene& s, Mesh m) {
    s.meshes.push_back(std::move(m));
    return uint32_t(s.meshes.size() - 1);
}

void add_object(Scene& s, const std::string& name, uint32_t mesh, uint32_t material,
                const glm::dmat4& transform) {
    Object o;
    o.name = name;
    o.mesh = mesh;
    o.material = material;
    o.transform = transform;
    s.objects.push_back(o);
}

Scene reference_scene(uint32_t image, uint32_t spp) {
    Scene s;
    s.path = "stress: reference scene";
    const uint32_t floor_m = add_material(s, "floor", phong(vec3(0.5f)));
    const uint32_t sphere_m =
        add_material(s, "sphere", phong(vec3(0.4f, 0.3f, 0.2f), vec3(0.3f), 40.0f));
    const uint32_t box_m = add_material(s, "box", phong(vec3(0.2f, 0.5f, 0.3f)));
    const uint32_t light_m = add_material(s, "light", emitter(vec3(6.0f)));
    const uint32_t quad = add_mesh(s, make_quad());
    const uint32_t sphere = add_mesh(s, make_icosphere(3, false));
    const uint32_t box = add_mesh(s, make_box());
    const glm::mat4 I(1.0f);
    add_object(s, "floor", quad, floor_m, glm::scale(I, vec3(2.0f)));
    add_object(s, "sphere", sphere, sphere_m,
               glm::scale(glm::translate(I, vec3(0.2f, 0.5f, 0.0f)), vec3(0.5f)));
    add_object(s, "box", box, box_m,
               glm::scale(glm::translate(I, vec3(-0.8f, 0.25f, 0.4f)), vec3(0.25f)));
    // The make_quad() square faces +Y; turned over it faces down onto the scene.
    add_object(s, "light", quad, light_m,
               glm::scale(glm::rotate(glm::translate(I, vec3(0.0f, 2.0f, 0.0f)), glm::pi<float>(),
                                      vec3(1, 0, 0)),
                          vec3(0.4f)));
    LightDesc p;
    p.type = LIGHT_POINT;
    p.position = glm::dvec3(1.0, 1.5, 1.0);
    p.value = vec3(2.0f);
    s.lights.push_back(p);
    s.environment.kind = EnvironmentKind::Constant;
    s.environment.radiance = vec3(0.2f);
    s.camera.given = true;
    s.camera.eye = vec3(0.0f, 1.3f, 3.6f);
    s.camera.target = vec3(0.0f, 0.4f, 0.0f);
    s.camera.fov_y_degrees = 40.0f;
    s.settings.width = s.settings.height = image;
    s.settings.spp = spp;
    s.settings.max_depth = 8;
    s.settings.min_depth = 3;
    return s;
}

Rendered render(const Engine& e, const FlatScene& f, uint32_t seed) {
    RenderOptions o;
    o.seed = seed;
    Rendered out;
    out.r = e.render(f, o);
    const Film& film = out.r.film;
    for (uint32_t p = 0; p < film.width() * film.height(); ++p) {
        const glm::dvec3 m = film.mean(p);
        if (!std::isfinite(m.x) || !std::isfinite(m.y) || !std::isfinite(m.z))
            ++out.nonfinite_pixels;
        if (m.x == 0.0 && m.y == 0.0 && m.z == 0.0) ++out.black_pixels;
    }
    return out;
}

bool render_reference(const Engine& e, const Scene& base, uint32_t seed, const char* group,
                      const char* name, Rendered& ref, std::vector<CaseResult>& failed) {
    try {
        ref = render(e, flatten(base), seed);
        return true;
    } catch (const std::exception& ex) {
        CaseResult c = make_case(group, name, e, "renders");
        c.measured = std::string("threw: ") + ex.what();
        failed = {c};
        return false;
    }
}

bool compare_consistent(const Rendered& a, const Rendered& b, double alpha, double& p) {
    ExrImage ea = a.r.film.to_exr(), eb = b.r.film.to_exr();
    ea.integers["twinpath:spp"] = a.r.stats.spp;
    eb.integers["twinpath:spp"] = b.r.stats.spp;
    CompareOptions opt;
    opt.alpha = alpha;
    const CompareResult c =
        compare_images(rgb_image_from_exr(ea, "a"), rgb_image_from_exr(eb, "b"), opt);
    p = c.p_value;
    return !c.different;
}

CaseResult make_case(const std::string& group, const std::string& name, const Engine& e,
                     const std::string& expected) {
    CaseResult c;
    c.group = group;
    c.name = name;
    c.backend = e.backend;
    c.mode = e.mode;
    c.expected = expected;
    return c;
}

void image_mean(const Film& f, double& mean, double& se) {
    const double m = double(f.width()) * f.height();
    mean = 0.0;
    double var = 0.0;
    for (uint32_t p = 0; p < f.width() * f.height(); ++p) {
        const glm::dvec3 v = f.mean(p), s2 = f.variance_of_mean(p);
        mean += (v.x + v.y + v.z) / (3.0 * m);
        // Channels of one pixel share their samples: their average's variance is at most the
        // average of their variances (Cauchy-Schwarz), a conservative bound.
        var += (s2.x + s2.y + s2.z) / (3.0 * m * m);
    }
    se = std::sqrt(var);
}

// Appends the render's NaN/Inf count (samples dropped by the engine, and film pixels that are
// not finite) to the case.
void count_nan(CaseResult& c, const Rendered& r) {
    c.nan += r.r.stats.nan_samples + r.nonfinite_pixels;
    c.checked += r.r.stats.samples;
}

// `variant` against `reference`: compare's two-sample test at alpha, no NaN/Inf, and no pixel
// black in the variant that is not black in the reference.
void expect_consistent(CaseResult& c, const Rendered& reference, const Rendered& variant,
                       double alpha) {
    count_nan(c, reference);
    count_nan(c, variant);
    double p = 0.0;
    const bool same = compare_consistent(reference, variant, alpha, p);
    c.pass = same && c.nan == 0 && variant.black_pixels <= reference.black_pixels;
    c.measured += fmt::format("{}compare p = {:.3g} ({}), black pixels {} (reference {})",
                              c.measured.empty() ? "" : "; ", p, same ? "consistent" : "different",
                              variant.black_pixels, reference.black_pixels);
}

} // namespace tp::stress
