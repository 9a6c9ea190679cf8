// The scene, film, camera and device flags that `render` and `view` share (docs/design.md,
// "Command line"), and the scene they describe.
#pragma once

#include "scene/flatten.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tp {

struct SceneArgs {
    std::string scene;
    std::optional<uint32_t> spp, width, height, min_depth, max_depth;
    uint32_t seed = 0, threads = 0;
    std::string sampler = "sobol";
    std::string device, vk_mode = "auto";
    std::string eye, target, up;
    std::optional<float> fov;
    std::optional<uint32_t> camera; // glTF: cameras[N]
};

// `vk_modes`: the words --vk-mode takes (verify adds "both").
void add_scene_options(CLI::App* c, SceneArgs& a,
                       const std::vector<std::string>& vk_modes = {"auto", "compute", "pipeline"});

// The `render` arguments that give the scene, film and camera these flags give (the scene as an
// absolute path when it is a file, so that they work from any directory), for commands that
// reproduce a render; `width` and `height` are the film's, always written.
std::vector<std::string> scene_render_args(const SceneArgs& a, uint32_t width, uint32_t height);

// Loads the scene (warnings on stderr) and applies the flags; `spp` replaces a missing --spp.
Scene load_scene_args(const SceneArgs& a, std::optional<uint32_t> spp = std::nullopt);

} // namespace tp
