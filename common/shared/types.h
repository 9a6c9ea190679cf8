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
// A material's texture slots, in the order the scene reads apply them (scene_access.h,
// material_texture): base colour, metallic-roughness, emission, transmission, specular, specular
// colour, normal map.
const uint MATERIAL_TEXTURE_SLOTS = 7u;

// ---- materials ---------------------------------------------------------------------------
const uint MATERIAL_PHONG = 0u;      // modified Phong, Lafortune & Willems 1994
const uint MATERIAL_MIRROR = 1u;     // perfect specular reflection tinted by ks
const uint MATERIAL_DIELECTRIC = 2u; // smooth dielectric: Fresnel reflection + refraction
const uint MATERIAL_PBR = 3u;        // glTF 2.0 metallic-roughness (pbr.h)

// Material::flags
const uint MATERIAL_FLAG_VOLUME = 1u; // PBR: a volume boundary (KHR_materials_volume), not thin

// Material::alpha_mode: glTF's alphaMode, alpha as coverage (alpha.h)
const uint ALPHA_OPAQUE = 0u;
const uint ALPHA_MASK = 1u;  // the surface is there where alpha >= alpha_cutoff
const uint ALPHA_BLEND = 2u; // the surface is there with probability alpha

// Every material kind uses the first 64 bytes; MATERIAL_PBR reads the rest too. A texture field
// is an index into the texture-slot table (TextureSlot) or NO_TEXTURE.
struct Material {
    vec3 kd;        // diffuse reflectance; PBR: base colour (linear RGB)
    int kd_texture; // multiplies kd: map_Kd, baseColorTexture (its alpha multiplies alpha)
    vec3 ks;        // Phong specular reflectance; the mirror's tint; PBR: specular colour
    float ns;       // Phong exponent
    vec3 ke;        // emitted radiance (W m^-2 sr^-1), front face only
    float ior;      // dielectric and PBR: index of refraction relative to the outside
    vec3 tf;        // dielectric: transmission filter; PBR: attenuation colour of the volume
    uint type;      // MATERIAL_*
    float metallic;
    float roughness; // glTF roughness: the GGX width is its square
    float transmission;
    float specular;                 // KHR_materials_specular's specularFactor
    float alpha;                    // coverage: baseColorFactor's alpha
    float alpha_cutoff;             // ALPHA_MASK's threshold
    uint alpha_mode;                // ALPHA_*
    float attenuation_distance;     // PBR volume: Beer-Lambert distance, FLOAT_MAX for none
    int metallic_roughness_texture; // B: metallic, G: roughness (linear)
    int normal_texture;             // tangent-space normal map, scaled by normal_scale
    int emissive_texture;           // multiplies ke (sRGB)
    int transmission_texture;       // R multiplies transmission (linear)
    int specular_texture;           // A multiplies specular (linear)
    int specular_color_texture;     // RGB multiplies ks (sRGB)
    float normal_scale;
    uint flags; // MATERIAL_FLAG_*
};

// ---- lights ------------------------------------------------------------------------------
const uint LIGHT_POINT = 0u;       // p0 position, value intensity I (W/sr)
const uint LIGHT_DIRECTIONAL = 1u; // p0 unit direction towards the light, value irradiance (W/m^2)
const uint LIGHT_TRIANGLE = 2u;    // p0..p2 world vertices (CCW = front), value radiance
const uint LIGHT_ENVIRONMENT = 3u; // value radiance scale; RenderParams holds the map
// p0 position, p1 unit direction of the cone's axis, p2.xy the cone's angular scale and offset
// (lights.h, spot_light_falloff), value intensity I on the axis (W/sr)
const uint LIGHT_SPOT = 4u;

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
const uint MESH_HAS_UV1 = 4u;      // a second uv set
const uint MESH_HAS_TANGENTS = 8u; // tangents (xyz) and bitangent sign (w) for normal maps

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
// An image: its size and how its texels are stored. The CPU keeps them as words
// (image/texture.h), the GPU as an integer image of the same bytes (shaders/scene_access.glsl);
// either fetches texel i = row * width + column through the scene_texel hook (scene_access.h).
const uint TEXEL_RGBA8 = 0u;   // one word per texel, R in the low byte (an 8-bit image)
const uint TEXEL_RGBA32F = 1u; // four words per texel, the float bits of R, G, B, A
const uint TEXEL_RGBA16 = 2u;  // two words per texel, R | G << 16 and B | A << 16 (16-bit)

struct TextureInfo {
    uint width;
    uint height;
    uint format; // TEXEL_*
    uint pad0;
};

// TextureSlot::sampling bits: the sampler's wrap mode per axis, its filter, the uv set, and
// whether 8-bit texels are sRGB-encoded colour (glTF's colour slots) or linear data.
const uint SLOT_WRAP_REPEAT = 0u;
const uint SLOT_WRAP_CLAMP = 1u;
const uint SLOT_WRAP_MIRROR = 2u;
const uint SLOT_WRAP_T_SHIFT = 2u; // wrap s in bits 0-1, wrap t in bits 2-3
const uint SLOT_NEAREST = 16u;     // nearest texel instead of bilinear
const uint SLOT_UV1 = 32u;         // the second uv set (glTF TEXCOORD_1)
const uint SLOT_SRGB = 64u;        // 8-bit texels hold sRGB-encoded colour

// A texture as a material reads it: the image, the affine map from the mesh's uv to image
// coordinates (s, t) (t = 0 at the top row, texture.h), which takes the format's uv convention
// and KHR_texture_transform, and how it is sampled.
struct TextureSlot {
    vec3 transform_s; // s = dot(transform_s, vec3(uv, 1))
    uint image;       // index into the image table (TextureInfo)
    vec3 transform_t; // t = dot(transform_t, vec3(uv, 1))
    uint sampling;    // SLOT_*
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
static_assert(sizeof(Material) == 128 && offsetof(Material, type) == 60 &&
                  offsetof(Material, flags) == 124,
              "Material layout");
static_assert(sizeof(Light) == 80 && offsetof(Light, normal) == 64, "Light layout");
static_assert(sizeof(AliasEntry) == 12, "AliasEntry layout");
static_assert(sizeof(MeshInfo) == 32, "MeshInfo layout");
static_assert(sizeof(Instance) == 112 && offsetof(Instance, mesh) == 96, "Instance layout");
static_assert(sizeof(TextureInfo) == 16 && offsetof(TextureInfo, format) == 8,
              "TextureInfo layout");
static_assert(sizeof(TextureSlot) == 32 && offsetof(TextureSlot, sampling) == 28,
              "TextureSlot layout");
static_assert(sizeof(Camera) == 64 && offsetof(Camera, height) == 60, "Camera layout");
static_assert(sizeof(RenderParams) == 112 && offsetof(RenderParams, sampler_id) == 96,
              "RenderParams layout");
#endif

TP_NAMESPACE_END

#endif // TP_SHARED_TYPES_H
