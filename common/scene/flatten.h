// The render-ready form of a scene: flat arrays of the shared structs (shared/types.h) that
// the CPU engine reads directly and the Vulkan engine uploads as they are. Everything both
// engines must agree on (light list and selection table, instance transforms, camera,
// texture layout) is decided here, once.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace tp {

// Command-line overrides of the scene's own settings (docs/design.md, command line).
struct SceneOverrides {
    std::optional<uint32_t> width, height, spp, max_depth, min_depth;
    std::optional<glm::dvec3> eye, target; // positions: double, as the scene keeps them
    std::optional<vec3> up;
    std::optional<float> fov;
};

void apply_overrides(Scene& scene, const SceneOverrides& o);

// The float32 range rule (docs/scene-format.md, "Range"): no vertex farther than 2^36 m (6.9e10
// m) from the camera in any coordinate, and no object larger than that in its own space: no
// vertex farther than 2^36 from the lowest corner of its mesh's bounding box in any coordinate
// (the float coordinates the engines store, FlatScene::positions). The triangle test's distance
// (shared/intersect.h) forms (v0 - o) . ((v1 - v0) x (v2 - v0)), cubic in the coordinates: with
// every coordinate within R, |.| <= (2 sqrt(3) R)^3 = 42 R^3, below float's 2^128 up to
// R = 2^40.9; 2^36 leaves a factor 2^14 for the light and offset arithmetic.
constexpr double kMaxWorldRange = 0x1p36;

struct FlatScene {
    std::string name;
    RenderParams params{}; // seed is set by the renderer
    uint32_t spp = 0;

    std::vector<Material> materials;
    std::vector<MeshInfo> meshes;
    std::vector<vec3> positions;
    std::vector<vec3> normals;    // parallel to positions (zero where a mesh has none)
    std::vector<vec2> uvs;        // parallel to positions (zero where a mesh has none)
    std::vector<vec2> uvs1;       // empty, or parallel to positions: the second uv set
    std::vector<vec4> tangents;   // empty, or parallel to positions: normal maps' tangents
    std::vector<uvec3> triangles; // mesh-local vertex indices
    std::vector<Instance> instances;
    std::vector<std::string> instance_names;

    std::vector<Light> lights;
    std::vector<AliasEntry> light_table; // one entry per light: selection by power
    std::vector<TextureInfo> textures;   // the images: sizes and formats
    std::vector<Texture> images;         // their texels (shared with the Scene's, not copied)
    std::vector<TextureSlot> texture_slots;  // how materials read the images
    std::vector<AliasEntry> env_table; // environment-map pixels, when there is a map

    // World space as both engines see it is camera-relative ("large world coordinates"): the
    // scene's point x is stored as x - origin, with origin the camera's eye, computed in double
    // from the scene's double description (scene/scene.h) and rounded to float once. A float's
    // spacing is proportional to its magnitude, so the world then keeps the precision of its
    // distance to the camera wherever the scene lies. Each mesh's positions are stored relative
    // to the lowest corner c of its own bounding box (rounded by 2^-24 of the mesh's size), and
    // each instance's translation is M c + (T - origin) (rounded by 2^-24 of the distance to the
    // camera). These are differences of the description's numbers (and the lowest corner moves
    // with the vertices exactly, where a centre would round), so a scene and its camera moved
    // together by any d that keeps those numbers exact (x + d - d == x) flatten to the same
    // floats and render the same image bit for bit. Instance translations, the camera,
    // point lights, emissive triangles and the bounds are rebased; directions (normals,
    // directional lights, the environment) are unchanged. Path logs record camera-relative
    // positions too, with origin in their header (docs/debugging.md).
    glm::dvec3 origin{0.0};
    vec3 bounds_min{0.0f}, bounds_max{0.0f}; // world bounding box (camera-relative)
    uint64_t instanced_triangles = 0;        // triangles as rendered (instances counted)
    uint64_t unique_triangles = 0;           // triangles stored
    // Coincident dielectric faces merged into interfaces (dielectric_interfaces.h).
    uint64_t dielectric_interfaces = 0;

    const Material& material_of(uint32_t instance) const {
        return materials[instances[instance].material];
    }
};

// Texel i of image `image` in linear values, as the engines decode it (shared/texture.h):
// integer texels sRGB-decoded where `srgb`.
vec4 flat_texel_linear(const FlatScene& scene, uint32_t image, size_t i, bool srgb);

// Coincident faces of touching dielectrics become one interface each (dielectric_interfaces.h).
// Throws InputError for an impossible camera or film, or geometry beyond kMaxWorldRange.
FlatScene flatten(const Scene& scene);

// How many instances use each mesh: more than one is instancing (FEATURE_INSTANCING), and the
// CPU engine instances exactly those meshes (cpu_ref/embree_accel.cpp).
std::vector<uint32_t> instances_per_mesh(const FlatScene& scene);

} // namespace tp
