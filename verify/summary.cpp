#include "verify/summary.h"

#include "compare/summary.h"

#include <fmt/format.h>

#include <cmath>

namespace tp {
namespace {

std::string join(const std::vector<std::string>& parts, const char* sep) {
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : sep) + p;
    return s;
}

std::string duration(double s) {
    if (!std::isfinite(s)) return "forever";
    if (s < 1.0) return fmt::format("{:.2f} s", s);
    if (s < 600.0) return fmt::format("{:.1f} s", s);
    if (s < 36000.0) return fmt::format("{:.0f} min", s / 60.0);
    return fmt::format("{:.0f} h", s / 3600.0);
}

std::string spp_list(const VerifyResult& v, const std::vector<uint32_t>& spp) {
    std::vector<std::string> parts;
    for (size_t k = 0; k < spp.size(); ++k)
        parts.push_back(fmt::format("{} {} spp", v.labels[k], spp[k]));
    return join(parts, ", ");
}

std::string pair_name(const VerifyResult& v, const PairVerdict& pv) {
    return v.labels[pv.a] + " against " + v.labels[pv.b];
}

} // namespace

std::string percent(double fraction) {
    if (!std::isfinite(fraction)) return "no bias";
    return fmt::format("{:.2g}%", 100.0 * fraction);
}

std::string pilot_line(const VerifyResult& v) {
    std::vector<std::string> cost, setup, kept;
    for (size_t k = 0; k < v.pilots.size(); ++k) {
        cost.push_back(fmt::format("{} {:.3g} ms", v.labels[k], 1e3 * v.costs[k].seconds_per_spp));
        setup.push_back(fmt::format("{:.2f} s", v.pilots[k].setup_s));
        if (v.costs[k].kept_spp)
            kept.push_back(fmt::format("{} keeps its {} spp", v.labels[k], v.costs[k].kept_spp));
    }
    return fmt::format("pilots: {} in {}; a sample of the image costs {} (set-up {}){}",
                       spp_list(v,
                                [&] {
                                    std::vector<uint32_t> s;
                                    for (const EngineRun& p : v.pilots)
                                        s.push_back(p.result.stats.spp);
                                    return s;
                                }()),
                       duration(v.pilot_wall_s), join(cost, ", "), join(setup, ", "),
                       kept.empty() ? "" : "; " + join(kept, ", "));
}

std::vector<std::string> plan_lines(const VerifyResult& v) {
    const Plan& p = v.plan;
    const PlanRequest& r = v.request;
    const std::string at =
        fmt::format("(alpha {}{})", v.alpha,
                    v.pairs.size() > 1
                        ? fmt::format(", {} pairs at alpha/{} each", v.pairs.size(), v.pairs.size())
                        : "");
    switch (p.limit) {
    case PlanLimit::Power:
        return {fmt::format("plan: {}, about {} at once: a uniform bias of {} is found with "
                            "probability {:.2g} {}",
                            spp_list(v, p.spp), duration(p.wall_s), percent(r.detect), r.power,
                            at)};
    case PlanLimit::Budget:
        return {fmt::format("plan: the time budget allows {}, about {} at once", spp_list(v, p.spp),
                            duration(p.wall_s)),
                fmt::format("plan: there a uniform bias of {} is found with probability {:.2g} {}; "
                            "{} needs about {} (--time-budget)",
                            percent(p.detectable), r.power, at, percent(r.detect),
                            duration(p.needed_wall_s))};
    case PlanLimit::Fixed:
        return {fmt::format("plan: --spp: {}, about {} at once: a uniform bias of {} is found with "
                            "probability {:.2g} {} ({}: probability {:.2g})",
                            spp_list(v, p.spp), duration(p.wall_s), percent(p.detectable), r.power,
                            at, percent(r.detect), p.power)};
    case PlanLimit::NoNoise:
        return {
            fmt::format("plan: the pilots have no noise (every sample of a pixel alike), so any "
                        "difference shows at once: {}",
                        spp_list(v, p.spp))};
    }
    return {};
}

