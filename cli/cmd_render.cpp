// twinpath render SCENE: load, render on the chosen backend, write EXR (+ PNG, stats).
#include "arg_parse.h"
#include "commands.h"
#include "output_paths.h"
#include "scene_args.h"

#include "compare/colormap.h"
#include "cpu_ref/cpu_renderer.h"
#include "image/exposure.h"
#include "image/png_io.h"
#include "render/render_header.h"
#include "render/sampler.h"
#include "scene/features.h"
#include "scene/flatten.h"
#include "util/error.h"
#include "util/interrupt.h"
#include "util/progress_bar.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <optional>

namespace tp {
namespace {

struct RenderArgs : SceneArgs {
    std::optional<std::string> output; // each output: given (perhaps as "") or not
    std::string backend = "cpu";
    std::optional<std::string> bvh; // --bvh binary|wide|auto (compute mode's BVH layout)
    uint32_t gpu_invocations = 0;   // --gpu-invocations (docs/gpu.md, "Work items")
    double time_limit = 0;
    uint32_t sample_offset = 0;
    std::string film = "lean"; // --film lean|full (render/film.h, FilmLayout)
    std::optional<std::string> stats, png;
    std::string exposure = "0";                // --exposure STOPS|auto, of the PNG preview
    std::optional<std::string> pipeline_stats; // --pipeline-stats FILE (docs/gpu.md)
    std::string features = "scene";            // --features: scene (specialized) or all
    // Debugging (docs/debugging.md).
    std::string aov, debug_pixel, integrator = "path";
    std::optional<std::string> debug_log;
    std::optional<uint32_t> debug_sample;
};

// --aov: "albedo,normal,depth,ids" in any subset, or "all". The layers come from one trace of
// the pixel centre, so every named layer is written; the names are checked.
bool parse_aov(const std::string& text) {
    if (text.empty()) return false;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find(',', start), text.size());
        const std::string name = text.substr(start, end - start);
        if (name != "albedo" && name != "normal" && name != "depth" && name != "ids" &&
            name != "all")
            input_error("--aov {}: '{}' is not an AOV (albedo, normal, depth, ids or all)", text,
                        name);
        start = end + 1;
    }
    return true;
}

// The cost view's preview: B (the total cost) as a heat map from blue (0) to red (the image's
// maximum), instead of a tone-mapped radiance.
std::vector<uint8_t> heat_map(const std::vector<float>& cost) {
    float max_cost = 0.0f;
    for (float c : cost)
        if (std::isfinite(c)) max_cost = std::max(max_cost, c);
    std::vector<uint8_t> rgb;
    rgb.reserve(cost.size() * 3);
    for (float c : cost) {
        const double t =
            max_cost > 0 && std::isfinite(c) ? 2.0 * double(c) / double(max_cost) - 1.0 : -1.0;
        for (uint8_t v : diverging_color(t)) rgb.push_back(v);
    }
    return rgb;
}

