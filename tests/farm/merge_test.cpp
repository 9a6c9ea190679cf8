// twinpath merge (compare/merge.h, docs/farm.md): the pooled variance against the variance of
// all samples computed directly, merged CPU parts against one render, and every refusal.
#include "compare/merge.h"
#include "image/exr_io.h"
#include "render/film.h"
#include "render/render_header.h"
#include "split_check.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

using namespace tp;
using tp::test::render_part;
using tp::test::run;
using tp::test::shell_quote;
using tp::test::twinpath;

namespace {

// A 1x1 render of the given samples as a twinpath part: mean and variance of the mean from
// the two-pass formulas.
ExrImage part_of(const std::vector<double>& x, uint64_t begin) {
    const double n = double(x.size());
    double mean = 0, ss = 0;
    for (double v : x) mean += v / n;
    for (double v : x) ss += (v - mean) * (v - mean);
    ExrImage img;
    img.width = img.height = 1;
    for (const char* c : {"R", "G", "B"}) {
        img.channels[c] = {float(mean)};
        img.channels[std::string("variance.") + c] = {float(ss / (n - 1) / n)};
    }
    img.integers[header::kSpp] = int64_t(x.size());
    img.strings[header::kSampleRanges] = format_sample_ranges({{0, begin, begin + x.size()}});
    img.strings[header::kSceneHash] = "0123456789abcdef";
    img.strings[header::kCamera] = "camera";
    img.strings[header::kSettings] = "settings";
    img.strings[header::kBackend] = "cpu/embree";
    img.strings[header::kVarianceEstimator] = kVarianceFromSamples;
    return img;
}

std::string merge_error(const std::vector<std::string>& files) {
    std::string args;
    for (const std::string& f : files) args += shell_quote(f) + " ";
    const auto r = run(twinpath("merge " + args + "-o " + shell_quote(files[0] + ".merged.exr")));
    INFO(r.out);
    CHECK(r.exit_code == 2);
    return r.out;
}

} // namespace

TEST_CASE("merge pools the variance of all samples, between-part spread included", "[farm]") {
    // Three parts of 5, 9 and 14 samples with different means (the second is shifted by 3),
    // so that averaging their variances of the mean would miss both the spread between them
    // and the larger total count.
    std::mt19937 rng(7);
    std::normal_distribution<double> g(1.0, 0.5);
    std::vector<std::vector<double>> samples = {{}, {}, {}};
    const size_t sizes[3] = {5, 9, 14};
    for (int k = 0; k < 3; ++k)
        for (size_t i = 0; i < sizes[k]; ++i) samples[k].push_back(g(rng) + (k == 1 ? 3.0 : 0.0));
    RenderMerger merger;
    std::vector<double> all;
    uint64_t begin = 0;
    double averaged = 0;
    for (int k = 0; k < 3; ++k) {
        const ExrImage p = part_of(samples[k], begin);
        averaged += double(p.channel("variance.R")[0]) / 3;
        merger.add("part" + std::to_string(k), p);
        begin += sizes[k];
        all.insert(all.end(), samples[k].begin(), samples[k].end());
    }
    const ExrImage m = merger.result();
    const ExrImage direct = part_of(all, 0);
    // The parts' float32 means and variances carry 2^-24 relative rounding each; 1e-6
    // relative bounds what that does to a mean and a variance of samples that spread by ~1.
    CHECK(m.channel("R")[0] == Approx(direct.channel("R")[0]).epsilon(1e-6));
    CHECK(m.channel("variance.G")[0] == Approx(direct.channel("variance.G")[0]).epsilon(1e-6));
    CHECK(std::fabs(double(m.channel("variance.G")[0]) - averaged) > 0.5 * averaged);
    CHECK(m.integers.at(header::kSpp) == 28);
    CHECK(m.strings.at(header::kSampleRanges) == "0:0-28");
    CHECK(m.integers.at(header::kSeed) == 0);
}

