// The textures of glTF materials as the scene's images and texture slots (scene.h): each image
// decoded once into one scene image, whatever reads it; each textureInfo one slot (shared by
// equal ones) that holds its uv set, KHR_texture_transform and sampler. glTF's uv (0, 0) is the
// image's top-left corner, as twinpath's image coordinates: the slot's map is the extension's
// matrix on the uv as given, the identity without it.
#pragma once

#include "scene/gltf_document.h"
#include "scene/gltf_resources.h"
#include "scene/scene.h"

#include <map>
#include <string>
#include <vector>

namespace tp {

class GltfTextures {
  public:
    // Keeps references to all three.
    GltfTextures(const GltfDocument& d, const GltfResources& res, Scene& scene)
        : d_(d), res_(res), s_(scene) {}

    // The slot of textureInfo `ref`, with texels read as sRGB colour or as linear data, or
    // NO_TEXTURE with the reason in `dropped` (no image twinpath decodes: none, or one in a
    // format other than PNG and JPEG; a uv set beyond TEXCOORD_1); what a path tracer ignores
    // of its sampler goes to `ignored`.
    int slot(const GltfTextureRef& ref, bool srgb, std::vector<std::string>& dropped,
             std::vector<std::string>& ignored);

  private:
    const GltfDocument& d_;
    const GltfResources& res_;
    Scene& s_;
    static constexpr uint32_t kUndecoded = 0xFFFFFFFFu;
    std::map<uint32_t, uint32_t> image_of_source_;     // glTF image -> scene image, or kUndecoded
    std::map<uint32_t, std::string> undecoded_format_; // glTF image -> its format, if undecoded
};

// The slot's map from a uv to image coordinates for KHR_texture_transform's matrix: its first
// two rows (s = row 0 . (u, v, 1), t = row 1 . (u, v, 1)).
void gltf_slot_transform(const glm::dmat3& m, vec3& transform_s, vec3& transform_t);

} // namespace tp
