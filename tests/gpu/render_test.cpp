// The Vulkan backend through the command line, as scripts and `make demo` use it: each bundled
// scene rendered on both backends must be statistically consistent under `twinpath compare`;
// with the same seed the two follow the same paths; bad devices and modes fail with exit code
// 2, pipeline mode on a device without it with 3; `twinpath info --json` lists the device and
// the mode auto picks; the statistics report what ran. Pipeline mode itself runs only where the
// device has it (not lavapipe). CTest runs this with TWINPATH_VALIDATION=1, and a render that
// drew a validation message exits with 3.
#include "image/exr_io.h"
#include "shaders/interface.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace tp::test {
namespace {

// Renders `scene` on a backend into dir/name.exr (+ .json statistics).
ProcessResult render(const std::string& scene, const std::string& backend, const std::string& dir,
                     const std::string& name, const std::string& extra) {
    return run(twinpath(fmt::format("render {} --backend {} -o {} --stats {} {}", scene, backend,
                                    shell_quote(dir + "/" + name + ".exr"),
                                    shell_quote(dir + "/" + name + ".json"), extra)));
}

bool compare_available() {
    const ProcessResult r = run(twinpath("compare --help"));
    if (r.exit_code != 0)
        WARN("twinpath compare is not available (exit " << r.exit_code
                                                        << "): the consistency checks are SKIPPED");
    return r.exit_code == 0;
}

// The mode `twinpath info` says --vk-mode auto picks on the default device (index 0 here).
std::string auto_mode() {
    const ProcessResult r = run(twinpath("info --json"));
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out)["backends"]["vulkan"]["devices"][0]["auto_mode"];
}

void check_vulkan_stats(const nlohmann::json& s, uint64_t pixel_samples, const char* mode) {
    CHECK(s["backend"] == "vulkan");
    CHECK(s["mode"] == mode);
    CHECK(s["nan_samples"] == 0);
    CHECK(s["samples"].get<uint64_t>() == pixel_samples);
    CHECK(s["rays"]["camera"].get<uint64_t>() == pixel_samples);
    CHECK(s["rays"]["shadow"].get<uint64_t>() > 0);
    CHECK(s["gpu_time_s"].is_number());
    CHECK(s["rays_per_second"].get<double>() > 0.0);
    CHECK(s["extra"]["validation"] == "on");
    CHECK(s["extra"]["validation_messages"] == "0");
    // The device holds at least the acceleration structure and the film's accumulators (one
    // PixelAccum a pixel and slot: shaders/interface.h), and a render of a bundled scene at
    // these sizes far less than 256 MiB.
    const uint64_t film = s["width"].get<uint64_t>() * s["height"].get<uint64_t>() *
                          accum_slots(s["sampler"] == "sobol" ? SAMPLER_SOBOL : SAMPLER_RANDOM) *
                          sizeof(PixelAccum);
    const uint64_t peak = s["device_memory_peak_bytes"].get<uint64_t>();
    CHECK(peak >= s["accel_bytes"].get<uint64_t>() + film);
    CHECK(peak < (uint64_t(256) << 20));
    CHECK(s["upload_time_s"].get<double>() >= 0);
}

} // namespace

