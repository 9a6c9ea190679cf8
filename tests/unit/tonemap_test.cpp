// The display transform of --png and the viewer (shared/tonemap.h) against the sRGB standard's
// numbers (IEC 61966-2-1) computed here in double.
#include "shared/tonemap.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

namespace {

// The 8-bit code of linear x in [0, 1] from the standard's formula in double.
unsigned reference_code(double x) {
    const double v = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    return unsigned(std::floor(v * 255.0 + 0.5));
}

} // namespace

TEST_CASE("display codes follow the sRGB transfer function and clamp", "[tonemap]") {
    // Every code boundary is far (> 1e-3 of a code) from the float evaluation's error at these
    // inputs, so the float and double codes must agree exactly.
    for (double x : {0.0, 0.001, 0.0031308, 0.01, 0.18, 0.5, 0.9, 1.0}) {
        CAPTURE(x);
        CHECK(tp::srgb8_code(float(x)) == reference_code(x));
    }
    CHECK(tp::srgb8_code(-1.0f) == 0u);
    CHECK(tp::srgb8_code(7.0f) == 255u);
}

TEST_CASE("a pixel with a non-finite channel shows magenta", "[tonemap]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    CHECK(tp::display_srgb8(tp::vec3(0.5f, nan, 0.5f), 1.0f) == tp::uvec3(255u, 0u, 255u));
    CHECK(tp::display_srgb8(tp::vec3(-inf, 0.0f, 0.0f), 1.0f) == tp::uvec3(255u, 0u, 255u));
    // Finite radiance is scaled by the exposure factor before encoding.
    CHECK(tp::display_srgb8(tp::vec3(0.25f, 0.0f, 2.0f), 2.0f) ==
          tp::uvec3(reference_code(0.5), 0u, 255u));
}
