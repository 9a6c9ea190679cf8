// The CPU's bounce-at-once random numbers (cpu_ref/rng_lanes.h) against rng.h's functions, the
// numbers the GPU draws: every word must be equal, for both samplers, over keys that cover the
// whole range of each counter (pixels and sample indices up to 2^32 - 1, every batch, bounces up to
// far past any max depth, arbitrary seeds). The lanes reuse rng.h's functions, so a difference can
// only come from the lane loop itself (a lane mapped to the wrong pair, a vectorization that is
// not exact), which is what this catches: equality is exact, there is no tolerance to justify.
// The lanes are computed through the path loop's instruction-set copies (TP_ISA_CLONES,
// cpu_ref/isa_clones.h), so on an AVX2 machine the vectorized code is the one tested.
#include "cpu_ref/integrator.h"
#include "cpu_ref/rng_lanes.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <set>

namespace {

tp::RngKey random_key(std::mt19937_64& gen, uint32_t sampler) {
    std::uniform_int_distribution<uint32_t> any;
    // Half of the sample indices small (the first points of each batch's net, where the index
    // shuffle acts on few bits), half anywhere.
    const uint32_t sample = gen() % 2 ? any(gen) % 4096u : any(gen);
    return tp::rng_key(sampler, any(gen), any(gen), sample);
}

TP_ISA_CLONES void words_as_in_the_loop(const tp::RngKey& key, uint32_t bounce,
                                        tp::BounceWords& out) {
    tp::bounce_words(key, bounce, out);
}

} // namespace

TEST_CASE("bounce words in lanes equal rng.h's pair draws", "[unit][rng]") {
    std::mt19937_64 gen(0x36b);
    for (const uint32_t sampler : {tp::SAMPLER_RANDOM, tp::SAMPLER_SOBOL}) {
        uint64_t compared = 0, mismatches = 0;
        for (int n = 0; n < 200000; ++n) {
            const tp::RngKey key = random_key(gen, sampler);
            const uint32_t bounce = n % 3 == 0 ? uint32_t(gen() % 400000000u) : uint32_t(n % 64);
            tp::BounceWords w;
            words_as_in_the_loop(key, bounce, w);
            for (uint32_t lane = 0; lane < tp::kBounceLanes; ++lane) {
                const uint32_t k = tp::kBounceLaneFirst[lane];
                const tp::uvec2 expected = tp::rng_bounce2_bits(key, bounce, k);
                const uint32_t at = tp::bounce_pair_lane(k);
                mismatches += (w.first[at] != expected.x) + (w.second[at] != expected.y);
                ++compared;
            }
        }
        INFO("sampler " << sampler << ": " << compared << " pairs compared");
        CHECK(mismatches == 0);
    }
}

TEST_CASE("bounce lanes hold every pair of a bounce once", "[unit][rng]") {
    // The five first dimensions of a bounce (rng.h's layout): each has its lane, and together
    // with their partners they are the bounce's ten dimensions.
    std::set<uint32_t> dims;
    for (uint32_t lane = 0; lane < tp::kBouncePairs; ++lane) {
        const uint32_t k = tp::kBounceLaneFirst[lane];
        CHECK(tp::bounce_pair_lane(k) == lane);
        const uint32_t first = tp::rng_bounce_dim(7, k);
        CHECK(tp::rng_group_first(first) == first);
        dims.insert(first);
        dims.insert(tp::rng_group_second(first));
    }
    CHECK(dims.size() == tp::RNG_DIMS_PER_BOUNCE);
    CHECK(*dims.begin() == tp::rng_bounce_dim(7, 0));
    CHECK(*dims.rbegin() == tp::rng_bounce_dim(7, tp::RNG_DIMS_PER_BOUNCE - 1));
}
