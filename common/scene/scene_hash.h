// Fingerprints of a flattened scene (64-bit FNV-1a, util/fnv1a.h): what a render sees of its
// scene, so that `twinpath merge` can refuse parts of different scenes (docs/farm.md), and what
// it renders, which keys the bench reference cache (docs/bench.md).
#pragma once

#include "scene/flatten.h"
#include "util/fnv1a.h"

#include <cstdint>
#include <string>

namespace tp {

// Adds every array both engines render from (materials, meshes, vertices, triangles,
// instances, lights, alias tables, textures) and the environment's parameters; not the camera,
// seed, depths or spp. The shared structs have no implicit padding (shared/types.h pins their
// layout) and flatten() value-initializes their pad fields, so their bytes are their values.
// Positions are camera-relative (FlatScene::origin): a moved camera changes them too.
void add_scene_content(Fnv1a& h, const FlatScene& scene);

// add_scene_content alone, as 16 hexadecimal digits (twinpath:scene_hash).
std::string scene_hash(const FlatScene& scene);

// add_scene_content after the render parameters (camera, film size, depths, seed, ...) and the
// spp: everything a render of the flattened scene depends on besides the renderer itself.
uint64_t render_inputs_hash(const FlatScene& scene);

} // namespace tp