std::string images_line(const VerifyResult& v) {
    std::vector<std::string> parts;
    for (size_t k = 0; k < v.images.size(); ++k)
        parts.push_back(fmt::format(
            "{} {} spp in {} on {}", v.labels[k], v.images[k].result.stats.spp,
            duration(v.images[k].setup_s + v.images[k].sampling_s), v.images[k].device));
    return fmt::format("images at once: {}; {} wall", join(parts, ", "), duration(v.image_wall_s));
}

std::vector<std::string> verdict_lines(const VerifyResult& v, const PairVerdict& pv) {
    const std::string prefix = v.pairs.size() > 1 ? pair_name(v, pv) + ": " : "";
    std::vector<std::string> lines = {prefix + compare_verdict_line(pv.compare)};
    for (const std::string& w : pv.compare.warnings) lines.push_back("warning: " + w);
    // What a consistent verdict rules out; the bias asked for too where the spp rendered
    // differ from the plan's (--spp, a budget, a window that stopped).
    if (!pv.compare.different)
        lines.push_back(fmt::format(
            "power: at these spp a uniform bias of {} is found with probability {:.2g}{}",
            percent(pv.detectable), v.request.power,
            std::fabs(pv.detectable / v.request.detect - 1.0) > 0.05
                ? fmt::format(" (a bias of {}: {:.2g})", percent(v.request.detect), pv.power)
                : ""));
    return lines;
}

std::string divergence_line(const VerifyResult& v, const PairVerdict& pv) {
    if (!pv.triage || !pv.triage->first) return "";
    const PixelPaths& pp = pv.triage->paths[*pv.triage->first];
    const PathDiffResult& d = pp.diff;
    return fmt::format("first divergence: field {} at vertex {} of pixel {},{} sample {}: {} {}, "
                       "{} {}",
                       d.field, d.vertex, pp.pixel.x, pp.pixel.y, d.sample, v.labels[pv.a],
                       d.value_a, v.labels[pv.b], d.value_b);
}

std::vector<std::string> triage_lines(const VerifyResult& v, const PairVerdict& pv) {
    if (!pv.triage) return {};
    const Triage& t = *pv.triage;
    const std::string prefix = v.pairs.size() > 1 ? pair_name(v, pv) + ", " : "";
    std::vector<std::string> lines;
    lines.push_back(fmt::format(
        "{}geometry (AOVs at the pixel centres, compare --exact): {}{}", prefix,
        exact_verdict_line(t.aov),
        t.aov.identical() ? ": the camera rays hit the same surfaces, the difference is in the "
                            "shading"
                          : ": the camera rays hit different surfaces or see them differently"));
    std::vector<std::string> picks;
    for (const PixelPaths& pp : t.paths)
        picks.push_back(fmt::format("{},{} (z = {:.3g}, {})", pp.pixel.x, pp.pixel.y, pp.pixel.z,
                                    pp.pixel.why));
    lines.push_back(prefix + "pixels logged: " + join(picks, "; "));
    for (const PixelPaths& pp : t.paths) {
        const PathDiffResult& d = pp.diff;
        lines.push_back(
            d.diverged
                ? fmt::format("pixel {},{}, samples 0-{}, seed {} on both: paths diverge at sample "
                              "{}, vertex {}, field {}: {}",
                              pp.pixel.x, pp.pixel.y, pp.samples - 1, v.seeds.log, d.sample,
                              d.vertex, d.field, d.why)
                : fmt::format("pixel {},{}, samples 0-{}, seed {} on both: the same paths within "
                              "tolerance ({} paths, {} vertices)",
                              pp.pixel.x, pp.pixel.y, pp.samples - 1, v.seeds.log, d.paths_compared,
                              d.vertices_compared));
    }
    const std::string first = divergence_line(v, pv);
    lines.push_back(!first.empty()
                        ? first
                        : "no logged path diverges: the difference is not in these pixels' first "
                          "samples (compare's significance map shows where it is; "
                          "docs/debugging.md)");
    return lines;
}

} // namespace tp
