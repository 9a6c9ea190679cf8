// The white furnace (scenes/furnace.json): a closed sphere that emits radiance 1 everywhere
// inwards and reflects diffusely with albedo rho, seen from inside. Every path sees
// L = 1 + rho L, so every pixel is exactly 1 / (1 - rho), whatever the geometry, whatever the
// path depth; an unbiased renderer must agree to within its own error bars. This exercises
// next-event estimation to 1280 emissive triangles, MIS between light and BSDF sampling, the
// cosine sampler and Russian roulette from the first bounce (min_depth 0).
#include "cpu_ref/cpu_renderer.h"
#include "render/sampler.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "shared/rng.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

// A copy of the bundled furnace with wall albedo rho.
std::string furnace_with_albedo(double rho, const fs::path& dir) {
    nlohmann::json scene =
        nlohmann::json::parse(std::ifstream(fs::path(tp::test::scenes_dir()) / "furnace.json"));
    scene["materials"]["wall"]["Kd"] = {rho, rho, rho};
    const fs::path path = dir / ("furnace_" + std::to_string(rho) + ".json");
    std::ofstream(path) << scene.dump(2);
    return path.string();
}

} // namespace

TEST_CASE("furnace: every pixel's expectation is 1 / (1 - rho)", "[integration][furnace]") {
    // 16 x 16 pixels x 1024 samples. The image mean's standard error comes from the film's
    // variance of each pixel mean (pixels are independent: their random numbers differ),
    //   SE^2 = sum_i var_i / M^2 over the M pixels,
    // and the mean must lie within 3 SE of 1 / (1 - rho) in every channel. Each rho has its own
    // seed; the render is deterministic, so the test is reproducible. Both samplers: with
    // Sobol, var_i is the batch estimate (7 degrees of freedom per pixel, ~1800 over the
    // image, so the 3 SE bound is as good as normal).
    const fs::path dir = tp::test::temp_dir("furnace");
    const uint32_t size = 16, spp = 1024;
    for (const uint32_t sampler : {tp::SAMPLER_RANDOM, tp::SAMPLER_SOBOL})
        for (const double rho : {0.3, 0.8, 0.95}) {
            DYNAMIC_SECTION("rho = " << rho << ", sampler " << tp::sampler_name(sampler)) {
                std::vector<std::string> warnings;
                tp::Scene scene = tp::load_scene(furnace_with_albedo(rho, dir), warnings);
                tp::SceneOverrides o;
                o.width = size;
                o.height = size;
                o.spp = spp;
                tp::apply_overrides(scene, o);
                tp::RenderOptions opt;
                opt.seed = uint32_t(1000 * rho);
                opt.sampler = sampler;
                const tp::RenderResult r = tp::render_cpu(tp::flatten(scene), opt);
                CHECK(r.stats.nan_samples == 0);
                CHECK(r.stats.spp == spp);
                const double expected = 1.0 / (1.0 - rho);
                const double m = double(size) * size;
                for (int c = 0; c < 3; ++c) {
                    double mean = 0.0, var = 0.0;
                    for (uint32_t p = 0; p < size * size; ++p) {
                        REQUIRE(r.film.count(p) == spp);
                        mean += r.film.mean(p)[c] / m;
                        var += r.film.variance_of_mean(p)[c] / (m * m);
                    }
                    const double se = std::sqrt(var);
                    std::printf(
                        "furnace %s rho = %.2f channel %d: mean %.6f, expected %.6f, SE %.6f "
                        "(%.2f SE off)\n",
                        tp::sampler_name(sampler), rho, c, mean, expected, se,
                        (mean - expected) / se);
                    CAPTURE(rho, c, mean, expected, se);
                    CHECK(se > 0.0);
                    CHECK(std::abs(mean - expected) <= 3.0 * se);
                }
            }
        }
    fs::remove_all(dir);
}
