#include "scene_args.h"

#include "arg_parse.h"

#include "scene/load.h"

#include <fmt/core.h>

#include <filesystem>

namespace tp {

void add_scene_options(CLI::App* c, SceneArgs& a, const std::vector<std::string>& vk_modes) {
    c->add_option("scene", a.scene, "Scene file or bundled scene name")->required();
    c->add_option("--vk-mode", a.vk_mode, "Vulkan mode")->check(CLI::IsMember(vk_modes));
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

std::vector<std::string> scene_render_args(const SceneArgs& a, uint32_t width, uint32_t height) {
    std::error_code ec;
    const bool file = std::filesystem::is_regular_file(a.scene, ec);
    std::vector<std::string> args = {file ? std::filesystem::absolute(a.scene).string() : a.scene,
                                     "--width", std::to_string(width), "--height",
                                     std::to_string(height)};
    auto flag = [&](const char* name, const std::string& value) {
        args.push_back(name);
        args.push_back(value);
    };
    if (a.min_depth) flag("--min-depth", std::to_string(*a.min_depth));
    if (a.max_depth) flag("--max-depth", std::to_string(*a.max_depth));
    if (!a.eye.empty()) flag("--eye", a.eye);
    if (!a.target.empty()) flag("--target", a.target);
    if (!a.up.empty()) flag("--up", a.up);
    if (a.fov) flag("--fov", fmt::format("{}", *a.fov));
    if (a.camera) flag("--camera", std::to_string(*a.camera));
    return args;
}

} // namespace tp
