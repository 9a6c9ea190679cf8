// twinpath info [--json]: what this build can do and which devices it sees.
// twinpath info SCENE [--json]: what the scene holds and which features it uses (the
// scene features the renderers specialize their path loop to, docs/gpu.md), each material as the
// engines see it with its texture slots, each explicit light (for glTF also in the file's
// photometric units), and, for glTF, what the file gives that a path tracer ignores and what is
// not rendered (docs/scene-format.md), and the load time.
#include "commands.h"

#include "scene/features.h"
#include "scene/flatten.h"
#include "scene/gltf_loader.h"
#include "scene/load.h"
#include "shared/math.h"
#include "util/clock.h"
#include "util/error.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <embree3/rtcore.h>

namespace tp {
namespace {

// The Vulkan devices as JSON; {"error": ...} instead when there is no usable Vulkan.
nlohmann::json vulkan_json() {
    nlohmann::json v;
    try {
        v["devices"] = nlohmann::json::array();
        for (const DeviceInfo& d : list_vulkan_devices()) {
            nlohmann::json j;
            j["index"] = d.index;
            j["name"] = d.name;
            j["type"] = d.type;
            j["api_version"] = d.api_version;
            j["driver"] = d.driver;
            j["memory_bytes"] = d.memory_bytes;
            j["modes"] = nlohmann::json::array();
            for (const VkMode m : d.modes()) j["modes"].push_back(vk_mode_name(m));
            if (d.compute()) j["auto_mode"] = vk_mode_name(resolve_vk_mode(std::nullopt, d));
            if (!d.compute()) j["compute_missing"] = d.compute_missing;
            if (!d.pipeline()) j["pipeline_missing"] = d.pipeline_missing;
            v["devices"].push_back(j);
        }
    } catch (const RuntimeError& e) {
        v = {{"error", e.what()}};
    }
    return v;
}

std::string rgb(const vec3& c) {
    return fmt::format("({:.4g}, {:.4g}, {:.4g})", c.x, c.y, c.z);
}

// What a material is, as the engines see it: "phong Kd (0.5, 0.5, 0.5) Ks (0.04, ...) Ns 7.5",
// "pbr base colour (0.8, 0.8, 0.8) metallic 0 roughness 0.5 ior 1.5 ...".
std::string describe(const Material& m) {
    std::string s;
    if (m.type == MATERIAL_MIRROR) s = "mirror Ks " + rgb(m.ks);
    if (m.type == MATERIAL_DIELECTRIC)
        s = fmt::format("dielectric Ni {:.4g} Tf {}", m.ior, rgb(m.tf));
    if (m.type == MATERIAL_PHONG) {
        s = "phong Kd " + rgb(m.kd);
        if (!is_black(m.ks)) s += fmt::format(" Ks {} Ns {:.4g}", rgb(m.ks), m.ns);
    }
    if (m.type == MATERIAL_PBR) {
        s = fmt::format("pbr base colour {} metallic {:.4g} roughness {:.4g} ior {:.4g} "
                        "transmission {:.4g} specular {:.4g} specular colour {}",
                        rgb(m.kd), m.metallic, m.roughness, m.ior, m.transmission, m.specular,
                        rgb(m.ks));
        if ((m.flags & MATERIAL_FLAG_VOLUME) == 0u)
            s += " thin";
        else if (m.attenuation_distance < FLOAT_MAX)
            s += fmt::format(" volume (attenuation colour {} at {:.4g} m)", rgb(m.tf),
                             m.attenuation_distance);
        else
            s += " volume (no attenuation)";
        if (m.alpha_mode == ALPHA_OPAQUE) s += " opaque";
        if (m.alpha_mode == ALPHA_MASK)
            s += fmt::format(" alpha mask (alpha {:.4g}, cutoff {:.4g})", m.alpha, m.alpha_cutoff);
        if (m.alpha_mode == ALPHA_BLEND) s += fmt::format(" alpha blend (alpha {:.4g})", m.alpha);
        if (m.normal_texture != NO_TEXTURE)
            s += fmt::format(" normal scale {:.4g}", m.normal_scale);
    }
    if (!is_black(m.ke)) s += " Ke " + rgb(m.ke);
    return s;
}

const char* wrap_name(uint32_t wrap) {
    return wrap == SLOT_WRAP_CLAMP ? "clamp" : wrap == SLOT_WRAP_MIRROR ? "mirror" : "repeat";
}

// A texture slot of a material as JSON: what reads it, the image, the uv set, the sampler and
// the map from uv to image coordinates.
nlohmann::json slot_json(const char* use, int slot, const Scene& scene) {
    const TextureSlot& ts = scene.texture_slots[size_t(slot)];
    const Texture& image = scene.textures[ts.image];
    nlohmann::json j = {{"slot", use},
                        {"image", image.name},
                        {"width", image.width},
                        {"height", image.height},
                        {"uv_set", (ts.sampling & SLOT_UV1) != 0u ? 1 : 0},
                        {"wrap_s", wrap_name(ts.sampling & 3u)},
                        {"wrap_t", wrap_name((ts.sampling >> SLOT_WRAP_T_SHIFT) & 3u)},
                        {"filter", (ts.sampling & SLOT_NEAREST) != 0u ? "nearest" : "bilinear"},
                        {"srgb", (ts.sampling & SLOT_SRGB) != 0u}};
    const vec3 s = ts.transform_s, t = ts.transform_t;
    if (s != vec3(1.0f, 0.0f, 0.0f) || t != vec3(0.0f, 1.0f, 0.0f))
        j["transform"] = {{s.x, s.y, s.z}, {t.x, t.y, t.z}};
    return j;
}

// An affine form a u + b v + c as "2 u + 0.25", "1 - v".
std::string affine(const nlohmann::json& row) {
    const char* names[] = {"u", "v", ""};
    std::string s;
    for (int k = 0; k < 3; ++k) {
        const float c = row[k].get<float>();
        if (c == 0.0f) continue;
        const float m = std::abs(c);
        const std::string term = m == 1.0f && k < 2 ? names[k]
                                 : k < 2            ? fmt::format("{:.4g} {}", m, names[k])
                                                    : fmt::format("{:.4g}", m);
        s += s.empty() ? (c < 0.0f ? "-" : "") + term : (c < 0.0f ? " - " : " + ") + term;
    }
    return s.empty() ? "0" : s;
}

// "'wood.png' 512x512, uv 0, repeat/clamp, bilinear, sRGB, s = 2 u + 0.25, t = 2 v"
std::string slot_text(const nlohmann::json& j) {
    std::string s =
        fmt::format("'{}' {}x{}, uv {}, {}/{}, {}{}", j["image"].get<std::string>(),
                    j["width"].get<uint32_t>(), j["height"].get<uint32_t>(), j["uv_set"].get<int>(),
                    j["wrap_s"].get<std::string>(), j["wrap_t"].get<std::string>(),
                    j["filter"].get<std::string>(), j["srgb"].get<bool>() ? ", sRGB" : ", linear");
    if (j.contains("transform"))
        s += ", s = " + affine(j["transform"][0]) + ", t = " + affine(j["transform"][1]);
    return s;
}

nlohmann::json material_textures(const Material& m, const Scene& scene) {
    const std::pair<const char*, int> slots[] = {
        {m.type == MATERIAL_PBR ? "base colour" : "Kd", m.kd_texture},
        {"metallic-roughness", m.metallic_roughness_texture},
        {"normal", m.normal_texture},
        {"emissive", m.emissive_texture},
        {"transmission", m.transmission_texture},
        {"specular", m.specular_texture},
        {"specular colour", m.specular_color_texture}};
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [use, slot] : slots)
        if (slot != NO_TEXTURE && (m.type == MATERIAL_PBR || slot == m.kd_texture))
            list.push_back(slot_json(use, slot, scene));
    return list;
}

bool is_gltf(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    return ext == ".gltf" || ext == ".glb";
}

// An explicit light in twinpath's units and, for glTF, in the file's (candela or lux,
// scene/gltf_loader.h).
nlohmann::json light_json(const LightDesc& l, bool gltf) {
    const bool directional = l.type == LIGHT_DIRECTIONAL;
    nlohmann::json j = {{"type", directional            ? "directional"
                                 : l.type == LIGHT_SPOT ? "spot"
                                                        : "point"},
                        {"value", {l.value.x, l.value.y, l.value.z}},
                        {"unit", directional ? "W/m^2" : "W/sr"}};
    if (gltf) {
        const glm::dvec3 v = glm::dvec3(l.value) * kGltfLumensPerWatt;
        j["file_value"] = {v.x, v.y, v.z};
        j["file_unit"] = directional ? "lx" : "cd";
    }
    if (directional)
        j["direction"] = {l.direction.x, l.direction.y, l.direction.z}; // towards the light
    else
        j["position"] = {l.position.x, l.position.y, l.position.z};
    if (l.type == LIGHT_SPOT) {
        j["direction"] = {l.direction.x, l.direction.y, l.direction.z}; // along the axis
        j["inner_cone_degrees"] = glm::degrees(double(l.inner_cone));
        j["outer_cone_degrees"] = glm::degrees(double(l.outer_cone));
    }
    return j;
}

// "(x, y, z)"; adding 0 turns a negative zero (a negated axis) into 0.
std::string triple(const nlohmann::json& v) {
    return fmt::format("({:.4g}, {:.4g}, {:.4g})", v[0].get<double>() + 0.0,
                       v[1].get<double>() + 0.0, v[2].get<double>() + 0.0);
}

std::string light_text(const nlohmann::json& l) {
    const std::string type = l["type"];
    std::string s = type + " " +
                    (type == "directional" ? "towards " + triple(l["direction"])
                                           : "at " + triple(l["position"])) +
                    ": " + triple(l["value"]) + " " + l["unit"].get<std::string>();
    if (l.contains("file_value"))
        s += fmt::format(" ({} {} in the file)", triple(l["file_value"]),
                         l["file_unit"].get<std::string>());
    if (type == "spot")
        s += fmt::format(", shining along {}, cone {:.4g} to {:.4g} degrees",
                         triple(l["direction"]), l["inner_cone_degrees"].get<double>(),
                         l["outer_cone_degrees"].get<double>());
    return s;
}

// The list `i` of a per-material list of lists that may be empty.
std::vector<std::string> of_material(const std::vector<std::vector<std::string>>& lists, size_t i) {
    return i < lists.size() ? lists[i] : std::vector<std::string>{};
}

// The scene's size, lights and features, its materials and what its file gave that is not
// rendered or that a path tracer ignores (glTF).
int scene_info(const std::string& path, bool json_out) {
    std::vector<std::string> warnings;
    const auto t0 = std::chrono::steady_clock::now();
    const Scene scene = load_scene(path, warnings);
    const double load_seconds = seconds_since(t0);
    for (const std::string& w : warnings) fmt::print(stderr, "twinpath: warning: {}\n", w);
    const FlatScene f = flatten(scene);
    const SceneFeatures features = analyze_features(f);
    nlohmann::json j;
    j["scene"] = scene.path;
    j["instances"] = f.instances.size();
    j["meshes"] = f.meshes.size();
    j["materials"] = f.materials.size();
    j["textures"] = f.textures.size();
    j["triangles"] = f.instanced_triangles;
    j["unique_triangles"] = f.unique_triangles;
    j["dielectric_interfaces"] = f.dielectric_interfaces;
    j["lights"] = f.lights.size();
    j["features"] = features.names();
    j["feature_mask"] = features.mask;
    j["material_list"] = nlohmann::json::array();
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& mat = scene.materials[i];
        nlohmann::json m = {{"name", scene.material_names[i]}, {"became", describe(mat)}};
        m["textures"] = material_textures(mat, scene);
        m["ignored"] = of_material(scene.material_ignored, i);
        m["dropped"] = of_material(scene.material_dropped, i);
        j["material_list"].push_back(m);
    }
    j["light_list"] = nlohmann::json::array();
    for (const LightDesc& l : scene.lights)
        j["light_list"].push_back(light_json(l, is_gltf(scene.path)));
    j["ignored"] = scene.ignored;
    j["dropped"] = scene.dropped;
    j["load_seconds"] = load_seconds; // reading the file into the scene model
    if (json_out) {
        fmt::print("{}\n", j.dump(2));
        return 0;
    }
    fmt::print("{}\n  {} instances of {} meshes, {} triangles ({} stored), {} materials, {} "
               "textures, {} lights\n  features: {}\n",
               scene.path, f.instances.size(), f.meshes.size(), f.instanced_triangles,
               f.unique_triangles, f.materials.size(), f.textures.size(), f.lights.size(),
               features.summary());
    if (f.dielectric_interfaces > 0)
        fmt::print("  {} coincident dielectric faces merged into interfaces\n",
                   f.dielectric_interfaces);
    fmt::print("  materials:\n");
    for (const nlohmann::json& m : j["material_list"]) {
        fmt::print("    {}: {}\n", m["name"].get<std::string>(), m["became"].get<std::string>());
        for (const auto& t : m["textures"])
            fmt::print("      {} texture: {}\n", t["slot"].get<std::string>(), slot_text(t));
        for (const auto& d : m["ignored"]) fmt::print("      {}\n", d.get<std::string>());
        for (const auto& d : m["dropped"])
            fmt::print("      not rendered: {}\n", d.get<std::string>());
    }
    if (!j["light_list"].empty()) fmt::print("  lights:\n");
    for (const nlohmann::json& l : j["light_list"]) fmt::print("    {}\n", light_text(l));
    for (const std::string& d : scene.ignored) fmt::print("  {}\n", d);
    for (const std::string& d : scene.dropped) fmt::print("  not rendered: {}\n", d);
    return 0;
}

} // namespace

