// The JSON part of a glTF 2.0 asset, read strictly into plain structs: every property twinpath
// uses is checked for its type, its range and, for indices, that it names an existing element,
// and an error names the file and the field (`accessors[3].count`). Structural rules that need
// no buffer data are checked here too: a buffer view inside its buffer, an accessor inside its
// buffer view, the node hierarchy a forest, the required extensions supported. Properties that
// twinpath does not render (animations, skins, morph targets, ...) are recorded so that the
// loader can say what it dropped.
//
// tinygltf's own parser is not used for this: it skips optional properties of the wrong type
// without a word (`"mesh": "0"` leaves a node without its mesh) and its messages do not name
// the element. The glTF 2.0 specification is https://registry.khronos.org/glTF/specs/2.0/.
#pragma once

#include "shared/lang.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace tp {

constexpr int GLTF_NONE = -1;

// glTF component types (accessor.componentType).
constexpr uint32_t GLTF_BYTE = 5120, GLTF_UNSIGNED_BYTE = 5121, GLTF_SHORT = 5122,
                   GLTF_UNSIGNED_SHORT = 5123, GLTF_UNSIGNED_INT = 5125, GLTF_FLOAT = 5126;

struct GltfBuffer {
    uint64_t byte_length = 0;
    std::string uri; // empty: the GLB's BIN chunk (buffer 0 of a .glb only)
};

struct GltfBufferView {
    uint32_t buffer = 0;
    uint64_t byte_offset = 0;
    uint64_t byte_length = 0;
    uint32_t byte_stride = 0; // 0: elements are tightly packed
};

struct GltfAccessor {
    int buffer_view = GLTF_NONE; // none: all zeros (before sparse substitution)
    uint64_t byte_offset = 0;
    uint32_t component_type = GLTF_FLOAT;
    bool normalized = false;
    uint32_t count = 0;
    uint32_t components = 1; // SCALAR 1, VEC2 2, VEC3 3, VEC4 4, MAT2 4, MAT3 9, MAT4 16
    std::string type;        // "SCALAR", "VEC3", ...
    // Sparse storage: `sparse_count` elements replaced, at the indices read from
    // `sparse_indices_view`, by the values read from `sparse_values_view`.
    uint32_t sparse_count = 0;
    int sparse_indices_view = GLTF_NONE;
    uint64_t sparse_indices_offset = 0;
    uint32_t sparse_indices_type = GLTF_UNSIGNED_INT;
    int sparse_values_view = GLTF_NONE;
    uint64_t sparse_values_offset = 0;
};

struct GltfImage {
    std::string uri;             // a relative file path or a data: URI; empty with a buffer view
    int buffer_view = GLTF_NONE; // the image's bytes in a buffer
    std::string mime_type;
};

struct GltfTexture {
    int source = GLTF_NONE; // image; none when only an extension (KTX2, WebP) gives the image
    int sampler = GLTF_NONE;
    std::vector<std::string> source_extensions; // extensions of the texture (KHR_texture_basisu)
};

// glTF sampler constants (section 5.26).
constexpr uint32_t GLTF_NEAREST = 9728, GLTF_LINEAR = 9729, GLTF_REPEAT = 10497,
                   GLTF_CLAMP_TO_EDGE = 33071, GLTF_MIRRORED_REPEAT = 33648;

struct GltfSampler {
    uint32_t mag_filter = 0, min_filter = 0;             // 0: undefined
    uint32_t wrap_s = GLTF_REPEAT, wrap_t = GLTF_REPEAT; // checked to be a glTF wrap mode
};

// A textureInfo: a texture, its uv set and KHR_texture_transform; texture GLTF_NONE when the
// material does not give it.
struct GltfTextureRef {
    int texture = GLTF_NONE;
    uint32_t tex_coord = 0;    // KHR_texture_transform's texCoord where it gives one
    glm::dmat3 transform{1.0}; // uv -> uv: T(offset) R(rotation) S(scale), as the extension
    std::string field;         // where it was given: "materials[2].emissiveTexture"
};

