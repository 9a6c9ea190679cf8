// roulette.h, thesis eq. 2.41-2.42: a path survives with q = min(max_rgb(T), 1) and a survivor's
// throughput is divided by q, so E[T after roulette] = T. Checked exactly by running the
// roulette for every one of the 2^24 values the renderer's uniform numbers take (rng.h).
#include "shared/roulette.h"

#include <catch2/catch.hpp>

namespace {

// E[T'] over u = k 2^-24, k = 0 .. 2^24 - 1, summed exactly in double.
tp::vec3 expected_throughput(const tp::vec3& t, uint32_t bounces, uint32_t min_depth) {
    glm::dvec3 sum(0.0);
    for (uint32_t k = 0; k < (1u << 24); ++k) {
        tp::vec3 x = t;
        if (tp::roulette_apply(x, bounces, min_depth, float(k) * 0x1p-24f)) sum += glm::dvec3(x);
    }
    return tp::vec3(sum * 0x1p-24);
}

} // namespace

TEST_CASE("Russian roulette is unbiased: E(survive / q) = 1", "[roulette]") {
    // Survival is u < q: ceil(q 2^24) of the 2^24 values, a probability above q by less than
    // 2^-24, so the expectation is T to a relative 2^-24 / q (plus the float division T / q).
    for (const tp::vec3& t : {tp::vec3(0.5f, 0.2f, 0.1f), tp::vec3(0.01f, 0.003f, 0.0f),
                              tp::vec3(0.9f, 0.95f, 0.3f), tp::vec3(1e-4f)}) {
        const float q = tp::roulette_survival(t, 5u, 3u);
        CAPTURE(t.x, t.y, t.z, q);
        CHECK(q == tp::max3(t));
        const tp::vec3 e = expected_throughput(t, 5u, 3u);
        for (int c = 0; c < 3; ++c) CHECK(std::abs(e[c] - t[c]) <= t[c] * (0x1p-24f / q + 4e-7f));
    }
}

TEST_CASE("Russian roulette leaves early bounces and bright paths alone", "[roulette]") {
    tp::vec3 t(0.1f, 0.2f, 0.05f);
    // Before min_depth: always survives, unchanged, even for u close to 1.
    CHECK(tp::roulette_apply(t, 2u, 3u, 0.99999994f));
    CHECK(t == tp::vec3(0.1f, 0.2f, 0.05f));
    // q capped at 1: a throughput >= 1 in some channel survives unchanged.
    tp::vec3 bright(1.5f, 0.1f, 0.1f);
    CHECK(tp::roulette_survival(bright, 9u, 0u) == 1.0f);
    CHECK(tp::roulette_apply(bright, 9u, 0u, 0.99999994f));
    CHECK(bright == tp::vec3(1.5f, 0.1f, 0.1f));
    // A survivor is divided by q exactly; u = q itself dies.
    tp::vec3 s(0.25f, 0.5f, 0.125f);
    CHECK(tp::roulette_apply(s, 3u, 3u, 0.49999997f));
    CHECK(s == tp::vec3(0.5f, 1.0f, 0.25f));
    tp::vec3 d(0.25f, 0.5f, 0.125f);
    CHECK_FALSE(tp::roulette_apply(d, 3u, 3u, 0.5f));
    // A black path always ends.
    tp::vec3 black(0.0f);
    CHECK_FALSE(tp::roulette_apply(black, 3u, 0u, 0.0f));
}
