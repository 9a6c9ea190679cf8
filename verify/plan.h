// The sample counts of a verification (docs/debugging.md, "verify", "The plan"): the spp of each
// engine such that compare finds a uniform relative bias of `detect` between every pair of
// engines with probability `power` at the least wall time, the lanes rendering at once.
//
// Each pair is compared at alpha / pairs (Bonferroni: the whole verification's false-alarm
// probability stays at most alpha) and its global test at half of that (compare.h). By the power
// model (compare/power.h) the power depends on the pair's spp only through
// n_eff = 1 / (1 / n_a + 1 / n_b), so the plan needs n_eff >= n* for every pair, with n* the
// smallest n_eff at which the model's power reaches `power`. An engine's image costs
// t(n) = setup + (n - kept) c (pilot.h); a lane's engines take turns and the lanes run at once, so
// the wall time is the longest lane's. For a wall time T each single-engine lane fills it,
// n = kept + (T - setup) / c, and a lane of two engines (compute and pipeline on one device)
// splits it where the weakest pair does best; T is the smallest with every n_eff >= n*
// (bisection: n_eff grows with T). With two engines both then finish together, which is where
// 1 / n_a + 1 / n_b = (c_a + c_b) / T is least for a given T.
//
// Limits: every image has at least kMinSpp samples (compare's calibration starts there:
// docs/compare.md), and no engine more than kMaxSppRatio times another's (the largest ratio the
// unequal-spp rule is calibrated at, docs/compare.md, "Calibration").
#pragma once

#include "compare/power.h"
#include "verify/pilot.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace tp {

constexpr uint32_t kMinSpp = 16;
constexpr double kMaxSppRatio = 64.0;

struct PlanRequest {
    double detect = 0.01; // --detect: the relative bias to find
    double power = 0.9;   // with this probability
    double alpha = 0.01;  // the whole verification's false-alarm probability
    // --time-budget: seconds for the images (the pilots' time already taken off); none: as long
    // as the plan needs.
    std::optional<double> budget_s;
    std::optional<uint32_t> spp; // --spp: every engine renders this many (no plan)
};

enum class PlanLimit {
    Power,   // the spp that find `detect` with `power`
    Budget,  // the budget was too short: what it allows
    Fixed,   // --spp
    NoNoise, // the pilots have no noise: no spp is needed to see a difference (kMinSpp)
};

struct Plan {
    std::vector<uint32_t> spp; // per engine
    PlanLimit limit = PlanLimit::Power;
    double wall_s = 0;        // predicted wall time of the images
    double needed_wall_s = 0; // what `detect` at `power` needs (= wall_s when limit is Power)
    double level = 0;         // each pair's global test's level: alpha / pairs / 2
    double power = 0;         // of the weakest pair against `detect` at these spp
    double detectable = 0;    // the least bias the weakest pair finds with `power` at these spp
};

// `pairs`: indices into `costs` of the engines compared.
Plan plan_samples(const PowerModel& model, const std::vector<EngineCost>& costs,
                  const std::vector<std::pair<size_t, size_t>>& pairs, const PlanRequest& request);

// The weakest pair's power against `bias`, and the bias it finds with `power`, at given spp.
double pairs_power(const PowerModel& model, const std::vector<uint32_t>& spp,
                   const std::vector<std::pair<size_t, size_t>>& pairs, double bias, double level);
double pairs_detectable(const PowerModel& model, const std::vector<uint32_t>& spp,
                        const std::vector<std::pair<size_t, size_t>>& pairs, double level,
                        double power);

} // namespace tp
