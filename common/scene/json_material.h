// A material of the native JSON scene format (docs/scene-format.md, "materials"): phong, mirror
// and dielectric with the MTL's spelling, and pbr, glTF's metallic-roughness material with its
// extensions (shared/pbr.h) spelt in snake case. Textures name entries of the scene's
// "textures" table; each becomes a texture slot with OBJ's uv convention (obj_texture_slot).
#pragma once

#include "scene/json_reader.h"
#include "scene/scene.h"

#include <map>
#include <string>

namespace tp {

// Reads the material at `field` ("materials.name"); `textures` maps the table's names to scene
// images; slots are added to `scene`. The material satisfies validate_material.
Material read_json_material(const JsonReader& r, const nlohmann::json& j, const std::string& field,
                            const std::map<std::string, uint32_t>& textures, Scene& scene);

} // namespace tp
