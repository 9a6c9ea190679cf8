// texture.h: bilinear footprints with repeat (and clamped-t) addressing, texel wrapping, and the
// latitude-longitude mapping of environment maps.
#include "shared/texture.h"

#include <algorithm>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

TEST_CASE("wrap_texel is the mathematical modulo for negative and large texel indices",
          "[texture]") {
    for (uint32_t n : {1u, 3u, 4u, 512u, 1000u})
        for (int i = -5000; i <= 5000; ++i) {
            const int expected = ((i % int(n)) + int(n)) % int(n);
            REQUIRE(tp::wrap_texel(float(i), n) == uint32_t(expected));
        }
    // Far away, within the documented |i| < 2^24.
    CHECK(tp::wrap_texel(16777215.0f, 1000u) == 16777215u % 1000u);
    CHECK(tp::wrap_texel(-16777215.0f, 1000u) == 1000u - 16777215u % 1000u);
}

constexpr uint32_t R = tp::SLOT_WRAP_REPEAT, C = tp::SLOT_WRAP_CLAMP, M = tp::SLOT_WRAP_MIRROR;

TEST_CASE("bilinear footprint at texel centres and midpoints and across the wrap", "[texture]") {
    const uint32_t w = 8, h = 4;
    SECTION("at a texel centre the weight is all on that texel") {
        const tp::TexelFootprint fp =
            tp::texture_footprint(tp::vec2(3.5f / w, 2.5f / h), w, h, R, R);
        CHECK(fp.f == tp::vec2(0.0f));
        CHECK(fp.i00 == 2 * w + 3);
        CHECK(fp.i10 == 2 * w + 4);
        CHECK(fp.i01 == 3 * w + 3);
        CHECK(fp.i11 == 3 * w + 4);
    }
    SECTION("halfway between centres the weights are 1/2") {
        const tp::TexelFootprint fp =
            tp::texture_footprint(tp::vec2(4.0f / w, 1.0f / h), w, h, R, R);
        CHECK(fp.f == tp::vec2(0.5f));
        CHECK(fp.i00 == 0 * w + 3);
        CHECK(fp.i11 == 1 * w + 4);
    }
    SECTION("s = 0 blends the last and the first column; t wraps likewise") {
        const tp::TexelFootprint fp = tp::texture_footprint(tp::vec2(0.0f, 0.0f), w, h, R, R);
        CHECK(fp.f == tp::vec2(0.5f));
        CHECK(fp.i00 == (h - 1) * w + (w - 1));
        CHECK(fp.i10 == (h - 1) * w + 0);
        CHECK(fp.i01 == 0 * w + (w - 1));
        CHECK(fp.i11 == 0);
    }
    SECTION("repeat: s and s + 1 and s - 1 give the same footprint") {
        for (float s : {0.13f, 0.5f, 0.97f}) {
            const tp::TexelFootprint a = tp::texture_footprint(tp::vec2(s, 0.3f), w, h, R, R);
            const tp::TexelFootprint b =
                tp::texture_footprint(tp::vec2(s - 1.0f, 0.3f), w, h, R, R);
            const tp::TexelFootprint c =
                tp::texture_footprint(tp::vec2(s + 2.0f, 0.3f), w, h, R, R);
            CHECK(a.i00 == b.i00);
            CHECK(a.i00 == c.i00);
            CHECK(a.f.x == Approx(b.f.x).margin(1e-5));
            CHECK(a.f.x == Approx(c.f.x).margin(1e-5));
        }
    }
    SECTION("clamped t stays on the first and last rows") {
        const tp::TexelFootprint top = tp::texture_footprint(tp::vec2(0.3f, 0.0f), w, h, R, C);
        CHECK(top.i00 / w == 0);
        CHECK(top.i01 / w == 0);
        const tp::TexelFootprint bottom = tp::texture_footprint(tp::vec2(0.3f, 1.0f), w, h, R, C);
        CHECK(bottom.i00 / w == h - 1);
        CHECK(bottom.i01 / w == h - 1);
    }
}

TEST_CASE("bilinear filtering reproduces a linear function between texel centres", "[texture]") {
    const uint32_t w = 16, h = 8;
    const auto value = [&](uint32_t i) {
        const float x = float(i % w) + 0.5f, y = float(i / w) + 0.5f;
        return tp::vec4(0.25f + 0.5f * x, 1.0f - 0.125f * y, x + y, 0.5f * x);
    };
    for (float s : {0.1f, 0.37f, 0.5f, 0.81f})
        for (float t : {0.2f, 0.5f, 0.74f}) {
            const tp::TexelFootprint fp = tp::texture_footprint(tp::vec2(s, t), w, h, R, R);
            const tp::vec4 c = tp::texture_bilerp(value(fp.i00), value(fp.i10), value(fp.i01),
                                                  value(fp.i11), fp.f);
            const float x = s * float(w), y = t * float(h);
            CHECK(c.x == Approx(0.25f + 0.5f * x).epsilon(1e-5));
            CHECK(c.y == Approx(1.0f - 0.125f * y).epsilon(1e-5));
            CHECK(c.z == Approx(x + y).epsilon(1e-5));
            CHECK(c.w == Approx(0.5f * x).epsilon(1e-5));
        }
}

