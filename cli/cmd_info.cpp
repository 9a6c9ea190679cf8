// twinpath info [--json]: what this build can do and which devices it sees.
// twinpath info SCENE [--json]: what the scene holds and which features it uses (issue 9:
// the features the renderers specialize their path loop to).
#include "commands.h"

#include "scene/features.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "util/error.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

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

// The scene's size, lights and features.
int scene_info(const std::string& path, bool json_out) {
    std::vector<std::string> warnings;
    const Scene scene = load_scene(path, warnings);
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
