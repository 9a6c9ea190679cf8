// The native JSON scene format, documented in docs/scene-format.md. Every error names the file
// and the field path (for example `materials.white.Kd[1]`).
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace tp {

Scene load_json_scene(const std::string& path, std::vector<std::string>& warnings);

} // namespace tp
