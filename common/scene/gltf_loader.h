// glTF 2.0 (.gltf with its files, or .glb) into the scene model (scene.h), so that both engines
// render it as any other scene (docs/scene-format.md, "glTF 2.0"):
//   - the default scene's node hierarchy: each node's world transform is the product of its
//     ancestors' transforms and its own; each primitive of a mesh becomes one Mesh, stored once
//     however many nodes use it, and each node that uses it one Object (instancing);
//   - triangles, strips and fans with positions, normals and one uv set (the one the base
//     colour texture reads); points and lines are dropped;
//   - the materials by gltf_material.h's rule, with base colour textures;
//   - a perspective camera: the first one the hierarchy places, or `camera` (--camera N);
//   - KHR_lights_punctual point and directional lights; a spot light is an error.
// What is not rendered is listed in Scene::dropped and Scene::material_dropped (twinpath info)
// and summarized in one warning. Errors name the file and the field.
#pragma once

#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace tp {

struct GltfOptions {
    std::optional<uint32_t> camera; // glTF cameras[N]; default: the first the scene places
};

Scene load_gltf_scene(const std::string& path, const GltfOptions& options,
                      std::vector<std::string>& warnings);

} // namespace tp
