// A glTF 2.0 material as twinpath's MATERIAL_PBR: the engines render glTF's own BSDF
// (shared/pbr.h, glTF 2.0 Appendix B with KHR_materials_ior, _specular, _transmission and
// _volume), so the mapping copies the factors one for one; docs/scene-format.md ("glTF
// materials") states it as a table. Pure: no I/O. The texture slots are the loader's
// (gltf_loader.cpp): which textureInfo feeds which Material field is gltf_material_textures.
#pragma once

#include "scene/gltf_document.h"
#include "shared/types.h"

#include <string>
#include <vector>

namespace tp {

// KHR_materials_ior's ior 0 (its specular-glossiness mode) stands for an infinite index, whose
// Fresnel term is 1 at every angle; rendered with this one, whose f0 is within 4e-6 of 1.
constexpr float kGltfInfiniteIor = 1e6f;

struct GltfMaterialMapping {
    Material material{};              // every texture field NO_TEXTURE: the loader sets them
    std::vector<std::string> ignored; // what a path tracer has no use for, with the reason
    std::vector<std::string> dropped; // what twinpath does not render, one entry each
};

// The material satisfies validate_material (scene.h) for every input read_gltf_document accepts.
GltfMaterialMapping map_gltf_material(const GltfMaterial& m);

// One texture a glTF material reads: its textureInfo, the Material field whose slot it becomes,
// and whether its texels are sRGB-encoded colour (glTF 2.0, section 3.9: base colour, emissive,
// and KHR_materials_specular's colour) or linear data.
struct GltfTextureUse {
    const GltfTextureRef* ref;
    int Material::*field;
    bool srgb;
    const char* name; // "baseColorTexture", for twinpath info
};

// The textures `m` gives (those with a texture index), in a fixed order.
std::vector<GltfTextureUse> gltf_material_textures(const GltfMaterial& m);

} // namespace tp
