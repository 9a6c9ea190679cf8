#include "scene/features.h"

#include "shared/math.h"

namespace tp {

const char* feature_name(uint32_t feature) {
    switch (feature) {
    case FEATURE_TEXTURES:
        return "textures";
    case FEATURE_PHONG_SPECULAR:
        return "phong_specular";
    case FEATURE_MIRROR:
        return "mirror";
    case FEATURE_DIELECTRIC:
        return "dielectric";
    case FEATURE_EMISSIVE_TRIANGLES:
        return "emissive_triangles";
    case FEATURE_POINT_LIGHTS:
        return "point_lights";
    case FEATURE_DIRECTIONAL_LIGHTS:
        return "directional_lights";
    case FEATURE_ENV_CONSTANT:
        return "environment_constant";
    case FEATURE_ENV_MAP:
        return "environment_map";
    case FEATURE_INSTANCING:
        return "instancing";
    case FEATURE_PBR:
        return "pbr";
    case FEATURE_NORMAL_MAPS:
        return "normal_maps";
    case FEATURE_ALPHA:
        return "alpha";
    default:
        return "";
    }
}

std::vector<std::string> SceneFeatures::names() const {
    std::vector<std::string> out;
    for (uint32_t i = 0; i < FEATURE_COUNT; ++i)
        if (mask & (1u << i)) out.push_back(feature_name(1u << i));
    return out;
}

std::string SceneFeatures::summary() const {
    std::string s;
    for (const std::string& n : names()) s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? "none" : s;
}

bool SceneFeatures::emits() const {
    return has(FEATURE_EMISSIVE_TRIANGLES | FEATURE_POINT_LIGHTS | FEATURE_DIRECTIONAL_LIGHTS |
               FEATURE_ENV_CONSTANT | FEATURE_ENV_MAP);
}

std::optional<std::string> dark_scene_warning(const FlatScene& scene, const std::string& where) {
    if (analyze_features(scene).emits()) return std::nullopt;
    return where + ": nothing in the scene emits light (no light with power, no emissive material "
                   "on an object, no environment): every render of it is black";
}

SceneFeatures analyze_features(const FlatScene& scene) {
    SceneFeatures f;
    for (uint32_t uses : instances_per_mesh(scene))
        if (uses > 1) f.mask |= FEATURE_INSTANCING;
    for (const Instance& inst : scene.instances) {
        const Material& m = scene.materials[inst.material];
        const bool pbr = m.type == MATERIAL_PBR;
        const int pbr_slots[] = {m.metallic_roughness_texture, m.normal_texture,
                                 m.emissive_texture,           m.transmission_texture,
                                 m.specular_texture,           m.specular_color_texture};
        if (m.kd_texture != NO_TEXTURE) f.mask |= FEATURE_TEXTURES;
        if (pbr) {
            f.mask |= FEATURE_PBR;
            for (int slot : pbr_slots)
                if (slot != NO_TEXTURE) f.mask |= FEATURE_TEXTURES;
            // A normal map bends normals only where the mesh has a tangent frame.
            if (m.normal_texture != NO_TEXTURE &&
                (scene.meshes[inst.mesh].flags & MESH_HAS_TANGENTS) != 0u)
                f.mask |= FEATURE_NORMAL_MAPS;
        }
        if (m.alpha_mode != ALPHA_OPAQUE) f.mask |= FEATURE_ALPHA;
        if (m.type == MATERIAL_PHONG && !is_black(m.ks)) f.mask |= FEATURE_PHONG_SPECULAR;
        if (m.type == MATERIAL_MIRROR) f.mask |= FEATURE_MIRROR;
        if (m.type == MATERIAL_DIELECTRIC) f.mask |= FEATURE_DIELECTRIC;
        // Emission is added wherever ke is not black (the path loop's step 1), whether or not
        // the instance's triangles are also in the light list.
        if (!is_black(m.ke)) f.mask |= FEATURE_EMISSIVE_TRIANGLES;
    }
    for (const Light& l : scene.lights) {
        if (l.type == LIGHT_POINT || l.type == LIGHT_SPOT) f.mask |= FEATURE_POINT_LIGHTS;
        if (l.type == LIGHT_DIRECTIONAL) f.mask |= FEATURE_DIRECTIONAL_LIGHTS;
    }
    if (scene.params.env_light != NO_INDEX)
        f.mask |= scene.params.env_texture == NO_TEXTURE ? FEATURE_ENV_CONSTANT : FEATURE_ENV_MAP;
    return f;
}

uint32_t render_feature_mask(const FlatScene& scene, bool all) {
    return all ? FEATURES_ALL : analyze_features(scene).mask;
}

} // namespace tp
