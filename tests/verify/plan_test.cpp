// verify's plan (verify/plan.h) and seeds (verify/seeds.h) on made-up engines: the sample counts
// reach the power asked for at the least wall time, within the limits and the budget.
#include "compare/power.h"
#include "verify/plan.h"
#include "verify/seeds.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

using namespace tp;

namespace {

// 32 x 32 pixels of mean 1 and per-sample variance 1 in every channel, channels independent.
PowerModel flat_model(double variance = 1.0) {
    Planes mean, var;
    for (size_t c = 0; c < 3; ++c) {
        mean[c].assign(32 * 32, 1.0);
        var[c].assign(32 * 32, variance);
    }
    return power_model(32, 32, mean, var, {0.0, 0.0, 0.0}, 8);
}

EngineCost cost(double setup, double per_spp, int lane, uint32_t kept = 0) {
    EngineCost c;
    c.setup_s = setup;
    c.seconds_per_spp = per_spp;
    c.lane = lane;
    c.kept_spp = kept;
    return c;
}

} // namespace

TEST_CASE("plan: two engines at once finish together and reach the power asked for",
          "[verify][unit]") {
    const PowerModel m = flat_model();
    PlanRequest rq;
    rq.detect = 0.02;
    const std::vector<std::pair<size_t, size_t>> pair = {{0, 1}};
    // The CPU 4 times slower per sample than the GPU, which needs a second to set up.
    const std::vector<EngineCost> costs = {cost(0.0, 0.004, 0), cost(1.0, 0.001, 1)};
    const Plan p = plan_samples(m, costs, pair, rq);
    CHECK(p.limit == PlanLimit::Power);
    CHECK(p.level == Approx(0.005));
    CHECK(p.power >= 0.9);
    CHECK(p.power < 0.91); // no more samples than needed: the bisection stops at the least T
    const double t_cpu = p.spp[0] * 0.004, t_gpu = 1.0 + p.spp[1] * 0.001;
    CHECK(t_cpu == Approx(t_gpu).epsilon(0.02));
    CHECK(p.wall_s == Approx(std::max(t_cpu, t_gpu)).epsilon(0.02));
    CHECK(p.detectable <= 0.02);
    // The model's n_eff is what the global test needs: sqrt(n_eff) scales the bias it sees.
    const double n_eff = effective_spp(p.spp[0], p.spp[1]);
    CHECK(global_test_power(m, 0.02, n_eff, p.level) >= 0.9);
    CHECK(detectable_bias(m, n_eff, p.level, 0.9) ==
          Approx(0.02 * std::sqrt(required_effective_spp(m, 0.02, p.level, 0.9) / n_eff)));
}

TEST_CASE("plan: at least kMinSpp, at most kMaxSppRatio between engines", "[verify][unit]") {
    const std::vector<std::pair<size_t, size_t>> pair = {{0, 1}};
    PlanRequest rq;
    rq.detect = 0.5; // found at once: the minimum
    Plan p = plan_samples(flat_model(), {cost(0, 0.01, 0), cost(0, 0.01, 1)}, pair, rq);
    CHECK(p.spp == std::vector<uint32_t>{kMinSpp, kMinSpp});
    // A GPU 1000 times faster: no more than 64 times the CPU's samples.
    rq.detect = 0.01;
    p = plan_samples(flat_model(), {cost(0, 0.01, 0), cost(0, 1e-5, 1)}, pair, rq);
    CHECK(double(p.spp[1]) <= kMaxSppRatio * double(p.spp[0]) + 1);
    CHECK(p.power >= 0.9);
}

