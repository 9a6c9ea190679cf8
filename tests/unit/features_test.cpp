// Scene feature analysis (scene/features.h) on every bundled scene (JSON and glTF), against
// what reading the scene files says they use; and the feature-restricted dispatch of
// shared/features.h, which must give the unrestricted result for every input its mask admits.
#include "scene/features.h"
#include "scene/load.h"
#include "shared/brdf.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

namespace fs = std::filesystem;

namespace {

tp::FlatScene flat(const std::string& name) {
    std::vector<std::string> warnings;
    return tp::flatten(tp::load_scene(name, warnings));
}

} // namespace

TEST_CASE("every bundled scene has the features its file describes", "[features]") {
    using namespace tp;
    // Read from scenes/*.json:
    //  cornell: Phong materials with Kd only, the "light" material has Ke; every mesh used once.
    //  cornell_glossy: cornell + five "cube" instances with Ks 0.8 (Ns 1..10000).
    //  cornell_spheres: the empty box's emitter, a mirror and a glass ball as two instances
    //           of "ball".
    //  furnace: one inward sphere of a Phong material with Kd and Ke; nothing else.
    //  spheres: floor with map_Kd "checker"; mirror, glass (dielectric) and a Phong ball with Ks
    //           0.5 as three instances of "ball"; a point and a directional light; a constant
    //           environment; nothing emissive.
    // Read from scenes/gltf_materials.gltf (docs/scene-format.md, "glTF materials"): every
    //  material glTF's own BSDF (pbr); textures on the floor (with a normal map), the leaf and
    //  the emissive panel; a leaf with alpha MASK and a pane with BLEND; an emissive panel, a
    //  directional and a spot KHR_lights_punctual light; 11 spheres naming one mesh's accessors.
    struct Case {
        const char* name;
        uint32_t mask;
    };
    const Case cases[] = {
        {"cornell", FEATURE_EMISSIVE_TRIANGLES},
        {"cornell_glossy",
         FEATURE_EMISSIVE_TRIANGLES | FEATURE_PHONG_SPECULAR | FEATURE_INSTANCING},
        {"cornell_spheres",
         FEATURE_EMISSIVE_TRIANGLES | FEATURE_MIRROR | FEATURE_DIELECTRIC | FEATURE_INSTANCING},
        {"furnace", FEATURE_EMISSIVE_TRIANGLES},
        {"spheres", FEATURE_TEXTURES | FEATURE_PHONG_SPECULAR | FEATURE_MIRROR |
                        FEATURE_DIELECTRIC | FEATURE_POINT_LIGHTS | FEATURE_DIRECTIONAL_LIGHTS |
                        FEATURE_ENV_CONSTANT | FEATURE_INSTANCING},
        {"gltf_materials", FEATURE_TEXTURES | FEATURE_PBR | FEATURE_NORMAL_MAPS | FEATURE_ALPHA |
                               FEATURE_EMISSIVE_TRIANGLES | FEATURE_POINT_LIGHTS |
                               FEATURE_DIRECTIONAL_LIGHTS | FEATURE_INSTANCING},
    };
    size_t bundled = 0;
    for (const auto& e : fs::directory_iterator(tp::test::scenes_dir()))
        bundled += e.path().extension() == ".json" || e.path().extension() == ".gltf" ||
                   e.path().extension() == ".glb";
    CHECK(bundled == std::size(cases)); // a new bundled scene needs its row here

    for (const Case& c : cases) {
        INFO(c.name);
        const SceneFeatures f = analyze_features(flat(c.name));
        CHECK(f.summary() == SceneFeatures{c.mask}.summary());
        CHECK(f.mask == c.mask);
        CHECK(render_feature_mask(flat(c.name), true) == FEATURES_ALL);
        CHECK(render_feature_mask(flat(c.name), false) == c.mask);
    }
    CHECK(SceneFeatures{0}.summary() == "none");
    CHECK(SceneFeatures{FEATURES_ALL}.names().size() == FEATURE_COUNT);
    CHECK(SceneFeatures{FEATURE_ENV_MAP | FEATURE_TEXTURES}.summary() ==
          "textures, environment_map");
}

TEST_CASE("a material or light no instance uses is not a feature", "[features]") {
    using namespace tp;
    FlatScene f = flat("cornell");
    Material mirror = f.materials[0];
    mirror.type = MATERIAL_MIRROR;
    f.materials.push_back(mirror); // defined but used by no instance
    CHECK(analyze_features(f).mask == FEATURE_EMISSIVE_TRIANGLES);
    f.instances[0].material = uint32_t(f.materials.size() - 1);
    CHECK(analyze_features(f).mask == (FEATURE_EMISSIVE_TRIANGLES | FEATURE_MIRROR));
    f.params.env_light = 0;
    f.params.env_texture = 0;
    CHECK(analyze_features(f).has(FEATURE_ENV_MAP));
    CHECK_FALSE(analyze_features(f).has(FEATURE_ENV_CONSTANT));
}

