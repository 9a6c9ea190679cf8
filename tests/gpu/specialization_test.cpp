// Scene features on Vulkan (compute mode; lavapipe in CI): the render shader specialized to each
// bundled scene's features, with the one-level BVH where the scene has no instancing, agrees
// with the all-features shader and its two-level BVH (`twinpath compare`, alpha 0.01,
// different seeds); and the pipeline cache on disk: the second render of a scene finds
// its pipelines there, and a corrupt or foreign cache file is ignored with a note, never a
// failure, and replaced.
#include "shared/features.h"
#include "support/test_paths.h"
#include "vulkan_rt/device/pipeline_cache.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace tp::test {
namespace {

// A compute-mode render with the pipeline cache in `cache`; returns its statistics.
nlohmann::json render(const std::string& scene, const std::string& dir, const std::string& name,
                      const std::string& cache, const std::string& extra, std::string* out) {
    const ProcessResult r = run(fmt::format(
        "TWINPATH_CACHE={} {}", shell_quote(cache),
        twinpath(fmt::format("render {} --backend vulkan --vk-mode compute -o {} --stats {} {}",
                             scene, shell_quote(dir + "/" + name + ".exr"),
                             shell_quote(dir + "/" + name + ".json"), extra))));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    if (out) *out = r.out;
    return read_json(dir + "/" + name + ".json");
}

} // namespace

TEST_CASE("Vulkan: the specialized shader agrees with the all-features shader on every scene",
          "[gpu][features]") {
    for (const char* scene :
         {"cornell", "cornell_glossy", "spheres", "furnace", "gltf_materials"}) {
        SECTION(scene) {
            const std::string dir = temp_dir(std::string("spec-vk-") + scene);
            const std::string cache = dir + "/cache";
            const std::string common = "--width 24 --height 24 --spp 64";
            const nlohmann::json spec =
                render(scene, dir, "scene", cache, common + " --seed 21 --features scene", nullptr);
            const nlohmann::json all =
                render(scene, dir, "all", cache, common + " --seed 22 --features all", nullptr);
            CHECK(spec["features"]["variant"] == "scene");
            CHECK(all["features"]["mask"] == tp::FEATURES_ALL);
            // The BVH's shape follows the mask (bvh_builder.h): one level for cornell and
            // furnace, which have no instancing, so the comparison below checks the one-level
            // traversal against the two-level one of the all-features shader.
            const bool instancing =
                (spec["features"]["mask"].get<uint32_t>() & FEATURE_INSTANCING) != 0;
            CHECK(spec["extra"]["bvh_levels"] == (instancing ? "2" : "1"));
            CHECK(all["extra"]["bvh_levels"] == "2");
            CHECK(spec["nan_samples"] == 0);
            CHECK(spec["extra"]["validation_messages"] == "0");
            const ProcessResult cmp = run(
                twinpath(fmt::format("compare {} {} --alpha 0.01", shell_quote(dir + "/scene.exr"),
                                     shell_quote(dir + "/all.exr"))));
            INFO(cmp.out);
            CHECK(cmp.exit_code == 0);
        }
    }
}

