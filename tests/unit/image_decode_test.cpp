// The one image decoder of every texture (image/png_io.h, image/jpeg_io.h, image/texture_io.h)
// and glTF's data: URIs (scene/gltf_resources.h): PNG of every colour type and bit depth and
// JPEG decode to the raw texel words the engines read (8-bit R in the low byte, 16-bit R | G << 16
// and B | A << 16), from memory and from files alike; images in other formats are told apart by
// their bytes; broken data is an InputError naming the image. The PNG files are written with
// libpng's writer from samples given by hand, the JPEG files with libjpeg's encoder
// (support/image_encoders.h).
#include "image/jpeg_io.h"
#include "image/png_io.h"
#include "image/texture_io.h"
#include "scene/gltf_resources.h"
#include "scene/load.h"
#include "support/gltf_builder.h"
#include "support/image_encoders.h"
#include "support/test_paths.h"
#include "util/error.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

using tp::test::encode_jpeg;
using tp::test::encode_png;
using tp::test::PngSpec;

std::string write_file(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

uint32_t rgba8(uint32_t r, uint32_t g, uint32_t b, uint32_t a) {
    return r | g << 8 | b << 16 | a << 24;
}

std::vector<uint32_t> words(const tp::Texture& t) {
    return std::vector<uint32_t>(t.words.begin(), t.words.end());
}

// Decoded from memory and from a file, the same texture; returns it.
tp::Texture decode_both(const std::string& png, const std::string& dir, const std::string& name) {
    const tp::Texture m = tp::decode_png(png, name);
    const tp::Texture f = tp::read_png(write_file(dir + "/" + name + ".png", png));
    CHECK(m.width == f.width);
    CHECK(m.height == f.height);
    CHECK(m.format == f.format);
    CHECK(words(m) == words(f));
    return m;
}

} // namespace

TEST_CASE("PNG: 8-bit grey, grey + alpha, RGB and RGBA decode to their texel words",
          "[unit][image]") {
    const std::string dir = tp::test::temp_dir("png-8bit");
    SECTION("grey repeats into R, G and B, opaque") {
        const tp::Texture t =
            decode_both(encode_png({3, 1, PNG_COLOR_TYPE_GRAY, 8}, {{0, 128, 255}}), dir, "g8");
        CHECK(t.format == tp::TEXEL_RGBA8);
        CHECK(words(t) == std::vector<uint32_t>{rgba8(0, 0, 0, 255), rgba8(128, 128, 128, 255),
                                                rgba8(255, 255, 255, 255)});
    }
    SECTION("grey + alpha") {
        const tp::Texture t = decode_both(
            encode_png({2, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 8}, {{10, 20, 30, 40}}), dir, "ga8");
        CHECK(words(t) == std::vector<uint32_t>{rgba8(10, 10, 10, 20), rgba8(30, 30, 30, 40)});
    }
    SECTION("RGB, two rows top to bottom") {
        const tp::Texture t = decode_both(
            encode_png({2, 2, PNG_COLOR_TYPE_RGB, 8}, {{1, 2, 3, 4, 5, 6}, {7, 8, 9, 10, 11, 12}}),
            dir, "rgb8");
        CHECK(t.width == 2);
        CHECK(t.height == 2);
        CHECK(words(t) == std::vector<uint32_t>{rgba8(1, 2, 3, 255), rgba8(4, 5, 6, 255),
                                                rgba8(7, 8, 9, 255), rgba8(10, 11, 12, 255)});
    }
    SECTION("RGBA") {
        const tp::Texture t = decode_both(
            encode_png({2, 1, PNG_COLOR_TYPE_RGBA, 8}, {{1, 2, 3, 4, 250, 251, 252, 253}}), dir,
            "rgba8");
        CHECK(words(t) == std::vector<uint32_t>{rgba8(1, 2, 3, 4), rgba8(250, 251, 252, 253)});
        // As the engines read it: values over 255, not sRGB-decoded here.
        CHECK(t.raw(0) == tp::vec4(1, 2, 3, 4) * (1.0f / 255.0f));
    }
    SECTION("RGB with a tRNS colour: that colour is transparent, the others opaque") {
        PngSpec s{2, 1, PNG_COLOR_TYPE_RGB, 8};
        s.trns = {0};
        s.trns_value.red = 4;
        s.trns_value.green = 5;
        s.trns_value.blue = 6;
        const tp::Texture t = decode_both(encode_png(s, {{1, 2, 3, 4, 5, 6}}), dir, "rgbt");
        CHECK(words(t) == std::vector<uint32_t>{rgba8(1, 2, 3, 255), rgba8(4, 5, 6, 0)});
    }
    SECTION("Adam7 interlacing gives the same words") {
        std::vector<std::vector<uint8_t>> rows;
        std::vector<uint32_t> expected;
        for (uint32_t y = 0; y < 9; ++y) {
            rows.emplace_back();
            for (uint32_t x = 0; x < 10; ++x) {
                const uint8_t r = uint8_t(x * 20 + y), g = uint8_t(y * 25), b = uint8_t(x ^ y);
                rows.back().insert(rows.back().end(), {r, g, b});
                expected.push_back(rgba8(r, g, b, 255));
            }
        }
        PngSpec s{10, 9, PNG_COLOR_TYPE_RGB, 8};
        s.interlaced = true;
        CHECK(words(decode_both(encode_png(s, rows), dir, "adam7")) == expected);
    }
}