TEST_CASE("merge refuses another variance estimator and overlapping ranges", "[farm]") {
    RenderMerger merger;
    merger.add("a.exr", part_of({1.0, 2.0}, 0));
    ExrImage other = part_of({1.0, 2.0}, 2);
    other.strings[header::kVarianceEstimator] = "batches";
    CHECK_THROWS_WITH(merger.add("b.exr", other),
                      Catch::Contains("b.exr") && Catch::Contains("twinpath:variance_estimator"));
    CHECK_THROWS_WITH(merger.add("c.exr", part_of({1.0, 2.0, 3.0}, 1)),
                      Catch::Contains("c.exr") && Catch::Contains("overlap") &&
                          Catch::Contains("a.exr"));
}

TEST_CASE("CPU parts of the random sampler tiling samples 0 to 2N merge into the 2N render",
          "[farm]") {
    const std::string dir = tp::test::temp_dir("merge-cpu");
    const std::string a = render_part(dir, "a.exr", "--sampler random --spp 4");
    const std::string b = render_part(dir, "b.exr", "--sampler random --spp 4 --sample-offset 4");
    const std::string single = render_part(dir, "single.exr", "--sampler random --spp 8");
    tp::test::check_merge_equals_single(dir, {b, a}, single);
    std::filesystem::remove_all(dir);
}

TEST_CASE("Sobol parts tiling samples 0 to 2N merge into the 2N render", "[farm]") {
    // Batch b of the whole holds samples s = b mod 8 of both parts (docs/sampling.md): 12 spp
    // from 0 fill batches 0-3 twice and 4-7 once, 12 from 12 the other way round, so the merge
    // must count each part's batches from its range to rebuild the 24-spp batch estimate, from
    // the batch means of the full film.
    const std::string dir = tp::test::temp_dir("merge-sobol");
    const std::string a = render_part(dir, "a.exr", "--sampler sobol --film full --spp 12");
    const std::string b =
        render_part(dir, "b.exr", "--sampler sobol --film full --spp 12 --sample-offset 12");
    const std::string single =
        render_part(dir, "single.exr", "--sampler sobol --film full --spp 24");
    tp::test::check_merge_equals_single(dir, {b, a}, single);
    std::filesystem::remove_all(dir);
}

TEST_CASE("Sobol parts merged with --film lean equal the default render of all their samples",
          "[farm]") {
    // What a farm hands the user: full parts, merged into the lean film that a plain render
    // writes by default. The full merge equals the full 24-spp render (the test above); the lean
    // files must differ from those only by lean_sample_variance's rounding of sample_variance.*
    // (render/film.h), so the lean merge meets the lean render within the full bound plus that
    // rounding of each file, at most 2^-11 of each value.
    const std::string dir = tp::test::temp_dir("merge-sobol-lean");
    const std::string a = render_part(dir, "a.exr", "--sampler sobol --film full --spp 12");
    const std::string b =
        render_part(dir, "b.exr", "--sampler sobol --film full --spp 12 --sample-offset 12");
    const std::string single_full =
        render_part(dir, "single_full.exr", "--sampler sobol --film full --spp 24");
    const std::string single_lean = render_part(dir, "single.exr", "--spp 24");
    const double full_tolerance = tp::test::check_merge_equals_single(dir, {b, a}, single_full);
    const std::string merged_lean = dir + "/merged_lean.exr";
    const auto r = run(twinpath("merge " + shell_quote(b) + " " + shell_quote(a) +
                                " --film lean -o " + shell_quote(merged_lean)));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);

    const ExrImage ml = read_exr(merged_lean), sl = read_exr(single_lean);
    const ExrImage mf = read_exr(dir + "/merged.exr"), sf = read_exr(single_full);
    CHECK(sl.strings.at("twinpath:film") == "lean");
    CHECK(sl.strings.at(header::kVarianceEstimator) == "batches");
    CHECK(ml.channels.size() == sl.channels.size());
    for (const char* c : {"R", "G", "B", "variance.R", "variance.G", "variance.B"}) {
        CHECK(sl.channel(c) == sf.channel(c));
        CHECK(ml.channel(c) == mf.channel(c));
    }
    constexpr double kLeanRound = 4.8828125e-4; // 2^-11: 11 significant bits, to nearest
    double tolerance = full_tolerance;
    for (int c = 0; c < 3; ++c) {
        const std::string name = sample_variance_channel(c);
        for (size_t i = 0; i < sl.channel(name).size(); ++i) {
            const double full_m = mf.channel(name)[i], full_s = sf.channel(name)[i];
            CHECK(sl.channel(name)[i] == lean_sample_variance(full_s));
            CHECK(ml.channel(name)[i] == lean_sample_variance(full_m));
            const double bound =
                std::fabs(full_m - full_s) + kLeanRound * (std::fabs(full_m) + std::fabs(full_s));
            CHECK(std::fabs(double(ml.channel(name)[i]) - double(sl.channel(name)[i])) <= bound);
            tolerance = std::max(tolerance, bound);
        }
    }
    const auto e =
        run(twinpath("compare --exact " + shell_quote(merged_lean) + " " +
                     shell_quote(single_lean) + fmt::format(" --tolerance {:.17g}", tolerance)));
    INFO(e.out);
    CHECK(e.exit_code == 0);
    std::filesystem::remove_all(dir);
}

