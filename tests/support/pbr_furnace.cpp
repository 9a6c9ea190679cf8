#include "support/pbr_furnace.h"

#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace tp::test::pbr {

std::vector<FurnaceCase> furnace_cases() {
    const auto params = [](glm::dvec3 base, double metallic, double roughness) {
        Params p;
        p.base_color = base;
        p.metallic = metallic;
        p.roughness = roughness;
        return p;
    };
    std::vector<FurnaceCase> v;
    v.push_back({"gold, roughness 0.5", params({1.0, 0.766, 0.336}, 1.0, 0.5), 45.0, false, true});
    v.push_back(
        {"red plastic, roughness 0.2", params({0.8, 0.1, 0.1}, 0.0, 0.2), 0.0, false, false});
    v.push_back(
        {"half metallic, roughness 0.35", params({0.5, 0.6, 0.7}, 0.5, 0.35), 70.0, false, false});
    {
        Params p = params({0.3, 0.4, 0.2}, 0.0, 0.3);
        p.ior = 2.0;
        p.specular = 0.5;
        p.specular_color = {1.0, 0.5, 20.0};
        v.push_back({"coloured specular, ior 2", p, 45.0, false, true});
    }
    v.push_back({"smooth plastic", params({0.5, 0.5, 0.5}, 0.0, 0.0), 60.0, false, false});
    {
        Params p = params({0.9, 0.8, 0.7}, 0.0, 0.3);
        p.transmission = 1.0;
        v.push_back({"thin transmission, roughness 0.3", p, 45.0, false, true});
    }
    {
        Params p = params({1.0, 1.0, 1.0}, 0.0, 0.3);
        p.transmission = 1.0;
        p.volume = true;
        v.push_back({"volume from outside, roughness 0.3", p, 30.0, false, false});
    }
    {
        Params p = params({1.0, 0.9, 0.8}, 0.0, 0.4);
        p.transmission = 1.0;
        p.volume = true;
        p.ior = 1.0 / 1.5;
        v.push_back({"volume from inside, roughness 0.4", p, 20.0, true, true});
    }
    return v;
}

glm::dvec3 furnace_view(const FurnaceCase& c) {
    const double t = c.view_degrees * M_PI / 180.0;
    return glm::dvec3(std::sin(t), 0.0, std::cos(t));
}

std::string write_furnace_scene(const FurnaceCase& c, const std::string& dir) {
    using nlohmann::json;
    const Params& p = c.p;
    json m = {{"type", "pbr"},
              {"base_color", {p.base_color.x, p.base_color.y, p.base_color.z}},
              {"metallic", p.metallic},
              {"roughness", p.roughness},
              // The file gives the index inside over outside; a camera below sees 1 / that.
              {"ior", c.from_below ? 1.0 / p.ior : p.ior},
              {"transmission", p.transmission},
              {"specular", p.specular},
              {"specular_color", {p.specular_color.x, p.specular_color.y, p.specular_color.z}}};
    if (p.volume) m["thickness"] = 0.1;
    // The quad faces +y; the camera looks at its centre from the xy plane, view_degrees off the
    // normal, above it or (from_below) under it.
    const double t = c.view_degrees * M_PI / 180.0, side = c.from_below ? -1.0 : 1.0;
    const json scene = {
        {"camera",
         {{"eye", {10.0 * std::sin(t), side * 10.0 * std::cos(t), 0.0}},
          {"target", {0.0, 0.0, 0.0}},
          {"up", {0.0, 0.0, 1.0}},
          {"fov", 0.5}}},
        {"film", {{"width", 8}, {"height", 8}}},
        {"render", {{"spp", 1024}, {"max_depth", 1}, {"min_depth", 8}}},
        {"materials", {{"surface", m}}},
        {"meshes", {{"plane", {{"type", "quad"}}}}},
        {"objects",
         {{{"mesh", "plane"}, {"material", "surface"}, {"transform", {{"scale", 1000.0}}}}}},
        {"environment", {{"type", "constant"}, {"radiance", {1.0, 1.0, 1.0}}}}};
    std::string name;
    for (char ch : c.name) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    const std::string path = dir + "/" + name + ".json";
    std::ofstream(path) << scene.dump(2);
    return path;
}

ImageMean image_mean(const std::string& exr_path) {
    const ExrImage img = read_exr(exr_path);
    const char* rgb[3] = {"R", "G", "B"};
    const char* var[3] = {"variance.R", "variance.G", "variance.B"};
    ImageMean r;
    for (int c = 0; c < 3; ++c) {
        const std::vector<float>& v = img.channels.at(rgb[c]);
        const std::vector<float>& s = img.channels.at(var[c]);
        const double n = double(v.size());
        double mean = 0.0, var_sum = 0.0;
        for (size_t i = 0; i < v.size(); ++i) {
            mean += v[i] / n;
            var_sum += s[i] / (n * n);
        }
        r.mean[c] = mean;
        r.se[c] = std::sqrt(var_sum);
    }
    return r;
}