TEST_CASE("Vulkan and CPU renders of every bundled scene are consistent", "[gpu]") {
    // Small images and different seeds, so that the two estimates are independent; the spp
    // give compare the power to see a bias of a few percent in 32 x 32 pixels. (With the same
    // seed the Vulkan image equals the CPU image up to rounding, so this comparison behaves
    // exactly like CPU seed 5 against CPU seed 6, which compare accepts for every scene.)
    // Both samplers: with sobol both sides carry the batch variance (docs/sampling.md).
    struct SceneCase {
        const char* name;
        uint32_t spp;
    };
    for (const SceneCase c :
         {SceneCase{"cornell", 256}, SceneCase{"cornell_glossy", 256},
          SceneCase{"cornell_spheres", 64}, SceneCase{"spheres", 256}, SceneCase{"furnace", 64}}) {
        for (const char* sampler : {"random", "sobol"}) {
            DYNAMIC_SECTION(c.name << " " << sampler) {
                const std::string dir = temp_dir(std::string("vk-") + c.name + "-" + sampler);
                const std::string common =
                    fmt::format("--width 32 --height 32 --spp {} --sampler {}", c.spp, sampler);
                const ProcessResult vk =
                    render(c.name, "vulkan", dir, "vulkan", common + " --seed 6 --vk-mode compute");
                INFO(vk.out);
                REQUIRE(vk.exit_code == 0);
                check_vulkan_stats(read_json(dir + "/vulkan.json"), 32ull * 32 * c.spp, "compute");
                const ProcessResult cpu = render(c.name, "cpu", dir, "cpu", common + " --seed 5");
                REQUIRE(cpu.exit_code == 0);
                if (!compare_available()) continue;
                const ProcessResult cmp = run(twinpath(fmt::format(
                    "compare {} {} --alpha 0.01 --json {}", shell_quote(dir + "/vulkan.exr"),
                    shell_quote(dir + "/cpu.exr"), shell_quote(dir + "/compare.json"))));
                INFO(cmp.out);
                std::printf("compare %-16s %s", c.name, cmp.out.c_str());
                CHECK(cmp.exit_code == 0);
            }
        }
    }
}

TEST_CASE("CPU and Vulkan at unequal spp on the caustic scene are consistent (1:8, 1:64)",
          "[gpu][unequal-spp]") {
    // The user's workflow that compare once got wrong (docs/compare.md "Unequal sample
    // counts"): one engine with few samples against the other with many, on cornell_spheres,
    // whose caustics give heavy-tailed pixels. Each backend takes each side once at 1:8; the
    // CPU takes the expensive side of 1:64 (lavapipe is ~10x slower). Independent seeds.
    struct Pair {
        const char* low;
        uint32_t spp_low;
        const char* high;
        uint32_t spp_high;
    };
    for (const Pair p : {Pair{"vulkan", 16, "cpu", 128}, Pair{"cpu", 16, "vulkan", 128},
                         Pair{"vulkan", 16, "cpu", 1024}}) {
        const std::string name = fmt::format("{}{}-{}{}", p.low, p.spp_low, p.high, p.spp_high);
        SECTION(name) {
            const std::string dir = temp_dir("vk-unequal-" + name);
            const std::string size = "--width 32 --height 32 --vk-mode compute";
            REQUIRE(render("cornell_spheres", p.low, dir, "low",
                           fmt::format("{} --spp {} --seed 21", size, p.spp_low))
                        .exit_code == 0);
            REQUIRE(render("cornell_spheres", p.high, dir, "high",
                           fmt::format("{} --spp {} --seed 22", size, p.spp_high))
                        .exit_code == 0);
            const ProcessResult cmp = run(
                twinpath(fmt::format("compare {} {} --alpha 0.01", shell_quote(dir + "/low.exr"),
                                     shell_quote(dir + "/high.exr"))));
            INFO(cmp.out);
            CHECK(cmp.exit_code == 0);
        }
    }
}

