// H0 on real renderings: the CPU reference against itself with different seeds and thread
// counts. Renders are bit-identical for any thread count (cpu_renderer.h), so the thread
// count only proves that; the seeds make the images independent.
#include "rates.h"
#include "renders.h"

#include "compare/compare.h"
#include "image/exr_io.h"
#include "render/sampler.h"
#include "shared/rng.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>

using namespace tp;
using namespace tp::test;

namespace {

// n null pairs: a and b with seeds seed + 2i and seed + 2i + 1. The count of false alarms at
// alpha 0.05 and 0.01 must be at or below the upper end of the 99% binomial interval (the
// whole test is valid; conservative where the channels correlate).
void check_null_pairs(const std::string& label, RenderSpec a, RenderSpec b, size_t n,
                      uint32_t seed) {
    size_t rejected05 = 0, rejected01 = 0;
    for (uint32_t i = 0; i < n; ++i) {
        a.seed = seed + 2 * i;
        b.seed = seed + 2 * i + 1;
        const CompareResult r =
            compare_images(render_cpu_image(a), render_cpu_image(b), CompareOptions{});
        rejected05 += r.p_value <= 0.05;
        rejected01 += r.p_value <= 0.01;
    }
    INFO(label);
    INFO(describe_rate("alpha 0.05", rejected05, n, 0.05));
    INFO(describe_rate("alpha 0.01", rejected01, n, 0.01));
    CHECK(rejected05 <= binomial_interval99(n, 0.05).hi);
    CHECK(rejected01 <= binomial_interval99(n, 0.01).hi);
}

} // namespace

TEST_CASE("size on real renders: independent CPU renders are consistent at the nominal rate",
          "[compare][renders]") {
    // 60 pairs per scene, 32x32 at 16 spp: cornell (diffuse, next-event estimation) and
    // spheres (glass and mirror caustics: the heavy-tailed case). The channels of a render are
    // correlated, which makes the Bonferroni combination conservative, so only the upper end
    // of the interval binds.
    for (const char* scene : {"cornell", "spheres"}) {
        RenderSpec a, b;
        a.sampler = b.sampler = SAMPLER_RANDOM;
        a.scene = b.scene = scene;
        a.width = b.width = a.height = b.height = 32;
        a.threads = 1;
        b.threads = 2;
        check_null_pairs(scene, a, b, 60, 1);
    }
}

TEST_CASE("size on real renders with the Sobol sampler: independent renders are consistent",
          "[compare][renders][batches]") {
    // As above with the Sobol sampler and its batch variance (docs/sampling.md) at 64 spp
    // (8 points in each of the 8 batches), so that the points within a batch are stratified;
    // cornell_spheres brings the caustics. 40 pairs per scene; only the upper end binds.
    for (const char* scene : {"cornell", "spheres", "cornell_spheres"}) {
        RenderSpec a;
        a.scene = scene;
        a.width = a.height = 32;
        a.spp = 64;
        a.sampler = SAMPLER_SOBOL;
        check_null_pairs(scene, a, a, 40, 3000);
    }
}

TEST_CASE("size on real renders with glTF's material: glossy caustics are consistent",
          "[compare][renders][batches][pbr]") {
    // cornell_spheres with its mirror a rough gold metal and its glass a rough transmitting
    // volume (pbr.h): the caustics under the small light become glossy, the GGX lobes add the
    // long tails of rare bright samples that the tile test's calibration must hold against.
    // As the Sobol case above: 64 spp in 8 batches, 40 pairs, only the upper end binds.
    const nlohmann::json pbr = {
        {"mirror",
         {{"type", "pbr"}, {"base_color", {1.0, 0.78, 0.34}}, {"metallic", 1}, {"roughness", 0.2}}},
        {"glass",
         {{"type", "pbr"},
          {"metallic", 0},
          {"roughness", 0.1},
          {"transmission", 1},
          {"ior", 1.5},
          {"thickness", 1}}}};
    RenderSpec a;
    a.scene = scene_with_materials("cornell_spheres", pbr, "pbr", temp_dir("null-pbr"));
    a.width = a.height = 32;
    a.spp = 64;
    a.sampler = SAMPLER_SOBOL;
    check_null_pairs("cornell_spheres, glTF's material", a, a, 40, 5000);
}

TEST_CASE("size on real renders at unequal spp: cornell_spheres (caustics), cornell and spheres "
          "at 1:1, 1:8, 1:64, both samplers",
          "[compare][renders][unequal-spp][batches]") {
    // The heavy-tailed case of docs/compare.md "Unequal sample counts": in cornell_spheres light
    // reaches the floor and walls through the glass sphere and off the mirror one, found only
    // by rare BSDF samples. A at 16 spp against B at 16 and 128, and A at 8 against B at 512,
    // independent seeds; before the borrowed variance (differences.h) 16 against 128 was
    // called different in 39 of 40 trials and 16 against 1024 in 20 of 20. cornell (no caustics)
    // and spheres (glass and mirror under a point light and a sun) check the existing scenes at 1:8
    // and 1:64. Trials fall with B's cost; the bound is the upper end of the 99% binomial interval
    // (the whole test is valid, conservative where the channels correlate). The Sobol sampler
    // (the default) lends B's sample_variance, the spread of its samples; borrowing n Var(mean)
    // instead, which B's stratified batches make small, rejected 4 of 20 Sobol pairs of cornell
    // at 16 against 128 spp at alpha 0.01 (docs/sampling.md). The random sampler's samples are
    // independent and it lends n Var(mean).
    const uint32_t sampler = GENERATE(SAMPLER_SOBOL, SAMPLER_RANDOM);
    struct Ratio {
        const char* scene;
        uint32_t spp_a, spp_b;
        size_t trials;
    };
    for (const Ratio ratio :
         {Ratio{"cornell_spheres", 16, 16, 20}, Ratio{"cornell_spheres", 16, 128, 30},
          Ratio{"cornell_spheres", 8, 512, 15}, Ratio{"cornell", 16, 128, 20},
          Ratio{"cornell", 8, 512, 8}, Ratio{"spheres", 16, 128, 20},
          Ratio{"spheres", 8, 512, 8}}) {
        RenderSpec a;
        a.scene = ratio.scene;
        a.width = a.height = 32;
        a.spp = ratio.spp_a;
        a.sampler = sampler;
        RenderSpec b = a;
        b.spp = ratio.spp_b;
        check_null_pairs(fmt::format("{}, {} against {} spp, {}", ratio.scene, ratio.spp_a,
                                     ratio.spp_b, sampler_name(sampler)),
                         a, b, ratio.trials, sampler == SAMPLER_SOBOL ? 5000 : 1000);
    }
}

