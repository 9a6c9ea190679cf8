// The benchmark scenes. `cornell` is the bundled Cornell box; the others are rebuilt from the
// shared test meshes (../shared/assets, or --assets DIR / $TWINPATH_ASSETS where only the
// repository travels): the thesis's Table 5.3 set (`monkeys`, `bunny`, `buddhas`,
// `buddhas_instanced`) and the rtxON scene of the second seed (`rtxon`). Their JSON is
// generated here (scene_catalogue.cpp) and written to the cache directory, so that the bundled
// scene list the tests check (scenes/*.json) stays as it is, and any of them can be rendered
// again with `twinpath render <cache>/scenes/NAME.json`.
#pragma once

#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tp::bench {

struct CatalogueEntry {
    std::string name;
    std::string description;
    std::vector<std::string> assets; // files it needs, relative to the assets directory
    // The scene as JSON (docs/scene-format.md) with mesh paths under `assets_dir`; null for
    // a bundled scene, which is loaded by name.
    std::function<nlohmann::json(const std::string& assets_dir)> generate;
};

const std::vector<CatalogueEntry>& scene_catalogue();

// The scene-size axis (`bench --sizes --scene-sizes`): `<family>_<N>` is N distinct copies of
// one mesh (each its own mesh, loaded from the same file: no instancing) in a square grid on a
// floor, the camera taking in the whole grid. Families: `buddhas` (the 112k-triangle Happy
// Buddha) and `suzannes` (968 triangles, for tests).
struct SizedScene {
    std::string family;
    uint32_t copies = 0;
};
constexpr uint32_t kMaxCopies = 10000;
const std::vector<std::string>& sized_scene_families();
std::string sized_scene_name(const SizedScene& s); // "buddhas_30"
// The family and copies a name gives; nullopt for any other name (also for N outside 1 to
// kMaxCopies).
std::optional<SizedScene> parse_sized_scene(const std::string& name);
// The catalogue's fixed entries, then the sized scenes; nullopt for any other name.
std::optional<CatalogueEntry> find_catalogue_entry(const std::string& name);

// The catalogue's names, comma-separated (for help and error messages).
std::string catalogue_names();

// The assets directory: `option` if given, else $TWINPATH_ASSETS, else ../shared/assets next to
// the source tree this binary was built from.
std::string resolve_assets_dir(const std::string& option);

// Loads a catalogue scene or a .json/.obj scene file. A catalogue scene whose meshes are not
// in `assets_dir` is not loaded: the result is empty and `skip_reason` says which file is
// missing where. Generated scene files go to `scene_dir`. Throws InputError for a name that is
// neither in the catalogue nor a file.
std::optional<Scene> load_bench_scene(const std::string& name, const std::string& assets_dir,
                                      const std::string& scene_dir, std::string& skip_reason);

} // namespace tp::bench
