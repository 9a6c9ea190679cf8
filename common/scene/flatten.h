// The render-ready form of a scene: flat arrays of the shared structs (shared/types.h) that
// the CPU engine reads directly and the Vulkan engine uploads as they are. Everything both
// engines must agree on (light list and selection table, instance transforms, camera,
// texture layout) is decided here, once.
#pragma once

#include "scene/scene.h"

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

    vec3 bounds_min{0.0f}, bounds_max{0.0f}; // world-space bounding box
    uint64_t instanced_triangles = 0;        // triangles as rendered (instances counted)
    uint64_t unique_triangles = 0;           // triangles stored

    const Material& material_of(uint32_t instance) const {
        return materials[instances[instance].material];
    }
};

// Throws InputError for an impossible camera or film.
FlatScene flatten(const Scene& scene);

} // namespace tp