TEST_CASE("PNG: 16-bit images keep their 16 bits, in R | G << 16 and B | A << 16",
          "[unit][image]") {
    const std::string dir = tp::test::temp_dir("png-16bit");
    SECTION("RGBA (big-endian in the file)") {
        const tp::Texture t =
            decode_both(encode_png({1, 1, PNG_COLOR_TYPE_RGBA, 16},
                                   {{0x12, 0x34, 0xAB, 0xCD, 0x00, 0x01, 0xFF, 0xFE}}),
                        dir, "rgba16");
        CHECK(t.format == tp::TEXEL_RGBA16);
        CHECK(words(t) == std::vector<uint32_t>{0xABCD1234u, 0xFFFE0001u});
    }
    SECTION("RGB: alpha 65535") {
        const tp::Texture t = decode_both(
            encode_png({1, 1, PNG_COLOR_TYPE_RGB, 16}, {{0x01, 0x02, 0x03, 0x04, 0x05, 0x06}}), dir,
            "rgb16");
        CHECK(words(t) == std::vector<uint32_t>{0x03040102u, 0xFFFF0506u});
    }
    SECTION("grey and grey + alpha") {
        const tp::Texture g =
            decode_both(encode_png({1, 1, PNG_COLOR_TYPE_GRAY, 16}, {{0x80, 0x01}}), dir, "g16");
        CHECK(words(g) == std::vector<uint32_t>{0x80018001u, 0xFFFF8001u});
        const tp::Texture ga = decode_both(
            encode_png({1, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 16}, {{0x80, 0x01, 0x00, 0x02}}), dir,
            "ga16");
        CHECK(words(ga) == std::vector<uint32_t>{0x80018001u, 0x00028001u});
        CHECK(ga.raw(0).x == 32769.0f / 65535.0f);
    }
}

TEST_CASE("PNG: palettes and low bit depths expand to 8-bit RGBA", "[unit][image]") {
    const std::string dir = tp::test::temp_dir("png-palette");
    SECTION("a 2-bit palette with tRNS alphas") {
        PngSpec s{4, 1, PNG_COLOR_TYPE_PALETTE, 2};
        s.palette = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {9, 8, 7}};
        s.trns = {128, 0}; // entries past the list are opaque
        // Indices 3, 2, 1, 0 packed high bits first: 0b11100100.
        const tp::Texture t = decode_both(encode_png(s, {{0xE4}}), dir, "pal2");
        CHECK(t.format == tp::TEXEL_RGBA8);
        CHECK(words(t) == std::vector<uint32_t>{rgba8(9, 8, 7, 255), rgba8(0, 0, 255, 255),
                                                rgba8(0, 255, 0, 0), rgba8(255, 0, 0, 128)});
    }
    SECTION("an 8-bit palette") {
        PngSpec s{2, 1, PNG_COLOR_TYPE_PALETTE, 8};
        s.palette = {{10, 20, 30}, {40, 50, 60}};
        const tp::Texture t = decode_both(encode_png(s, {{1, 0}}), dir, "pal8");
        CHECK(words(t) == std::vector<uint32_t>{rgba8(40, 50, 60, 255), rgba8(10, 20, 30, 255)});
    }
    SECTION("1-bit grey scales to 0 and 255, 4-bit grey to 17 per step") {
        const tp::Texture one =
            decode_both(encode_png({3, 1, PNG_COLOR_TYPE_GRAY, 1}, {{0xA0}}), dir, "g1");
        CHECK(words(one) == std::vector<uint32_t>{rgba8(255, 255, 255, 255), rgba8(0, 0, 0, 255),
                                                  rgba8(255, 255, 255, 255)});
        const tp::Texture four =
            decode_both(encode_png({2, 1, PNG_COLOR_TYPE_GRAY, 4}, {{0x3F}}), dir, "g4");
        CHECK(words(four) ==
              std::vector<uint32_t>{rgba8(51, 51, 51, 255), rgba8(255, 255, 255, 255)});
    }
}

