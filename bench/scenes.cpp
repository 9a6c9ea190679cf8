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
    for (const std::string& f : sized_scene_families()) names += "," + f + "_N";
    return names;
}

std::string sized_scene_name(const SizedScene& s) {
    return s.family + "_" + std::to_string(s.copies);
}

std::optional<SizedScene> parse_sized_scene(const std::string& name) {
    for (const std::string& family : sized_scene_families()) {
        if (name.size() <= family.size() + 1 || name.compare(0, family.size() + 1, family + "_"))
            continue;
        const std::string n = name.substr(family.size() + 1);
        if (n.size() > 5 || n.find_first_not_of("0123456789") != std::string::npos || n[0] == '0')
            return std::nullopt;
        const unsigned long copies = std::stoul(n);
        if (copies > kMaxCopies) return std::nullopt;
        return SizedScene{family, uint32_t(copies)};
    }
    return std::nullopt;
}

std::string resolve_assets_dir(const std::string& option) {
    if (!option.empty()) return option;
    if (const char* env = std::getenv("TWINPATH_ASSETS")) return env;
    return TWINPATH_DEFAULT_ASSETS_DIR;
}

std::optional<Scene> load_bench_scene(const std::string& name, const std::string& assets_dir,
                                      const std::string& scene_dir, std::string& skip_reason) {
    std::vector<std::string> warnings; // the generated scenes are clean; files say their own
    if (const std::optional<CatalogueEntry> entry = find_catalogue_entry(name)) {
        const CatalogueEntry& e = *entry;
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
