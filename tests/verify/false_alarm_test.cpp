// The false-alarm rate of verify as a whole (verify/verify.h): the CPU reference against Vulkan
// compute mode (lavapipe in CI) on an unmodified build, each run with its own seeds, its own
// pilots, its own plan and unequal spp. Every run's verdict must be "different" with probability
// at most alpha.
//
// Size and tolerance. The measurement over 60 seeds at the default alpha = 0.01 is
// benchmarks/verify-false-alarms.sh (BENCHMARKS.md, "verify-false-alarms"): it takes about a
// quarter of an hour on 2 cores. Here, 8 runs at alpha = 0.2, whose plans need fewer samples and
// whose rate is large enough that 8 runs say something: the count must stay at or below the
// upper end of the central 99 % binomial interval (a valid test exceeds it with probability
// below 0.005). It catches what breaks the calibration as a whole (images that are
// not independent, a variance that is too small, a level not split between the parts); a small
// excess over alpha is the benchmark's to see.
#include "rates.h"
#include "scenes.h"

#include "verify/render_engines.h"
#include "verify/verify.h"

#include <catch2/catch.hpp>

using namespace tp;
using namespace tp::test;

TEST_CASE("verify's false alarms: the CPU against Vulkan compute, unmodified, at alpha 0.2",
          "[verify][gpu]") {
    const double alpha = 0.2;
    const size_t runs = 8;
    const FlatScene scene = small_scene("cornell", 32, 32);
    EngineSetup setup;
    setup.scene = &scene;
    setup.scene_path = "cornell";
    VulkanOptions vk;
    const std::vector<std::unique_ptr<Engine>> engines =
        make_engines(setup, vulkan_engine_modes("compute", ""), vk);
    size_t alarms = 0;
    for (uint32_t seed = 0; seed < runs; ++seed) {
        VerifyOptions o;
        o.seed = seed;
        o.plan.alpha = alpha;
        o.triage = false;
        const VerifyResult v = verify({engines[0].get(), engines[1].get()}, o, {});
        INFO("seed " << seed << ": spp " << v.plan.spp[0] << ", " << v.plan.spp[1] << ", p "
                     << v.verdicts[0].compare.p_value);
        CHECK(v.verdicts[0].compare.warnings.empty()); // no shared samples
        alarms += v.different();
    }
    const CountInterval ci = binomial_interval99(runs, alpha);
    INFO(describe_rate("verify, cornell 32x32", alarms, runs, alpha));
    CHECK(alarms <= ci.hi);
}