TEST_CASE("wrap modes: clamp to edge and mirrored repeat, as glTF's samplers define them",
          "[texture]") {
    // An axis of 4 texels: clamp keeps the edge texel beyond either end; mirrored repeat has
    // period 8 with its second half reversed: 0 1 2 3 3 2 1 0 | 0 1 ...
    const uint32_t n = 4;
    const uint32_t mirrored[] = {0, 1, 2, 3, 3, 2, 1, 0};
    for (int i = -9; i < 13; ++i) {
        CHECK(tp::wrap_texel_mode(float(i), n, C) == uint32_t(std::clamp(i, 0, int(n) - 1)));
        CHECK(tp::wrap_texel_mode(float(i), n, M) == mirrored[((i % 8) + 8) % 8]);
        CHECK(tp::wrap_texel_mode(float(i), n, R) == uint32_t(((i % 4) + 4) % 4));
    }
    // Nearest: the texel that contains st, wrapped per axis.
    CHECK(tp::texture_nearest(tp::vec2(0.30f, 0.99f), 4, 2, R, R) == 1 * 4 + 1);
    CHECK(tp::texture_nearest(tp::vec2(-0.01f, 1.2f), 4, 2, C, C) == 1 * 4 + 0);
    CHECK(tp::texture_nearest(tp::vec2(1.1f, -0.2f), 4, 2, M, M) == 0 * 4 + 3);
}

TEST_CASE("texel decoding: 8- and 16-bit words, sRGB's transfer function", "[texture]") {
    const tp::vec4 c = tp::unpack_rgba8(0x80FF4000u);
    CHECK(c.x == 0.0f);
    CHECK(c.y == Approx(64.0f / 255.0f).epsilon(1e-7));
    CHECK(c.z == 1.0f);
    CHECK(c.w == Approx(128.0f / 255.0f).epsilon(1e-7));
    const tp::vec4 d = tp::unpack_rgba16(0xFFFF0000u, 0x00018000u);
    CHECK(d.x == 0.0f);
    CHECK(d.y == 1.0f);
    CHECK(d.z == Approx(32768.0f / 65535.0f).epsilon(1e-7));
    CHECK(d.w == Approx(1.0f / 65535.0f).epsilon(1e-6));
    // IEC 61966-2-1: the linear segment below 0.04045, the power law above, continuous at the
    // joint (to the 4 digits of the standard's constants), 0 and 1 fixed.
    CHECK(tp::srgb_to_linear(0.0f) == 0.0f);
    CHECK(tp::srgb_to_linear(1.0f) == Approx(1.0f).epsilon(1e-6));
    CHECK(tp::srgb_to_linear(0.04f) == Approx(0.04f / 12.92f).epsilon(1e-6));
    CHECK(tp::srgb_to_linear(0.5f) == Approx(0.2140411f).epsilon(1e-5));
    CHECK(tp::srgb_to_linear(0.0404f) == Approx(tp::srgb_to_linear(0.0405f)).margin(1e-5));
}

TEST_CASE("uv_to_image flips v: OBJ's v = 0 is the bottom row", "[texture]") {
    CHECK(tp::uv_to_image(tp::vec2(0.25f, 0.0f)) == tp::vec2(0.25f, 1.0f));
    CHECK(tp::uv_to_image(tp::vec2(0.25f, 0.75f)) == tp::vec2(0.25f, 0.25f));
}

TEST_CASE("lat-long mapping looks down -Z at its centre and up at t = 0 and round-trips",
          "[texture]") {
    CHECK(glm::length(tp::latlong_to_direction(tp::vec2(0.5f, 0.5f)) - tp::vec3(0, 0, -1)) < 1e-6f);
    CHECK(glm::length(tp::latlong_to_direction(tp::vec2(0.75f, 0.5f)) - tp::vec3(1, 0, 0)) < 1e-6f);
    CHECK(glm::length(tp::latlong_to_direction(tp::vec2(0.3f, 0.0f)) - tp::vec3(0, 1, 0)) < 1e-6f);
    CHECK(tp::direction_to_latlong(tp::vec3(0, 1, 0)) == tp::vec2(0.5f, 0.0f));
    CHECK(tp::direction_to_latlong(tp::vec3(0, -1, 0)) == tp::vec2(0.5f, 1.0f));
    for (float s = 0.01f; s < 1.0f; s += 0.049f)
        for (float t = 0.001f; t < 1.0f; t += 0.0333f) {
            const tp::vec2 st = tp::direction_to_latlong(tp::latlong_to_direction(tp::vec2(s, t)));
            CAPTURE(s, t);
            CHECK(st.x == Approx(s).margin(2e-6));
            CHECK(st.y == Approx(t).margin(2e-6));
        }
    // Near the poles theta keeps its relative precision (atan, not acos).
    const float theta = 1e-3f;
    const tp::vec2 st = tp::direction_to_latlong(tp::vec3(std::sin(theta), std::cos(theta), 0.0f));
    CHECK(st.y * tp::PI == Approx(theta).epsilon(1e-5));
}

TEST_CASE("rotate_y is a right-handed rotation about +Y", "[texture]") {
    // Right-handed: +X turns towards -Z.
    CHECK(glm::length(tp::rotate_y(tp::vec3(1, 0, 0), tp::PI / 2.0f) - tp::vec3(0, 0, -1)) < 1e-6f);
    CHECK(glm::length(tp::rotate_y(tp::vec3(0, 0, 1), tp::PI / 2.0f) - tp::vec3(1, 0, 0)) < 1e-6f);
    const tp::vec3 d = glm::normalize(tp::vec3(0.3f, -0.4f, 0.8f));
    CHECK(glm::length(tp::rotate_y(tp::rotate_y(d, 0.7f), -0.7f) - d) < 1e-6f);
}