TEST_CASE("PNG: broken data is an InputError naming the image", "[unit][image]") {
    const std::string good =
        encode_png({4, 4, PNG_COLOR_TYPE_RGB, 8},
                   std::vector<std::vector<uint8_t>>(4, std::vector<uint8_t>(12, 7)));
    CHECK_THROWS_WITH(tp::decode_png("not a PNG", "images[3]"),
                      Catch::Contains("images[3]") && Catch::Contains("PNG"));
    CHECK_THROWS_AS(tp::decode_png(good.substr(0, good.size() / 2), "cut"), tp::InputError);
    std::string bad_crc = good;
    bad_crc[20] ^= 0x55; // inside IHDR: its CRC no longer matches
    CHECK_THROWS_AS(tp::decode_png(bad_crc, "crc"), tp::InputError);
    CHECK_THROWS_WITH(tp::read_png("/nonexistent/t.png"), Catch::Contains("/nonexistent/t.png"));
}

TEST_CASE("an image of more texels than a 32-bit index reaches is refused before allocation",
          "[unit][image]") {
    CHECK_THROWS_WITH(tp::texel_storage(65536, 65537, tp::TEXEL_RGBA8, "huge.png"),
                      Catch::Contains("huge.png") && Catch::Contains("65536x65537"));
    CHECK(tp::texel_storage(3, 2, tp::TEXEL_RGBA16, "small").size() == 12);
}

TEST_CASE("JPEG: RGB and grey decode to 8-bit texel words, opaque", "[unit][image]") {
    const std::string dir = tp::test::temp_dir("jpeg");
    SECTION("flat RGB blocks decode to their colours (within JPEG's rounding)") {
        // 16 x 8: a red and a blue 8 x 8 block, each one flat colour (at quality 100 without
        // subsampling a flat block keeps its colour to a unit or two).
        std::vector<uint8_t> rgb;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 16; ++x) {
                const bool left = x < 8;
                rgb.insert(rgb.end(), {uint8_t(left ? 200 : 20), uint8_t(left ? 40 : 90),
                                       uint8_t(left ? 30 : 220)});
            }
        const std::string jpeg = encode_jpeg(16, 8, 3, rgb);
        const tp::Texture m = tp::decode_jpeg(jpeg, "mem.jpg");
        const tp::Texture f = tp::read_jpeg(write_file(dir + "/f.jpg", jpeg));
        CHECK(words(m) == words(f));
        REQUIRE(m.format == tp::TEXEL_RGBA8);
        REQUIRE(m.width == 16);
        REQUIRE(m.height == 8);
        for (size_t i = 0; i < m.texel_count(); ++i) {
            CAPTURE(i);
            const tp::uvec4 c = m.channels(i);
            const tp::uvec4 want =
                i % 16 < 8 ? tp::uvec4(200, 40, 30, 255) : tp::uvec4(20, 90, 220, 255);
            for (int k = 0; k < 3; ++k) CHECK(std::abs(int(c[k]) - int(want[k])) <= 2);
            CHECK(c.w == 255);
        }
    }
    SECTION("grey repeats into R, G and B") {
        std::vector<uint8_t> grey(8 * 8, 77);
        const tp::Texture t = tp::decode_jpeg(encode_jpeg(8, 8, 1, grey), "grey.jpg");
        for (size_t i = 0; i < t.texel_count(); ++i) {
            const tp::uvec4 c = t.channels(i);
            CHECK(c.x == c.y);
            CHECK(c.y == c.z);
            CHECK(std::abs(int(c.x) - 77) <= 1);
            CHECK(c.w == 255);
        }
    }
    SECTION("a truncated JPEG, CMYK and garbage are InputErrors naming the image") {
        std::vector<uint8_t> rgb(32 * 32 * 3);
        for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t(i * 37);
        const std::string jpeg = encode_jpeg(32, 32, 3, rgb);
        CHECK_THROWS_WITH(tp::decode_jpeg(jpeg.substr(0, jpeg.size() / 2), "cut.jpg"),
                          Catch::Contains("cut.jpg") && Catch::Contains("Premature end"));
        CHECK_THROWS_WITH(
            tp::decode_jpeg(encode_jpeg(8, 8, 4, std::vector<uint8_t>(256, 9)), "k.jpg"),
            Catch::Contains("k.jpg") && Catch::Contains("CMYK"));
        CHECK_THROWS_WITH(tp::decode_jpeg("\xFF\xD8\xFF garbage", "g.jpg"),
                          Catch::Contains("g.jpg"));
    }
}