std::string write_debug_scene(const std::string& dir, bool textured, const char* alpha_mode) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "camera": { "eye": [0, 2.5, 3], "target": [0, 0.3, 0], "fov": 40 },
      "film": { "width": 16, "height": 16 },
      "render": { "spp": 4, "max_depth": 4, "min_depth": 2 },
      "materials": {
        "floor": { "type": "pbr", "base_color": [0.2, 0.4, 0.6], "metallic": 0.25,
                   "roughness": 0.45, "transmission": 0.3, "alpha": 0.6 },
        "ball": { "type": "pbr", "base_color": [0.9, 0.7, 0.3], "metallic": 1, "roughness": 0.3 }
      },
      "meshes": { "plane": { "type": "quad" }, "sphere": { "type": "sphere", "subdivisions": 3 } },
      "objects": [
        { "mesh": "plane", "material": "floor", "transform": { "scale": 3 } },
        { "mesh": "sphere", "material": "ball",
          "transform": { "translate": [0, 0.5, 0], "scale": 0.5 } }
      ],
      "lights": [ { "type": "point", "position": [1, 3, 1], "intensity": [5, 5, 5] } ],
      "environment": { "type": "constant", "radiance": [0.3, 0.3, 0.3] }
    })");
    scene["materials"]["floor"]["alpha_mode"] = alpha_mode;
    if (textured) {
        scene["textures"] = nlohmann::json::parse(R"({ "mr": { "generator": "checker",
            "size": 64, "checks": 4, "colors": [[0.9, 0.8, 0.5], [0.9, 0.2, 0.1]] } })");
        scene["materials"]["floor"]["metallic_roughness_texture"] = "mr";
    }
    const std::string path =
        dir + "/pbr_debug_" + alpha_mode + (textured ? "_textured" : "") + ".json";
    std::ofstream(path) << scene.dump(2);
    return path;
}

namespace {

// The floor's roughness and metallic: the factors, or their products with the checker's G and B
// (blends between the two at the checks' edges).
void check_floor_values(double r, double m, bool textured) {
    if (textured) {
        CHECK(r >= 0.45 * 0.2 - 1e-6);
        CHECK(r <= 0.45 * 0.8 + 1e-6);
        CHECK(m >= 0.25 * 0.1 - 1e-6);
        CHECK(m <= 0.25 * 0.5 + 1e-6);
    } else {
        CHECK(r == Approx(0.45));
        CHECK(m == Approx(0.25));
    }
}

} // namespace

std::pair<size_t, size_t> check_debug_log(const std::string& log, bool textured) {
    INFO(log);
    size_t floor_hits = 0, ball_hits = 0;
    const nlohmann::json j = tp::test::read_json(log);
    for (const auto& path : j["paths"])
        for (const auto& v : path["vertices"]) {
            if (v["event"] != "hit") continue;
            const double r = v["roughness"], m = v["metallic"];
            const double t = v["transmission"], al = v["alpha"];
            const std::vector<double> bc = v["base_color"];
            // The ball is the only metal (material indices follow the loader's order).
            if (m < 0.99) {
                ++floor_hits;
                check_floor_values(r, m, textured);
                CHECK(t == Approx(0.3));
                CHECK(al == Approx(0.6));
                CHECK_THAT(bc, Catch::Approx(std::vector<double>{0.2, 0.4, 0.6}).epsilon(1e-6));
            } else {
                ++ball_hits;
                CHECK(r == Approx(0.3));
                CHECK(m == Approx(1.0));
                CHECK(t == 0.0);
                CHECK(al == 1.0);
                CHECK_THAT(bc, Catch::Approx(std::vector<double>{0.9, 0.7, 0.3}).epsilon(1e-6));
            }
        }
    return {floor_hits, ball_hits};
}

void check_debug_aovs(const std::string& exr, bool textured) {
    INFO(exr);
    const ExrImage img = read_exr(exr);
    REQUIRE(img.channels.count("pbr.roughness"));
    REQUIRE(img.channels.count("pbr.metallic"));
    const std::vector<float>& mat = img.channels.at("id.material");
    const std::vector<float>& r = img.channels.at("pbr.roughness");
    const std::vector<float>& m = img.channels.at("pbr.metallic");
    size_t floor = 0, ball = 0, low = 0, high = 0;
    for (size_t i = 0; i < mat.size(); ++i) {
        if (mat[i] >= 0.0f && m[i] < 0.99f) {
            ++floor;
            check_floor_values(r[i], m[i], textured);
            low += r[i] < 0.2f;
            high += r[i] > 0.3f;
        } else if (mat[i] >= 0.0f) {
            ++ball;
            CHECK(r[i] == Approx(0.3));
            CHECK(m[i] == Approx(1.0));
        } else {
            CHECK(r[i] == 0.0f);
            CHECK(m[i] == 0.0f);
        }
    }
    CHECK(floor > 20);
    CHECK(ball > 10);
    if (textured) { // both checks in view: the texture applied, not the factor alone
        CHECK(low > 0);
        CHECK(high > 0);
    }
}

} // namespace tp::test::pbr
