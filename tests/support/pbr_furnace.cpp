#include "support/pbr_furnace.h"

#include "image/exr_io.h"

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

} // namespace tp::test::pbr
