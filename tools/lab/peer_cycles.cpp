#include "tools/lab/peer_cycles.h"

#include "image/exr_io.h"
#include "tools/lab/cycles_script.h"
#include "tools/lab/peer_scene.h"
#include "util/json_file.h"
#include "util/output_file.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp::lab {
namespace {

json rgb(const vec3& v) {
    return json::array({v.x, v.y, v.z});
}

const char* material_kind(uint32_t type) {
    return type == MATERIAL_MIRROR       ? "mirror"
           : type == MATERIAL_DIELECTRIC ? "dielectric"
                                         : "phong";
}

// Texture t as an EXR of its linear texels, top row first (image/texture.h's layout, which is
// also how Blender shows an image: uv (0, 0) at the bottom left, as twinpath's uv_to_image).
std::string write_texture(const FlatScene& s, size_t t, bool srgb, const std::string& dir) {
    const TextureInfo& info = s.textures[t];
    ExrImage img;
    img.width = int(info.width);
    img.height = int(info.height);
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        std::vector<float>& ch = img.channels[names[c]];
        ch.resize(size_t(info.width) * info.height);
        for (size_t i = 0; i < ch.size(); ++i) ch[i] = flat_texel_linear(s, uint32_t(t), i, srgb)[c];
    }
    const std::string path = (fs::path(dir) / fmt::format("texture{}.exr", t)).string();
    write_exr(path, img);
    return path;
}

// The seconds of a progress line's "Time:[HH:]MM:SS.cc", or -1.
double progress_time(const std::string& line) {
    const size_t at = line.find("| Time:");
    if (at == std::string::npos) return -1;
    double seconds = 0;
    for (size_t i = at + 7; i < line.size();) {
        size_t used = 0;
        seconds = seconds * 60.0 + std::stod(line.substr(i), &used);
        i += used;
        if (i >= line.size() || line[i] != ':') break;
        ++i;
    }
    return seconds;
}

} // namespace

std::string cycles_unsupported(const FlatScene& s) {
    if (s.params.env_light != NO_INDEX && s.params.env_texture != NO_TEXTURE)
        return "an environment map (the Cycles export writes a constant environment only)";
    for (const Material& m : s.materials)
        if (m.type == MATERIAL_PBR)
            return "a glTF material (the Cycles export writes Phong, mirror and glass; render "
                   "the .glb in Blender instead)";
    return "";
}

void write_cycles_scene(const FlatScene& s, const std::string& dir) {
    fs::create_directories(dir);
    const std::string obj = (fs::path(dir) / "scene.obj").string();
    write_obj(s, obj);

    json materials = json::array();
    std::vector<std::string> textures(s.textures.size());
    for (size_t i = 0; i < s.materials.size(); ++i) {
        const Material& m = s.materials[i];
        json j = {{"name", fmt::format("m{}", i)},
                  {"type", material_kind(m.type)},
                  {"kd", rgb(m.kd)},
                  {"ks", rgb(m.ks)},
                  {"ns", m.ns},
                  {"ke", rgb(m.ke)},
                  {"ior", m.ior},
                  {"tf", rgb(m.tf)}};
        if (m.kd_texture != NO_TEXTURE) {
            // The slot's image, decoded as the slot reads it; the export keeps OBJ's uv
            // convention, which the peer scenes' slots use (obj_texture_slot).
            const TextureSlot& slot = s.texture_slots[size_t(m.kd_texture)];
            std::string& path = textures[slot.image];
            if (path.empty())
                path = write_texture(s, slot.image, (slot.sampling & SLOT_SRGB) != 0u, dir);
            j["texture"] = path;
        }
        materials.push_back(j);
    }
    json lights = json::array();
    vec3 environment(0.0f);
    for (uint32_t i = 0; i < s.lights.size(); ++i) {
        const Light& l = s.lights[i];
        if (l.type == LIGHT_POINT)
            lights.push_back({{"type", "point"}, {"position", rgb(l.p0)}, {"value", rgb(l.value)}});
        else if (l.type == LIGHT_DIRECTIONAL)
            lights.push_back(
                {{"type", "directional"}, {"direction", rgb(l.p0)}, {"value", rgb(l.value)}});
        else if (l.type == LIGHT_ENVIRONMENT)
            environment = l.value;
        // LIGHT_TRIANGLE: the emissive triangles are in the OBJ with their material's Ke.
    }
    const Camera& c = s.params.camera;
    const json desc = {{"obj", obj},
                       {"materials", materials},
                       {"lights", lights},
                       {"environment", rgb(environment)},
                       {"camera",
                        {{"eye", rgb(c.eye)},
                         {"forward", rgb(c.forward)},
                         {"up", rgb(c.up)},
                         {"fov_y", 2.0 * std::atan(double(c.tan_half_fov_y)) * 180.0 / M_PI}}},
                       {"width", c.width},
                       {"height", c.height},
                       {"max_depth", s.params.max_depth}};
    write_json((fs::path(dir) / "scene.json").string(), desc);
    write_output_file((fs::path(dir) / "cycles_scene.py").string(), kCyclesScript);
}

CyclesRun run_cycles(const std::string& blender, const std::string& dir, const std::string& exr,
                     uint32_t spp, uint32_t seed, uint32_t threads, const std::string& log) {
    CyclesRun run;
    fs::remove(exr);
    fs::remove(log);
    run.process = run_process({blender, "-b", "--factory-startup", "-noaudio", "--python-exit-code",
                               "2", "-P", (fs::path(dir) / "cycles_scene.py").string(), "--",
                               (fs::path(dir) / "scene.json").string(), exr, std::to_string(spp),
                               std::to_string(seed), std::to_string(threads)},
                              log);
    if (run.process.exit_code == 0 && fs::exists(exr))
        run.image = load_rgb_image(exr);
    else if (run.process.exit_code == 0)
        run.process.exit_code = -1; // exited without an image
    std::ifstream in(log);
    const std::string total = fmt::format("/{}", spp);
    for (std::string line; std::getline(in, line);) {
        const size_t at = line.find("| Sample ");
        if (at == std::string::npos ||
            line.compare(line.size() - total.size(), total.size(), total) != 0)
            continue;
        const uint32_t k = uint32_t(std::stoul(line.substr(at + 9)));
        if (k >= 1 && run.first_sample_s < 0) {
            run.first_samples = k;
            run.first_sample_s = progress_time(line);
        }
        if (k == spp) run.finished_s = progress_time(line);
    }
    return run;
}

std::string cycles_version(const std::string& blender, const std::string& log) {
    const std::string out = log + ".version";
    fs::remove(out);
    const ProcessRun p = run_process({blender, "-b", "--factory-startup", "--version"}, out);
    std::ifstream in(out);
    std::string line;
    if (p.exit_code != 0 || !std::getline(in, line)) return "";
    return line;
}

} // namespace tp::lab
