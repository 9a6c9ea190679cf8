// Scene loading entry points: native JSON (docs/scene-format.md) or a plain OBJ file, and the
// lookup of bundled scenes by name.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace tp {

// A path to an existing file, or the name of a bundled scene ("cornell" finds
// scenes/cornell.json next to the executable or in the source tree; TWINPATH_SCENES overrides).
std::string resolve_scene_path(const std::string& path_or_name);

// Loads a .json or .obj scene. Warnings (skipped triangles, ignored MTL statements, defaults
// that were filled in) are appended to `warnings`. Throws InputError.
Scene load_scene(const std::string& path_or_name, std::vector<std::string>& warnings);

// The directory the bundled scenes are read from.
std::string bundled_scenes_dir();

} // namespace tp