int run_render(const RenderArgs& a) {
    // First, before the scene loads: a signal from here until the first pass exits at once with
    // its code (util/interrupt.h), where the default action would end the process without one.
    install_interrupt_handlers();
    // With --time-limit and no --spp: until the time runs out.
    const Scene scene =
        load_scene_args(a, a.time_limit > 0 ? std::optional<uint32_t>(1u << 30) : std::nullopt);
    const FlatScene flat = flatten(scene);

    DebugRequest debug;
    debug.integrator = integrator_from_name(a.integrator);
    debug.aov = parse_aov(a.aov);
    debug.log = a.debug_log.has_value();
    debug.sample = a.debug_sample;
    if (debug.integrator == INTEGRATOR_PATH)
        if (const std::optional<std::string> w = dark_scene_warning(flat, scene.path))
            fmt::print(stderr, "twinpath: warning: {}\n", *w);
    if (debug.log != !a.debug_pixel.empty())
        input_error("--debug-log and --debug-pixel go together (the log of which pixel?)");
    if (a.debug_sample && !debug.log) input_error("--debug-sample needs --debug-log");
    if (debug.log) {
        const uvec2 p = parse_pixel("--debug-pixel", a.debug_pixel);
        if (p.x >= flat.params.camera.width || p.y >= flat.params.camera.height)
            input_error("--debug-pixel {}: outside the {}x{} image", a.debug_pixel,
                        flat.params.camera.width, flat.params.camera.height);
        debug.pixel_x = p.x;
        debug.pixel_y = p.y;
        if (debug.sample &&
            (*debug.sample < a.sample_offset || *debug.sample - a.sample_offset >= flat.spp))
            input_error("--debug-sample {}: the render has samples {} to {}", *debug.sample,
                        a.sample_offset, uint64_t(a.sample_offset) + flat.spp - 1);
        if (debug.integrator != INTEGRATOR_PATH)
            input_error("--debug-log records the path integrator, not --integrator {}",
                        a.integrator);
    }

    if (uint64_t(a.sample_offset) + flat.spp > (uint64_t(1) << 32))
        input_error("--sample-offset {} --spp {}: sample indices end at 2^32", a.sample_offset,
                    flat.spp);
    const std::string out =
        a.output ? *a.output : std::filesystem::path(scene.path).stem().string() + ".exr";
    std::vector<std::pair<std::string, std::string>> outputs = {{"-o", out}};
    if (a.png) outputs.emplace_back("--png", *a.png);
    if (a.stats) outputs.emplace_back("--stats", *a.stats);
    if (a.pipeline_stats) {
        if (a.backend != "vulkan")
            input_error("--pipeline-stats reports the Vulkan driver's pipelines: use --backend "
                        "vulkan");
        outputs.emplace_back("--pipeline-stats", *a.pipeline_stats);
    }
    if (debug.log) outputs.emplace_back("--debug-log", *a.debug_log);
    check_output_paths(outputs);

    ProgressBar bar(fmt::format("render {}", a.backend));
    RenderOptions opt;
    opt.stop = &interrupt_flag();
    // The line that says the render has begun (scripts and tests wait for it): from here on a
    // first signal saves the passes done. Once, though each device's thread calls it.
    std::atomic<bool> begun{false};
    opt.on_first_pass = [&] {
        if (begun.exchange(true)) return;
        save_on_interrupt();
        const std::string length = a.time_limit > 0 && !a.spp ? fmt::format("{} s", a.time_limit)
                                   : a.time_limit > 0
                                       ? fmt::format("{} spp or {} s", flat.spp, a.time_limit)
                                       : fmt::format("{} spp", flat.spp);
        fmt::print(stderr,
                   "twinpath: rendering {}x{}, {}: a first SIGINT or SIGTERM saves the passes "
                   "done, a second exits at once\n",
                   flat.params.camera.width, flat.params.camera.height, length);
    };
    opt.seed = a.seed;
    opt.sample_offset = a.sample_offset;
    opt.sampler = sampler_from_name(a.sampler);
    opt.film = film_layout_from_name(a.film);
    opt.time_limit_s = a.time_limit;
    opt.threads = a.threads;
    opt.gpu_invocations = a.gpu_invocations;
    opt.all_features = a.features == "all";
    opt.progress = bar.callback();
    opt.debug = debug;

    RenderResult result;
    if (a.backend == "cpu") {
        result = render_cpu(flat, opt);
    } else {
        VulkanOptions vk;
        vk.device = a.device;
        vk.mode = parse_vk_mode_request(a.vk_mode);
        if (a.bvh) vk.bvh = parse_bvh_layout(*a.bvh);
        vk.pipeline_statistics = a.pipeline_stats.has_value();
        result = render_vulkan(flat, opt, vk);
    }
    result.stats.scene = scene.path;

    write_exr(out, render_exr(result, flat, opt));
    if (a.png) {
        const ExrImage img = result.film.to_exr();
        const std::vector<float>&r = img.channel("R"), &g = img.channel("G"), &b = img.channel("B");
        float stops = 0.0f;
        if (a.exposure == "auto") {
            stops = auto_exposure_stops(r, g, b);
            fmt::print(stderr, "twinpath: --png exposure {:+.2f} stops (auto)\n", stops);
        } else {
            stops = float(std::stod(a.exposure));
        }
        write_png(*a.png, img.width, img.height,
                  debug.integrator == INTEGRATOR_COST ? heat_map(img.channel("B"))
                                                      : tonemap_srgb8(r, g, b, stops));
    }
    if (debug.log) {
        write_path_log(*a.debug_log, path_log_info(result, flat, scene.path, debug),
                       result.debug.records);
        if (result.debug.dropped)
            fmt::print(stderr,
                       "twinpath: warning: {} path-log records did not fit and were dropped\n",
                       result.debug.dropped);
    }
    if (a.stats) write_stats_json(*a.stats, result.stats);
    if (a.pipeline_stats) write_pipeline_stats_json(*a.pipeline_stats, result.stats);
    const RenderStats& s = result.stats;
    fmt::print("{}: {}x{} {} spp on {} in {:.2f} s ({:.2f} Mrays/s), {} NaN/Inf samples -> {}\n",
               scene.path, s.width, s.height, s.spp, s.device, s.wall_time_s,
               s.rays_per_second() * 1e-6, s.nan_samples, out);
    if (const int code = interrupt_exit_code()) {
        fmt::print(stderr, "twinpath: interrupted: wrote the {} of {} spp accumulated\n", s.spp,
                   flat.spp);
        return code;
    }
    return 0;
}

} // namespace

