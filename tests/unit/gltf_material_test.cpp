// The glTF material mapping (scene/gltf_material.h, docs/scene-format.md "glTF materials") as a
// table: each row a glTF material and the twinpath material the rule gives, the expected values
// worked out by hand from the rule's formulas; the Phong exponent against Walter et al.'s
// relation and the lobe widths it is meant to match; energy conservation over a grid.
#include "scene/gltf_material.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>

#include <cmath>

using tp::GltfMaterial;
using tp::vec3;

namespace {

GltfMaterial pbr(vec3 base, float metallic, float roughness) {
    GltfMaterial m;
    m.base_color = base;
    m.metallic = metallic;
    m.roughness = roughness;
    return m;
}

bool mentions(const std::vector<std::string>& notes, const std::string& s) {
    for (const std::string& n : notes)
        if (n.find(s) != std::string::npos) return true;
    return false;
}

// Float rounding of the rule's few products: a relative 1e-6.
void check_near(vec3 a, vec3 b) {
    for (int c = 0; c < 3; ++c) CHECK(a[c] == Approx(b[c]).epsilon(1e-6).margin(1e-7));
}

} // namespace

TEST_CASE("glTF material mapping table", "[unit][gltf]") {
    const vec3 one(1.0f), none(1.0f); // no emissive texture: its mean is 1
    SECTION("the specification's default material: metallic 1, roughness 1, white") {
        const auto r = tp::map_gltf_material(GltfMaterial{}, none);
        CHECK(r.material.type == tp::MATERIAL_PHONG);
        check_near(r.material.kd, vec3(0.0f));
        check_near(r.material.ks, one);
        CHECK(r.material.ns == 0.0f);
        CHECK(r.dropped.empty());
    }
    SECTION("a dielectric (plastic): F0 = 0.04 at ior 1.5 over a diffuse base of 0.96") {
        const auto r = tp::map_gltf_material(pbr(vec3(0.8f, 0.2f, 0.1f), 0.0f, 0.5f), none);
        CHECK(r.material.type == tp::MATERIAL_PHONG);
        check_near(r.material.kd, vec3(0.768f, 0.192f, 0.096f));
        check_near(r.material.ks, vec3(0.04f));
        CHECK(r.material.ns == Approx(7.5)); // 1 / (2 * 0.5^4) - 1/2
    }
    SECTION("a rough metal: the base colour is the specular reflectance, no diffuse") {
        const auto r = tp::map_gltf_material(pbr(vec3(1.0f, 0.78f, 0.34f), 1.0f, 0.3f), none);
        CHECK(r.material.type == tp::MATERIAL_PHONG);
        check_near(r.material.kd, vec3(0.0f));
        check_near(r.material.ks, vec3(1.0f, 0.78f, 0.34f));
        CHECK(r.material.ns == Approx(0.5 / std::pow(0.3, 4) - 0.5).epsilon(1e-6)); // 61.23
    }
    SECTION("half metallic: the two parts mixed") {
        const auto r = tp::map_gltf_material(pbr(vec3(0.5f), 0.5f, 1.0f), none);
        check_near(r.material.kd, vec3(0.5f * 0.96f * 0.5f));        // 0.24
        check_near(r.material.ks, vec3(0.5f * 0.04f + 0.5f * 0.5f)); // 0.27
    }
    SECTION("metallic 1 and roughness 0: the mirror, tinted by the base colour") {
        const auto r = tp::map_gltf_material(pbr(vec3(0.9f, 0.8f, 0.7f), 1.0f, 0.0f), none);
        CHECK(r.material.type == tp::MATERIAL_MIRROR);
        check_near(r.material.ks, vec3(0.9f, 0.8f, 0.7f));
    }
    SECTION("nearly smooth metal stays Phong, its exponent capped") {
        const auto r = tp::map_gltf_material(pbr(one, 1.0f, 1e-3f), none);
        CHECK(r.material.type == tp::MATERIAL_PHONG);
        CHECK(r.material.ns == tp::kMaxGltfPhongExponent);
    }
    SECTION("smooth plastic (roughness 0, metallic 0) stays Phong with the capped exponent") {
        const auto r = tp::map_gltf_material(pbr(vec3(0.5f), 0.0f, 0.0f), none);
        CHECK(r.material.type == tp::MATERIAL_PHONG);
        CHECK(r.material.ns == tp::kMaxGltfPhongExponent);
    }
    SECTION("transmission and ior: the dielectric, tinted by the base colour") {
        GltfMaterial m = pbr(vec3(0.9f, 1.0f, 0.9f), 0.0f, 0.0f);
        m.transmission = 1.0f;
        m.ior = 1.33f;
        const auto r = tp::map_gltf_material(m, none);
        CHECK(r.material.type == tp::MATERIAL_DIELECTRIC);
        CHECK(r.material.ior == 1.33f);
        check_near(r.material.tf, vec3(0.9f, 1.0f, 0.9f));
        CHECK(r.dropped.empty());
        m.transmission = 0.5f;
        m.roughness = 0.2f;
        const auto partial = tp::map_gltf_material(m, none);
        CHECK(partial.material.type == tp::MATERIAL_DIELECTRIC);
        CHECK(mentions(partial.dropped, "transmissionFactor 0.5"));
        CHECK(mentions(partial.dropped, "roughnessFactor 0.2"));
    }
    SECTION("KHR_materials_ior changes F0 of a dielectric that does not transmit") {
        GltfMaterial m = pbr(one, 0.0f, 1.0f);
        m.ior = 2.0f; // F0 = ((2 - 1) / (2 + 1))^2 = 1/9
        const auto r = tp::map_gltf_material(m, none);
        check_near(r.material.ks, vec3(1.0f / 9.0f));
        check_near(r.material.kd, vec3(8.0f / 9.0f));
    }
    SECTION("KHR_materials_specular scales F0; F0 is clamped to 1") {
        GltfMaterial m = pbr(vec3(0.6f), 0.0f, 1.0f);
        m.specular = 0.0f;
        const auto off = tp::map_gltf_material(m, none);
        check_near(off.material.kd, vec3(0.6f));
        check_near(off.material.ks, vec3(0.0f));
        m.specular = 1.0f;
        m.specular_color = vec3(50.0f, 1.0f, 0.5f); // F0 = min(1, 0.04 * (50, 1, 0.5))
        const auto tinted = tp::map_gltf_material(m, none);
        check_near(tinted.material.ks, vec3(1.0f, 0.04f, 0.02f));
        check_near(tinted.material.kd, vec3(0.0f, 0.6f * 0.96f, 0.6f * 0.98f));
    }
    SECTION("emission: factor times strength times the emissive texture's mean") {
        GltfMaterial m = pbr(one, 0.0f, 1.0f);
        m.emissive = vec3(1.0f, 0.5f, 0.25f);
        m.emissive_strength = 4.0f;
        check_near(tp::map_gltf_material(m, none).material.ke, vec3(4.0f, 2.0f, 1.0f));
        m.emissive_texture.texture = 0;
        const auto textured = tp::map_gltf_material(m, vec3(0.5f, 0.25f, 1.0f));
        check_near(textured.material.ke, vec3(2.0f, 0.5f, 1.0f));
        CHECK(mentions(textured.dropped, "emissiveTexture"));
    }
    SECTION("what is not rendered is listed") {
        GltfMaterial m = pbr(one, 0.5f, 1.0f);
        m.alpha_mode = "BLEND";
        m.base_color_texture.texture = 0;
        m.unused = {"normalTexture", "KHR_materials_clearcoat"};
        const auto r = tp::map_gltf_material(m, none);
        CHECK(r.uses_base_color_texture);
        CHECK(mentions(r.dropped, "alphaMode BLEND"));
        CHECK(mentions(r.dropped, "normalTexture"));
        CHECK(mentions(r.dropped, "KHR_materials_clearcoat"));
        CHECK(mentions(r.dropped, "baseColorTexture: tints the diffuse part only"));
        m.metallic = 1.0f;
        m.roughness = 0.0f;
        const auto mirror = tp::map_gltf_material(m, none);
        CHECK_FALSE(mirror.uses_base_color_texture);
        CHECK(mentions(mirror.dropped, "baseColorTexture"));
    }
}

