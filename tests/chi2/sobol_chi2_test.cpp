// The Sobol sampler of shared/rng.h: its numbers are uniform in every dimension and every pair
// of dimensions of a bounce block (chi-square over many pixels, whose scrambles are
// independent), and every pair keeps the (0, 2)-sequence stratification of Sobol's
// first two dimensions after Burley's shuffle and scramble (an exact count).
#include "chi2/suite.h"

#include "shared/rng.h"

#include <vector>

using namespace tp::test::chi2;

namespace {

// Pixel jitter and bounce 1's block: the 12 dimensions one bounce of a path reads.
std::vector<uint32_t> block_dimensions() {
    std::vector<uint32_t> d = {tp::RNG_PIXEL_X, tp::RNG_PIXEL_Y};
    for (uint32_t k = 0; k < tp::RNG_DIMS_PER_BOUNCE; ++k) d.push_back(tp::rng_bounce_dim(1u, k));
    return d;
}

constexpr uint32_t kPixels = 4096, kSpp = 64; // 8 points in each of the 8 batches

// The sampler's words for every (pixel, sample) in dimension d, as unit floats.
std::vector<double> column(uint32_t d) {
    std::vector<double> out;
    out.reserve(size_t(kPixels) * kSpp);
    for (uint32_t p = 0; p < kPixels; ++p)
        for (uint32_t s = 0; s < kSpp; ++s)
            out.push_back(tp::rng_get(tp::rng_key(tp::SAMPLER_SOBOL, 11u, p, s), d));
    return out;
}

// The family of this file: 12 dimensions and their 66 pairs, at a suite-wide level of 1 %
// (suite.h); a family of its own so that the samplers' tests keep their level.
constexpr int kTests = 12 + 66;

void check_uniform(const char* name, const Result& r) {
    report(name, r);
    INFO(name << ": " << r.summary());
    CHECK(r.accepted(sidak_alpha(kSuiteAlpha, kTests)));
}

// Exactly one of the 2^m points in every elementary interval [i 2^-a, (i+1) 2^-a) x
// [j 2^-(m-a), (j+1) 2^-(m-a)), for every a = 0..m: a (0, m, 2)-net in base 2.
bool is_net(const std::vector<uint32_t>& u, const std::vector<uint32_t>& v, uint32_t m) {
    for (uint32_t a = 0; a <= m; ++a) {
        std::vector<int> count(size_t(1) << m, 0);
        for (size_t i = 0; i < u.size(); ++i) {
            const uint32_t x = a ? u[i] >> (32 - a) : 0u, y = a < m ? v[i] >> (32 - (m - a)) : 0u;
            if (++count[(size_t(x) << (m - a)) | y] > 1) return false;
        }
    }
    return true;
}

} // namespace

TEST_CASE("sobol sampler: every dimension of a bounce block is uniform", "[chi2][sobol]") {
    for (uint32_t d : block_dimensions()) {
        const std::vector<double> x = column(d);
        std::vector<uint64_t> counts(64, 0);
        for (double v : x) ++counts[size_t(v * 64.0)];
        INFO("dimension " << d);
        check_uniform("sobol 1-D", test_discrete(counts, std::vector<double>(64, 1.0 / 64.0)));
    }
}

TEST_CASE("sobol sampler: every pair of dimensions of a bounce block is uniform", "[chi2][sobol]") {
    // Pairs within one Sobol group are stratified, pairs across groups are decorrelated by
    // their independent index shuffles; both must fill the square evenly over many pixels.
    const std::vector<uint32_t> dims = block_dimensions();
    std::vector<std::vector<double>> columns;
    for (uint32_t d : dims) columns.push_back(column(d));
    const Grid grid = Grid::uniform(0.0, 1.0, 32, 0.0, 1.0, 32);
    for (size_t i = 0; i < dims.size(); ++i)
        for (size_t j = i + 1; j < dims.size(); ++j) {
            PointSamples s;
            for (size_t k = 0; k < columns[i].size(); ++k)
                s.points.emplace_back(columns[i][k], columns[j][k]);
            INFO("dimensions " << dims[i] << " and " << dims[j]);
            check_uniform("sobol 2-D", test_points(grid, s, [](double, double) { return 1.0; }));
        }
}