TEST_CASE("Sobol parts of two seeds merge batch by batch", "[farm]") {
    // 8 spp of seeds 1 and 2: one sample in each batch of each part. Independent seeds are
    // independent randomizations, so batch b of the whole is the two parts' batch b, mean
    // (x_1b + x_2b) / 2, and the variance of the mean is the random-group estimator over those
    // 8 batch means (render/moments.h), recomputed here from the parts' files.
    const std::string dir = tp::test::temp_dir("merge-sobol-seeds");
    const std::string a = render_part(dir, "a.exr", "--sampler sobol --film full --spp 8 --seed 1");
    const std::string b = render_part(dir, "b.exr", "--sampler sobol --film full --spp 8 --seed 2");
    const std::string merged = dir + "/merged.exr";
    const auto r = run(
        twinpath("merge " + shell_quote(a) + " " + shell_quote(b) + " -o " + shell_quote(merged)));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const ExrImage m = read_exr(merged), pa = read_exr(a), pb = read_exr(b);
    CHECK(m.strings.at(header::kVarianceEstimator) == "batches");
    CHECK(m.integers.at(header::kVarianceDof) == 7);
    CHECK(m.integers.at(header::kSpp) == 16);
    size_t varied = 0;
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < m.channel("R").size(); ++i) {
            double mean_b[8], mean = 0;
            for (uint32_t k = 0; k < 8; ++k) {
                mean_b[k] = (double(pa.channel(batch_channel(k, c))[i]) +
                             double(pb.channel(batch_channel(k, c))[i])) /
                            2;
                mean += mean_b[k] / 8;
            }
            double v = 0;
            for (double x : mean_b) v += (x - mean) * (x - mean) / 64;
            v *= 8.0 / 7.0;
            const std::string name = std::string(1, "RGB"[c]);
            // Float32 inputs and outputs: 1e-6 relative of the mean (a few roundings of
            // 2^-24), and of the variance through the squared differences of such means.
            CHECK(m.channel(name)[i] == Approx(mean).epsilon(1e-6).margin(1e-12));
            CHECK(m.channel("variance." + name)[i] ==
                  Approx(v).epsilon(1e-4).margin(1e-6 * mean * mean));
            varied += v > 0;
        }
    CHECK(varied > m.channel("R").size());
    std::filesystem::remove_all(dir);
}

