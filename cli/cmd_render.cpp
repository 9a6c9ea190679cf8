// twinpath render SCENE: load, render on the chosen backend, write EXR (+ PNG, stats).
#include "arg_parse.h"
#include "commands.h"
#include "progress.h"

#include "cpu_ref/cpu_renderer.h"
#include "image/png_io.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "util/error.h"
#include "vulkan_rt/vulkan_renderer.h"

#include <fmt/core.h>

#include <unistd.h>

#include <filesystem>
#include <optional>

namespace tp {
namespace {

struct RenderArgs {
    std::string scene;
    std::string output;
    std::string backend = "cpu";
    std::string vk_mode = "auto";
    std::optional<uint32_t> spp, width, height, min_depth, max_depth;
    double time_limit = 0;
    uint32_t seed = 0;
    uint32_t threads = 0;
    std::string device;
    std::string eye, target, up;
    std::optional<float> fov;
    std::string stats, png;
    std::string features = "scene"; // --features: scene (specialized) or all
};

ExrImage render_image(const RenderResult& r) {
    ExrImage img = r.film.to_exr();
    img.integers["twinpath:spp"] = r.stats.spp;
    img.integers["twinpath:seed"] = r.stats.seed;
    img.strings["twinpath:backend"] =
        r.stats.mode.empty() ? r.stats.backend : r.stats.backend + "/" + r.stats.mode;
    img.strings["twinpath:device"] = r.stats.device;
    img.strings["twinpath:scene"] = r.stats.scene;
    img.reals["twinpath:render_time_s"] = r.stats.wall_time_s;
    return img;
}

// An output file can be written when its directory exists and is writable and the path is not
// a directory or a read-only file. Checked for every output before rendering, so that a bad
// path fails at once (exit 2) and leaves no file behind instead of failing after the render.
void check_output_path(const std::string& path, const char* option) {
    namespace fs = std::filesystem;
    const fs::path p(path);
    const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        input_error("{} {}: the directory {} does not exist", option, path, dir.string());
    if (fs::is_directory(p, ec)) input_error("{} {}: is a directory", option, path);
    if (access(dir.c_str(), W_OK) != 0)
        input_error("{} {}: the directory {} is not writable", option, path, dir.string());
    if (fs::exists(p, ec) && access(p.c_str(), W_OK) != 0)
        input_error("{} {}: the file is not writable", option, path);
}

int run_render(const RenderArgs& a) {
    std::vector<std::string> warnings;
    Scene scene = load_scene(a.scene, warnings);
    for (const std::string& w : warnings) fmt::print(stderr, "twinpath: warning: {}\n", w);

    SceneOverrides o;
    o.spp = a.spp;
    if (a.time_limit > 0 && !a.spp) o.spp = 1u << 30; // until the time runs out
    o.width = a.width;
    o.height = a.height;
    o.min_depth = a.min_depth;
    o.max_depth = a.max_depth;
    if (!a.eye.empty()) o.eye = parse_vec3("--eye", a.eye);
    if (!a.target.empty()) o.target = parse_vec3("--target", a.target);
    if (!a.up.empty()) o.up = parse_vec3("--up", a.up);
    o.fov = a.fov;
    apply_overrides(scene, o);
    const FlatScene flat = flatten(scene);

    const std::string out =
        !a.output.empty() ? a.output : std::filesystem::path(scene.path).stem().string() + ".exr";
    check_output_path(out, "-o");
    if (!a.png.empty()) check_output_path(a.png, "--png");
    if (!a.stats.empty()) check_output_path(a.stats, "--stats");

    ProgressBar bar(fmt::format("render {}", a.backend));
    RenderOptions opt;
    opt.seed = a.seed;
    opt.time_limit_s = a.time_limit;
    opt.threads = a.threads;
    opt.all_features = a.features == "all";
    opt.progress = bar.callback();

    RenderResult result;
    if (a.backend == "cpu") {
        result = render_cpu(flat, opt);
    } else {
        VulkanOptions vk;
        vk.device = a.device;
        vk.mode = a.vk_mode;
        result = render_vulkan(flat, opt, vk);
    }
    result.stats.scene = scene.path;

    write_exr(out, render_image(result));
    if (!a.png.empty()) {
        const ExrImage img = result.film.to_exr();
        write_png(a.png, img.width, img.height,
                  tonemap_srgb8(img.channel("R"), img.channel("G"), img.channel("B"), 0.0f));
    }
    if (!a.stats.empty()) write_stats_json(a.stats, result.stats);
    const RenderStats& s = result.stats;
    fmt::print("{}: {}x{} {} spp on {} in {:.2f} s ({:.2f} Mrays/s), {} NaN/Inf samples -> {}\n",
               scene.path, s.width, s.height, s.spp, s.device, s.wall_time_s,
               s.rays_per_second() * 1e-6, s.nan_samples, out);
    return 0;
}

} // namespace

Subcommand add_render_command(CLI::App& app) {
    auto a = std::make_shared<RenderArgs>();
    CLI::App* c = app.add_subcommand(
        "render", "Render a scene (.json, .obj or a bundled scene name) to OpenEXR");
    c->add_option("scene", a->scene, "Scene file or bundled scene name")->required();
    c->add_option("-o,--output", a->output, "Output OpenEXR file (default: <scene>.exr)");
    c->add_option("--backend", a->backend, "cpu or vulkan")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    c->add_option("--vk-mode", a->vk_mode, "Vulkan mode")
        ->check(CLI::IsMember({"auto", "compute", "pipeline"}));
    c->add_option("--spp", a->spp, "Samples per pixel")->check(CLI::Range(1u, 1u << 30));
    c->add_option("--time-limit", a->time_limit, "Stop after this many seconds (whole passes)")
        ->check(CLI::Range(0.0, 1e9));
    c->add_option("--seed", a->seed, "Random seed");
    c->add_option("--width", a->width, "Image width")->check(CLI::Range(1u, 16384u));
    c->add_option("--height", a->height, "Image height")->check(CLI::Range(1u, 16384u));
    c->add_option("--min-depth", a->min_depth, "Bounces before Russian roulette")
        ->check(CLI::Range(0u, 100000u));
    c->add_option("--max-depth", a->max_depth, "Maximum scattering events")
        ->check(CLI::Range(1u, 100000u));
    c->add_option("--threads", a->threads, "CPU threads (0: all)")->check(CLI::Range(0u, 4096u));
    c->add_option("--device", a->device, "Vulkan device index or name substring");
    c->add_option("--eye", a->eye, "Camera position X,Y,Z");
    c->add_option("--target", a->target, "Camera target X,Y,Z");
    c->add_option("--up", a->up, "Camera up vector X,Y,Z");
    c->add_option("--fov", a->fov, "Vertical field of view in degrees")
        ->check(CLI::Range(1e-3f, 179.0f));
    c->add_option("--stats", a->stats, "Write render statistics as JSON");
    c->add_option("--png", a->png, "Write a tone-mapped sRGB PNG preview");
    c->add_option("--features", a->features,
                  "Path loop: scene (specialized to the scene's features) or all (every feature)")
        ->check(CLI::IsMember({"scene", "all"}));
    return {c, [a] { return run_render(*a); }};
}

} // namespace tp
