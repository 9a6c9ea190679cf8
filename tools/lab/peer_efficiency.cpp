#include "tools/lab/peer_efficiency.h"

#include "bench/reference.h"
#include "compare/metrics.h"
#include "cpu_ref/cpu_renderer.h"
#include "render/render_header.h"
#include "render/sampler.h"
#include "scene/scene_hash.h"
#include "tools/lab/cycles_script.h"
#include "tools/lab/peer_cycles.h"
#include "util/fnv1a.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::bench::BenchOptions;
using tp::bench::kReferenceSeed;
using tp::bench::Reference;
using tp::bench::reference_for;

namespace tp::lab {
namespace {

// Seeds of a peer's two reference halves: neither is the measured renders' seed (options.seed),
// which the options keep away from kReferenceSeed.
constexpr uint32_t kPeerReferenceSeeds[2] = {kReferenceSeed, kReferenceSeed + 1};

// mean(w Var R) over pixels and channels, with Var R from `var` (a plane per channel).
double weighted_noise(const RgbImage& ref, const Planes& var) {
    double sum = 0;
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < ref.pixels(); ++i) {
            const double r = ref.mean[c][i];
            sum += var[c][i] / (r * r + kRelativeEpsilon);
        }
    return sum / (3.0 * double(ref.pixels()));
}

// A converged image and the variance of its pixels.
struct Converged {
    RgbImage image;
    double noise = 0; // mean(w Var R)
    uint32_t spp = 0;
    std::string how;
    std::vector<std::string> files;

    json to_json() const {
        return {{"how", how}, {"spp", spp}, {"noise", noise}, {"files", files}};
    }
};

struct Measured {
    uint32_t spp = 0;
    double per_spp_s = -1; // time per spp after the first; -1: not measured
    RgbImage image;
    int exit_code = 0;
};

uint32_t spp_for_budget(double budget_s, double per_spp_s) {
    if (!(per_spp_s > 0)) return 2 * kCalibrationSpp;
    return uint32_t(std::clamp(std::lround(budget_s / per_spp_s), 2l, 1l << 20));
}

Measured render_twinpath(const FlatScene& scene, uint32_t sampler, uint32_t threads, uint32_t spp,
                         uint32_t seed) {
    FlatScene s = scene;
    s.spp = spp;
    RenderOptions opt;
    opt.seed = seed;
    opt.sampler = sampler;
    opt.threads = threads;
    opt.checkpoints = {1, spp};
    Measured m;
    m.spp = spp;
    double t1 = 0;
    opt.on_checkpoint = [&](const RenderResult& snap) {
        if (snap.stats.spp == 1) t1 = snap.stats.wall_time_s;
    };
    const RenderResult r = render_cpu(s, opt);
    m.per_spp_s = (r.stats.wall_time_s - t1) / double(spp - 1);
    m.image = rgb_image_from_exr(render_exr(r, s, opt), "twinpath");
    return m;
}

json row_json(const std::string& renderer, uint32_t threads, const Measured& m,
              const Converged& ref) {
    json row = {{"renderer", renderer},
                {"threads", threads},
                {"spp", m.spp},
                {"time_per_spp_s", m.per_spp_s},
                {"exit_code", m.exit_code}};
    if (m.exit_code != 0 || !(m.per_spp_s > 0)) return row;
    const double relmse = error_metrics(m.image, ref.image, ref.image).all.relmse;
    const double t = m.per_spp_s * double(m.spp);
    const double excess = relmse - ref.noise;
    row["time_s"] = t;
    row["relmse"] = relmse;
    row["relmse_excess"] = excess;
    row["relmse_times_time"] = excess * t;
    row["efficiency"] = excess > 0 && t > 0 ? json(1.0 / (excess * t)) : json(nullptr);
    return row;
}

// The peer's converged image, cached under a key of the scene, the Blender version and the
// script: the mean of two half-spp renders, and their difference for its variance.
Converged cycles_reference(const std::string& blender, const std::string& version,
                           const FlatScene& scene, const std::string& dir, uint32_t spp,
                           const std::string& log, std::string& failure) {
    Fnv1a h;
    FlatScene keyed = scene;
    keyed.spp = spp;
    h.value(render_inputs_hash(keyed));
    h.bytes(version.data(), version.size());
    h.bytes(kCyclesScript, std::char_traits<char>::length(kCyclesScript));
    Converged ref;
    ref.spp = spp;
    RgbImage half[2];
    for (int k = 0; k < 2; ++k) {
        const std::string file =
            (fs::path(dir) / fmt::format("reference-{:016x}-{}.exr", h.get(), k)).string();
        ref.files.push_back(file);
        if (fs::exists(file)) {
            half[k] = load_rgb_image(file);
            continue;
        }
        const std::string tmp = file + ".part.exr";
        const CyclesRun r = run_cycles(blender, dir, tmp, spp / 2, kPeerReferenceSeeds[k], 0, log);
        if (r.process.exit_code != 0) {
            failure = fmt::format("Cycles failed rendering its reference (exit {}; log {})",
                                  r.process.exit_code, log);
            return ref;
        }
        fs::rename(tmp, file);
        half[k] = r.image;
    }
    ref.image = half[0];
    Planes var;
    for (int c = 0; c < 3; ++c) {
        var[c].resize(ref.image.pixels());
        for (size_t i = 0; i < ref.image.pixels(); ++i) {
            const double a = half[0].mean[c][i], b = half[1].mean[c][i];
            ref.image.mean[c][i] = 0.5 * (a + b);
            var[c][i] = 0.25 * (a - b) * (a - b);
        }
    }
    ref.noise = weighted_noise(ref.image, var);
    ref.how = fmt::format("mean of two Cycles renders of {} spp (seeds {} and {})", spp / 2,
                          kPeerReferenceSeeds[0], kPeerReferenceSeeds[1]);
    return ref;
}

} // namespace