// A glTF material's parameters: the metallic-roughness model and the extensions twinpath reads,
// defaults as the specification gives them.
struct GltfMaterial {
    std::string name;
    vec3 base_color{1.0f};
    float base_alpha = 1.0f;
    GltfTextureRef base_color_texture;
    float metallic = 1.0f;
    float roughness = 1.0f;
    GltfTextureRef metallic_roughness_texture;
    GltfTextureRef normal_texture;
    float normal_scale = 1.0f; // normalTexture.scale
    vec3 emissive{0.0f};
    GltfTextureRef emissive_texture;
    float emissive_strength = 1.0f; // KHR_materials_emissive_strength
    std::string alpha_mode = "OPAQUE";
    float alpha_cutoff = 0.5f;
    float transmission = 0.0f; // KHR_materials_transmission
    GltfTextureRef transmission_texture;
    float ior = 1.5f;      // KHR_materials_ior; 0 is its specular-glossiness mode (infinite ior)
    float specular = 1.0f; // KHR_materials_specular
    GltfTextureRef specular_texture;
    vec3 specular_color{1.0f};
    GltfTextureRef specular_color_texture;
    float thickness = 0.0f; // KHR_materials_volume: 0 is thin-walled
    vec3 attenuation_color{1.0f};
    float attenuation_distance = std::numeric_limits<float>::infinity();
    // What the material gives that a path tracer has no use for, as property names
    // ("occlusionTexture"), and what it gives that twinpath does not read (extensions).
    std::vector<std::string> ignored;
    std::vector<std::string> unused;
};

struct GltfPrimitive {
    std::map<std::string, uint32_t> attributes; // semantic -> accessor
    int indices = GLTF_NONE;
    int material = GLTF_NONE;
    uint32_t mode = 4; // TRIANGLES
    bool morph_targets = false;
};

struct GltfMesh {
    std::string name;
    std::vector<GltfPrimitive> primitives;
};

struct GltfNode {
    std::string name;
    int mesh = GLTF_NONE;
    int camera = GLTF_NONE;
    int light = GLTF_NONE; // KHR_lights_punctual
    bool skin = false;
    std::vector<uint32_t> children;
    glm::dmat4 local{1.0}; // matrix, or T * R * S
};

struct GltfCamera {
    std::string name;
    bool perspective = true;
    double yfov = 0.0;         // radians
    double aspect_ratio = 0.0; // 0: not given
};

struct GltfLight {
    std::string name;
    std::string type; // point, spot, directional
    vec3 color{1.0f};
    float intensity = 1.0f; // candela (point, spot) or lux (directional)
    bool has_range = false;
    float inner_cone = 0.0f;       // spot.innerConeAngle (radians)
    float outer_cone = 0.7853982f; // spot.outerConeAngle, pi / 4 by default
};

struct GltfDocument {
    std::string path;
    std::vector<std::string> extensions_used, extensions_required;
    std::vector<GltfBuffer> buffers;
    std::vector<GltfBufferView> buffer_views;
    std::vector<GltfAccessor> accessors;
    std::vector<GltfImage> images;
    std::vector<GltfSampler> samplers;
    std::vector<GltfTexture> textures;
    std::vector<GltfMaterial> materials;
    std::vector<GltfMesh> meshes;
    std::vector<GltfNode> nodes;
    std::vector<GltfCamera> cameras;
    std::vector<GltfLight> lights;
    std::vector<std::vector<uint32_t>> scenes; // each scene's root nodes
    int scene = GLTF_NONE;                     // the default scene
    size_t animations = 0, skins = 0;
};

// The extensions twinpath reads; any other in extensionsRequired is an error.
const std::vector<std::string>& gltf_supported_extensions();

// Bytes of one component of `component_type` (0 for an unknown type).
uint32_t gltf_component_size(uint32_t component_type);

// Reads and checks the glTF JSON `root` of the file `path`; `is_glb` allows buffer 0 without a
// uri (the BIN chunk). Throws InputError naming the file and the field.
GltfDocument read_gltf_document(const std::string& path, const nlohmann::json& root, bool is_glb);

} // namespace tp
