// The bundled scenes: the committed scenes/*.json and *.gltf are exactly what
// scenes/generate_scenes.py writes (the generator is the source of truth), and each loads,
// flattens and renders a few samples without a NaN.
#include "cpu_ref/cpu_renderer.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST_CASE("the bundled scene files are what scenes/generate_scenes.py writes",
          "[integration][scenes]") {
    const fs::path dir = tp::test::temp_dir("generated-scenes");
    const fs::path src = fs::path(tp::test::source_dir()) / "scenes";
    const auto r =
        tp::test::run("python3 " + tp::test::shell_quote((src / "generate_scenes.py").string()) +
                      " " + tp::test::shell_quote(dir.string()));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    size_t generated = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        ++generated;
        const fs::path committed = src / e.path().filename();
        CAPTURE(committed.string());
        REQUIRE(fs::exists(committed));
        CHECK(read(committed) == read(e.path()));
    }
    // And no committed scene that the generator no longer writes.
    size_t committed = 0;
    for (const auto& e : fs::directory_iterator(src))
        committed += e.path().extension() == ".json" || e.path().extension() == ".gltf";
    CHECK(generated == committed);
    CHECK(generated >= 4);
    fs::remove_all(dir);
}

TEST_CASE("every bundled scene loads and flattens and renders without NaN",
          "[integration][scenes]") {
    for (const char* name :
         {"cornell", "cornell_glossy", "cornell_spheres", "spheres", "furnace", "gltf_materials"}) {
        DYNAMIC_SECTION(name) {
            std::vector<std::string> warnings;
            tp::Scene scene = tp::load_scene(name, warnings);
            CHECK(warnings.empty());
            CHECK(scene.skipped_triangles == 0);
            tp::SceneOverrides o;
            o.width = 16;
            o.height = 12;
            o.spp = 8;
            tp::apply_overrides(scene, o);
            const tp::FlatScene flat = tp::flatten(scene);
            CHECK(flat.params.light_count > 0);
            const tp::RenderResult r = tp::render_cpu(flat, tp::RenderOptions{});
            CHECK(r.stats.nan_samples == 0);
            CHECK(r.stats.samples == 16u * 12u * 8u);
            double sum = 0.0;
            for (uint32_t p = 0; p < 16 * 12; ++p) sum += r.film.mean(p).x;
            CHECK(sum > 0.0); // something is lit
        }
    }
}
