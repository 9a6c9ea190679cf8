// The scene's images on the GPU (vulkan_rt/render_loop/scene_images.h; docs/gpu.md,
// "Textures"): each image a sampled image read with texelFetch, decoded and filtered by the
// shared code, so that both engines read every format alike (8- and 16-bit PNG, JPEG, float EXR,
// the environment map); two dozen 4096 x 4096 textures render in compute mode on lavapipe; and a
// texture the device cannot hold is one error naming it, its size and the limit, before any
// work, where the CPU renders it.
#include "gpu_harness.h"
#include "image/exr_io.h"
#include "shared/texture.h"
#include "support/gltf_builder.h"
#include "support/image_encoders.h"
#include "support/test_paths.h"
#include "util/error.h"
#include "vulkan_rt/render_loop/scene_images.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <set>

namespace tp::test {
namespace {

std::string write_file(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

ProcessResult render(const std::string& scene, const std::string& out, const std::string& args) {
    return run(
        twinpath(fmt::format("render {} -o {} {}", shell_quote(scene), shell_quote(out), args)));
}

Texture sized(const std::string& name, uint32_t w, uint32_t h, uint32_t format = TEXEL_RGBA8) {
    Texture t;
    t.name = name;
    t.source = name + ".png";
    t.width = w;
    t.height = h;
    t.format = format;
    return t;
}

} // namespace

TEST_CASE("an image that does not fit the device is one error naming it, its size and the limit",
          "[gpu][texture]") {
    // Limits of a small device, given to the pure check (the device's own come from
    // image_limits); sizes only: the check reads no texel.
    ImageLimits l;
    l.device = "small GPU";
    l.max_images = 3;
    l.max_dimension = 1024;
    l.max_image_bytes = 2u << 20;
    l.memory_budget = 5u << 20;
    l.memory_budget_source = "budget";
    CHECK_NOTHROW(check_images({sized("a", 512, 512), sized("b", 1024, 256)}, l));
    CHECK_THROWS_AS(check_images({sized("a", 2048, 8)}, l), RuntimeError);
    CHECK_THROWS_WITH(
        check_images({sized("a", 8, 8), sized("tall", 16, 1025)}, l),
        Catch::Contains("'tall' (tall.png, 16x1025)") && Catch::Contains("1025 texels tall") &&
            Catch::Contains("maxImageDimension2D 1024") && Catch::Contains("small GPU"));
    // 1024 x 1024 x 16 bytes = 16 MiB in one image, more than 2 MiB.
    CHECK_THROWS_WITH(check_images({sized("f", 1024, 1024, TEXEL_RGBA32F)}, l),
                      Catch::Contains("'f'") && Catch::Contains("16.0 MiB") &&
                          Catch::Contains("2.0 MiB"));
    // Three 2 MiB images: the third brings them to 6 MiB, past the 5 MiB budget.
    CHECK_THROWS_WITH(
        check_images({sized("x", 512, 1024), sized("y", 512, 1024), sized("z", 512, 1024)}, l),
        Catch::Contains("'z'") && Catch::Contains("6.0 MiB") && Catch::Contains("5.0 MiB") &&
            Catch::Contains("budget"));
    // One image more than the engine binds: the first one past the slots is named.
    CHECK_THROWS_WITH(
        check_images({sized("a", 4, 4), sized("b", 4, 4), sized("c", 4, 4), sized("d", 4, 4)}, l),
        Catch::Contains("'d'") && Catch::Contains("image 4 of the scene's 4") &&
            Catch::Contains("at most 3 images"));
    // The real device's limits are the engine's slots and nothing smaller than Vulkan's minimum.
    const ImageLimits device = image_limits(gpu_context());
    CHECK(device.max_images == IMAGE_SLOTS);
    CHECK(device.max_dimension >= 4096);
    CHECK(device.memory_budget > 0);
    WARN("the device's image limits: "
         << device.device << ": maxImageDimension2D " << device.max_dimension
         << ", one image at most " << device.max_image_bytes / 1048576 << " MiB, "
         << device.memory_budget / 1048576 << " MiB device-local memory ("
         << device.memory_budget_source << ")");
}

TEST_CASE("a glTF with a 20000 x 2 PNG renders on the CPU and is refused by the GPU by name",
          "[gpu][texture][gltf]") {
    const uint32_t limit = gpu_context().limits().maxImageDimension2D;
    if (limit >= 20000) {
        WARN("SKIPPED: the device holds 2D images " << limit << " texels wide (lavapipe: 16384)");
        return;
    }
    const std::string dir = temp_dir("gltf-wide-image");
    std::vector<std::vector<uint8_t>> rows(2, std::vector<uint8_t>(20000 * 3, 180));
    const std::string png = encode_png({20000, 2, PNG_COLOR_TYPE_RGB, 8}, rows);
    GltfBuilder g;
    const uint32_t pos = g.vec3s({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
    const uint32_t uv = g.vec2s({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    const uint32_t idx = g.indices({0, 1, 2, 0, 2, 3});
    g.add("images", {{"bufferView", g.view(png.data(), png.size())}, {"mimeType", "image/png"}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                        {"emissiveFactor", {1, 1, 1}},
                        {"emissiveTexture", {{"index", 0}}}});
    g.mesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, int(idx), 0);
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    const std::string glb = g.write_glb(dir, "wide");
    const std::string flags = "--width 8 --height 8 --spp 1";
    const ProcessResult cpu = render(glb, dir + "/cpu.exr", flags + " --backend cpu");
    INFO(cpu.out);
    CHECK(cpu.exit_code == 0);
    const auto t0 = std::chrono::steady_clock::now();
    const ProcessResult gpu =
        render(glb, dir + "/gpu.exr", flags + " --backend vulkan --vk-mode compute");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    INFO(gpu.out);
    CHECK(gpu.exit_code == 3);
    CHECK_THAT(gpu.out, Catch::Contains("images[0]") && Catch::Contains("20000x2") &&
                            Catch::Contains("20000 texels wide") &&
                            Catch::Contains(fmt::format("maxImageDimension2D {}", limit)));
    // One line: the error, not a trace of what failed after it.
    CHECK(std::count(gpu.out.begin(), gpu.out.end(), '\n') <= 2);
    // Refused before the render's work (no pipeline compiled, nothing uploaded).
    CHECK(seconds < 20.0);
}

TEST_CASE("two dozen distinct 4096 x 4096 textures render in compute mode", "[gpu][texture]") {
    // 24 flat-coloured 4096^2 8-bit images (64 MiB each on the device, 1.5 GiB in all: within
    // lavapipe's 2 GiB heap and its one-allocation limit per image), one per quad of a 6 x 4 grid
    // seen from above under a directional light. With max_depth 1 and no environment a quad's
    // pixel is exactly its texel's linear colour x Kd / pi x the irradiance, so each quad shows
    // its own image.
    const std::string dir = temp_dir("two-dozen-4k");
    const uint32_t n = 24, size = 4096;
    std::string textures, materials, objects;
    std::vector<vec3> colour(n);
    for (uint32_t i = 0; i < n; ++i) {
        const uint8_t r = uint8_t(10 * i + 5), g = uint8_t(250 - 9 * i),
                      b = uint8_t((i * 53) % 256);
        colour[i] = vec3(srgb_to_linear(r / 255.0f), srgb_to_linear(g / 255.0f),
                         srgb_to_linear(b / 255.0f));
        std::vector<uint8_t> row(size_t(size) * 3);
        for (size_t k = 0; k < row.size(); k += 3) {
            row[k] = r;
            row[k + 1] = g;
            row[k + 2] = b;
        }
        PngSpec spec{size, size, PNG_COLOR_TYPE_RGB, 8};
        spec.fast = true;
        write_file(fmt::format("{}/t{}.png", dir, i),
                   encode_png(spec, std::vector<std::vector<uint8_t>>(size, row)));
        const char* sep = i ? ", " : "";
        textures += fmt::format(R"({}"t{}": {{"file": "t{}.png"}})", sep, i, i);
        materials += fmt::format(R"({}"m{}": {{"Kd": [1, 1, 1], "map_Kd": "t{}"}})", sep, i, i);
        objects += fmt::format(
            R"({}{{"mesh": "q", "material": "m{}", "transform": {{"translate": [{}, 0, {}]}}}})",
            sep, i, 2.0 * (i % 6) - 5.0, 2.0 * (i / 6) - 3.0);
    }
    // An orthographic-like view: far away, narrow field of view; 8 x 8 pixels per quad.
    std::ofstream(dir + "/grid.json") << fmt::format(
        R"({{"camera": {{"eye": [0, 400, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 1.146}},
 "film": {{"width": 48, "height": 32}}, "render": {{"spp": 1, "max_depth": 1}},
 "textures": {{{}}}, "materials": {{{}}}, "meshes": {{"q": {{"type": "quad"}}}},
 "objects": [{}],
 "lights": [{{"type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3]}}]}})",
        textures, materials, objects);
    const auto t0 = std::chrono::steady_clock::now();
    const ProcessResult r =
        render(dir + "/grid.json", dir + "/gpu.exr",
               "--backend vulkan --vk-mode compute --stats " + shell_quote(dir + "/gpu.json"));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    WARN("24 textures of 4096^2: the compute-mode render took " << seconds << " s");
    const ExrImage img = read_exr(dir + "/gpu.exr");
    std::set<std::tuple<float, float, float>> seen;
    for (uint32_t i = 0; i < n; ++i) {
        // Quad i's centre: column 8 (i % 6) + 4, row 8 (i / 6) + 4 (the image's top is -Z).
        const size_t px = size_t(8 * (i / 6) + 4) * 48 + 8 * (i % 6) + 4;
        const vec3 want = colour[i] * (3.0f / 3.14159265f);
        const vec3 got(img.channel("R")[px], img.channel("G")[px], img.channel("B")[px]);
        CAPTURE(i, got.x, got.y, got.z, want.x, want.y, want.z);
        for (int k = 0; k < 3; ++k) CHECK(std::abs(got[k] - want[k]) <= 1e-4f * (1.0f + want[k]));
        seen.insert({got.x, got.y, got.z});
    }
    CHECK(seen.size() == n);
}

TEST_CASE("textures of every format and the environment map read alike on both engines",
          "[gpu][texture]") {
    // One quad per format, each an 8 x 8 image of varied texels so that bilinear filtering and
    // sRGB decoding matter, magnified on a 128 x 32 film, and a lat-long environment map (EXR)
    // seen around them and sampled for light: with the same seed both engines trace the same
    // paths, so per pixel they agree to float rounding.
    const std::string dir = temp_dir("texture-formats-both-engines");
    std::vector<std::vector<uint8_t>> rgb8(8), rgba16(8);
    std::vector<uint8_t> jpeg_rgb;
    ExrImage sky, floaty;
    sky.width = 16;
    sky.height = 8;
    floaty.width = floaty.height = 8;
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x) {
            const uint8_t a = uint8_t(31 * x + 3 * y), b = uint8_t(200 - 20 * y),
                          c = uint8_t(x * y * 4);
            rgb8[y].insert(rgb8[y].end(), {a, b, c});
            const uint16_t w[4] = {uint16_t(8000 * x + 7 * y), uint16_t(65535 - 9000 * y),
                                   uint16_t(x * y * 1000), uint16_t(65535)};
            for (uint16_t v : w) rgba16[y].insert(rgba16[y].end(), {uint8_t(v >> 8), uint8_t(v)});
            jpeg_rgb.insert(jpeg_rgb.end(), {c, a, b});
            floaty.channels["R"].push_back(0.1f * float(x));
            floaty.channels["G"].push_back(0.05f * float(y) + 0.2f);
            floaty.channels["B"].push_back(x == y ? 2.0f : 0.3f);
        }
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 16; ++x) {
            sky.channels["R"].push_back(0.2f + 0.1f * float(x % 4));
            sky.channels["G"].push_back(0.3f + 0.2f * float(y == 2));
            sky.channels["B"].push_back(0.5f + (x == 5 && y == 1 ? 20.0f : 0.0f));
        }
    write_file(dir + "/p8.png", encode_png({8, 8, PNG_COLOR_TYPE_RGB, 8}, rgb8));
    write_file(dir + "/p16.png", encode_png({8, 8, PNG_COLOR_TYPE_RGBA, 16}, rgba16));
    write_file(dir + "/j.jpg", encode_jpeg(8, 8, 3, jpeg_rgb));
    write_exr(dir + "/f.exr", floaty);
    write_exr(dir + "/sky.exr", sky);
    std::ofstream(dir + "/formats.json") << R"({
 "camera": {"eye": [0, 7, 2], "target": [0, 0, 0], "fov": 22},
 "film": {"width": 128, "height": 32}, "render": {"spp": 4, "max_depth": 2},
 "textures": {"p8": {"file": "p8.png"}, "p16": {"file": "p16.png"}, "j": {"file": "j.jpg"},
              "f": {"file": "f.exr"}},
 "materials": {"p8": {"Kd": [0.9, 0.9, 0.9], "map_Kd": "p8"},
               "p16": {"Kd": [0.9, 0.9, 0.9], "map_Kd": "p16"},
               "j": {"Kd": [0.9, 0.9, 0.9], "map_Kd": "j"},
               "f": {"Kd": [0.4, 0.4, 0.4], "map_Kd": "f"}},
 "meshes": {"q": {"type": "quad"}},
 "objects": [{"mesh": "q", "material": "p8", "transform": {"translate": [-3.3, 0, 0]}},
             {"mesh": "q", "material": "p16", "transform": {"translate": [-1.1, 0, 0]}},
             {"mesh": "q", "material": "j", "transform": {"translate": [1.1, 0, 0]}},
             {"mesh": "q", "material": "f", "transform": {"translate": [3.3, 0, 0]}}],
 "environment": {"type": "map", "file": "sky.exr"}
})";
    const std::string flags = "--seed 11 --sampler random";
    const ProcessResult gpu = render(dir + "/formats.json", dir + "/gpu.exr",
                                     flags + " --backend vulkan --vk-mode compute");
    INFO(gpu.out);
    REQUIRE(gpu.exit_code == 0);
    const ProcessResult cpu =
        render(dir + "/formats.json", dir + "/cpu.exr", flags + " --backend cpu");
    INFO(cpu.out);
    REQUIRE(cpu.exit_code == 0);
    const ExrImage a = read_exr(dir + "/gpu.exr"), b = read_exr(dir + "/cpu.exr");
    size_t differ = 0, total = 0;
    std::set<float> values;
    for (const char* ch : {"R", "G", "B"}) {
        const std::vector<float>&va = a.channel(ch), &vb = b.channel(ch);
        for (size_t i = 0; i < va.size(); ++i, ++total) {
            differ += std::abs(va[i] - vb[i]) > 1e-4f * std::max(1.0f, std::abs(vb[i]));
            values.insert(vb[i]);
        }
    }
    INFO(differ << " of " << total << " pixel-channels differ");
    // As the bundled scenes' same-seed test: a path may branch differently where a decision
    // sits within rounding of its threshold.
    CHECK(differ <= total / 100);
    CHECK(values.size() > total / 4); // the textures and the sky make the pixels differ
}

} // namespace tp::test
