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

// Command-line overrides of the scene's own settings (DESIGN.md, command line).
struct SceneOverrides {
    std::optional<uint32_t> width, height, spp, max_depth, min_depth;
    std::optional<vec3> eye, target, up;
    std::optional<float> fov;
};

void apply_overrides(Scene& scene, const SceneOverrides& o);

// The float32 range rule (docs/scene-format.md, "Range"): no vertex farther than 2^36 m (6.9e10
// m) from the camera in any coordinate, in the world or in its object's space. The triangle
// test's distance (shared/intersect.h) forms (v0 - o) . ((v1 - v0) x (v2 - v0)), cubic in the
// coordinates: with every coordinate within R, |.| <= (2 sqrt(3) R)^3 = 42 R^3, below float's
// 2^128 up to R = 2^40.9; 2^36 leaves a factor 2^14 for the light and offset arithmetic.
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
    std::vector<uvec3> triangles; // mesh-local vertex indices
    std::vector<Instance> instances;
    std::vector<std::string> instance_names;

    std::vector<Light> lights;
    std::vector<AliasEntry> light_table; // one entry per light: selection by power
    std::vector<TextureInfo> textures;
    std::vector<vec3> texels;
    std::vector<AliasEntry> env_table; // environment-map pixels, when there is a map

    // World space as both engines see it is camera-relative ("large world coordinates"): the
    // scene's point x is stored as x - origin, computed in double and rounded to float once, with
    // origin the camera's eye. A float's spacing is proportional to its magnitude, so positions
    // then keep the precision of their distance to the camera wherever the scene lies: at 1e5
    // from the scene's own origin, float coordinates are multiples of 2^-7 = 0.0078 and round by
    // up to a tenth of a pixel in the stress scene (docs/stress.md); camera-relative, by ~1e-7.
    // Instance translations, the camera, point lights, emissive triangles and the bounds are
    // rebased; directions (normals, directional lights, the environment) are unchanged. Positions
    // shown to the user (path logs) add origin back.
    glm::dvec3 origin{0.0};
    vec3 bounds_min{0.0f}, bounds_max{0.0f}; // world-space bounding box (camera-relative)
    uint64_t instanced_triangles = 0;        // triangles as rendered (instances counted)
    uint64_t unique_triangles = 0;           // triangles stored
    // Coincident dielectric faces merged into interfaces (dielectric_interfaces.h).
    uint64_t dielectric_interfaces = 0;

    const Material& material_of(uint32_t instance) const {
        return materials[instances[instance].material];
    }
};

// Coincident faces of touching dielectrics become one interface each (dielectric_interfaces.h).
// Throws InputError for an impossible camera or film, or geometry beyond kMaxWorldRange.
FlatScene flatten(const Scene& scene);

// How many instances use each mesh: more than one is instancing (FEATURE_INSTANCING), and the
// CPU engine instances exactly those meshes (cpu_ref/embree_accel.cpp).
std::vector<uint32_t> instances_per_mesh(const FlatScene& scene);

} // namespace tp
