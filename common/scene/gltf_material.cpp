#include "scene/gltf_material.h"

#include "scene/scene.h"
#include "shared/math.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tp {
namespace {

// Why a path tracer has no use for what read_gltf_document lists as ignored.
std::string ignored_reason(const std::string& property) {
    if (property == "occlusionTexture")
        return "occlusionTexture: ignored by a path tracer (it computes occlusion)";
    if (property == "KHR_materials_volume.thicknessTexture")
        return "KHR_materials_volume.thicknessTexture: ignored (a ray tracer measures thickness)";
    return property + ": ignored";
}

} // namespace

GltfMaterialMapping map_gltf_material(const GltfMaterial& m) {
    GltfMaterialMapping out;
    Material& mat = out.material;
    mat = default_pbr_material();
    mat.kd = m.base_color;
    mat.alpha = m.base_alpha;
    mat.metallic = m.metallic;
    mat.roughness = m.roughness;
    // Emission: glTF's emissive times KHR_materials_emissive_strength is radiance (W m^-2 sr^-1),
    // as Blender reads it (emission strength); the emissive texture is a slot that multiplies it.
    mat.ke = m.emissive * m.emissive_strength;
    mat.ior = m.ior == 0.0f ? kGltfInfiniteIor : m.ior;
    mat.specular = m.specular;
    mat.ks = m.specular_color;
    mat.transmission = m.transmission;
    // KHR_materials_volume: thickness 0 is a thin-walled surface, any other a volume boundary
    // (ray tracers measure the thickness along the ray, the factor only says there is one).
    if (m.thickness > 0.0f) mat.flags |= MATERIAL_FLAG_VOLUME;
    mat.tf = m.attenuation_color;
    mat.attenuation_distance =
        std::isinf(m.attenuation_distance) ? FLOAT_MAX : m.attenuation_distance;
    mat.normal_scale = m.normal_scale;
    mat.alpha_mode = m.alpha_mode == "MASK"    ? ALPHA_MASK
                     : m.alpha_mode == "BLEND" ? ALPHA_BLEND
                                               : ALPHA_OPAQUE;
    // A cutoff above 1 masks everything out (alpha never exceeds 1): so does alpha 0 at cutoff
    // 1, which stays in the range the engines read.
    mat.alpha_cutoff = std::min(m.alpha_cutoff, 1.0f);
    if (mat.alpha_mode == ALPHA_MASK && m.alpha_cutoff > 1.0f) mat.alpha = 0.0f;
    for (const std::string& p : m.ignored) out.ignored.push_back(ignored_reason(p));
    for (const std::string& u : m.unused)
        out.dropped.push_back(u + ": an extension twinpath does not read");
    return out;
}

std::vector<GltfTextureUse> gltf_material_textures(const GltfMaterial& m) {
    const GltfTextureUse all[] = {
        {&m.base_color_texture, &Material::kd_texture, true, "baseColorTexture"},
        {&m.metallic_roughness_texture, &Material::metallic_roughness_texture, false,
         "metallicRoughnessTexture"},
        {&m.normal_texture, &Material::normal_texture, false, "normalTexture"},
        {&m.emissive_texture, &Material::emissive_texture, true, "emissiveTexture"},
        {&m.transmission_texture, &Material::transmission_texture, false, "transmissionTexture"},
        {&m.specular_texture, &Material::specular_texture, false, "specularTexture"},
        {&m.specular_color_texture, &Material::specular_color_texture, true,
         "specularColorTexture"}};
    std::vector<GltfTextureUse> used;
    for (const GltfTextureUse& u : all)
        if (u.ref->texture != GLTF_NONE) used.push_back(u);
    return used;
}

} // namespace tp
