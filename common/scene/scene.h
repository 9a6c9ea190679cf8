// The scene as the loaders describe it: named materials, meshes, textures, objects (instances
// of meshes with a transform), explicit lights and the environment. flatten.h turns it into
// the arrays both engines render from.
#pragma once

#include "shared/types.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

namespace tp {

struct Texture {
    std::string name;
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<vec3> texels; // linear RGB, rows top to bottom
};

struct Mesh {
    std::string name;
    std::vector<vec3> positions;
    std::vector<vec3> normals; // empty, or one per position
    std::vector<vec2> uvs;     // empty, or one per position
    std::vector<uvec3> triangles;
};

// An instance of a mesh. Objects that share a mesh store its triangles once.
struct Object {
    std::string name;
    uint32_t mesh = 0;
    uint32_t material = 0;
    glm::mat4 transform{1.0f}; // object to world
};

struct CameraDesc {
    vec3 eye{0.0f, 0.0f, 5.0f};
    vec3 target{0.0f};
    vec3 up{0.0f, 1.0f, 0.0f};
    float fov_y_degrees = 45.0f;
    bool given = false; // false: frame the scene automatically
};

enum class EnvironmentKind { None, Constant, Map };

struct EnvironmentDesc {
    EnvironmentKind kind = EnvironmentKind::None;
    vec3 radiance{0.0f}; // constant radiance, or the map's scale
    int texture = NO_TEXTURE;
    float rotation_degrees = 0.0f; // about +Y
};

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t spp = 64;
    uint32_t max_depth = 8;
    uint32_t min_depth = 3;
};

struct Scene {
    std::string path; // where it was loaded from (or the bundled name)
    CameraDesc camera;
    RenderSettings settings;
    std::vector<Material> materials;
    std::vector<std::string> material_names;
    std::vector<Texture> textures;
    std::vector<Mesh> meshes;
    std::vector<Object> objects;
    std::vector<Light> lights; // point and directional; emitters and environment are derived
    EnvironmentDesc environment;
    uint64_t skipped_triangles = 0; // degenerate triangles dropped while loading
};

// A material with every field at its neutral value: black Phong, ior 1.5, tf 1.
Material default_material();

// Checks what a material must satisfy (finite, non-negative, kd + ks <= 1 per channel,
// ns >= 0, ior > 0) and throws InputError naming `where` otherwise.
void validate_material(const Material& m, const std::string& where);

// Drops zero-area triangles (counted in scene.skipped_triangles) and checks indices and that
// every attribute is finite; `where` names the source in error messages.
void finalize_mesh(Mesh& mesh, const std::string& where, uint64_t& skipped_triangles);

} // namespace tp
