// glTF 2.0 (.gltf with its files, or .glb) into the scene model (scene.h), so that both engines
// render it as any other scene (docs/scene-format.md, "glTF 2.0"):
//   - the default scene's node hierarchy: each node's world transform is the product of its
//     ancestors' transforms and its own; each primitive of a mesh becomes one Mesh, stored once
//     however many nodes use it, and each node that uses it one Object (instancing);
//   - triangles, strips and fans with positions, normals, and the uv sets and tangents its
//     material's texture slots read (flat normals and generated tangents where a normal map
//     needs them and the file has none: tangents.h); points and lines are dropped;
//   - the materials as MATERIAL_PBR, glTF's own BSDF (gltf_material.h), every texture a slot
//     (gltf_textures.h);
//   - a perspective camera: the first one the hierarchy places, or `camera` (--camera N);
//   - KHR_lights_punctual point, spot and directional lights in radiometric units.
// What is not rendered is listed in Scene::dropped and Scene::material_dropped, what a path
// tracer has no use for in Scene::ignored and Scene::material_ignored (twinpath info); the
// first are summarized in one warning. Errors name the file and the field.
#pragma once

#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace tp {

struct GltfOptions {
    std::optional<uint32_t> camera; // glTF cameras[N]; default: the first the scene places
};

// glTF's lights are photometric, twinpath's radiometric: converted as Blender's importer does
// in its default mode ("Standard", io_scene_gltf2 PBR_WATTS_TO_LUMENS), at 683 lm/W, the
// luminous efficacy of 555 nm light that defines the candela.
constexpr double kGltfLumensPerWatt = 683.0;

// KHR_lights_punctual's color x intensity in twinpath's units: candela (point and spot lights)
// to radiant intensity in W/sr, lux (directional lights) to irradiance in W/m^2. (Blender makes
// a point light of c/683 * 4 pi W from c candela, and its point light of P W has intensity
// P / (4 pi) W/sr.)
vec3 gltf_light_value(vec3 color, double intensity);

Scene load_gltf_scene(const std::string& path, const GltfOptions& options,
                      std::vector<std::string>& warnings);

} // namespace tp
