// The alias tables of scene/alias_table.h (Vose's construction) and the slot choice of
// shared/sampling.h (alias_slot_from_bits): the table reproduces the weights exactly up to the
// rounding of its float entries, and zero weights are never chosen.
#include "scene/alias_table.h"
#include "shared/sampling.h"
#include "util/error.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace {

// Probability that sampling the table picks item i: slot j is chosen with probability 1/n and
// keeps itself with prob_j, else jumps to alias_j. Summed in double from the stored floats.
std::vector<double> item_mass(const std::vector<tp::AliasEntry>& table) {
    const double n = double(table.size());
    std::vector<double> mass(table.size(), 0.0);
    for (size_t j = 0; j < table.size(); ++j) {
        mass[j] += double(table[j].prob) / n;
        mass[table[j].alias] += (1.0 - double(table[j].prob)) / n;
    }
    return mass;
}

void check_table(const std::vector<double>& w) {
    const std::vector<tp::AliasEntry> table = tp::build_alias_table(w);
    REQUIRE(table.size() == w.size());
    const double n = double(w.size());
    const double sum = std::accumulate(w.begin(), w.end(), 0.0);
    // Each float pdf is w_i / sum rounded (relative error <= 2^-24): the sum is 1 to n 2^-24.
    double pdf_sum = 0.0;
    for (const tp::AliasEntry& e : table) pdf_sum += double(e.pdf);
    CHECK(std::abs(pdf_sum - 1.0) <= n * 0x1p-24);

    // In exact arithmetic the table gives item i exactly w_i / sum. What remains is the rounding
    // of each stored prob to float, <= 2^-25 absolute as prob lies in [0, 1], counted once for
    // the item's own slot and once for every slot that aliases to it, over n; plus Vose's
    // double-precision bookkeeping, < 1e-12.
    std::vector<int> aliased(w.size(), 0);
    for (size_t j = 0; j < table.size(); ++j)
        if (table[j].alias != j) ++aliased[table[j].alias];
    const std::vector<double> mass = item_mass(table);
    for (size_t i = 0; i < w.size(); ++i) {
        CAPTURE(i, w[i], mass[i] * sum);
        CHECK(table[i].prob >= 0.0f);
        CHECK(table[i].prob <= 1.0f);
        CHECK(table[i].alias < table.size());
        CHECK(std::abs(mass[i] - w[i] / sum) <= (1.0 + aliased[i]) * 0x1p-25 / n + 1e-12);
        if (w[i] == 0.0) CHECK(mass[i] == 0.0); // never chosen, not even by rounding
    }
}

} // namespace

TEST_CASE("alias table reproduces its weights", "[alias]") {
    SECTION("hand-picked") {
        check_table({1.0, 0.0, 3.0, 0.5, 10.0, 2.0, 7.0, 0.01, 4.0, 0.0});
    }
    SECTION("one item") {
        check_table({2.5});
    }
    SECTION("equal weights") {
        check_table(std::vector<double>(17, 0.3));
    }
    SECTION("one heavy item among many light ones") {
        std::vector<double> w(1000, 1e-6);
        w[123] = 1e6;
        check_table(w);
    }
    SECTION("random weights over 12 decades, a third of them zero") {
        std::mt19937 g(3);
        std::uniform_real_distribution<double> e(-6.0, 6.0);
        std::vector<double> w(5000);
        for (size_t i = 0; i < w.size(); ++i) w[i] = i % 3 == 0 ? 0.0 : std::pow(10.0, e(g));
        check_table(w);
    }
}

TEST_CASE("alias table rejects weights it cannot sample", "[alias]") {
    CHECK_THROWS_AS(tp::build_alias_table({}), tp::RuntimeError);
    CHECK_THROWS_AS(tp::build_alias_table({0.0, 0.0}), tp::RuntimeError);
    CHECK_THROWS_AS(tp::build_alias_table({1.0, -1.0}), tp::RuntimeError);
    CHECK_THROWS_AS(tp::build_alias_table({1.0, NAN}), tp::RuntimeError);
    CHECK_THROWS_AS(tp::build_alias_table({1.0, INFINITY}), tp::RuntimeError);
}

// The exact probability of every slot, as a relative deviation from 1/n: the largest
// |count_s n / N - 1| over the slots, where count_s of the N equally likely inputs pick slot s.
double worst_slot_error(const std::vector<uint64_t>& count, double inputs) {
    const double n = double(count.size());
    double worst = 0.0;
    for (uint64_t c : count) worst = std::max(worst, std::abs(double(c) * n / inputs - 1.0));
    return worst;
}

TEST_CASE("alias slot choice is even to n 2^-32 for every table size", "[alias]") {
    // The 32-bit hash word h takes its 2^32 values with equal probability. alias_slot_from_bits
    // is floor(h n / 2^32), non-decreasing in h, so slot s receives exactly the h in
    // [b_s, b_{s+1}) with b_s = ceil(s 2^32 / n): checking the slot on both sides of every
    // boundary proves every count without enumerating 2^32 inputs. The counts are
    // floor(2^32 / n) or ceil(2^32 / n), so each slot's probability is 1/n within n 2^-32.
    const double inputs = 0x1p32;
    for (uint32_t n : {1u, 3u, 1000u, 10000u, 2000000u, 16777217u}) {
        CAPTURE(n);
        std::vector<uint64_t> count(n);
        uint64_t begin = 0;
        for (uint32_t s = 0; s < n; ++s) {
            const uint64_t end = ((uint64_t(s) + 1) << 32) / n +
                                 ((((uint64_t(s) + 1) << 32) % n) != 0); // ceil((s+1) 2^32 / n)
            REQUIRE(tp::alias_slot_from_bits(uint32_t(begin), n) == s);
            REQUIRE(tp::alias_slot_from_bits(uint32_t(end - 1), n) == s);
            count[s] = end - begin;
            begin = end;
        }
        REQUIRE(begin == (uint64_t(1) << 32));
        CHECK(worst_slot_error(count, inputs) <= double(n) * 0x1p-32);
    }
}

TEST_CASE("a 24-bit float slot choice was biased by up to n 2^-24", "[alias]") {
    // What alias_slot_from_bits replaced: floor(u n) with u = (h >> 8) 2^-24, the top 24 bits
    // of the same word. Counting all 2^24 values of u gives every slot's exact probability.
    // For the 2 * 10^6 pixels of a 2000 x 1000 environment map each slot gets 8 or 9 of them
    // against 2^24 / n = 8.39, a relative error of -5 % to +7 % that the renderer's estimate
    // inherits (it divides by the table's pdf); the 32-bit choice stays within 5e-4.
    const uint32_t n = 2000000;
    std::vector<uint64_t> count(n, 0);
    for (uint32_t k = 0; k < (1u << 24); ++k)
        ++count[std::min(uint32_t(float(k) * 0x1p-24f * float(n)), n - 1)];
    const double old_error = worst_slot_error(count, 0x1p24);
    CAPTURE(old_error);
    CHECK(old_error > 0.05);
    CHECK(old_error > 100.0 * double(n) * 0x1p-32);
    CHECK(tp::alias_slot_from_bits(0xFFFFFFFFu, 3000000u) == 2999999u);
    CHECK(tp::alias_slot_from_bits(0u, 3000000u) == 0u);
}

TEST_CASE("alias coin keeps the slot below its probability", "[alias]") {
    CHECK(tp::alias_resolve(4u, 0.25f, 9u, 0.2f) == 4u);
    CHECK(tp::alias_resolve(4u, 0.25f, 9u, 0.25f) == 9u);
}
