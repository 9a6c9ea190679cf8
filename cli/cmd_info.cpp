// twinpath info [--json]: what this build can do and which devices it sees.
// twinpath info SCENE [--json]: what the scene holds and which features it uses (the
// scene features the renderers specialize their path loop to, docs/gpu.md), each material as the
// engines see it and, for glTF, what the file gives that is not rendered (docs/scene-format.md),
// and the load time.
#include "commands.h"

#include "scene/features.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "shared/math.h"
#include "util/clock.h"
#include "util/error.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <chrono>
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

// What a material is, as the engines see it: "phong Kd (0.5, 0.5, 0.5) Ks (0.04, ...) Ns 7.5".
std::string describe(const Material& m, const Scene& scene) {
    auto rgb = [](const vec3& c) { return fmt::format("({:.4g}, {:.4g}, {:.4g})", c.x, c.y, c.z); };
    std::string s;
    if (m.type == MATERIAL_MIRROR) s = "mirror Ks " + rgb(m.ks);
    if (m.type == MATERIAL_DIELECTRIC)
        s = fmt::format("dielectric Ni {:.4g} Tf {}", m.ior, rgb(m.tf));
    if (m.type == MATERIAL_PHONG) {
        s = "phong Kd " + rgb(m.kd);
        if (m.kd_texture != NO_TEXTURE)
            s += fmt::format(" x texture '{}'", scene.textures[size_t(m.kd_texture)].name);
        if (!is_black(m.ks)) s += fmt::format(" Ks {} Ns {:.4g}", rgb(m.ks), m.ns);
    }
    if (!is_black(m.ke)) s += " Ke " + rgb(m.ke);
    return s;
}

// The scene's size, lights and features, its materials and what its file gave that is not
// rendered (glTF).
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
        nlohmann::json m = {{"name", scene.material_names[i]},
                            {"became", describe(scene.materials[i], scene)}};
        m["dropped"] = i < scene.material_dropped.size() ? scene.material_dropped[i]
                                                         : std::vector<std::string>{};
        j["material_list"].push_back(m);
    }
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
        for (const auto& d : m["dropped"])
            fmt::print("      not rendered: {}\n", d.get<std::string>());
    }
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
