#include "scene/json_material.h"

#include "scene/texture_slots.h"
#include "shared/math.h"
#include "util/error.h"

namespace tp {
namespace {

using json = nlohmann::json;

// The slot of the texture named by j[key], read as sRGB colour or linear data; NO_TEXTURE when
// the key is absent.
int texture_slot(const JsonReader& r, const json& j, const std::string& field, const char* key,
                 const std::map<std::string, uint32_t>& textures, bool srgb, Scene& scene) {
    if (!j.contains(key)) return NO_TEXTURE;
    const std::string f = field + "." + key;
    const std::string name = r.string(j[key], f);
    const auto it = textures.find(name);
    if (it == textures.end()) r.fail(f, fmt::format("no texture named '{}'", name));
    return add_texture_slot(scene, obj_texture_slot(it->second, srgb));
}

// A colour with every channel in [0, 1].
vec3 unit_color(const JsonReader& r, const json& j, const std::string& field) {
    const vec3 c = r.color(j, field);
    if (max3(c) > 1.0f) r.fail(field, "channels must lie in [0, 1]");
    return c;
}

Material read_classic(const JsonReader& r, const json& j, const std::string& field,
                      const std::string& type, const std::map<std::string, uint32_t>& textures,
                      Scene& scene) {
    r.keys(j, field, {"type", "Kd", "Ks", "Ns", "Ke", "Ni", "Tf", "map_Kd"});
    Material m = default_material();
    m.type = type == "mirror"       ? MATERIAL_MIRROR
             : type == "dielectric" ? MATERIAL_DIELECTRIC
                                    : MATERIAL_PHONG;
    if (j.contains("Kd")) m.kd = r.color(j["Kd"], field + ".Kd");
    if (j.contains("Ks")) m.ks = r.color(j["Ks"], field + ".Ks");
    if (j.contains("Ke")) m.ke = r.color(j["Ke"], field + ".Ke");
    if (j.contains("Tf")) m.tf = r.color(j["Tf"], field + ".Tf");
    if (j.contains("Ns")) m.ns = r.number(j["Ns"], field + ".Ns", 0.0f, 1e7f);
    if (j.contains("Ni")) m.ior = r.number(j["Ni"], field + ".Ni", 1e-3f, 100.0f);
    m.kd_texture = texture_slot(r, j, field, "map_Kd", textures, true, scene);
    if (m.type == MATERIAL_MIRROR && !j.contains("Ks")) m.ks = vec3(1.0f);
    if (m.type == MATERIAL_PHONG && !j.contains("Kd") && !j.contains("Ks") && !j.contains("Ke"))
        r.fail(field, "a phong material needs at least one of Kd, Ks, Ke");
    return m;
}

// glTF's material, its defaults glTF's (default_pbr_material).
Material read_pbr(const JsonReader& r, const json& j, const std::string& field,
                  const std::map<std::string, uint32_t>& textures, Scene& scene) {
    r.keys(j, field,
           {"type",
            "base_color",
            "metallic",
            "roughness",
            "ior",
            "transmission",
            "specular",
            "specular_color",
            "Ke",
            "alpha",
            "alpha_mode",
            "alpha_cutoff",
            "thickness",
            "attenuation_color",
            "attenuation_distance",
            "normal_scale",
            "base_color_texture",
            "metallic_roughness_texture",
            "normal_texture",
            "emissive_texture",
            "transmission_texture",
            "specular_texture",
            "specular_color_texture"});
    Material m = default_pbr_material();
    auto unit = [&](const char* key, float& out) {
        if (j.contains(key)) out = r.number(j[key], field + "." + key, 0.0f, 1.0f);
    };
    if (j.contains("base_color")) m.kd = unit_color(r, j["base_color"], field + ".base_color");
    unit("metallic", m.metallic);
    unit("roughness", m.roughness);
    unit("transmission", m.transmission);
    unit("specular", m.specular);
    unit("alpha", m.alpha);
    unit("alpha_cutoff", m.alpha_cutoff);
    if (j.contains("ior")) m.ior = r.number(j["ior"], field + ".ior", 1.0f, FLOAT_MAX);
    if (j.contains("specular_color"))
        m.ks = r.color(j["specular_color"], field + ".specular_color");
    if (j.contains("Ke")) m.ke = r.color(j["Ke"], field + ".Ke");
    if (j.contains("alpha_mode")) {
        const std::string mode = r.string(j["alpha_mode"], field + ".alpha_mode");
        if (mode != "opaque" && mode != "mask" && mode != "blend")
            r.fail(field + ".alpha_mode",
                   fmt::format("unknown alpha mode '{}' (expected opaque, mask, blend)", mode));
        m.alpha_mode = mode == "mask" ? ALPHA_MASK : mode == "blend" ? ALPHA_BLEND : ALPHA_OPAQUE;
    }
    // KHR_materials_volume: a thickness above 0 makes the surface a volume's boundary.
    if (j.contains("thickness") &&
        r.number(j["thickness"], field + ".thickness", 0.0f, FLOAT_MAX) > 0.0f)
        m.flags |= MATERIAL_FLAG_VOLUME;
    if (j.contains("attenuation_color"))
        m.tf = unit_color(r, j["attenuation_color"], field + ".attenuation_color");
    if (j.contains("attenuation_distance")) {
        const std::string f = field + ".attenuation_distance";
        m.attenuation_distance = r.number(j["attenuation_distance"], f, 0.0f, FLOAT_MAX);
        if (!(m.attenuation_distance > 0.0f)) r.fail(f, "must be greater than 0");
    }
    if (j.contains("normal_scale"))
        m.normal_scale = r.number(j["normal_scale"], field + ".normal_scale");
    const std::pair<const char*, std::pair<int Material::*, bool>> slots[] = {
        {"base_color_texture", {&Material::kd_texture, true}},
        {"metallic_roughness_texture", {&Material::metallic_roughness_texture, false}},
        {"normal_texture", {&Material::normal_texture, false}},
        {"emissive_texture", {&Material::emissive_texture, true}},
        {"transmission_texture", {&Material::transmission_texture, false}},
        {"specular_texture", {&Material::specular_texture, false}},
        {"specular_color_texture", {&Material::specular_color_texture, true}}};
    for (const auto& [key, use] : slots)
        m.*use.first = texture_slot(r, j, field, key, textures, use.second, scene);
    return m;
}

} // namespace

Material read_json_material(const JsonReader& r, const json& j, const std::string& field,
                            const std::map<std::string, uint32_t>& textures, Scene& scene) {
    if (!j.is_object()) r.fail(field, "expected an object");
    const std::string type = j.contains("type") ? r.string(j["type"], field + ".type") : "phong";
    if (type != "phong" && type != "mirror" && type != "dielectric" && type != "pbr")
        r.fail(field + ".type",
               fmt::format("unknown material type '{}' (expected phong, mirror, dielectric, pbr)",
                           type));
    const Material m = type == "pbr" ? read_pbr(r, j, field, textures, scene)
                                     : read_classic(r, j, field, type, textures, scene);
    validate_material(m, fmt::format("{}: {}", r.file(), field));
    return m;
}

} // namespace tp
