#include "bench/scenes.h"

#include "scene/load.h"
#include "util/error.h"
#include "util/json_file.h"

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace tp::bench {

std::string catalogue_names() {
    std::string names;
    for (const CatalogueEntry& e : scene_catalogue()) names += (names.empty() ? "" : ",") + e.name;
    return names;
}

std::string resolve_assets_dir(const std::string& option) {
    if (!option.empty()) return option;
    if (const char* env = std::getenv("TWINPATH_ASSETS")) return env;
    return TWINPATH_DEFAULT_ASSETS_DIR;
}

std::optional<Scene> load_bench_scene(const std::string& name, const std::string& assets_dir,
                                      const std::string& scene_dir, std::string& skip_reason) {
    std::vector<std::string> warnings; // the generated scenes are clean; files say their own
    for (const CatalogueEntry& e : scene_catalogue()) {
        if (e.name != name) continue;
        if (!e.generate) {
            Scene s = load_scene(name, warnings);
            s.path = name;
            return s;
        }
        for (const std::string& file : e.assets)
            if (!fs::exists(fs::path(assets_dir) / file)) {
                skip_reason = fmt::format(
                    "scene '{}' needs {} from the shared test meshes, which is not in '{}' "
                    "(give --assets DIR or set TWINPATH_ASSETS)",
                    name, file, assets_dir);
                return std::nullopt;
            }
        fs::create_directories(scene_dir);
        const fs::path path = fs::path(scene_dir) / (name + ".json");
        write_json(path.string(), e.generate(fs::absolute(assets_dir).lexically_normal().string()));
        Scene s = load_scene(path.string(), warnings);
        s.path = name;
        return s;
    }
    if (fs::is_regular_file(name) || find_bundled_scene(name)) {
        Scene s = load_scene(name, warnings);
        for (const std::string& w : warnings) fmt::print(stderr, "twinpath: warning: {}\n", w);
        return s;
    }
    input_error("--scenes: '{}' is neither a benchmark scene ({}) nor a bundled scene or "
                ".json/.obj/.gltf/.glb file",
                name, catalogue_names());
}

} // namespace tp::bench