TEST_CASE("sobol sampler: every pair is a (0, m, 2)-net in every aligned block of a batch",
          "[sobol]") {
    // Samples s = b + K j of batch b, for j in an aligned block [c 2^m, (c + 1) 2^m): the first
    // 2^m points of a batch (c = 0) and a later block, as a sample range split elsewhere gets.
    // Every pair of the layout, each in a different bounce; a net's coordinates are also
    // stratified one by one (the intervals with a = 0 and a = m).
    const uint32_t m = 8, n = 1u << m;
    const uint32_t firsts[6] = {tp::RNG_PIXEL_X,
                                tp::rng_bounce_dim(0u, tp::RNG_LIGHT_SLOT),
                                tp::rng_bounce_dim(0u, tp::RNG_LIGHT_U),
                                tp::rng_bounce_dim(1u, tp::RNG_ENV_SLOT),
                                tp::rng_bounce_dim(2u, tp::RNG_LOBE),
                                tp::rng_bounce_dim(3u, tp::RNG_DIR_U)};
    for (uint32_t pixel : {0u, 77u, 4095u})
        for (uint32_t b = 0; b < tp::SOBOL_BATCHES; ++b)
            for (uint32_t c : {0u, 5u})
                for (uint32_t first : firsts) {
                    std::vector<uint32_t> u, v, u1, v1;
                    for (uint32_t j = c * n; j < (c + 1) * n; ++j) {
                        const tp::RngKey key =
                            tp::rng_key(tp::SAMPLER_SOBOL, 3u, pixel, b + tp::SOBOL_BATCHES * j);
                        const tp::uvec2 w = tp::rng_get2_bits(key, first);
                        u.push_back(w.x);
                        v.push_back(w.y);
                        // The single draws are the pair's coordinates.
                        u1.push_back(tp::rng_get_bits(key, first));
                        v1.push_back(tp::rng_get_bits(key, tp::rng_group_second(first)));
                    }
                    CAPTURE(pixel, b, c, first);
                    CHECK(is_net(u, v, m));
                    CHECK(u1 == u);
                    CHECK(v1 == v);
                }
}

TEST_CASE("sobol sampler: every dimension of a bounce block belongs to exactly one pair",
          "[sobol]") {
    // Pixel jitter and two bounce blocks: rng_group_first and rng_group_second are inverse on
    // the layout's pairs, and every dimension is the first or the second of one pair.
    std::vector<int> seen(tp::rng_bounce_dim(2u, 0u), 0);
    for (uint32_t d = 0; d < seen.size(); ++d) {
        const uint32_t first = tp::rng_group_first(d);
        CAPTURE(d, first);
        CHECK(tp::rng_group_first(first) == first);
        CHECK((d == first || tp::rng_group_second(first) == d));
        if (d == first) {
            ++seen[first];
            ++seen[tp::rng_group_second(first)];
        }
    }
    for (uint32_t d = 0; d < seen.size(); ++d) {
        CAPTURE(d);
        CHECK(seen[d] == 1);
    }
}

TEST_CASE("power: two groups that share the index shuffle are rejected", "[chi2][sobol][power]") {
    // What padding without a per-group shuffle would give: two dimensions scrambled
    // independently but driven by the same index are digit-wise functions of each other, so
    // their points crowd into 32 of the 1024 cells of a 32 x 32 grid.
    PointSamples s;
    for (uint32_t p = 0; p < kPixels; ++p)
        for (uint32_t j = 0; j < kSpp; ++j) {
            const uint32_t x = tp::nested_uniform_scramble(tp::bitfieldReverse(j), p * 2u);
            const uint32_t y = tp::nested_uniform_scramble(tp::bitfieldReverse(j), p * 2u + 1u);
            s.points.emplace_back(tp::uint_to_unit_float(x), tp::uint_to_unit_float(y));
        }
    check_rejected("sobol groups sharing an index",
                   test_points(Grid::uniform(0.0, 1.0, 32, 0.0, 1.0, 32), s,
                               [](double, double) { return 1.0; }));
}

TEST_CASE("sobol_dim1 is Sobol's second dimension", "[sobol]") {
    // Joe & Kuo's m_1, m_2, m_3 = 1, 3, 5 for the polynomial x + 1 give the direction numbers
    // v = 1/2, 3/4, 5/8, and point i is the xor of v_k over the set bits k of i (natural
    // order, not Gray-code order): 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8.
    const double expected[8] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    for (uint32_t i = 0; i < 8; ++i) CHECK(double(tp::sobol_dim1(i)) * 0x1p-32 == expected[i]);
}