Subcommand add_render_command(CLI::App& app) {
    auto a = std::make_shared<RenderArgs>();
    CLI::App* c = app.add_subcommand(
        "render", "Render a scene (.json, .obj, .gltf, .glb or a bundled scene name) to OpenEXR");
    add_scene_options(c, *a);
    c->add_option("-o,--output", a->output, "Output OpenEXR file (default: <scene>.exr)");
    c->add_option("--backend", a->backend, "cpu or vulkan")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    c->add_option("--bvh", a->bvh,
                  "Compute mode's BVH layout: binary, wide, or auto (default: wide where the "
                  "binary tree's estimated work per ray is long, docs/gpu.md)")
        ->check(CLI::IsMember({"binary", "wide", "auto"}));
    c->add_option("--gpu-invocations", a->gpu_invocations,
                  "Vulkan: render invocations per launch (0: as many as the device keeps "
                  "resident where it says, else one per sample; docs/gpu.md)")
        ->check(CLI::Range(0u, 1u << 30));
    c->add_option("--time-limit", a->time_limit, "Stop after this many seconds (whole passes)")
        ->check(number_in(0.0, 1e9));
    c->add_option("--sample-offset", a->sample_offset,
                  "First sample index: render samples K..K+spp-1 (docs/farm.md)");
    c->add_option("--film", a->film,
                  "EXR channels: lean (what compare reads) or full (also the batch means that "
                  "merge needs for Sobol parts; docs/sampling.md)")
        ->check(CLI::IsMember({"lean", "full"}))
        ->capture_default_str();
    c->add_option("--stats", a->stats, "Write render statistics as JSON");
    c->add_option("--png", a->png, "Write a tone-mapped sRGB PNG preview");
    c->add_option("--exposure", a->exposure,
                  "The PNG preview's exposure: STOPS (radiance times 2^STOPS; default 0) or "
                  "auto (the 99th percentile of the pixels maps to white)")
        ->check(CLI::IsMember({"auto"}) | number_in(-60.0, 60.0));
    c->add_option("--pipeline-stats", a->pipeline_stats,
                  "Vulkan: write the driver's statistics of the render pipeline (register "
                  "counts, ...) as JSON (docs/gpu.md)");
    c->add_option("--features", a->features,
                  "Path loop: scene (specialized to the scene's features) or all (every feature)")
        ->check(CLI::IsMember({"scene", "all"}));
    c->add_option("--aov", a->aov,
                  "Add AOV layers albedo, normal, depth, ids (list or 'all'; docs/debugging.md)");
    c->add_option("--debug-pixel", a->debug_pixel, "Pixel X,Y whose paths --debug-log records");
    c->add_option("--debug-sample", a->debug_sample,
                  "Record only this sample of the debug pixel (default: all)");
    c->add_option("--debug-log", a->debug_log, "Write the debug pixel's path log (JSON)");
    c->add_option("--integrator", a->integrator,
                  "path (default) or a debug view: normals, albedo, depth, cost")
        ->check(CLI::IsMember({"path", "normals", "albedo", "depth", "cost"}));
    return {c, [a] { return run_render(*a); }};
}

} // namespace tp