TEST_CASE("with the same seed both backends trace the same paths", "[gpu]") {
    // Same (seed, pixel, sample) -> same random numbers -> the same path up to float rounding:
    // per-pixel values agree almost everywhere; a path may take another branch where a
    // decision sits within rounding of its threshold, so 1 % of pixel-channels may differ.
    // Cornell has no instancing: compute mode traces it through the one-level BVH, whose
    // world-space triangles are the CPU's (scene/world_vertex.h); the other two have two levels.
    // The Sobol sampler at 10 spp fills its 8 per-batch accumulators unequally on the GPU; the
    // film must merge them as the CPU's film does, variance included.
    for (const char* scene : {"cornell", "cornell_glossy", "spheres"})
        for (const char* sampler : {"random", "sobol"}) {
            DYNAMIC_SECTION(scene << " " << sampler) {
                const std::string dir = temp_dir(std::string("replay-") + scene + "-" + sampler);
                const std::string common =
                    fmt::format("--width 24 --height 24 --spp {} --seed 5 --sampler {}",
                                sampler == std::string("sobol") ? 10 : 2, sampler);
                REQUIRE(render(scene, "vulkan", dir, "vulkan", common).exit_code == 0);
                REQUIRE(render(scene, "cpu", dir, "cpu", common).exit_code == 0);
                const ExrImage a = read_exr(dir + "/vulkan.exr"), b = read_exr(dir + "/cpu.exr");
                size_t differ = 0, total = 0;
                for (const char* ch : {"R", "G", "B", "variance.R", "variance.G", "variance.B"}) {
                    const std::vector<float>&va = a.channel(ch), &vb = b.channel(ch);
                    for (size_t i = 0; i < va.size(); ++i, ++total)
                        differ += std::abs(va[i] - vb[i]) > 1e-3f * std::max(1.0f, std::abs(vb[i]));
                }
                INFO(differ << " of " << total << " pixel-channels differ");
                CHECK(differ <= total / 100);
                CHECK(a.strings.at("twinpath:backend") == "vulkan/" + auto_mode());
                CHECK(a.strings.at("twinpath:sampler") == sampler);
                CHECK(a.strings.at("twinpath:variance_estimator") ==
                      b.strings.at("twinpath:variance_estimator"));
            }
        }
}

TEST_CASE("the wide BVH traces the CPU's paths and its images are consistent", "[gpu]") {
    // --bvh wide (vulkan_rt/compute_mode/wide_bvh.h): the same-seed replay of the test above, and
    // an independent-seed comparison as in the first test, on cornell (one-level BVH), spheres (two
    // levels) and cornell_spheres (its glass and mirror spheres: the longest paths); and
    // --bvh auto (vulkan_rt/compute_mode/bvh_estimate.h), which today picks wide on cornell and
    // cornell_spheres and binary on spheres, so that both of its outcomes run.
    for (const char* scene : {"cornell", "spheres", "cornell_spheres"}) {
        SECTION(scene) {
            const std::string dir = temp_dir(std::string("wide-") + scene);
            const std::string wide = " --vk-mode compute --bvh wide --width 24 --height 24";
            REQUIRE(render(scene, "vulkan", dir, "same", "--spp 2 --seed 5" + wide).exit_code == 0);
            REQUIRE(render(scene, "cpu", dir, "cpu", "--width 24 --height 24 --spp 2 --seed 5")
                        .exit_code == 0);
            const ExrImage a = read_exr(dir + "/same.exr"), b = read_exr(dir + "/cpu.exr");
            size_t differ = 0, total = 0;
            for (const char* ch : {"R", "G", "B"}) {
                const std::vector<float>&va = a.channel(ch), &vb = b.channel(ch);
                for (size_t i = 0; i < va.size(); ++i, ++total)
                    differ += std::abs(va[i] - vb[i]) > 1e-3f * std::max(1.0f, std::abs(vb[i]));
            }
            INFO(differ << " of " << total << " pixel-channels differ"); // tolerance: see above
            CHECK(differ <= total / 100);
            const nlohmann::json stats = read_json(dir + "/same.json");
            CHECK(stats["extra"]["bvh_layout"] == "wide");
            CHECK(stats["accel_bytes"].get<uint64_t>() > 0);
            // --bvh auto renders with the layout it chose (the same BVH: the same image, bit for
            // bit) and says which.
            const std::string small = " --vk-mode compute --width 24 --height 24 --spp 2 --seed 5";
            REQUIRE(render(scene, "vulkan", dir, "auto", "--bvh auto" + small).exit_code == 0);
            const nlohmann::json chosen = read_json(dir + "/auto.json");
            CHECK(chosen["extra"]["bvh_requested"] == "auto");
            const std::string layout = chosen["extra"]["bvh_layout"];
            REQUIRE(render(scene, "vulkan", dir, "chosen", "--bvh " + layout + small).exit_code ==
                    0);
            const ExrImage by_auto = read_exr(dir + "/auto.exr");
            const ExrImage by_name = read_exr(dir + "/chosen.exr");
            for (const char* ch : {"R", "G", "B"})
                CHECK(by_auto.channel(ch) == by_name.channel(ch));
            if (!compare_available()) continue;
            REQUIRE(render(scene, "vulkan", dir, "wide", "--spp 64 --seed 6" + wide).exit_code ==
                    0);
            REQUIRE(render(scene, "cpu", dir, "cpu64", "--width 24 --height 24 --spp 64 --seed 7")
                        .exit_code == 0);
            const ProcessResult cmp = run(
                twinpath(fmt::format("compare {} {} --alpha 0.01", shell_quote(dir + "/wide.exr"),
                                     shell_quote(dir + "/cpu64.exr"))));
            INFO(cmp.out);
            CHECK(cmp.exit_code == 0);
        }
    }
    const std::string dir = temp_dir("wide-bad");
    const ProcessResult bad = render("cornell", "vulkan", dir, "x", "--spp 1 --bvh quad");
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.out, Catch::Contains("--bvh"));
}

