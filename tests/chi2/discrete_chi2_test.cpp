// Chi-square test of discrete selection: the alias tables of scene/alias_table.h sampled with
// shared/sampling.h's alias_slot_from_bits + alias_resolve (light selection, environment-map
// pixels) must pick item i with probability w_i / sum(w).
#include "chi2/suite.h"

#include "scene/alias_table.h"
#include "shared/sampling.h"

#include <cmath>
#include <numeric>

using namespace tp::test::chi2;

namespace {

std::vector<uint64_t> alias_counts(const std::vector<tp::AliasEntry>& table, uint64_t n,
                                   uint64_t seed) {
    Uniform u(seed);
    std::vector<uint64_t> counts(table.size(), 0);
    for (uint64_t i = 0; i < n; ++i) {
        const uint32_t slot = tp::alias_slot_from_bits(u.bits(), uint32_t(table.size()));
        const tp::AliasEntry& e = table[slot];
        ++counts[tp::alias_resolve(slot, e.prob, e.alias, u.next())];
    }
    return counts;
}

std::vector<double> normalised(const std::vector<double>& w) {
    const double sum = std::accumulate(w.begin(), w.end(), 0.0);
    std::vector<double> p;
    for (double x : w) p.push_back(x / sum);
    return p;
}

} // namespace

TEST_CASE("alias table picks items in proportion to their weights", "[chi2]") {
    SECTION("ten weights with zeros and a tiny one") {
        // A zero weight must never be picked (its cell expects 0: one pick rejects).
        const std::vector<double> w = {1.0, 0.0, 3.0, 0.5, 10.0, 2.0, 7.0, 0.01, 4.0, 0.0};
        const Result r =
            test_discrete(alias_counts(tp::build_alias_table(w), kSamples, 801), normalised(w));
        check_accepted("alias table, 10 weights", r);
    }
    SECTION("a thousand weights over four decades") {
        std::vector<double> w(1000);
        for (size_t i = 0; i < w.size(); ++i)
            w[i] = std::pow(10.0, 4.0 * double((i * 389) % 1000) / 1000.0);
        const Result r =
            test_discrete(alias_counts(tp::build_alias_table(w), kSamples, 802), normalised(w));
        check_accepted("alias table, 1000 weights", r);
    }
}