json run_efficiency(const FlatScene& scene, const std::string& name, const BenchOptions& o,
                    const std::string& cache_dir, const std::function<void(double)>& progress) {
    json out = {{"budget_s", o.peer_budget_s},
                {"ref_spp", o.ref_spp},
                {"rows", json::array()},
                {"skipped", json::array()}};
    const size_t renderers = o.samplers.size() + 1;
    const double steps = double(2 + o.peer_threads.size() * renderers * 2);
    double step = 0;
    const auto advance = [&] {
        if (progress) progress(++step / steps);
    };

    const Reference ours = reference_for(scene, name, o.ref_spp, cache_dir, nullptr);
    const Converged ours_ref{ours.image,
                             weighted_noise(ours.image, ours.image.var),
                             ours.spp,
                             fmt::format("twinpath CPU, {} spp, seed {}", ours.spp, kReferenceSeed),
                             {ours.file}};
    out["references"] = {{"twinpath", ours_ref.to_json()}};
    advance();

    // The peer: Blender's Cycles, when installed and able to render the scene.
    const fs::path dir = fs::path(cache_dir) / "peer" / name / "cycles";
    const std::string log = (dir / "blender.log").string();
    std::string skip;
    std::string version;
    if (!fs::exists(o.blender))
        skip =
            fmt::format("Blender is not at {} (Debian package blender; --blender PATH)", o.blender);
    else if (std::string why = cycles_unsupported(scene); !why.empty())
        skip = "Cycles: " + why;
    Converged peer_ref;
    if (skip.empty()) {
        fs::create_directories(dir);
        fs::remove(log);
        version = cycles_version(o.blender, log);
        write_cycles_scene(scene, dir.string());
        peer_ref = cycles_reference(o.blender, version, scene, dir.string(), o.ref_spp, log, skip);
        out["references"]["peer"] = peer_ref.to_json();
        out["peer"] = {{"name", "Cycles"}, {"version", version}, {"log", log}};
    }
    if (!skip.empty()) out["skipped"].push_back(skip);
    advance();

    for (const uint32_t threads : o.peer_threads) {
        for (const std::string& sampler_word : o.samplers) {
            const uint32_t sampler = sampler_from_name(sampler_word);
            const Measured cal = render_twinpath(scene, sampler, threads, kCalibrationSpp, o.seed);
            advance();
            const uint32_t n = spp_for_budget(o.peer_budget_s, cal.per_spp_s);
            const Measured m = render_twinpath(scene, sampler, threads, n, o.seed);
            json row =
                row_json(fmt::format("twinpath cpu ({})", sampler_word), threads, m, ours_ref);
            row["sampler"] = sampler_word;
            out["rows"].push_back(row);
            advance();
        }
        if (!skip.empty()) continue;
        const std::string exr = (dir / "measured.exr").string();
        const CyclesRun cal =
            run_cycles(o.blender, dir.string(), exr, kCalibrationSpp, o.seed, threads, log);
        advance();
        Measured m;
        m.exit_code = cal.process.exit_code;
        if (m.exit_code == 0) {
            m.spp = spp_for_budget(o.peer_budget_s, cal.time_per_spp(kCalibrationSpp));
            const CyclesRun r =
                run_cycles(o.blender, dir.string(), exr, m.spp, o.seed, threads, log);
            m.exit_code = r.process.exit_code;
            m.per_spp_s = r.time_per_spp(m.spp);
            m.image = r.image;
        }
        out["rows"].push_back(row_json(version.empty() ? "Cycles" : version, threads, m, peer_ref));
        out["rows"].back()["peer"] = true;
        advance();
    }
    return out;
}

} // namespace tp::lab
