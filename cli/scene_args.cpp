#include "scene_args.h"

#include "arg_parse.h"

#include "scene/load.h"

#include <fmt/core.h>

namespace tp {

void add_scene_options(CLI::App* c, SceneArgs& a) {
    c->add_option("scene", a.scene, "Scene file or bundled scene name")->required();
    c->add_option("--vk-mode", a.vk_mode, "Vulkan mode")
        ->check(CLI::IsMember({"auto", "compute", "pipeline"}));
    c->add_option("--spp", a.spp, "Samples per pixel")->check(CLI::Range(1u, 1u << 30));
    c->add_option("--seed", a.seed, "Random seed");
    c->add_option("--sampler", a.sampler,
                  "sobol (Owen-scrambled Sobol, variance from 8 independent batches) or random "
                  "(independent numbers); docs/sampling.md")
        ->check(CLI::IsMember({"random", "sobol"}))
        ->capture_default_str();
    c->add_option("--width", a.width, "Image width")->check(CLI::Range(1u, 16384u));
    c->add_option("--height", a.height, "Image height")->check(CLI::Range(1u, 16384u));
    c->add_option("--min-depth", a.min_depth, "Bounces before Russian roulette")
        ->check(CLI::Range(0u, 100000u));
    c->add_option("--max-depth", a.max_depth, "Maximum scattering events")
        ->check(CLI::Range(1u, 100000u));
    c->add_option("--threads", a.threads, "CPU threads (0: all)")->check(CLI::Range(0u, 4096u));
    c->add_option("--device", a.device,
                  "Vulkan device index or name substring; all, or a list: several at once");
    c->add_option("--eye", a.eye, "Camera position X,Y,Z");
    c->add_option("--target", a.target, "Camera target X,Y,Z");
    c->add_option("--up", a.up, "Camera up vector X,Y,Z");
    c->add_option("--fov", a.fov, "Vertical field of view in degrees")
        ->check(number_in(1e-3, 179.0));
    c->add_option("--camera", a.camera,
                  "glTF: render the asset's camera N (default: the first its scene places)");
}

Scene load_scene_args(const SceneArgs& a, std::optional<uint32_t> spp) {
    std::vector<std::string> warnings;
    Scene scene = load_scene(a.scene, warnings, LoadOptions{a.camera});
    for (const std::string& w : warnings) fmt::print(stderr, "twinpath: warning: {}\n", w);
    SceneOverrides o;
    o.spp = a.spp ? a.spp : spp;
    o.width = a.width;
    o.height = a.height;
    o.min_depth = a.min_depth;
    o.max_depth = a.max_depth;
    if (!a.eye.empty()) o.eye = parse_xyz("--eye", a.eye);
    if (!a.target.empty()) o.target = parse_xyz("--target", a.target);
    if (!a.up.empty()) o.up = vec3(parse_xyz("--up", a.up));
    o.fov = a.fov;
    apply_overrides(scene, o);
    return scene;
}

} // namespace tp
