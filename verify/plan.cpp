#include "verify/plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace tp {
namespace {

// The samples an engine reaches in `seconds` of its lane's time.
double samples_in(const EngineCost& c, double seconds) {
    if (!(c.seconds_per_spp > 0.0)) return std::numeric_limits<double>::infinity();
    return double(c.kept_spp) + std::max(0.0, seconds - c.setup_s) / c.seconds_per_spp;
}

// The time an engine takes for n samples.
double seconds_for(const EngineCost& c, double n) {
    const double more = std::max(0.0, n - double(c.kept_spp));
    return more > 0.0 ? c.setup_s + more * c.seconds_per_spp : 0.0;
}

// Every image at least kMinSpp (and at least what it has), none more than kMaxSppRatio times
// the fewest.
std::vector<double> within_limits(std::vector<double> n, const std::vector<EngineCost>& costs) {
    for (size_t i = 0; i < n.size(); ++i)
        n[i] = std::max({n[i], double(kMinSpp), double(costs[i].kept_spp)});
    const double fewest = *std::min_element(n.begin(), n.end());
    for (size_t i = 0; i < n.size(); ++i)
        n[i] = std::max(std::min(n[i], kMaxSppRatio * fewest), double(costs[i].kept_spp));
    return n;
}

double weakest_n_eff(const std::vector<double>& n,
                     const std::vector<std::pair<size_t, size_t>>& pairs) {
    double weakest = std::numeric_limits<double>::infinity();
    for (const auto& [a, b] : pairs) weakest = std::min(weakest, effective_spp(n[a], n[b]));
    return weakest;
}

// The samples of every engine at wall time T: single engines fill their lane; the two engines
// of a two-engine lane split it where the weakest pair's n_eff is largest (a grid of 1 %).
std::vector<double> allocation(double T, const std::vector<EngineCost>& costs,
                               const std::vector<std::pair<size_t, size_t>>& pairs) {
    std::map<int, std::vector<size_t>> lanes;
    for (size_t i = 0; i < costs.size(); ++i) lanes[costs[i].lane].push_back(i);
    std::vector<double> n(costs.size(), 0.0);
    std::vector<size_t> split;
    for (const auto& [lane, engines] : lanes) {
        if (engines.size() == 1)
            n[engines[0]] = samples_in(costs[engines[0]], T);
        else if (engines.size() == 2)
            split = engines;
        else
            throw std::logic_error("plan_samples: a lane of more than two engines");
    }
    if (split.empty()) return within_limits(n, costs);
    std::vector<double> best;
    double best_n_eff = -1.0;
    for (int percent = 1; percent < 100; ++percent) {
        const double f = percent / 100.0;
        n[split[0]] = samples_in(costs[split[0]], f * T);
        n[split[1]] = samples_in(costs[split[1]], (1.0 - f) * T);
        const std::vector<double> limited = within_limits(n, costs);
        const double e = weakest_n_eff(limited, pairs);
        if (e > best_n_eff) {
            best_n_eff = e;
            best = limited;
        }
    }
    return best;
}

// The wall time of the images: the longest lane's.
double wall_time(const std::vector<double>& n, const std::vector<EngineCost>& costs) {
    std::map<int, double> lane_time;
    for (size_t i = 0; i < n.size(); ++i) lane_time[costs[i].lane] += seconds_for(costs[i], n[i]);
    double wall = 0.0;
    for (const auto& [lane, t] : lane_time) wall = std::max(wall, t);
    return wall;
}

std::vector<uint32_t> rounded(const std::vector<double>& n) {
    std::vector<uint32_t> spp;
    for (double x : n) spp.push_back(uint32_t(std::min(std::ceil(x - 1e-9), double(1u << 30))));
    return spp;
}

// The least wall time whose allocation gives every pair n_eff >= target (doubling, then
// bisection: n_eff grows with T).
double least_wall(double target, const std::vector<EngineCost>& costs,
                  const std::vector<std::pair<size_t, size_t>>& pairs) {
    auto enough = [&](double T) {
        return weakest_n_eff(allocation(T, costs, pairs), pairs) >= target;
    };
    double hi = 1e-3;
    while (!enough(hi) && hi < 1e9) hi *= 2.0;
    if (!enough(hi)) return std::numeric_limits<double>::infinity();
    double lo = 0.0;
    for (int i = 0; i < 60 && hi - lo > 1e-4 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (enough(mid) ? hi : lo) = mid;
    }
    return hi;
}

} // namespace

double pairs_power(const PowerModel& model, const std::vector<uint32_t>& spp,
                   const std::vector<std::pair<size_t, size_t>>& pairs, double bias, double level) {
    double weakest = 1.0;
    for (const auto& [a, b] : pairs)
        weakest =
            std::min(weakest, global_test_power(model, bias, effective_spp(spp[a], spp[b]), level));
    return weakest;
}

double pairs_detectable(const PowerModel& model, const std::vector<uint32_t>& spp,
                        const std::vector<std::pair<size_t, size_t>>& pairs, double level,
                        double power) {
    double weakest = 0.0;
    for (const auto& [a, b] : pairs)
        weakest =
            std::max(weakest, detectable_bias(model, effective_spp(spp[a], spp[b]), level, power));
    return weakest;
}

Plan plan_samples(const PowerModel& model, const std::vector<EngineCost>& costs,
                  const std::vector<std::pair<size_t, size_t>>& pairs, const PlanRequest& request) {
    Plan plan;
    plan.level = request.alpha / double(pairs.size()) / 2.0;
    std::vector<double> n;
    if (request.spp) {
        plan.limit = PlanLimit::Fixed;
        for (const EngineCost& c : costs)
            n.push_back(std::max(double(*request.spp), double(c.kept_spp)));
    } else if (!model.informative()) {
        plan.limit = PlanLimit::NoNoise;
        n = within_limits(std::vector<double>(costs.size(), 0.0), costs);
    } else {
        const double target =
            required_effective_spp(model, request.detect, plan.level, request.power);
        plan.needed_wall_s = least_wall(target, costs, pairs);
        const bool over = request.budget_s && plan.needed_wall_s > *request.budget_s;
        plan.limit = over ? PlanLimit::Budget : PlanLimit::Power;
        n = allocation(over ? *request.budget_s : plan.needed_wall_s, costs, pairs);
    }
    plan.spp = rounded(n);
    plan.wall_s = wall_time(n, costs);
    if (plan.limit != PlanLimit::Power && plan.limit != PlanLimit::Budget)
        plan.needed_wall_s = plan.wall_s;
    plan.power = pairs_power(model, plan.spp, pairs, request.detect, plan.level);
    plan.detectable = pairs_detectable(model, plan.spp, pairs, plan.level, request.power);
    return plan;
}

} // namespace tp
