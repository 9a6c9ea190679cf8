// Scene loading entry points: native JSON (docs/scene-format.md), a plain OBJ file or glTF 2.0
// (.gltf, .glb), chosen by the file's extension, and the lookup of bundled scenes by name.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tp {

// A path to an existing file, or the name of a bundled scene ("cornell" finds
// scenes/cornell.json, or .gltf or .glb, next to the executable or in the source tree;
// TWINPATH_SCENES overrides).
std::string resolve_scene_path(const std::string& path_or_name);

// The file of the bundled scene `name` (scenes/NAME.json, .gltf or .glb, in that order), or
// nothing when `name` is a path or no bundled scene has that name.
std::optional<std::string> find_bundled_scene(const std::string& name);

struct LoadOptions {
    std::optional<uint32_t> camera; // a glTF file's cameras[N] (--camera N); an error otherwise
};

// Loads a .json, .obj, .gltf or .glb scene. Warnings (skipped triangles, ignored MTL
// statements, what a glTF file gives that is not rendered, defaults that were filled in) are
// appended to `warnings`. Throws InputError.
Scene load_scene(const std::string& path_or_name, std::vector<std::string>& warnings,
                 const LoadOptions& options = {});

// The directory the bundled scenes are read from.
std::string bundled_scenes_dir();

} // namespace tp
