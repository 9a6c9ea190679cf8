// The glTF material's furnace on the CPU engine (tests/support/pbr_furnace.h): a flat surface
// under a constant white environment, rendered through the command line at max depth 1, shows
// its directional albedo, which pbr_reference.h computes from the specification's formulas by
// quadrature (good to 1e-5 and better, tests/unit/pbr_albedo_test.cpp). 8 x 8 pixels x 1024
// independent samples (--sampler random, so that each pixel's variance is the samples' own);
// the image mean must lie within 4 standard errors + 0.5 % of the albedo in every channel
// (8 materials x 3 channels: a correct renderer fails one check with probability 24 x 6.3e-5 at
// 4 SE alone; the seeds are fixed, so a run is reproducible). The 0.5 % also covers the albedo's
// change over the pixels' 0.25 degrees of view angle, which is second order in the mean.
#include "support/pbr_furnace.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

namespace tp::test {
namespace {

// Renders the cases that `transmitting` selects and checks each image mean against the albedo.
void check_furnaces(bool transmitting) {
    const std::string dir = temp_dir("pbr-furnace-cpu");
    uint32_t seed = 70;
    for (const pbr::FurnaceCase& c : pbr::furnace_cases()) {
        ++seed;
        if (c.transmits() != transmitting) continue;
        const std::string scene = pbr::write_furnace_scene(c, dir);
        const std::string out = dir + "/cpu.exr";
        const ProcessResult r = run(twinpath(fmt::format(
            "render {} --backend cpu --sampler random --seed {} -o {} --stats {}",
            shell_quote(scene), seed, shell_quote(out), shell_quote(dir + "/cpu.json"))));
        INFO(c.name << ": " << r.out);
        REQUIRE(r.exit_code == 0);
        CHECK(read_json(dir + "/cpu.json")["nan_samples"] == 0);
        const pbr::ImageMean img = pbr::image_mean(out);
        const pbr::QuadratureResult albedo = pbr::albedo(c.p, pbr::furnace_view(c));
        for (int ch = 0; ch < 3; ++ch) {
            const double a = albedo.value[ch];
            std::printf("furnace cpu %-36s %2.0f deg ch %d: image %.5f +- %.5f, albedo %.5f "
                        "(%+.2f SE, %+.3f %%)\n",
                        c.name.c_str(), c.view_degrees, ch, img.mean[ch], img.se[ch], a,
                        (img.mean[ch] - a) / img.se[ch], 100.0 * (img.mean[ch] - a) / a);
            CAPTURE(c.name, ch, img.mean[ch], img.se[ch], a);
            CHECK(std::abs(img.mean[ch] - a) <= 4.0 * img.se[ch] + 0.005 * a);
        }
    }
}

} // namespace

TEST_CASE("glTF material furnace: a flat surface renders its directional albedo on the CPU",
          "[integration][pbr]") {
    check_furnaces(false);
}

// Light that arrives through a transmitting surface (pbr_furnace.h, FurnaceCase::transmits):
// next-event estimation samples the environment below it and weighs it by |dot(ns, wi)|
// (common/shared/integrator.h, step 3): with the signed cosine such a sample would be
// subtracted and a thin-walled transmitter render darker than its albedo.
TEST_CASE("glTF material furnace through the surface on the CPU", "[integration][pbr]") {
    check_furnaces(true);
}

} // namespace tp::test
