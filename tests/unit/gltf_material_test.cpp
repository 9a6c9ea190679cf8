// The glTF material mapping (scene/gltf_material.h, docs/scene-format.md "glTF materials"):
// every factor of the metallic-roughness model and of KHR_materials_emissive_strength, _ior,
// _specular, _transmission and _volume lands, unchanged, in its MATERIAL_PBR field; the texture
// uses and their colour spaces; what is ignored or dropped; and every material in range
// passing validate_material.
#include "scene/gltf_material.h"
#include "scene/scene.h"
#include "shared/math.h"

#include <catch2/catch.hpp>

#include <limits>

using tp::GltfMaterial;
using tp::vec3;

namespace {

bool mentions(const std::vector<std::string>& notes, const std::string& s) {
    for (const std::string& n : notes)
        if (n.find(s) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_CASE("glTF's default material is the PBR default", "[unit][gltf]") {
    const auto r = tp::map_gltf_material(GltfMaterial{});
    const tp::Material& m = r.material;
    CHECK(m.type == tp::MATERIAL_PBR);
    CHECK(m.kd == vec3(1.0f));
    CHECK(m.alpha == 1.0f);
    CHECK(m.metallic == 1.0f);
    CHECK(m.roughness == 1.0f);
    CHECK(m.ke == vec3(0.0f));
    CHECK(m.ior == 1.5f);
    CHECK(m.specular == 1.0f);
    CHECK(m.ks == vec3(1.0f));
    CHECK(m.transmission == 0.0f);
    CHECK(m.flags == 0u); // thin-walled
    CHECK(m.tf == vec3(1.0f));
    CHECK(m.attenuation_distance == tp::FLOAT_MAX);
    CHECK(m.alpha_mode == tp::ALPHA_OPAQUE);
    CHECK(m.alpha_cutoff == 0.5f);
    CHECK(m.normal_scale == 1.0f);
    for (int tp::Material::*slot :
         {&tp::Material::kd_texture, &tp::Material::metallic_roughness_texture,
          &tp::Material::normal_texture, &tp::Material::emissive_texture,
          &tp::Material::transmission_texture, &tp::Material::specular_texture,
          &tp::Material::specular_color_texture})
        CHECK(m.*slot == tp::NO_TEXTURE);
    CHECK(r.dropped.empty());
    CHECK(r.ignored.empty());
    CHECK(tp::gltf_material_textures(GltfMaterial{}).empty());
}

TEST_CASE("every glTF factor lands in its MATERIAL_PBR field", "[unit][gltf]") {
    GltfMaterial g;
    g.base_color = vec3(0.8f, 0.6f, 0.4f);
    g.base_alpha = 0.7f;
    g.metallic = 0.25f;
    g.roughness = 0.35f;
    g.emissive = vec3(1.0f, 0.5f, 0.25f);
    g.emissive_strength = 4.0f;
    g.ior = 1.33f;
    g.specular = 0.45f;
    g.specular_color = vec3(2.0f, 1.0f, 0.5f);
    g.transmission = 0.9f;
    g.thickness = 0.02f;
    g.attenuation_color = vec3(0.9f, 0.5f, 0.1f);
    g.attenuation_distance = 0.3f;
    g.alpha_mode = "MASK";
    g.alpha_cutoff = 0.6f;
    g.normal_scale = -0.75f;
    const auto r = tp::map_gltf_material(g);
    const tp::Material& m = r.material;
    CHECK(m.type == tp::MATERIAL_PBR);
    CHECK(m.kd == vec3(0.8f, 0.6f, 0.4f));
    CHECK(m.alpha == 0.7f);
    CHECK(m.metallic == 0.25f);
    CHECK(m.roughness == 0.35f);
    CHECK(m.ke == vec3(4.0f, 2.0f, 1.0f)); // emissiveFactor x emissiveStrength
    CHECK(m.ior == 1.33f);
    CHECK(m.specular == 0.45f);
    CHECK(m.ks == vec3(2.0f, 1.0f, 0.5f));
    CHECK(m.transmission == 0.9f);
    CHECK(m.flags == tp::MATERIAL_FLAG_VOLUME); // thickness > 0
    CHECK(m.tf == vec3(0.9f, 0.5f, 0.1f));
    CHECK(m.attenuation_distance == 0.3f);
    CHECK(m.alpha_mode == tp::ALPHA_MASK);
    CHECK(m.alpha_cutoff == 0.6f);
    CHECK(m.normal_scale == -0.75f);
    CHECK(r.dropped.empty());
    CHECK_NOTHROW(tp::validate_material(m, "all factors"));

    g.alpha_mode = "BLEND";
    g.thickness = 0.0f;
    CHECK(tp::map_gltf_material(g).material.alpha_mode == tp::ALPHA_BLEND);
    CHECK(tp::map_gltf_material(g).material.flags == 0u);
}

TEST_CASE("glTF material corner cases map exactly", "[unit][gltf]") {
    SECTION("KHR_materials_ior's ior 0 is an infinite index: f0 within 4e-6 of 1") {
        GltfMaterial g;
        g.ior = 0.0f;
        const float ior = tp::map_gltf_material(g).material.ior;
        CHECK(ior == tp::kGltfInfiniteIor);
        const double f = (double(ior) - 1.0) / (double(ior) + 1.0);
        CHECK(f * f > 1.0 - 4e-6);
    }
    SECTION("alphaCutoff above 1 masks everything out: alpha 0 below cutoff 1") {
        GltfMaterial g;
        g.alpha_mode = "MASK";
        g.alpha_cutoff = 1.5f;
        const tp::Material m = tp::map_gltf_material(g).material;
        CHECK(m.alpha_cutoff == 1.0f);
        CHECK(m.alpha == 0.0f);
        CHECK_NOTHROW(tp::validate_material(m, "cutoff"));
        g.alpha_mode = "BLEND"; // the cutoff means nothing there
        CHECK(tp::map_gltf_material(g).material.alpha == 1.0f);
    }
    SECTION("no attenuation distance is FLOAT_MAX, the engines' 'none'") {
        GltfMaterial g;
        g.attenuation_distance = std::numeric_limits<float>::infinity();
        CHECK(tp::map_gltf_material(g).material.attenuation_distance == tp::FLOAT_MAX);
    }
}

TEST_CASE("glTF texture uses: which field, which colour space", "[unit][gltf]") {
    GltfMaterial g;
    int next = 0;
    for (tp::GltfTextureRef* t : {&g.base_color_texture, &g.metallic_roughness_texture,
                                  &g.normal_texture, &g.emissive_texture, &g.transmission_texture,
                                  &g.specular_texture, &g.specular_color_texture})
        t->texture = next++;
    const std::vector<tp::GltfTextureUse> uses = tp::gltf_material_textures(g);
    REQUIRE(uses.size() == 7);
    struct Expected {
        int tp::Material::*field;
        bool srgb;
    };
    // glTF 2.0, section 3.9: colour textures are sRGB-encoded, data textures linear.
    const Expected expected[] = {{&tp::Material::kd_texture, true},
                                 {&tp::Material::metallic_roughness_texture, false},
                                 {&tp::Material::normal_texture, false},
                                 {&tp::Material::emissive_texture, true},
                                 {&tp::Material::transmission_texture, false},
                                 {&tp::Material::specular_texture, false},
                                 {&tp::Material::specular_color_texture, true}};
    for (size_t i = 0; i < uses.size(); ++i) {
        CAPTURE(uses[i].name);
        CHECK(uses[i].ref->texture == int(i));
        CHECK(uses[i].field == expected[i].field);
        CHECK(uses[i].srgb == expected[i].srgb);
    }
}

TEST_CASE("what a path tracer ignores and what twinpath does not read are listed apart",
          "[unit][gltf]") {
    GltfMaterial g;
    g.ignored = {"occlusionTexture", "KHR_materials_volume.thicknessTexture"};
    g.unused = {"KHR_materials_clearcoat"};
    const auto r = tp::map_gltf_material(g);
    REQUIRE(r.ignored.size() == 2);
    CHECK(
        mentions(r.ignored, "occlusionTexture: ignored by a path tracer (it computes occlusion)"));
    CHECK(mentions(r.ignored, "thicknessTexture: ignored (a ray tracer measures thickness)"));
    REQUIRE(r.dropped.size() == 1);
    CHECK(mentions(r.dropped, "KHR_materials_clearcoat"));
}

TEST_CASE("every glTF material in range passes validate_material", "[unit][gltf]") {
    // validate_material (scene.h) checks the ranges the BSDF is defined for; the mapping must
    // never produce a material outside them from input read_gltf_document accepts.
    for (float factor : {0.0f, 0.5f, 1.0f})
        for (float spec_color : {0.0f, 1.0f, 1000.0f})
            for (float ior : {0.0f, 1.0f, 1.5f, 100.0f})
                for (float cutoff : {0.0f, 0.5f, 7.0f})
                    for (const char* mode : {"OPAQUE", "MASK", "BLEND"}) {
                        GltfMaterial g;
                        g.base_color = vec3(factor, 1.0f, 0.0f);
                        g.base_alpha = factor;
                        g.metallic = g.roughness = g.transmission = g.specular = factor;
                        g.specular_color = vec3(spec_color);
                        g.ior = ior;
                        g.alpha_cutoff = cutoff;
                        g.alpha_mode = mode;
                        g.thickness = factor;
                        g.attenuation_color = vec3(factor);
                        CHECK_NOTHROW(
                            tp::validate_material(tp::map_gltf_material(g).material, "grid"));
                    }
}
