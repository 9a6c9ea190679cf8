// The alias tables of scene/alias_table.h (Vose's construction) and the slot choice of
// shared/sampling.h: the table reproduces the weights exactly up to the rounding of its float
// entries, and zero weights are never chosen.
#include "scene/alias_table.h"
#include "shared/sampling.h"
#include "util/error.h"

#include <catch2/catch.hpp>

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

TEST_CASE("alias slot choice covers every slot evenly", "[alias]") {
    // u takes the 2^24 values k 2^-24 (rng.h). Counting the slot alias_slot picks for each of
    // them: every slot is reachable, the largest u stays in range, and each slot receives
    // 2^24 / n values to within the rounding of the float product u n at its two boundaries,
    // so its probability is 1/n to a relative ~n 2^-24 (exact for powers of two). That error
    // grows with n: 6e-5 at n = 1000, but 0.06 for the 2 * 10^6 pixels of a 2000 x 1000
    // environment map.
    for (uint32_t n : {1u, 2u, 3u, 10u, 1000u, 4096u}) {
        CAPTURE(n);
        std::vector<uint32_t> count(n, 0);
        for (uint32_t k = 0; k < (1u << 24); ++k) ++count[tp::alias_slot(float(k) * 0x1p-24f, n)];
        const double share = double(1u << 24) / double(n);
        for (uint32_t j = 0; j < n; ++j) REQUIRE(std::abs(double(count[j]) - share) <= 2.0);
    }
    CHECK(tp::alias_slot(1.0f - 0x1p-24f, 3000000u) == 2999999u);
    CHECK(tp::alias_resolve(4u, 0.25f, 9u, 0.2f) == 4u);
    CHECK(tp::alias_resolve(4u, 0.25f, 9u, 0.25f) == 9u);
}
