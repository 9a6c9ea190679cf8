// Split renders on the Vulkan engine (lavapipe in CI): --sample-offset shifts the sample index
// the shaders hash, parts merge into one render, and --device all renders on every device.
#include "image/exr_io.h"
#include "split_check.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

using tp::test::render_part;

TEST_CASE("render --sample-offset shifts the samples of the Vulkan compute engine", "[farm][gpu]") {
    tp::test::check_offset_shifts_samples(tp::test::temp_dir("offset-vk"),
                                          "--backend vulkan --vk-mode compute");
}

TEST_CASE("Vulkan parts tiling samples 0 to 2N merge into the 2N render", "[farm][gpu]") {
    // With the Sobol sampler 12 + 12 spp fill each of the 8 batches 3 times, 2 + 1 from the
    // parts in either order (merge_test.cpp).
    const std::string sampler = GENERATE(as<std::string>(), "random", "sobol");
    const std::string dir = tp::test::temp_dir("merge-vk-" + sampler);
    const std::string vk =
        "--backend vulkan --vk-mode compute --film full --sampler " + sampler + " ";
    const uint32_t n = sampler == "sobol" ? 12 : 3;
    const std::string a = render_part(dir, "a.exr", vk + "--spp " + std::to_string(n));
    const std::string b = render_part(
        dir, "b.exr", vk + "--spp " + std::to_string(n) + " --sample-offset " + std::to_string(n));
    const std::string single =
        render_part(dir, "single.exr", vk + "--spp " + std::to_string(2 * n));
    tp::test::check_merge_equals_single(dir, {a, b}, single);
    std::filesystem::remove_all(dir);
}

TEST_CASE("render --device all on one device renders the image of that device", "[farm][gpu]") {
    // lavapipe is CI's only device: the share hands it several ranges one after another
    // (sample_share.h), accumulated in one accumulator, so the image is the one-device render's
    // up to the order of double-precision additions (~1e-16 relative) before the one float32
    // rounding: each value within 2^-23 relative (one float step either way). With the Sobol
    // sampler the ranges' samples keep their batches (s mod 8), so the batch estimate of the
    // variance is the one-device render's too; 10 spp from sample 2 fill batches 2 and 3 twice.
    const std::string sampler = GENERATE(as<std::string>(), "random", "sobol");
    const std::string dir = tp::test::temp_dir("device-all-" + sampler);
    const std::string vk = "--backend vulkan --vk-mode compute --spp " +
                           std::string(sampler == "sobol" ? "10" : "6") +
                           " --sample-offset 2 --sampler " + sampler + " ";
    const std::string all =
        render_part(dir, "all.exr", vk + "--device all --stats " + dir + "/all.json");
    const std::string one = render_part(dir, "one.exr", vk);
    const tp::ExrImage a = tp::read_exr(all), b = tp::read_exr(one);
    const uint32_t spp = sampler == "sobol" ? 10 : 6;
    CHECK(a.strings.at("twinpath:sample_ranges") == "0:2-" + std::to_string(2 + spp));
    CHECK(a.strings.at("twinpath:variance_estimator") ==
          b.strings.at("twinpath:variance_estimator"));
    if (sampler == "sobol") CHECK(a.integers.at("twinpath:variance_dof") == 7);
    for (const auto& [name, data] : b.channels)
        for (size_t i = 0; i < data.size(); ++i)
            CHECK(std::fabs(double(a.channel(name)[i]) - double(data[i])) <=
                  1.2e-7 * std::fabs(double(data[i])));
    const nlohmann::json stats = tp::test::read_json(dir + "/all.json");
    REQUIRE(stats.at("devices").size() == 1);
    const nlohmann::json& d = stats.at("devices")[0];
    CHECK(d.at("spp") == spp);
    CHECK(d.at("samples") == spp * 16 * 16);
    uint64_t covered = 0;
    for (const nlohmann::json& r : d.at("sample_ranges")) {
        CHECK(r.at("begin") >= 2);
        CHECK(r.at("end") <= 2 + spp);
        covered += r.at("end").get<uint64_t>() - r.at("begin").get<uint64_t>();
    }
    CHECK(covered == spp);
    CHECK(stats.at("spp") == spp);
    std::filesystem::remove_all(dir);
}