TEST_CASE("the pipeline cache: a second render hits it and a bad file is ignored and replaced",
          "[gpu][features]") {
    const std::string dir = temp_dir("pipeline-cache");
    const std::string cache = dir + "/cache";
    const std::string small = "--width 8 --height 8 --spp 1";
    std::string out;
    const nlohmann::json first = render("cornell", dir, "first", cache, small, &out);
    CHECK(first["extra"]["pipeline_cache"] == "miss");
    const std::string file = first["extra"]["pipeline_cache_file"];
    REQUIRE(fs::exists(file));
    CHECK(fs::path(file).parent_path() == fs::path(cache) / "pipelines");

    const nlohmann::json second = render("cornell", dir, "second", cache, small, &out);
    CHECK(second["extra"]["pipeline_cache"] == "hit");
    CHECK(second["extra"]["pipeline_cache_file"] == file);
    // Another feature set compiles into the same cache file.
    const nlohmann::json other =
        render("cornell", dir, "other", cache, small + " --features all", &out);
    CHECK(other["extra"]["pipeline_cache"] == "hit");

    // Garbage, a truncated file and one from "another driver": a note, a miss, a rewritten file.
    std::ifstream in(file, std::ios::binary);
    std::vector<char> good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(good.size() >= 64);
    std::vector<char> foreign = good;
    foreign[12] ^= 0x5a; // vendorID in the header
    std::vector<char> flipped = good;
    flipped.back() ^= 0x01;
    const std::vector<std::pair<std::string, std::vector<char>>> bad = {
        {"garbage", std::vector<char>(100, 'x')},
        {"truncated", std::vector<char>(good.begin(), good.begin() + 20)},
        {"foreign", foreign},
        {"flipped", flipped},
        {"empty", {}}};
    for (const auto& [what, bytes] : bad) {
        INFO(what);
        {
            std::ofstream f(file, std::ios::binary | std::ios::trunc);
            f.write(bytes.data(), std::streamsize(bytes.size()));
        }
        const nlohmann::json s = render("cornell", dir, "bad_" + what, cache, small, &out);
        CHECK(s["extra"]["pipeline_cache"] == "miss");
        CHECK(out.find("twinpath: note: pipeline cache ignored") != std::string::npos);
        const nlohmann::json again = render("cornell", dir, "again_" + what, cache, small, &out);
        CHECK(again["extra"]["pipeline_cache"] == "hit");
    }
    // An unwritable cache directory: the render still succeeds.
    const nlohmann::json none =
        render("cornell", dir, "unwritable", "/proc/twinpath-no-cache", small, &out);
    CHECK(none["extra"]["pipeline_cache"] == "miss");
}

TEST_CASE("pipeline cache files: encode and decode under their key", "[gpu][features]") {
    PipelineCacheKey key;
    key.vendor_id = 0x10de;
    key.device_id = 0x2335;
    key.driver_version = 42;
    key.uuid[3] = 7;
    key.shader_hash = 0x1234;
    // A driver blob whose own header (VkPipelineCacheHeaderVersionOne) names the same device.
    std::vector<uint8_t> data(48, 0xab);
    const uint32_t words[4] = {32, VK_PIPELINE_CACHE_HEADER_VERSION_ONE, key.vendor_id,
                               key.device_id};
    std::memcpy(data.data(), words, sizeof(words));
    std::memcpy(data.data() + 16, key.uuid.data(), VK_UUID_SIZE);
    const std::vector<uint8_t> file = encode_pipeline_cache(key, data);
    std::vector<uint8_t> back;
    std::string reason;
    CHECK(decode_pipeline_cache(file, key, back, reason));
    CHECK(back == data);
    const auto rejects = [&](PipelineCacheKey k, std::vector<uint8_t> f, const char* why) {
        std::vector<uint8_t> d;
        std::string r;
        INFO(why);
        CHECK_FALSE(decode_pipeline_cache(f, k, d, r));
        CHECK(r.find(why) != std::string::npos);
        CHECK(d.empty());
    };
    PipelineCacheKey k = key;
    k.driver_version = 43;
    rejects(k, file, "another device or driver");
    k = key;
    k.shader_hash = 1;
    rejects(k, file, "other shaders");
    rejects(key, std::vector<uint8_t>(file.begin(), file.begin() + 63), "truncated");
    rejects(key, std::vector<uint8_t>(file.begin(), file.end() - 1), "data bytes");
    std::vector<uint8_t> f = file;
    f[70] ^= 1;
    rejects(key, f, "corrupt");
    f = file;
    f[0] = 'X';
    rejects(key, f, "not a twinpath pipeline cache");
    // Our header intact, the driver's naming another device.
    std::vector<uint8_t> other = data;
    other[8] ^= 1;
    rejects(key, encode_pipeline_cache(key, other), "driver's header");
    CHECK(key.hash() != k.hash());
}

} // namespace tp::test