TEST_CASE("merge refuses mixing samplers and Sobol parts without their batch channels", "[farm]") {
    const std::string dir = tp::test::temp_dir("merge-sobol-refuse");
    const std::string random = render_part(dir, "random.exr", "--sampler random --spp 2");
    const std::string sobol =
        render_part(dir, "sobol.exr", "--sampler sobol --film full --spp 2 --sample-offset 2");
    CHECK_THAT(merge_error({random, sobol}),
               Catch::Contains("sobol.exr") && Catch::Contains("twinpath:settings"));
    const std::string other = render_part(dir, "other.exr", "--sampler sobol --film full --spp 2");
    ExrImage img = read_exr(other);
    img.channels.erase("batch3.G");
    write_exr(dir + "/broken.exr", img);
    CHECK_THAT(merge_error({sobol, dir + "/broken.exr"}),
               Catch::Contains("broken.exr") && Catch::Contains("batch3.G"));
    // The lean film (the default) keeps no batch means: refused, in either position, with the
    // fix.
    const std::string lean =
        render_part(dir, "lean.exr", "--sampler sobol --spp 2 --sample-offset 4");
    CHECK(read_exr(lean).strings.at("twinpath:film") == "lean");
    for (const auto& parts : {std::vector<std::string>{sobol, lean}, {lean, sobol}})
        CHECK_THAT(merge_error(parts), Catch::Contains("lean.exr") &&
                                           Catch::Contains("twinpath:film") &&
                                           Catch::Contains("--film full"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("merge reads full Sobol parts written before twinpath:film and writes either layout",
          "[farm]") {
    // Files of earlier versions have every channel of the full film and no twinpath:film: they
    // merge as full films. merge --film lean writes what render writes by default: no batch
    // means, the pooled sample variance rounded to 11 significant bits (render/film.h), every
    // other channel as the full merge writes it.
    const std::string dir = tp::test::temp_dir("merge-sobol-layouts");
    const std::string a = render_part(dir, "a.exr", "--sampler sobol --film full --spp 8");
    const std::string b =
        render_part(dir, "b.exr", "--sampler sobol --film full --spp 8 --sample-offset 8");
    ExrImage img = read_exr(a);
    REQUIRE(img.strings.erase("twinpath:film") == 1);
    write_exr(dir + "/old.exr", img);
    const std::string full = dir + "/full.exr", lean = dir + "/lean.exr";
    const std::string parts = shell_quote(dir + "/old.exr") + " " + shell_quote(b);
    REQUIRE(run(twinpath("merge " + parts + " -o " + shell_quote(full))).exit_code == 0);
    REQUIRE(run(twinpath("merge " + parts + " --film lean -o " + shell_quote(lean))).exit_code ==
            0);
    const ExrImage f = read_exr(full), l = read_exr(lean);
    CHECK(f.strings.at("twinpath:film") == "full");
    CHECK(l.strings.at("twinpath:film") == "lean");
    CHECK(f.has(batch_channel(7, 2)));
    CHECK_FALSE(l.has(batch_channel(0, 0)));
    CHECK(l.channels.size() == 9);
    for (const char* c : {"R", "G", "B", "variance.R", "variance.G", "variance.B"})
        CHECK(l.channel(c) == f.channel(c));
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < f.channel("R").size(); ++i)
            CHECK(l.channel(sample_variance_channel(c))[i] ==
                  lean_sample_variance(f.channel(sample_variance_channel(c))[i]));
    std::filesystem::remove_all(dir);
}

TEST_CASE("render --sample-offset shifts the samples of the CPU reference", "[farm]") {
    tp::test::check_offset_shifts_samples(tp::test::temp_dir("offset-cpu"), "--backend cpu");
}

TEST_CASE("merge refuses parts that are not of one render, naming file and field", "[farm]") {
    // Parts with the full film, which merge accepts whatever the sampler (docs/farm.md).
    const std::string dir = tp::test::temp_dir("merge-refuse");
    const std::string a = render_part(dir, "a.exr", "--film full --spp 2");
    const std::string b = render_part(dir, "b.exr", "--film full --spp 2 --sample-offset 2");
    auto refused = [&](const std::string& name, const std::string& args, const char* field) {
        const std::string p = render_part(dir, name, "--film full " + args);
        const std::string out = merge_error({a, p});
        CHECK_THAT(out, Catch::Contains(p) && Catch::Contains(field));
    };
    refused("fov.exr", "--spp 2 --sample-offset 2 --fov 30", "twinpath:camera");
    refused("depth.exr", "--spp 2 --sample-offset 2 --min-depth 2", "twinpath:settings");
    refused("overlap.exr", "--spp 2 --sample-offset 1", "twinpath:sample_ranges");
    CHECK_THAT(merge_error({a, a}), Catch::Contains("overlap"));
    {
        const std::string p = dir + "/size.exr";
        REQUIRE(
            run(twinpath("render cornell --width 8 --height 16 --max-depth 4 --spp 2 --film full "
                         "--sample-offset 2 -o " +
                         shell_quote(p)))
                .exit_code == 0);
        CHECK_THAT(merge_error({a, p}), Catch::Contains(p) && Catch::Contains("8x16"));
    }
    {
        const std::string p = dir + "/scene.exr";
        REQUIRE(
            run(twinpath("render spheres --width 16 --height 16 --max-depth 4 --spp 2 --film full "
                         "--sample-offset 2 -o " +
                         shell_quote(p)))
                .exit_code == 0);
        CHECK_THAT(merge_error({a, p}), Catch::Contains(p));
        CHECK_THAT(merge_error({a, p}),
                   Catch::Contains("twinpath:camera") || Catch::Contains("twinpath:scene_hash"));
    }
    // Fields that renders of one scene and camera on this backend cannot differ in: a copy of
    // a part with the field changed.
    {
        ExrImage img = read_exr(b);
        img.strings["twinpath:backend"] = "vulkan/compute";
        write_exr(dir + "/backend.exr", img);
        CHECK_THAT(merge_error({a, dir + "/backend.exr"}),
                   Catch::Contains("backend.exr") && Catch::Contains("twinpath:backend"));
        img = read_exr(b);
        img.strings["twinpath:scene_hash"] = "ffffffffffffffff";
        write_exr(dir + "/hash.exr", img);
        CHECK_THAT(merge_error({a, dir + "/hash.exr"}),
                   Catch::Contains("hash.exr") && Catch::Contains("twinpath:scene_hash"));
        img = read_exr(b);
        img.strings.erase("twinpath:sample_ranges");
        write_exr(dir + "/old.exr", img);
        CHECK_THAT(merge_error({a, dir + "/old.exr"}),
                   Catch::Contains("old.exr") && Catch::Contains("twinpath:sample_ranges"));
    }
    // Independent seeds: accepted and recorded, no single seed claimed.
    const std::string s1 = render_part(dir, "seed1.exr", "--film full --spp 2 --seed 1");
    const std::string merged = dir + "/seeds.exr";
    REQUIRE(run(twinpath("merge " + shell_quote(a) + " " + shell_quote(s1) + " -o " +
                         shell_quote(merged)))
                .exit_code == 0);
    const ExrImage m = read_exr(merged);
    CHECK(m.strings.at("twinpath:sample_ranges") == "0:0-2,1:0-2");
    CHECK(m.integers.at("twinpath:spp") == 4);
    CHECK(m.integers.count("twinpath:seed") == 0);
    std::filesystem::remove_all(dir);
    CHECK_THAT(m.strings.at("twinpath:parts"),
               Catch::Contains("a.exr") && Catch::Contains("seed1.exr"));
}

TEST_CASE("merge merges the AOV layers", "[farm]") {
    const std::string dir = tp::test::temp_dir("merge-aov");
    const std::string a = render_part(dir, "a.exr", "--film full --spp 1 --aov all");
    const std::string b =
        render_part(dir, "b.exr", "--film full --spp 1 --sample-offset 1 --aov all");
    const std::string single = render_part(dir, "single.exr", "--film full --spp 2 --aov all");
    const std::string merged = dir + "/merged.exr";
    REQUIRE(run(twinpath("merge " + shell_quote(a) + " " + shell_quote(b) + " -o " +
                         shell_quote(merged)))
                .exit_code == 0);
    // Both trace the same pixel centres: --exact's AOV rules (ids exact, the rest 1e-4).
    const auto r =
        run(twinpath("compare --exact " + shell_quote(merged) + " " + shell_quote(single)));
    INFO(r.out);
    CHECK(r.exit_code == 0);
    const ExrImage m = read_exr(merged);
    for (const char* c : {"albedo.R", "normal.Y", "depth.Z", "id.instance", "id.material"})
        CHECK(m.has(c));
    std::filesystem::remove_all(dir);
}
