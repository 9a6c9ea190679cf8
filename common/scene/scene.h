// The scene as the loaders describe it: named materials, meshes, textures, objects (instances
// of meshes with a transform), explicit lights and the environment. flatten.h turns it into
// the arrays both engines render from.
//
// Positions are kept exactly as given, in double: mesh vertices, object translations, the
// camera's eye and target and point lights. A float at 1e4 m is a multiple of 2^-10 m (1 mm),
// so rounding them here would make a scene's image depend on where it sits; flatten() moves
// everything next to the camera first and rounds to float only then (flatten.h, FlatScene).
// Directions, colours and the rest are float: they do not depend on where the scene sits.
#pragma once

#include "image/texture.h"
#include "shared/types.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace tp {

struct Mesh {
    std::string name;
    std::vector<glm::dvec3> positions; // in the mesh's own space
    std::vector<vec3> normals;         // empty, or one per position
    std::vector<vec2> uvs;             // empty, or one per position: the first uv set, as given
    std::vector<vec2> uvs1;            // empty, or one per position: the second uv set
    std::vector<vec4> tangents;        // empty, or one per position: xyz and bitangent sign w
    std::vector<uvec3> triangles;
};

// An instance of a mesh. Objects that share a mesh store its triangles once.
struct Object {
    std::string name;
    uint32_t mesh = 0;
    uint32_t material = 0;
    glm::dmat4 transform{1.0}; // object to world
};

// An explicit light: a point or spot light at `position`, or a directional light.
struct LightDesc {
    uint32_t type = LIGHT_POINT; // LIGHT_POINT, LIGHT_SPOT or LIGHT_DIRECTIONAL
    glm::dvec3 position{0.0};    // point, spot: where it is
    vec3 direction{0.0f};        // directional: unit vector towards the light; spot: its axis,
                                 // the unit direction it shines along
    vec3 value{0.0f}; // point, spot: intensity (W/sr, on the axis); directional: irradiance (W/m^2)
    float inner_cone = 0.0f;         // spot: full intensity within this angle of the axis (rad)
    float outer_cone = 0.7853982f;   // spot: none beyond it (rad), pi / 4 by default
};

struct CameraDesc {
    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 target{0.0};
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
    std::vector<Texture> textures;          // the images
    std::vector<TextureSlot> texture_slots; // how materials read them (Material's *_texture)
    std::vector<Mesh> meshes;
    std::vector<Object> objects;
    std::vector<LightDesc> lights; // emitters and the environment are derived
    EnvironmentDesc environment;
    uint64_t skipped_triangles = 0; // degenerate triangles dropped while loading
    // What an imported format (glTF) gives and twinpath does not render, for `twinpath info`:
    // per material (parallel to `materials`, or empty) and for the scene as a whole.
    std::vector<std::vector<std::string>> material_dropped;
    std::vector<std::string> dropped;
    // What it gives that a path tracer has no use for (an occlusion texture, a sampler's
    // minification filter, a light's range), each with the reason: `twinpath info` lists them
    // as ignored. Parallel to `materials` or empty, as above.
    std::vector<std::vector<std::string>> material_ignored;
    std::vector<std::string> ignored;
};

// A material with every field at its neutral value: black Phong, ior 1.5, tf 1, opaque, no
// texture; the PBR fields at glTF's defaults where a Phong material ignores them.
Material default_material();

// glTF's default material (glTF 2.0, section 3.9.6): white base colour, metallic 1, roughness 1.
Material default_pbr_material();

// Checks what a material must satisfy (finite, non-negative, kd + ks <= 1 per channel,
// ns >= 0, ior > 0; PBR: base colour, metallic, roughness, transmission, specular and alpha in
// [0, 1], attenuation distance > 0) and throws InputError naming `where` otherwise.
void validate_material(const Material& m, const std::string& where);

// A scene in which nothing emits light (no explicit light, no emissive material an object
// uses, no environment) is lit by a constant white environment of radiance 1, with a warning:
// OBJ and glTF files often carry no lights.
void light_if_unlit(Scene& scene, std::vector<std::string>& warnings);

// A texture slot reading image `image` with uv -> (s, t) the affine map given by its two rows,
// and the sampling bits (SLOT_*, shared/types.h).
TextureSlot make_texture_slot(uint32_t image, vec3 transform_s, vec3 transform_t,
                              uint32_t sampling);

// The slot of an OBJ/MTL or JSON texture: OBJ's uv convention (v = 0 at the bottom row:
// s = u, t = 1 - v), repeat, bilinear, the first uv set; `srgb` for a colour texture.
TextureSlot obj_texture_slot(uint32_t image, bool srgb);

// Drops zero-area triangles (counted in scene.skipped_triangles) and checks indices and that
// every attribute is finite; `where` names the source in error messages.
void finalize_mesh(Mesh& mesh, const std::string& where, uint64_t& skipped_triangles);

} // namespace tp
