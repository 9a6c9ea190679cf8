// The scene-size table of a `twinpath bench --sizes --scene-sizes` result (bench/scenes.h,
// SizedScene): for each scene of N distinct meshes, in order of triangles, each backend and
// mode's Mrays/s and build seconds at one image size.
#pragma once

#include "bench/sizes.h"

#include <nlohmann/json.hpp>

#include <string>

namespace tp::lab {

// The table at `size`, with a line that says what it shows; empty when the result has no sized
// scene.
std::string scene_sizes_table(const nlohmann::json& result, const bench::ImageSize& size);

} // namespace tp::lab