TEST_CASE("load_texture tells formats by their bytes, not their names", "[unit][image]") {
    const std::string dir = tp::test::temp_dir("texture-formats");
    const std::string png = encode_png({1, 1, PNG_COLOR_TYPE_RGB, 8}, {{9, 8, 7}});
    // A PNG named .jpg is read as the PNG it is.
    const tp::Texture t = tp::load_texture(write_file(dir + "/named-wrong.jpg", png));
    CHECK(words(t) == std::vector<uint32_t>{rgba8(9, 8, 7, 255)});
    CHECK(t.source == dir + "/named-wrong.jpg");
    CHECK(tp::image_format_of(png) == tp::ImageFormat::png);
    CHECK(tp::image_format_of("\xFF\xD8\xFF\xE0") == tp::ImageFormat::jpeg);
    CHECK(tp::image_format_of(std::string("\x76\x2F\x31\x01", 4)) == tp::ImageFormat::exr);
    CHECK(tp::image_format_of("BM...") == tp::ImageFormat::other);
    CHECK(tp::undecoded_format_name("BM\x36\x00\x00\x00") == "BMP");
    CHECK(tp::undecoded_format_name("GIF89a......") == "GIF");
    CHECK(tp::undecoded_format_name(std::string("RIFF\x10\0\0\0WEBPVP8 ", 16)) == "WebP");
    CHECK(tp::undecoded_format_name("RIFF").empty()); // too short to tell: not WebP
    CHECK(tp::undecoded_format_name("\xABKTX 20\xBB\r\n\x1A\n") == "KTX2");
    CHECK(tp::undecoded_format_name("garbage").empty());
}

TEST_CASE("data: URIs decode base64 with or without padding, and refuse what is not base64",
          "[unit][gltf]") {
    for (const std::string& bytes :
         {std::string(""), std::string("a"), std::string("ab"), std::string("abc"),
          std::string("\x89PNG\r\n\x1a\n\xff\0", 10)}) {
        const std::string b64 = tp::test::base64(bytes);
        const auto d = tp::parse_data_uri("data:image/png;base64," + b64);
        REQUIRE(d);
        CHECK(d->bytes == bytes);
        CHECK(d->media_type == "image/png");
        std::string unpadded = b64;
        while (!unpadded.empty() && unpadded.back() == '=') unpadded.pop_back();
        const auto u = tp::parse_data_uri("data:application/octet-stream;base64," + unpadded);
        REQUIRE(u);
        CHECK(u->bytes == bytes);
    }
    CHECK_FALSE(tp::parse_data_uri("data:image/png,plain"));
    CHECK_FALSE(tp::parse_data_uri("data:image/png;base64,ab$d"));
    CHECK_FALSE(tp::parse_data_uri("data:image/png;base64,a"));
    CHECK_FALSE(tp::parse_data_uri("file.png"));
}

