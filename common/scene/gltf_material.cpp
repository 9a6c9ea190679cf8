#include "scene/gltf_material.h"

#include "scene/scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tp {

float gltf_phong_exponent(float roughness) {
    const double r2 = double(roughness) * double(roughness);
    const double ns = 0.5 / (r2 * r2) - 0.5; // +inf at r = 0
    return float(std::min(ns, double(kMaxGltfPhongExponent)));
}

GltfMaterialMapping map_gltf_material(const GltfMaterial& m, const vec3& emissive_texture_mean) {
    GltfMaterialMapping out;
    Material& mat = out.material;
    mat = default_material();
    std::vector<std::string>& dropped = out.dropped;
    // Emission: glTF's emissive (cd/m^2) times KHR_materials_emissive_strength, read as
    // radiance in twinpath's units. twinpath has no emission texture: its mean keeps the power.
    mat.ke = m.emissive * m.emissive_strength * emissive_texture_mean;
    if (m.emissive_texture.texture != GLTF_NONE)
        dropped.push_back(fmt::format("emissiveTexture: emission uses its mean ({:.3g}, {:.3g}, "
                                      "{:.3g}) over the whole surface",
                                      emissive_texture_mean.x, emissive_texture_mean.y,
                                      emissive_texture_mean.z));
    const bool textured = m.base_color_texture.texture != GLTF_NONE;
    if (m.transmission > 0.0f) {
        // KHR_materials_transmission: a thin or solid dielectric tinted by the base colour;
        // twinpath's dielectric is smooth and fully transmissive.
        mat.type = MATERIAL_DIELECTRIC;
        mat.ior = m.ior;
        mat.tf = m.base_color;
        if (m.transmission < 1.0f)
            dropped.push_back(fmt::format("transmissionFactor {}: rendered as 1", m.transmission));
        if (m.roughness > 0.0f)
            dropped.push_back(
                fmt::format("roughnessFactor {}: the dielectric is smooth", m.roughness));
        if (m.metallic > 0.0f)
            dropped.push_back(
                fmt::format("metallicFactor {}: the dielectric is not metallic", m.metallic));
        if (textured)
            dropped.push_back("baseColorTexture: the dielectric's tint is baseColorFactor");
    } else if (m.metallic == 1.0f && m.roughness == 0.0f) {
        mat.type = MATERIAL_MIRROR;
        mat.ks = m.base_color;
        if (textured) dropped.push_back("baseColorTexture: the mirror's tint is baseColorFactor");
    } else {
        // glTF 2.0 Appendix B: the dielectric part is a specular layer of reflectance F0 at
        // normal incidence (((ior - 1) / (ior + 1))^2 = 0.04 at ior 1.5, scaled by
        // KHR_materials_specular) over a diffuse base of weight 1 - F0; the metallic part
        // reflects the base colour specularly. Phong has no Fresnel term: F0 stands for the
        // specular reflectance at every angle. Kd + Ks = (1 - m)((1 - F0) b + F0) + m b <= 1.
        const double f = (double(m.ior) - 1.0) / (double(m.ior) + 1.0);
        const vec3 f0 = glm::min(vec3(float(f * f) * m.specular) * m.specular_color, vec3(1.0f));
        const float metal = m.metallic;
        mat.type = MATERIAL_PHONG;
        mat.kd = (1.0f - metal) * (vec3(1.0f) - f0) * m.base_color;
        mat.ks = (1.0f - metal) * f0 + metal * m.base_color;
        mat.ns = gltf_phong_exponent(m.roughness);
        out.uses_base_color_texture = textured;
        if (textured && metal > 0.0f)
            dropped.push_back(fmt::format("baseColorTexture: tints the diffuse part only, not "
                                          "the metallic specular (metallicFactor {})",
                                          metal));
    }
    if (m.alpha_mode != "OPAQUE")
        dropped.push_back(fmt::format("alphaMode {}: rendered opaque", m.alpha_mode));
    for (const std::string& u : m.unused) dropped.push_back(u);
    return out;
}

} // namespace tp