TEST_CASE("glTF roughness to Phong exponent: Walter's relation and the lobe widths",
          "[unit][gltf]") {
    for (double r : {1.0, 0.8, 0.5, 0.3, 0.2, 0.1, 0.05}) {
        CAPTURE(r);
        // Walter et al. 2007, section 5.2: a_p = 2 / alpha^2 - 2 with glTF's alpha = r^2.
        const double alpha = r * r, a_p = 2.0 / (alpha * alpha) - 2.0;
        const double ns = tp::gltf_phong_exponent(float(r));
        CHECK(ns == Approx(a_p / 4.0).epsilon(1e-6).margin(1e-6));
        if (a_p < 50.0) continue;
        // The factor 1/4: where the half-vector lobe cos^a_p(theta) has fallen to one half,
        // the mirror-direction lobe cos^ns(2 theta) has too (angles small for a_p >= 50: the
        // two agree to a few percent; with a factor 1/2 or 1 it would be 0.25 or 0.06).
        const double theta = std::acos(std::pow(0.5, 1.0 / a_p));
        CHECK(std::pow(std::cos(2.0 * theta), ns) == Approx(0.5).epsilon(0.05));
    }
}

TEST_CASE("every glTF material in range maps to one that conserves energy", "[unit][gltf]") {
    // validate_material (scene.h) rejects Kd + Ks > 1 per channel; the rule must never produce
    // it from valid input (factors in [0, 1], specular colour and ior unbounded above).
    for (float metallic : {0.0f, 0.3f, 1.0f})
        for (float roughness : {0.0f, 0.5f, 1.0f})
            for (float base : {0.0f, 0.7f, 1.0f})
                for (float spec : {0.0f, 1.0f})
                    for (float spec_color : {0.0f, 1.0f, 1000.0f})
                        for (float ior : {1.0f, 1.5f, 100.0f}) {
                            GltfMaterial m = pbr(vec3(base, 1.0f, 0.0f), metallic, roughness);
                            m.specular = spec;
                            m.specular_color = vec3(spec_color);
                            m.ior = ior;
                            const auto r = tp::map_gltf_material(m, vec3(1.0f));
                            CHECK_NOTHROW(tp::validate_material(r.material, "grid"));
                        }
}