namespace {

// A glTF quad whose material's base colour reads image 0, with `images` as given and the
// image bytes `data` in buffer views where an image names "bufferView": -1 (replaced here).
std::string textured_gltf(const std::string& dir, const std::string& name, nlohmann::json image,
                          const std::string& data = "") {
    tp::test::GltfBuilder g;
    const uint32_t pos = g.vec3s({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const uint32_t uv = g.vec2s({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    const uint32_t idx = g.indices({0, 1, 2, 0, 2, 3});
    if (image.contains("bufferView")) image["bufferView"] = g.view(data.data(), data.size());
    g.add("images", image);
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    g.mesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, int(idx), 0);
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    return g.write_glb(dir, name);
}

} // namespace

TEST_CASE("glTF images go through the textures' decoders: a 20000 x 2 PNG, a JPEG data: URI, "
          "a BMP dropped",
          "[unit][gltf][image]") {
    const std::string dir = tp::test::temp_dir("gltf-images");
    std::vector<std::string> warnings;
    SECTION("a 20000 x 2 PNG in a buffer view (stb_image refused it: 'Unknown image format')") {
        std::vector<std::vector<uint8_t>> rows(2, std::vector<uint8_t>(20000 * 3));
        for (uint32_t x = 0; x < 20000; ++x) {
            rows[0][3 * x] = uint8_t(x);
            rows[1][3 * x + 2] = uint8_t(x >> 8);
        }
        const std::string png = encode_png({20000, 2, PNG_COLOR_TYPE_RGB, 8}, rows);
        const tp::Scene s = tp::load_scene(
            textured_gltf(dir, "wide", {{"bufferView", -1}, {"mimeType", "image/png"}}, png),
            warnings);
        REQUIRE(s.textures.size() == 1);
        const tp::Texture& t = s.textures[0];
        CHECK(t.width == 20000);
        CHECK(t.height == 2);
        CHECK(t.format == tp::TEXEL_RGBA8);
        CHECK(t.name == "images[0]");
        CHECK(t.words[300] == rgba8(300 % 256, 0, 0, 255));
        CHECK(t.words[20000 + 19999] == rgba8(0, 0, 19999 >> 8, 255));
    }
    SECTION("a JPEG as a data: URI") {
        const std::string jpeg = encode_jpeg(8, 8, 1, std::vector<uint8_t>(64, 100));
        const tp::Scene s = tp::load_scene(
            textured_gltf(dir, "jpeg",
                          {{"uri", "data:image/jpeg;base64," + tp::test::base64(jpeg)}}),
            warnings);
        REQUIRE(s.textures.size() == 1);
        CHECK(s.textures[0].width == 8);
        CHECK(std::abs(int(s.textures[0].channels(0).x) - 100) <= 1);
        CHECK(s.materials[0].kd_texture != tp::NO_TEXTURE);
    }
    SECTION("a BMP file: the texture is dropped, said so, the material rendered without it") {
        write_file(dir + "/t.bmp",
                   std::string("BM\x3e\0\0\0\0\0\0\0\x36\0\0\0", 14) + std::string(48, '\0'));
        const tp::Scene s = tp::load_scene(textured_gltf(dir, "bmp", {{"uri", "t.bmp"}}), warnings);
        CHECK(s.textures.empty());
        CHECK(s.materials[0].kd_texture == tp::NO_TEXTURE);
        REQUIRE(s.material_dropped.size() == 1);
        REQUIRE(s.material_dropped[0].size() == 1);
        CHECK_THAT(s.material_dropped[0][0],
                   Catch::Contains("images[0] is BMP") && Catch::Contains("PNG and JPEG"));
    }
    SECTION("a WebP buffer view, known by its mimeType alone: dropped") {
        const tp::Scene s = tp::load_scene(
            textured_gltf(dir, "webp", {{"bufferView", -1}, {"mimeType", "image/webp"}}, "xxxx"),
            warnings);
        CHECK(s.textures.empty());
        CHECK_THAT(s.material_dropped.at(0).at(0), Catch::Contains("image/webp"));
    }
    SECTION("bytes that are no image, as a PNG: an error naming the file, field and user") {
        CHECK_THROWS_WITH(
            tp::load_scene(textured_gltf(dir, "junk",
                                         {{"bufferView", -1}, {"mimeType", "image/png"}}, "junk!"),
                           warnings),
            Catch::Contains("junk.glb") && Catch::Contains("images[0]") &&
                Catch::Contains("baseColorTexture") && Catch::Contains("cannot decode"));
    }
}
