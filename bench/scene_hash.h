// Identity of a rendered image's inputs, for the reference cache: a hash of the flattened
// scene (every array both engines render from, the camera, film size, depths, spp and seed)
// and the renderer version (project version + the hash of the integrator sources,
// bench/renderer_version.cmake).
#pragma once

#include "scene/scene_hash.h"

#include <cstdint>
#include <string>

namespace tp::bench {

// 64-bit FNV-1a over the render parameters, spp and the scene's content (scene/scene_hash.h).
// Names are left out: they do not change the image.
uint64_t hash_flat_scene(const FlatScene& scene);

// "0.1.0+<16 hex digits>".
std::string renderer_version();

} // namespace tp::bench
