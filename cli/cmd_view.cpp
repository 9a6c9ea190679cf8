// twinpath view SCENE: the interactive progressive window (view/viewer.h).
#include "arg_parse.h"
#include "commands.h"
#include "scene_args.h"

#include "render/sampler.h"
#include "view/viewer.h"

#include <optional>

namespace tp {

struct ViewArgs : SceneArgs {
    ViewOptions view;
    std::string detect = "1%";
    std::optional<double> time_budget;
};

Subcommand add_view_command(CLI::App& app) {
    auto a = std::make_shared<ViewArgs>();
    CLI::App* c = app.add_subcommand("view", "Interactive progressive window (Vulkan)");
    add_scene_options(c, *a);
    ViewOptions& v = a->view;
    c->add_option("--frames", v.frames, "Exit after this many frames");
    c->add_option("--screenshot", v.screenshot, "Save the last frame's window as PNG");
    c->add_option("--script", v.script, "Replay timed input (docs/view.md)");
    c->add_flag("--headless", v.headless, "No window: run the frame loop, report frame times");
    c->add_option("--spp-per-frame", v.progressive.samples_per_frame,
                  "Samples per frame (default: adapt to ~16 ms)");
    c->add_option("--exposure", v.exposure,
                  "The display's exposure: STOPS (radiance times 2^STOPS; default 0) or auto (the "
                  "99th percentile of the first whole pass maps to white); [ and ] change it")
        ->check(CLI::IsMember({"auto"}) | number_in(-60.0, 60.0));
    c->add_option("--detect", a->detect,
                  "C: the relative bias the live compare finds with probability 0.9 (default 1%)");
    c->add_option("--time-budget", a->time_budget,
                  "C: seconds for the live compare's renders (default: as long as --detect needs)")
        ->check(number_in(1e-3, 1e9));
    return {c, [a] {
                const FlatScene scene = flatten(load_scene_args(*a, 1u << 30));
                ViewOptions v = a->view;
                v.scene_path = a->scene;
                v.device = a->device;
                v.vk_mode = parse_vk_mode_request(a->vk_mode);
                v.threads = a->threads;
                v.progressive.seed = a->seed;
                v.progressive.sampler = sampler_from_name(a->sampler);
                v.progressive.max_spp = scene.spp;
                v.verify.detect = parse_relative_bias("--detect", a->detect);
                v.verify.budget_s = a->time_budget;
                return run_view(scene, v);
            }};
}

} // namespace tp