TEST_CASE("the restricted dispatch equals the full one wherever its mask admits the input",
          "[features]") {
    using namespace tp;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const auto unit = [&] {
        return glm::normalize(vec3(u01(rng) - 0.5f, u01(rng) - 0.5f, u01(rng) - 0.5f));
    };
    for (int i = 0; i < 20000; ++i) {
        Material m{};
        m.kd = vec3(u01(rng), u01(rng), u01(rng)) * 0.9f;
        m.ns = 10.0f;
        m.ior = 1.5f;
        m.tf = vec3(1.0f);
        const vec3 n = unit(), wo = unit(), wi = unit();
        const float ul = u01(rng);
        const vec2 ud(u01(rng), u01(rng));
        // Diffuse-only Phong: the Lambert path without FEATURE_PHONG_SPECULAR.
        const uint32_t diffuse = FEATURE_EMISSIVE_TRIANGLES;
        CHECK(bsdf_eval_in(diffuse, m, n, wo, wi) == bsdf_eval(m, n, wo, wi));
        CHECK(bsdf_pdf_in(diffuse, m, n, wo, wi) == bsdf_pdf(m, n, wo, wi));
        const BsdfSample a = bsdf_sample_in(diffuse, m, n, wo, ul, ud),
                         b = bsdf_sample(m, n, wo, ul, ud);
        CHECK(a.lobe == b.lobe);
        CHECK(a.wi == b.wi);
        CHECK(a.pdf == b.pdf);
        CHECK(a.weight == b.weight);
        CHECK_FALSE(material_is_delta_in(diffuse, m));
        // Every material type under the full mask and under the mask that names it.
        m.ks = vec3(0.05f);
        for (uint32_t type : {MATERIAL_PHONG, MATERIAL_MIRROR, MATERIAL_DIELECTRIC}) {
            m.type = type;
            const uint32_t own = type == MATERIAL_MIRROR       ? FEATURE_MIRROR
                                 : type == MATERIAL_DIELECTRIC ? FEATURE_DIELECTRIC
                                                               : FEATURE_PHONG_SPECULAR;
            for (uint32_t mask : {FEATURES_ALL, own}) {
                const BsdfSample x = bsdf_sample_in(mask, m, n, wo, ul, ud),
                                 y = bsdf_sample(m, n, wo, ul, ud);
                CHECK(x.lobe == y.lobe);
                CHECK(x.wi == y.wi);
                CHECK(bsdf_eval_in(mask, m, n, wo, wi) == bsdf_eval(m, n, wo, wi));
                CHECK(bsdf_pdf_in(mask, m, n, wo, wi) == bsdf_pdf(m, n, wo, wi));
                CHECK(material_is_delta_in(mask, m) == material_is_delta(m));
            }
        }
    }
    // Lights: each type under its own bit gives sample_light's answer; a masked-out type none.
    Light l{};
    l.p0 = vec3(0.0f, 1.0f, 0.0f);
    l.p1 = vec3(1.0f, 1.0f, 0.0f);
    l.p2 = vec3(0.0f, 1.0f, 1.0f);
    l.area = 0.5f;
    l.value = vec3(2.0f);
    const vec3 p(0.2f, 0.0f, 0.1f);
    const vec2 u(0.3f, 0.6f);
    for (uint32_t type : {LIGHT_POINT, LIGHT_DIRECTIONAL, LIGHT_TRIANGLE, LIGHT_ENVIRONMENT}) {
        l.type = type;
        const uint32_t own = type == LIGHT_POINT         ? FEATURE_POINT_LIGHTS
                             : type == LIGHT_DIRECTIONAL ? FEATURE_DIRECTIONAL_LIGHTS
                             : type == LIGHT_TRIANGLE    ? FEATURE_EMISSIVE_TRIANGLES
                                                         : FEATURE_ENV_CONSTANT;
        const LightSample full = sample_light(l, p, u, false);
        for (uint32_t mask : {FEATURES_ALL, own}) {
            const LightSample s = sample_light_in(mask, l, p, u, false);
            CHECK(s.wi == full.wi);
            CHECK(s.pdf == full.pdf);
            CHECK(s.radiance == full.radiance);
            CHECK(s.delta == full.delta);
        }
    }
    CHECK(features_mis(FEATURE_POINT_LIGHTS | FEATURE_DIRECTIONAL_LIGHTS) == false);
    CHECK(features_mis(FEATURE_ENV_CONSTANT));
    CHECK(features_sample_lights(FEATURE_TEXTURES | FEATURE_MIRROR | FEATURE_INSTANCING) == false);
}