TEST_CASE("unequal spp with caustics: 64 vs 4096 and 256 vs 2048 are consistent, the latter "
          "with a 2% brighter B is different",
          "[compare][renders][unequal-spp]") {
    // The pairs of the issue that found the defect (there at 256x256: the same per-pixel
    // statistics on fewer pixels; docs/compare.md has the full size). Scaling B by 1.02 (mean,
    // and both variances by 1.02^2) is the whole-image bias the 256-vs-2048 pair must find. Both
    // samplers. At 64 spp
    // the caustic pixels of A are too noisy for a 2% bias at this size (docs/compare.md,
    // "Power at unequal spp").
    struct Pair {
        uint32_t size, spp_a, spp_b;
    };
    const uint32_t sampler = GENERATE(SAMPLER_SOBOL, SAMPLER_RANDOM);
    for (const Pair pair : {Pair{32, 64, 4096}, Pair{48, 256, 2048}}) {
        RenderSpec a;
        a.sampler = sampler;
        a.scene = "cornell_spheres";
        a.width = a.height = pair.size;
        a.spp = pair.spp_a;
        a.seed = 5;
        RenderSpec b = a;
        b.spp = pair.spp_b;
        b.seed = 14;
        const RgbImage ia = render_cpu_image(a);
        RgbImage ib = render_cpu_image(b);
        const CompareResult same = compare_images(ia, ib, {});
        INFO(sampler_name(sampler)
             << ", " << pair.spp_a << " against " << pair.spp_b << " spp: p = " << same.p_value
             << ", global p = " << same.global.p_value);
        CHECK_FALSE(same.different);
        if (pair.spp_a != 256) continue;
        for (size_t c = 0; c < 3; ++c)
            for (size_t i = 0; i < ib.pixels(); ++i) {
                ib.mean[c][i] *= 1.02;
                ib.var[c][i] *= 1.02 * 1.02;
                if (ib.has_sample_variance()) ib.sample_var[c][i] *= 1.02 * 1.02;
            }
        const CompareResult brighter = compare_images(ia, ib, {});
        INFO("B x 1.02: p = " << brighter.p_value << ", global p = " << brighter.global.p_value);
        CHECK(brighter.different);
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

TEST_CASE("reference mode through the command line: a render against a 1024-spp reference "
          "without variance",
          "[compare][renders][cli]") {
    // cornell 32x32: the reference has 64x the samples of the 16-spp images (its ignored
    // noise inflates z^2 by 1/64) and its variance channels are removed, as an external
    // reference would come. A depth-1 render (no indirect light) must be found, darker.
    const std::string dir = temp_dir("reference-mode");
    RenderSpec ref;
    ref.width = ref.height = 32;
    ref.spp = 1024;
    ref.seed = 40;
    render_cpu_file(ref, dir + "/ref_var.exr");
    // A new image with the colour channels only (re-writing what read_exr returns would also
    // copy the header's standard float attributes, which write_exr cannot re-insert).
    const ExrImage with_var = read_exr(dir + "/ref_var.exr");
    ExrImage exact;
    exact.width = with_var.width;
    exact.height = with_var.height;
    for (const char* c : {"R", "G", "B"}) exact.channels[c] = with_var.channel(c);
    write_exr(dir + "/ref.exr", exact);
    RenderSpec img = ref;
    img.spp = 16;
    img.seed = 41;
    render_cpu_file(img, dir + "/img.exr");
    img.max_depth = 1;
    render_cpu_file(img, dir + "/direct.exr");

    auto compare = [&](const std::string& file) {
        const ProcessResult r =
            run(fmt::format("{} compare {} {} --json {}", shell_quote(twinpath_bin()),
                            shell_quote(dir + "/" + file), shell_quote(dir + "/ref.exr"),
                            shell_quote(dir + "/r.json")));
        INFO(r.out);
        return std::make_pair(r.exit_code, nlohmann::json::parse(std::ifstream(dir + "/r.json")));
    };
    const auto [ok_exit, ok] = compare("img.exr");
    CHECK(ok_exit == 0);
    CHECK(ok["mode"] == "reference");
    CHECK(ok["local"]["in_verdict"] == false);
    CHECK(ok["global"]["tile"] == 32); // ceil(sqrt(65536 / 16)) = 64: the whole image
    CHECK(ok["metrics"]["reference"] == "b");
    CHECK(ok["metrics"]["relmse"]["all"].get<double>() > 0.0);

    const auto [bad_exit, bad] = compare("direct.exr");
    CHECK(bad_exit == 1);
    for (const char* c : {"R", "G", "B"}) CHECK(bad["metrics"]["bias"][c].get<double>() < 0.0);
}
