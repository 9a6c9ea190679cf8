// Wavefront OBJ + MTL. The parser is our own and strict: tinyobjloader (Debian's) reads a
// malformed number such as "1 zz 0" as 0 without an error, and every malformed line here must
// fail with its file and line number (docs/design.md, "Files").
//
// MTL mapping (docs/design.md): Kd diffuse, Ks + Ns Phong specular, Ke emission, illum 3 mirror
// (Ks tint), illum 7 glass (Ni index of refraction, Tf tint), map_Kd texture (multiplies Kd).
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace tp {

struct ObjPart {
    uint32_t mesh;
    uint32_t material;
};

// Appends the OBJ's meshes (one per `usemtl` group, so each mesh has one material) and its
// materials to `scene`; returns the parts. Unknown MTL statements are reported once each in
// `warnings`. `default_material` is used for faces without a material.
std::vector<ObjPart> load_obj(const std::string& path, Scene& scene, uint32_t default_material,
                              std::vector<std::string>& warnings);

} // namespace tp
