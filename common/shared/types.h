// Structs that cross the host/device boundary. GLSL declares its buffers with
// `layout(scalar)` (GL_EXT_scalar_block_layout), where a vec3 takes 12 bytes with 4-byte
// alignment, exactly like glm::vec3; the static_asserts below pin the C++ side to that layout.
// Members are ordered so that every struct is also a multiple of 16 bytes.
#ifndef TP_SHARED_TYPES_H
#define TP_SHARED_TYPES_H

#include "lang.h"

TP_NAMESPACE_BEGIN

const uint NO_INDEX = 0xFFFFFFFFu;
const int NO_TEXTURE = -1;

// ---- materials ---------------------------------------------------------------------------
const uint MATERIAL_PHONG = 0u;      // modified Phong, Lafortune & Willems 1994
const uint MATERIAL_MIRROR = 1u;     // perfect specular reflection tinted by ks
const uint MATERIAL_DIELECTRIC = 2u; // smooth dielectric: Fresnel reflection + refraction

struct Material {
    vec3 kd;        // diffuse reflectance; multiplied by texture kd_texture when it is set
    int kd_texture; // index into the texture table or NO_TEXTURE
    vec3 ks;        // Phong specular reflectance, or the mirror's tint
    float ns;       // Phong exponent
    vec3 ke;        // emitted radiance (W m^-2 sr^-1), front face only
    float ior;      // dielectric index of refraction relative to the outside
    vec3 tf;        // dielectric transmission filter
    uint type;      // MATERIAL_*
};

// ---- lights ------------------------------------------------------------------------------
const uint LIGHT_POINT = 0u;       // p0 position, value intensity I (W/sr)
const uint LIGHT_DIRECTIONAL = 1u; // p0 unit direction towards the light, value irradiance (W/m^2)
const uint LIGHT_TRIANGLE = 2u;    // p0..p2 world vertices (CCW = front), value radiance
const uint LIGHT_ENVIRONMENT = 3u; // value radiance scale; RenderParams holds the map

struct Light {
    vec3 p0;
    uint type;
    vec3 p1;
    float area; // triangle area (m^2)
    vec3 p2;
    uint instance; // triangle: the instance it belongs to
    vec3 value;
    uint primitive; // triangle: its index inside the instance's mesh
    vec3 normal;    // triangle: triangle_light_normal(p0, p1, p2), computed once at load
    uint pad0;
};

// One slot of a Walker/Vose alias table (lights, environment-map pixels).
struct AliasEntry {
    float prob; // probability of keeping this slot rather than jumping to `alias`
    uint alias;
    float pdf; // probability of picking this item overall
};

// ---- geometry ----------------------------------------------------------------------------
const uint MESH_HAS_NORMALS = 1u;
const uint MESH_HAS_UVS = 2u;

struct MeshInfo {
    uint first_triangle; // into the triangle-index array
    uint first_vertex;   // into the position / normal / uv arrays
    uint triangle_count;
    uint vertex_count;
    uint flags;    // MESH_HAS_*
    uint bvh_root; // compute mode: index of this mesh's bottom-level root node
    uint pad0;
    uint pad1;
};

struct Instance {
    vec4 to_world0; // rows of the 3x4 object-to-world matrix
    vec4 to_world1;
    vec4 to_world2;
    vec4 to_object0; // rows of its inverse (its transpose maps normals to world)
    vec4 to_object1;
    vec4 to_object2;
    uint mesh;
    uint material;
    uint light_offset; // light index of the mesh's triangle 0 when emissive, else NO_INDEX
    uint pad0;
};

// ---- textures ----------------------------------------------------------------------------
struct TextureInfo {
    uint offset; // first texel (RGB float) in the texel array
    uint width;
    uint height;
    uint pad0;
};

// ---- camera and render parameters ---------------------------------------------------------
struct Camera {
    vec3 eye;
    float tan_half_fov_y;
    vec3 forward; // unit
    float aspect; // width / height
    vec3 right;   // unit
    uint width;
    vec3 up; // unit, orthogonal to forward and right
    uint height;
};

struct RenderParams {
    Camera camera;
    uint seed;
    uint max_depth; // maximum number of scattering events (pbrt's maxdepth)
    uint min_depth; // Russian roulette starts after this many
    uint light_count;
    uint env_light;        // index of the environment in the light list, or NO_INDEX
    int env_texture;       // lat-long radiance map, or NO_TEXTURE for a constant environment
    uint env_alias_offset; // first entry of the map's pixel alias table
    float env_rotation;    // rotation of the map about +Y (radians)
    uint sampler_id;       // SAMPLER_* (rng.h)
    uint pad0;
    uint pad1;
    uint pad2;
};

#ifdef __cplusplus
static_assert(sizeof(Material) == 64 && offsetof(Material, type) == 60, "Material layout");
static_assert(sizeof(Light) == 80 && offsetof(Light, normal) == 64, "Light layout");
static_assert(sizeof(AliasEntry) == 12, "AliasEntry layout");
static_assert(sizeof(MeshInfo) == 32, "MeshInfo layout");
static_assert(sizeof(Instance) == 112 && offsetof(Instance, mesh) == 96, "Instance layout");
static_assert(sizeof(TextureInfo) == 16, "TextureInfo layout");
static_assert(sizeof(Camera) == 64 && offsetof(Camera, height) == 60, "Camera layout");
static_assert(sizeof(RenderParams) == 112 && offsetof(RenderParams, sampler_id) == 96,
              "RenderParams layout");
#endif

TP_NAMESPACE_END

#endif // TP_SHARED_TYPES_H
