// The GLSL built-ins the shared headers use, as the host sees them through GLM (lang.h), against
// their definitions in the GLSL 4.60 specification, sec. 8. Where the C library's function of a
// similar name differs (fmod, modf, signbit, atan2's argument order), the host must still follow
// GLSL, or the C++ engine and the shaders compute different things from the same header.
#include "shared/lang.h"
#include "shared/math.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

namespace {

uint32_t bits(float x) {
    uint32_t u;
    std::memcpy(&u, &x, sizeof u);
    return u;
}

} // namespace

TEST_CASE("sign is 0 at both zeros and +-1 elsewhere (GLSL 8.3)", "[glsl]") {
    // math.h's orthonormal_basis writes copysign out because of exactly this.
    CHECK(tp::sign(0.0f) == 0.0f);
    CHECK(tp::sign(-0.0f) == 0.0f);
    CHECK(tp::sign(-3.5f) == -1.0f);
    CHECK(tp::sign(std::numeric_limits<float>::denorm_min()) == 1.0f);
    CHECK(tp::sign(-std::numeric_limits<float>::denorm_min()) == -1.0f);
}

TEST_CASE("fract is x - floor(x) so negatives map into 0 to 1 (GLSL 8.3)", "[glsl]") {
    CHECK(tp::fract(-0.25f) == 0.75f);
    CHECK(tp::fract(-1.0f) == 0.0f);
    CHECK(tp::fract(2.5f) == 0.5f);
    float whole;
    CHECK(std::modf(-0.25f, &whole) == -0.25f); // the C function keeps the sign
    // The spec's formula rounds: x - floor(x) for a tiny negative x is 1 in float. GLM uses
    // the same formula, so both engines agree even there.
    CHECK(tp::fract(-1e-9f) == 1.0f);
    CHECK(tp::floor(-0.5f) == -1.0f);
}

TEST_CASE("reflect is I - 2 dot(N I) N unnormalised (GLSL 8.5)", "[glsl]") {
    CHECK(tp::reflect(tp::vec3(1, -1, 0), tp::vec3(0, 1, 0)) == tp::vec3(1, 1, 0));
    CHECK(tp::reflect(tp::vec3(0.6f, -0.8f, 0), tp::vec3(0, 1, 0)) == tp::vec3(0.6f, 0.8f, 0));
    // With a non-unit N the result is the formula's, not a mirror direction.
    CHECK(tp::reflect(tp::vec3(0, -1, 0), tp::vec3(0, 2, 0)) == tp::vec3(0, 7, 0));
}

TEST_CASE("two-argument atan is atan2 with y first (GLSL 8.1)", "[glsl]") {
    CHECK(tp::atan(1.0f, 0.0f) == Approx(tp::PI / 2.0f));
    CHECK(tp::atan(0.0f, -1.0f) == Approx(tp::PI));
    CHECK(tp::atan(-1.0f, 0.0f) == Approx(-tp::PI / 2.0f));
    CHECK(tp::atan(1.0f, 1.0f) == Approx(tp::PI / 4.0f));
}

TEST_CASE("float bit casts round-trip every bit pattern class (GLSL 8.3)", "[glsl]") {
    const float values[] = {0.0f,
                            -0.0f,
                            1.0f,
                            -1.0f,
                            std::numeric_limits<float>::min(),
                            std::numeric_limits<float>::denorm_min(),
                            -std::numeric_limits<float>::denorm_min(),
                            std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            3.14159265f,
                            -1e30f};
    for (float x : values) {
        CAPTURE(x);
        CHECK(bits(tp::intBitsToFloat(tp::floatBitsToInt(x))) == bits(x));
        CHECK(bits(tp::uintBitsToFloat(tp::floatBitsToUint(x))) == bits(x));
        CHECK(tp::floatBitsToUint(x) == bits(x));
        CHECK(uint32_t(tp::floatBitsToInt(x)) == bits(x));
    }
}

