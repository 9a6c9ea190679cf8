#include "renders.h"

#include "cpu_ref/cpu_renderer.h"
#include "image/exr_io.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "support/test_paths.h"

#include <fmt/format.h>

#include <fstream>

namespace tp::test {
namespace {

ExrImage render_exr(const RenderSpec& spec) {
    std::vector<std::string> warnings;
    Scene scene = load_scene(spec.scene, warnings);
    SceneOverrides o;
    o.width = spec.width;
    o.height = spec.height;
    o.spp = spec.spp;
    o.max_depth = spec.max_depth;
    o.eye = spec.eye;
    o.target = spec.target;
    o.fov = spec.fov;
    apply_overrides(scene, o);
    RenderOptions opt;
    opt.seed = spec.seed;
    opt.sampler = spec.sampler;
    opt.threads = spec.threads;
    const RenderResult r = render_cpu(flatten(scene), opt);
    ExrImage img = r.film.to_exr();
    img.integers["twinpath:spp"] = r.stats.spp;
    img.integers["twinpath:seed"] = spec.seed;
    img.strings["twinpath:backend"] = "cpu";
    return img;
}

} // namespace

RgbImage render_cpu_image(const RenderSpec& spec) {
    return rgb_image_from_exr(render_exr(spec),
                              fmt::format("{}-seed{}-{}spp", spec.scene, spec.seed, spec.spp));
}

void render_cpu_file(const RenderSpec& spec, const std::string& path) {
    write_exr(path, render_exr(spec));
}

std::string scene_with_scaled_albedo(const std::string& scene, const std::string& material,
                                     double factor, const std::string& dir) {
    const std::string src = resolve_scene_path(scene);
    nlohmann::json j = nlohmann::json::parse(std::ifstream(src));
    for (auto& v : j.at("materials").at(material).at("Kd")) v = v.get<double>() * factor;
    const std::string out = dir + "/" + scene + "_" + material + ".json";
    std::ofstream(out) << j.dump(2);
    return out;
}

std::string scene_with_materials(const std::string& scene, const nlohmann::json& replacements,
                                 const std::string& tag, const std::string& dir) {
    nlohmann::json j = nlohmann::json::parse(std::ifstream(resolve_scene_path(scene)));
    for (const auto& [name, material] : replacements.items()) j.at("materials").at(name) = material;
    const std::string out = dir + "/" + scene + "_" + tag + ".json";
    std::ofstream(out) << j.dump(2);
    return out;
}

BackendComparison compare_backends(const std::string& scene, uint32_t width, uint32_t height,
                                   uint32_t spp, const BackendRun& a, const BackendRun& b,
                                   double alpha) {
    BackendComparison out;
    const std::string dir = temp_dir("backends-" + scene);
    auto render = [&](const BackendRun& r, const std::string& file) {
        const ProcessResult p = run(fmt::format(
            "{} render {} --backend {} --vk-mode {} --seed {} --threads {} --spp {} --width {} "
            "--height {} -o {}",
            shell_quote(twinpath_bin()), shell_quote(scene), r.backend, r.vk_mode, r.seed,
            r.threads, spp, width, height, shell_quote(file)));
        out.output += p.out;
        return p.exit_code;
    };
    const std::string fa = dir + "/a.exr", fb = dir + "/b.exr", js = dir + "/result.json";
    out.render_exit_a = render(a, fa);
    out.render_exit_b = render(b, fb);
    if (out.render_exit_a != 0 || out.render_exit_b != 0) return out;
    const ProcessResult c =
        run(fmt::format("{} compare {} {} --alpha {} --json {}", shell_quote(twinpath_bin()),
                        shell_quote(fa), shell_quote(fb), alpha, shell_quote(js)));
    out.output += c.out;
    out.compare_exit = c.exit_code;
    if (std::ifstream f(js); f) out.result = nlohmann::json::parse(f, nullptr, false);
    return out;
}

} // namespace tp::test
