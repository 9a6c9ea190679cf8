// H0 on real renderings: the CPU reference against itself with different seeds and thread
// counts. Renders are bit-identical for any thread count (cpu_renderer.h), so the thread
// count only proves that; the seeds make the images independent.
#include "rates.h"
#include "renders.h"

#include "compare/compare.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace tp;
using namespace tp::test;

TEST_CASE("size on real renders: independent CPU renders are consistent at the nominal rate",
          "[compare][renders]") {
    // 60 pairs per scene, 32x32 at 16 spp: cornell (diffuse, next-event estimation) and
    // spheres (glass and mirror caustics: the heavy-tailed case). The channels of a render are
    // correlated, which makes the Bonferroni combination conservative, so only the upper end
    // of the interval binds.
    for (const char* scene : {"cornell", "spheres"}) {
        const size_t n = 60;
        size_t rejected05 = 0, rejected01 = 0;
        for (uint32_t i = 0; i < n; ++i) {
            RenderSpec a, b;
            a.scene = b.scene = scene;
            a.width = b.width = a.height = b.height = 32;
            a.seed = 2 * i + 1;
            b.seed = 2 * i + 2;
            a.threads = 1;
            b.threads = 2;
            const CompareResult r =
                compare_images(render_cpu_image(a), render_cpu_image(b), CompareOptions{});
            rejected05 += r.p_value <= 0.05;
            rejected01 += r.p_value <= 0.01;
        }
        INFO(scene);
        INFO(describe_rate("alpha 0.05", rejected05, n, 0.05));
        INFO(describe_rate("alpha 0.01", rejected01, n, 0.01));
        CHECK(rejected05 <= binomial_interval99(n, 0.05).hi);
        CHECK(rejected01 <= binomial_interval99(n, 0.01).hi);
    }
}

TEST_CASE("thread count does not change a render: same seed, 1 and 2 threads, exact match",
          "[compare][renders]") {
    RenderSpec a;
    a.width = a.height = 32;
    a.threads = 1;
    RenderSpec b = a;
    b.threads = 2;
    const CompareResult r = compare_images(render_cpu_image(a), render_cpu_image(b), {});
    CHECK(r.p_value == 1.0);
    CHECK(r.metrics.all.mse == 0.0);
}

TEST_CASE("cross-backend: every bundled scene passes CPU vs CPU at alpha 0.01 (different "
          "seeds and threads)",
          "[compare][renders][cross-backend]") {
    // Through the command line, as a user runs it. compare_backends is the hook a CPU vs
    // Vulkan test calls with BackendRun{"vulkan", ...}.
    size_t scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(scenes_dir())) {
        if (entry.path().extension() != ".json") continue;
        const std::string scene = entry.path().stem().string();
        ++scenes;
        BackendRun a, b;
        a.seed = 11;
        a.threads = 1;
        b.seed = 12;
        b.threads = 2;
        const BackendComparison c = compare_backends(scene, 48, 48, 32, a, b, 0.01);
        INFO(scene << ":\n" << c.output);
        REQUIRE(c.render_exit_a == 0);
        REQUIRE(c.render_exit_b == 0);
        CHECK(c.compare_exit == 0);
        CHECK(c.result.value("verdict", "") == "consistent");
    }
    CHECK(scenes >= 4);
}