TEST_CASE("bad --device and --vk-mode fail with exit code 2 and a clear message", "[gpu]") {
    const std::string dir = temp_dir("vk-bad");
    const ProcessResult index = render("cornell", "vulkan", dir, "a", "--spp 1 --device 99");
    CHECK(index.exit_code == 2);
    CHECK_THAT(index.out,
               Catch::Contains("no Vulkan device with that index") && Catch::Contains("0: "));
    const ProcessResult name = render("cornell", "vulkan", dir, "b", "--spp 1 --device nosuchgpu");
    CHECK(name.exit_code == 2);
    CHECK_THAT(name.out, Catch::Contains("no Vulkan device name contains it"));
    const ProcessResult mode = render("cornell", "vulkan", dir, "c", "--spp 1 --vk-mode rtx");
    CHECK(mode.exit_code == 2);
    CHECK_THAT(mode.out, Catch::Contains("--vk-mode"));
}

TEST_CASE("vk-mode auto runs what info promises and pipeline needs a device with it", "[gpu]") {
    const std::string dir = temp_dir("vk-auto");
    const std::string expected = auto_mode(); // compute on lavapipe
    REQUIRE(render("cornell", "vulkan", dir, "a", "--spp 1 --width 8 --height 8").exit_code == 0);
    const nlohmann::json s = read_json(dir + "/a.json");
    CHECK(s["mode"] == expected);
    CHECK(s["extra"]["vk_mode_requested"] == "auto");
    CHECK(read_exr(dir + "/a.exr").strings.at("twinpath:backend") == "vulkan/" + expected);

    const ProcessResult p =
        render("cornell", "vulkan", dir, "p", "--spp 1 --width 8 --height 8 --vk-mode pipeline");
    INFO(p.out);
    if (expected == "pipeline") {
        CHECK(p.exit_code == 0);
    } else {
        // A device without the ray-tracing extensions: a runtime failure (exit 3), not bad
        // usage, with what is missing and what to use instead; no image.
        CHECK(p.exit_code == 3);
        CHECK_THAT(p.out, Catch::Contains("cannot run the ray-tracing pipeline mode") &&
                              Catch::Contains("--vk-mode compute"));
        CHECK_FALSE(std::ifstream(dir + "/p.exr").good());
    }
}

