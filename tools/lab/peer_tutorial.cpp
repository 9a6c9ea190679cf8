#include "tools/lab/peer_tutorial.h"

#include "cpu_ref/cpu_renderer.h"
#include "tools/lab/peer_scene.h"
#include "tools/lab/process.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>

namespace fs = std::filesystem;

namespace tp::lab {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

double per_spp(double low, double high, uint32_t spp) {
    return (high - low) / double(spp - 1);
}

// Rays (intersect + occluded) of one tutorial run under the counting module; -1 when the module or
// its output is missing or the run failed.
double counted_rays(const std::vector<std::string>& argv, const std::string& log,
                    const std::string& module, const std::string& count_file) {
    fs::remove(count_file);
    const ProcessRun p =
        run_process(argv, log, {"LD_PRELOAD=" + module, "TWINPATH_RAY_COUNT_FILE=" + count_file});
    std::ifstream in(count_file);
    double intersect = 0, occluded = 0;
    if (p.exit_code != 0 || !(in >> intersect >> occluded)) return -1;
    return intersect + occluded;
}

} // namespace

PeerRun run_peer(const FlatScene& scene, const bench::BenchOptions& options,
                 const std::string& work_dir, const std::function<void(double)>& progress) {
    PeerRun run;
    run.spp = options.peer_spp;
    fs::create_directories(work_dir);
    run.obj = (fs::path(work_dir) / (fs::path(scene.name).stem().string() + ".obj")).string();
    write_obj(scene, run.obj);
    const std::string log = (fs::path(work_dir) / "pathtracer.log").string();
    fs::remove(log);

    const std::vector<std::string> scene_args = peer_scene_arguments(scene);
    const auto peer_args = [&](uint32_t spp, uint32_t threads) {
        std::vector<std::string> a = {"-i",
                                      run.obj,
                                      "-o",
                                      (fs::path(work_dir) / "peer.ppm").string(),
                                      "--spp",
                                      std::to_string(spp),
                                      "--max-path-length",
                                      std::to_string(scene.params.max_depth),
                                      "--threads",
                                      std::to_string(threads)};
        a.insert(a.end(), scene_args.begin(), scene_args.end());
        return a;
    };
    run.peer_arguments = peer_args(run.spp, options.peer_threads.front());

    const double steps = double(options.peer_threads.size() * kPeerRepeats * 3 + 2);
    double step = 0;
    const auto advance = [&] {
        if (progress) progress(++step / steps);
    };
    for (uint32_t threads : options.peer_threads) {
        PeerRow row;
        row.threads = threads;
        row.peer_low_s = row.peer_high_s = kNever;
        double ours_best = kNever; // the best of the repeats' (t(N) - t(1))
        for (int rep = 0; rep < kPeerRepeats; ++rep) {
            FlatScene s = scene;
            s.spp = run.spp;
            RenderOptions opt;
            opt.seed = options.seed;
            opt.threads = threads;
            opt.checkpoints = {1, run.spp};
            double low = 0;
            opt.on_checkpoint = [&](const RenderResult& snap) {
                if (snap.stats.spp == 1) low = snap.stats.wall_time_s;
            };
            const RenderResult r = render_cpu(s, opt);
            if (r.stats.wall_time_s - low < ours_best) {
                ours_best = r.stats.wall_time_s - low;
                row.ours_low_s = low;
                row.ours_high_s = r.stats.wall_time_s;
            }
            row.ours_rays_per_spp = double(r.stats.rays.total()) / double(r.stats.spp);
            advance();
            for (uint32_t spp : {1u, run.spp}) {
                std::vector<std::string> argv = {options.peer_binary};
                const std::vector<std::string> a = peer_args(spp, threads);
                argv.insert(argv.end(), a.begin(), a.end());
                const ProcessRun p = run_process(argv, log);
                if (p.exit_code != 0) row.peer_exit = p.exit_code;
                double& best = spp == 1 ? row.peer_low_s : row.peer_high_s;
                best = std::min(best, p.wall_s);
                advance();
            }
        }
        run.rows.push_back(row);
    }

    const std::string module =
        (fs::read_symlink("/proc/self/exe").parent_path() / "twinpath_ray_counter.so").string();
    if (fs::exists(module)) {
        const std::string count_file = (fs::path(work_dir) / "ray_count.txt").string();
        double counts[2];
        int k = 0;
        for (uint32_t spp : {1u, run.spp}) {
            std::vector<std::string> argv = {options.peer_binary};
            const std::vector<std::string> a = peer_args(spp, options.peer_threads.front());
            argv.insert(argv.end(), a.begin(), a.end());
            counts[k++] = counted_rays(argv, log, module, count_file);
            advance();
        }
        if (counts[0] >= 0 && counts[1] > counts[0])
            run.peer_rays_per_spp = (counts[1] - counts[0]) / double(run.spp - 1);
    }
    return run;
}

nlohmann::json peer_json(const PeerRun& run) {
    nlohmann::json rows = nlohmann::json::array();
    const bool counted = run.peer_rays_per_spp > 0;
    for (const PeerRow& r : run.rows) {
        const double ours = per_spp(r.ours_low_s, r.ours_high_s, run.spp);
        const double peer = per_spp(r.peer_low_s, r.peer_high_s, run.spp);
        // Below timer resolution (a tiny image) the difference can be zero or negative: no rate.
        const bool ours_ok = ours > 0;
        const bool ok = r.peer_exit == 0 && peer > 0 && ours_ok;
        rows.push_back(
            {{"threads", r.threads},
             {"ours",
              {{"t_1spp_s", r.ours_low_s},
               {"t_nspp_s", r.ours_high_s},
               {"time_per_spp_s", ours_ok ? nlohmann::json(ours) : nlohmann::json(nullptr)},
               {"rays_per_spp", r.ours_rays_per_spp},
               {"mrays_per_s", ours_ok ? nlohmann::json(1e-6 * r.ours_rays_per_spp / ours)
                                       : nlohmann::json(nullptr)}}},
             {"peer",
              {{"exit_code", r.peer_exit},
               {"t_1spp_s", r.peer_low_s},
               {"t_nspp_s", r.peer_high_s},
               {"time_per_spp_s", ok ? nlohmann::json(peer) : nlohmann::json(nullptr)},
               {"mrays_per_s_inferred",
                ok ? nlohmann::json(1e-6 * r.ours_rays_per_spp / peer) : nlohmann::json(nullptr)},
               {"rays_per_spp",
                counted ? nlohmann::json(run.peer_rays_per_spp) : nlohmann::json(nullptr)},
               {"mrays_per_s", counted && ok ? nlohmann::json(1e-6 * run.peer_rays_per_spp / peer)
                                             : nlohmann::json(nullptr)}}},
             {"speedup", ok ? nlohmann::json(peer / ours) : nlohmann::json(nullptr)},
             // Our rays/s over the tutorial's counted rays/s (> 1: twinpath traces faster).
             {"rays_per_s_ratio", counted && ok ? nlohmann::json(r.ours_rays_per_spp / ours /
                                                                 (run.peer_rays_per_spp / peer))
                                                : nlohmann::json(nullptr)}});
    }
    return {
        {"spp", run.spp}, {"obj", run.obj}, {"peer_arguments", run.peer_arguments}, {"rows", rows}};
}

} // namespace tp::lab
