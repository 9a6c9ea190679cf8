#include "cpu_ref/cpu_renderer.h"

#include "cpu_ref/debug_views.h"
#include "cpu_ref/embree_accel.h"
#include "cpu_ref/integrator.h"
#include "render/sampler.h"
#include "scene/features.h"
#include "shared/math.h"
#include "util/clock.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <optional>

namespace tp {
namespace {

constexpr uint32_t kTile = 16;
// Samples per pass aimed at ~1M, so that a pass is long against TBB's scheduling cost and short
// against --time-limit granularity.
constexpr uint64_t kSamplesPerPass = 1u << 20;

struct TileCounters {
    RayCounts rays;
    uint64_t nan = 0;
};

// Adds sample s of pixel (x, y) to the film, or counts it where it is not finite (docs/design.md,
// "No silent NaN").
void add_sample(Film& film, uint32_t x, uint32_t y, uint32_t s, vec3 L, TileCounters& c) {
    if (!is_finite3(L)) {
        ++c.nan;
        return;
    }
    film.add_sample(y * film.width() + x, glm::dvec3(L), s);
}

// Samples [s0, s1) of every pixel of tile (tx, ty), added to the film row by row, each pixel's
// samples in sequence: in groups of the integrator's camera packets (a pixel's samples and the
// next pixel's), or one by one for a debug view.
void render_tile(const CpuIntegrator& integrator, const CpuDebugViews& views, bool view,
                 uint32_t tx, uint32_t ty, uint32_t s0, uint32_t s1, Film& film, TileCounters& c) {
    const uint32_t x0 = tx * kTile, y0 = ty * kTile;
    const uint32_t x1 = std::min(x0 + kTile, film.width()),
                   y1 = std::min(y0 + kTile, film.height());
    CpuIntegrator::PixelSample group[CpuIntegrator::kGroup];
    uint32_t n = 0;
    const auto flush = [&] {
        vec3 L[CpuIntegrator::kGroup];
        integrator.radiance_group(group, n, L, c.rays);
        for (uint32_t i = 0; i < n; ++i)
            add_sample(film, group[i].x, group[i].y, group[i].sample, L[i], c);
        n = 0;
    };
    for (uint32_t y = y0; y < y1; ++y)
        for (uint32_t x = x0; x < x1; ++x)
            for (uint32_t s = s0; s < s1; ++s) {
                if (view) {
                    add_sample(film, x, y, s, views.radiance(x, y, s), c);
                    continue;
                }
                group[n++] = {x, y, s};
                if (n == CpuIntegrator::kGroup) flush();
            }
    if (n > 0) flush();
}

} // namespace

RenderResult render_cpu(const FlatScene& scene, const RenderOptions& options) {
    std::optional<tbb::global_control> limit;
    if (options.threads > 0)
        limit.emplace(tbb::global_control::max_allowed_parallelism, options.threads);

    RenderResult result;
    RenderStats& st = result.stats;
    st.backend = "cpu";
    st.mode = "embree";
    st.device = "CPU (Embree 3, TBB)";
    st.scene = scene.name;
    st.seed = options.seed;
    st.sampler = sampler_name(options.sampler);
    st.threads =
        uint32_t(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));

    const uint32_t W = scene.params.camera.width, H = scene.params.camera.height;

    const auto t_build = std::chrono::steady_clock::now();
    const EmbreeAccel accel(scene);
    st.build_time_s = seconds_since(t_build);
    st.accel_bytes = accel.memory_bytes();
    count_triangles(st, scene);
    const SceneFeatures features = analyze_features(scene);
    st.scene_features = features.names();
    st.feature_mask = render_feature_mask(scene, options.all_features);
    st.feature_variant = options.all_features ? "all" : "scene";
    const CpuIntegrator integrator(scene, accel, st.feature_mask, options.seed, options.sampler);

    const DebugRequest& debug = options.debug;
    const CpuDebugViews views(scene, accel, debug.integrator, options.seed, options.sampler);
    const bool view = debug.integrator != INTEGRATOR_PATH;

    result.film = Film(W, H, film_batches(options.sampler));
    st.width = W;
    st.height = H;
    const uint32_t tiles_x = (W + kTile - 1) / kTile, tiles_y = (H + kTile - 1) / kTile;
    const uint32_t pass_spp =
        uint32_t(std::clamp<uint64_t>(kSamplesPerPass / (uint64_t(W) * H), 1, 1024));

    const auto t0 = std::chrono::steady_clock::now();
    double snapshot_seconds = 0; // film copies for checkpoints: not rendering time
    uint32_t done = 0;
    if (options.on_first_pass) options.on_first_pass();
    while (done < scene.spp) {
        // Samples [s0, s1) of the render are samples [K + s0, K + s1) of the sequence.
        const uint32_t K = options.sample_offset;
        const uint32_t s0 = K + done,
                       s1 = K + std::min(options.next_stop(done, scene.spp), done + pass_spp);
        tbb::combinable<TileCounters> counters;
        tbb::parallel_for(tbb::blocked_range<uint32_t>(0, tiles_x * tiles_y),
                          [&](const tbb::blocked_range<uint32_t>& r) {
                              TileCounters& c = counters.local();
                              for (uint32_t tile = r.begin(); tile != r.end(); ++tile)
                                  render_tile(integrator, views, view, tile % tiles_x,
                                              tile / tiles_x, s0, s1, result.film, c);
                          });
        counters.combine_each([&](const TileCounters& c) {
            st.rays += c.rays;
            st.nan_samples += c.nan;
        });
        done = s1 - K;
        if (options.progress) options.progress(double(done) / double(scene.spp));
        if (options.on_checkpoint && options.is_checkpoint(done)) {
            const auto t_snap = std::chrono::steady_clock::now();
            RenderResult snapshot{result.film, st, {}};
            snapshot.stats.wall_time_s = seconds_since(t0) - snapshot_seconds;
            snapshot.stats.spp = done;
            snapshot.stats.samples = uint64_t(done) * W * H - st.nan_samples;
            options.on_checkpoint(snapshot);
            snapshot_seconds += seconds_since(t_snap);
        }
        if (options.time_limit_s > 0 && seconds_since(t0) >= options.time_limit_s) break;
        if (options.stop_requested()) break;
    }
    st.wall_time_s = seconds_since(t0) - snapshot_seconds;
    st.spp = done;
    st.samples = uint64_t(done) * W * H - st.nan_samples;

    if (debug.aov) {
        result.debug.aovs.resize(size_t(W) * H);
        tbb::parallel_for(uint32_t(0), H, [&](uint32_t y) {
            for (uint32_t x = 0; x < W; ++x)
                result.debug.aovs[size_t(y) * W + x] =
                    views.primary_aov(camera_center_ray(scene.params.camera, x, y));
        });
    }
    if (debug.log) {
        RayCounts ignored;
        const uint32_t K = options.sample_offset;
        for (uint32_t s = debug.first_sample(K); s < std::min(debug.end_sample(K, done), K + done);
             ++s)
            integrator.record(debug.pixel_x, debug.pixel_y, s, ignored, result.debug.records);
    }
    return result;
}

} // namespace tp