TEST_CASE("pipeline mode agrees with compute mode and the CPU where the device has it", "[gpu]") {
    if (auto_mode() != "pipeline") {
        WARN("the Vulkan device has no ray-tracing pipeline: pipeline mode is SKIPPED here (it "
             "is checked on a GPU by scripts/gpu_check.sh, docs/gpu.md)");
        return;
    }
    for (const char* scene :
         {"cornell", "cornell_glossy", "cornell_spheres", "spheres", "furnace", "gltf_materials"}) {
        SECTION(scene) {
            const std::string dir = temp_dir(std::string("rt-") + scene);
            const std::string common = "--width 32 --height 32 --spp 256";
            REQUIRE(render(scene, "vulkan", dir, "rt", common + " --seed 7 --vk-mode pipeline")
                        .exit_code == 0);
            check_vulkan_stats(read_json(dir + "/rt.json"), 32ull * 32 * 256, "pipeline");
            REQUIRE(render(scene, "cpu", dir, "cpu", common + " --seed 8").exit_code == 0);
            const ProcessResult cmp =
                run(twinpath(fmt::format("compare {} {} --alpha 0.01", shell_quote(dir + "/rt.exr"),
                                         shell_quote(dir + "/cpu.exr"))));
            INFO(cmp.out);
            CHECK(cmp.exit_code == 0);
        }
    }
}

TEST_CASE("without a Vulkan driver a render fails with exit code 3 and info still works", "[gpu]") {
    // Points the loader at a driver manifest that does not exist: no ICD at all.
    const std::string no_driver =
        "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json ";
    const std::string dir = temp_dir("vk-none");
    const ProcessResult r = run(no_driver + twinpath("render cornell --backend vulkan --spp 1 -o " +
                                                     shell_quote(dir + "/x.exr")));
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.out, Catch::Contains("no usable Vulkan driver"));
    const ProcessResult info = run(no_driver + twinpath("info"));
    CHECK(info.exit_code == 0);
    CHECK_THAT(info.out, Catch::Contains("vulkan: unavailable"));
}

TEST_CASE("twinpath info --json lists the Vulkan devices and their modes", "[gpu]") {
    const ProcessResult r = run(twinpath("info --json"));
    REQUIRE(r.exit_code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const nlohmann::json& devices = j["backends"]["vulkan"]["devices"];
    REQUIRE(devices.size() >= 1);
    for (const nlohmann::json& d : devices) {
        CHECK(d["name"].is_string());
        CHECK(d["type"].is_string());
        CHECK(d["api_version"].is_string());
        CHECK(d["driver"].is_string());
        CHECK(d["modes"].is_array());
    }
    CHECK(devices[0]["modes"][0] == "compute");
}

// The 1 s limit decides nothing by itself: however loaded the machine, the render makes at
// least one pass (spp >= 1), and no device makes 10^8 spp of 16 x 16 in a second or ten; what is
// checked is that it stopped on a pass boundary (samples = pixels x spp).
TEST_CASE("a Vulkan render's statistics give its peak device memory", "[gpu]") {
    const std::string dir = temp_dir("vk-memory");
    for (const char* sampler : {"sobol", "random"}) {
        const ProcessResult r = render("cornell", "vulkan", dir, sampler,
                                       fmt::format("--vk-mode compute --width 48 --height 32 "
                                                   "--spp 4 --sampler {}",
                                                   sampler));
        INFO(r.out);
        REQUIRE(r.exit_code == 0);
        check_vulkan_stats(read_json(dir + "/" + sampler + ".json"), 48ull * 32 * 4, "compute");
    }
    // The CPU holds no device memory and uploads nothing.
    REQUIRE(render("cornell", "cpu", dir, "cpu", "--width 8 --height 8 --spp 1").exit_code == 0);
    const nlohmann::json cpu = read_json(dir + "/cpu.json");
    CHECK(cpu["device_memory_peak_bytes"].is_null());
    CHECK(cpu["upload_time_s"].is_null());
}

TEST_CASE("a Vulkan render with a time limit stops after whole passes", "[gpu]") {
    const std::string dir = temp_dir("vk-time");
    const ProcessResult r = render("cornell", "vulkan", dir, "t",
                                   "--width 16 --height 16 --spp 100000000 --time-limit 1");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const nlohmann::json s = read_json(dir + "/t.json");
    const uint64_t spp = s["spp"];
    CHECK(spp >= 1);
    CHECK(spp < 100000000);
    CHECK(s["samples"].get<uint64_t>() == 16 * 16 * spp);
}

} // namespace tp::test