TEST_CASE("plan: a short budget gives what it allows and says what it detects", "[verify][unit]") {
    const std::vector<std::pair<size_t, size_t>> pair = {{0, 1}};
    const std::vector<EngineCost> costs = {cost(0, 0.01, 0), cost(0, 0.01, 1)};
    PlanRequest rq;
    rq.detect = 0.01;
    const Plan free = plan_samples(flat_model(), costs, pair, rq);
    rq.budget_s = free.wall_s / 4;
    const Plan p = plan_samples(flat_model(), costs, pair, rq);
    CHECK(p.limit == PlanLimit::Budget);
    CHECK(p.wall_s == Approx(*rq.budget_s).epsilon(0.02));
    CHECK(p.needed_wall_s == Approx(free.wall_s).epsilon(0.01));
    CHECK(p.power < 0.9);
    // A quarter of the samples: the bias found with the same power is twice as large.
    CHECK(p.detectable == Approx(2 * free.detectable).epsilon(0.03));
    // More than enough budget changes nothing.
    rq.budget_s = free.wall_s * 4;
    CHECK(plan_samples(flat_model(), costs, pair, rq).spp == free.spp);
    // --spp fixes every engine.
    rq.spp = 100;
    const Plan fixed = plan_samples(flat_model(), costs, pair, rq);
    CHECK(fixed.limit == PlanLimit::Fixed);
    CHECK(fixed.spp == std::vector<uint32_t>{100, 100});
}

TEST_CASE("plan: without noise nothing is needed beyond the minimum", "[verify][unit]") {
    const PowerModel m = flat_model(0.0);
    CHECK_FALSE(m.informative());
    const Plan p = plan_samples(m, {cost(0, 0.01, 0), cost(0, 0.01, 1)}, {{0, 1}}, PlanRequest{});
    CHECK(p.limit == PlanLimit::NoNoise);
    CHECK(p.spp == std::vector<uint32_t>{kMinSpp, kMinSpp});
}

TEST_CASE("plan: three engines, two of them on one device, at alpha / 3 per pair",
          "[verify][unit]") {
    const PowerModel m = flat_model();
    const std::vector<std::pair<size_t, size_t>> pairs = {{0, 1}, {0, 2}, {1, 2}};
    const std::vector<EngineCost> costs = {cost(0, 0.004, 0), cost(0.5, 0.001, 1),
                                           cost(0.5, 0.002, 1)};
    PlanRequest rq;
    rq.detect = 0.02;
    const Plan p = plan_samples(m, costs, pairs, rq);
    CHECK(p.level == Approx(0.01 / 3 / 2));
    for (const auto& [a, b] : pairs)
        CHECK(global_test_power(m, 0.02, effective_spp(p.spp[a], p.spp[b]), p.level) >= 0.9);
    // The device's two modes take turns within the wall time.
    const double gpu = 1.0 + p.spp[1] * 0.001 + p.spp[2] * 0.002;
    CHECK(gpu <= p.wall_s * 1.02);
    CHECK(p.spp[0] * 0.004 <= p.wall_s * 1.02);
}

TEST_CASE("plan: an engine that keeps its samples (the viewer's window) costs only the rest",
          "[verify][unit]") {
    PlanRequest rq;
    rq.detect = 0.02;
    const Plan p =
        plan_samples(flat_model(), {cost(0, 0.004, 0), cost(0, 0.004, 1, 500)}, {{0, 1}}, rq);
    CHECK(p.spp[1] >= 500);
    CHECK(p.power >= 0.9);
}

TEST_CASE("verify's seeds are all different, an engine's own seed is kept, and runs of "
          "consecutive seeds share none",
          "[verify][unit]") {
    std::set<uint32_t> all;
    size_t count = 0;
    for (uint32_t s = 0; s < 100; ++s) {
        const VerifySeeds v = verify_seeds(s, {std::nullopt, std::nullopt});
        for (uint32_t x : {v.pilot[0], v.pilot[1], v.image[0], v.image[1]}) {
            all.insert(x);
            ++count;
        }
        CHECK(v.log == v.image[0]);
    }
    CHECK(all.size() == count);
    // The window's seed: its pilot and image keep it, every other seed differs from it.
    const uint32_t own = verify_seeds(7, {std::nullopt, std::nullopt}).image[0];
    const VerifySeeds w = verify_seeds(7, {own, std::nullopt});
    CHECK(w.image[0] == own);
    CHECK(w.pilot[0] == own);
    CHECK(w.image[1] != own);
    CHECK(w.pilot[1] != own);
    CHECK(w.image[1] != w.pilot[1]);
}