Subcommand add_info_command(CLI::App& app) {
    auto json_out = std::make_shared<bool>(false);
    auto scene = std::make_shared<std::string>();
    CLI::App* c = app.add_subcommand(
        "info", "Show the build, the CPU backend and the Vulkan devices, or a scene's features");
    c->add_option("scene", *scene, "Scene file or bundled name: show its contents and features");
    c->add_flag("--json", *json_out, "Machine-readable output");
    return {c, [json_out, scene] {
                if (!scene->empty()) return scene_info(*scene, *json_out);
                nlohmann::json j;
                j["version"] = TWINPATH_VERSION;
                j["backends"]["cpu"] = {{"embree", RTC_VERSION_STRING}};
                j["backends"]["vulkan"] = vulkan_json();
                if (*json_out) {
                    fmt::print("{}\n", j.dump(2));
                    return 0;
                }
                fmt::print("twinpath {}\n  cpu: Embree {} + TBB\n", TWINPATH_VERSION,
                           RTC_VERSION_STRING);
                const nlohmann::json& v = j["backends"]["vulkan"];
                if (v.contains("error")) {
                    fmt::print("  vulkan: unavailable: {}\n", v["error"].get<std::string>());
                    return 0;
                }
                fmt::print("  vulkan: {} device(s)\n", v["devices"].size());
                for (const nlohmann::json& d : v["devices"]) {
                    std::string modes;
                    for (const auto& m : d["modes"])
                        modes += (modes.empty() ? "" : ", ") + m.get<std::string>();
                    fmt::print("    [{}] {} ({}), Vulkan {}, {}; modes: {}{}\n",
                               d["index"].get<uint32_t>(), d["name"].get<std::string>(),
                               d["type"].get<std::string>(), d["api_version"].get<std::string>(),
                               d["driver"].get<std::string>(), modes.empty() ? "none" : modes,
                               d.contains("auto_mode")
                                   ? " (auto: " + d["auto_mode"].get<std::string>() + ")"
                                   : "");
                    if (d.contains("compute_missing"))
                        fmt::print("        compute mode needs: {}\n",
                                   d["compute_missing"].get<std::string>());
                    if (d.contains("pipeline_missing"))
                        fmt::print("        pipeline mode needs: {}\n",
                                   d["pipeline_missing"].get<std::string>());
                }
                return 0;
            }};
}

} // namespace tp