TEST_CASE("integer steps on the bit pattern are ulp steps away from zero", "[glsl]") {
    // The sign bit sits apart from the magnitude, so adding k to the int pattern grows |x| by k
    // ulps for either sign; offset.h therefore subtracts for a negative coordinate to move it
    // towards +inf.
    for (float x : {1.0f, 1e-3f, 123.456f, 1e20f}) {
        CAPTURE(x);
        CHECK(tp::intBitsToFloat(tp::floatBitsToInt(x) + 1) == std::nextafter(x, 2.0f * x));
        CHECK(tp::intBitsToFloat(tp::floatBitsToInt(-x) + 1) == std::nextafter(-x, -2.0f * x));
        CHECK(tp::intBitsToFloat(tp::floatBitsToInt(x) - 1) == std::nextafter(x, 0.0f));
    }
}

TEST_CASE("is_finite tests the exponent bits: NaN and both infinities are not finite", "[glsl]") {
    CHECK(tp::is_finite(0.0f));
    CHECK(tp::is_finite(std::numeric_limits<float>::max()));
    CHECK(tp::is_finite(-std::numeric_limits<float>::denorm_min()));
    CHECK_FALSE(tp::is_finite(std::numeric_limits<float>::infinity()));
    CHECK_FALSE(tp::is_finite(-std::numeric_limits<float>::infinity()));
    CHECK_FALSE(tp::is_finite(std::numeric_limits<float>::quiet_NaN()));
    CHECK_FALSE(tp::is_finite(-std::numeric_limits<float>::quiet_NaN()));
}

TEST_CASE("mix is x (1 - a) + y a and exact at both ends (GLSL 8.3)", "[glsl]") {
    // texture.h blends texels with mix; the spec's form returns y exactly at a = 1, which the
    // shorter x + a (y - x) does not guarantee.
    CHECK(tp::mix(2.0f, 4.0f, 0.25f) == 2.5f);
    CHECK(tp::mix(1e8f, 1.0f, 1.0f) == 1.0f);
    CHECK(tp::mix(1e8f, 1.0f, 0.0f) == 1e8f);
    CHECK(tp::mix(tp::vec3(0.1f), tp::vec3(0.7f), 1.0f) == tp::vec3(0.7f));
}

TEST_CASE("clamp is min of max and exp2 inverts log2 (GLSL 8.2 and 8.3)", "[glsl]") {
    CHECK(tp::clamp(-2.0f, -1.0f, 1.0f) == -1.0f);
    CHECK(tp::clamp(0.3f, -1.0f, 1.0f) == 0.3f);
    CHECK(tp::clamp(7.0f, -1.0f, 1.0f) == 1.0f);
    // sampling.h's phong_power computes cos^n as exp2(n log2 c), as GPUs do. The round trip
    // loses the rounding of log2 x, relative 2^-24 |log2 x|, times ln 2, plus one ulp.
    for (float x : {1e-30f, 0.001f, 0.5f, 0.999999f, 1.0f, 3.0f})
        CHECK(double(tp::exp2(tp::log2(x))) ==
              Approx(double(x)).epsilon(0x1p-24 * (2.0 + std::abs(std::log2(double(x))))));
    CHECK(tp::log2(1.0f) == 0.0f);
    CHECK(tp::exp2(0.0f) == 1.0f);
}

TEST_CASE("bitfieldReverse moves bit n to bit 31 - n (GLSL 8.8)", "[glsl]") {
    // rng.h's Sobol sampler reads the van der Corput point and Burley's scramble through it.
    CHECK(tp::bitfieldReverse(0u) == 0u);
    CHECK(tp::bitfieldReverse(1u) == 0x80000000u);
    CHECK(tp::bitfieldReverse(0x80000000u) == 1u);
    CHECK(tp::bitfieldReverse(3u) == 0xC0000000u);
    CHECK(tp::bitfieldReverse(0x12345678u) == 0x1E6A2C48u);
    CHECK(tp::bitfieldReverse(0xFFFFFFFFu) == 0xFFFFFFFFu);
    // Against the definition, bit by bit, on words of every bit pattern density.
    uint32_t x = 0x9E3779B9u;
    for (int i = 0; i < 1000; ++i) {
        x = x * 1664525u + 1013904223u;
        const uint32_t w = i % 3 == 0 ? x & (x >> 7) : i % 3 == 1 ? x | (x << 5) : x;
        uint32_t expected = 0;
        for (int b = 0; b < 32; ++b) expected |= ((w >> b) & 1u) << (31 - b);
        CHECK(tp::bitfieldReverse(w) == expected);
    }
}
