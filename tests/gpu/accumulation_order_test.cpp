// A pixel's accumulated sums must not depend on how its samples were split into submissions,
// nor on which invocation traced which sample: the batch planner follows measured time
// (vulkan_rt/render_loop/batch_planner.h), a launch's invocations take its samples in whatever
// order they finish their paths (shaders/render_items.glsl), and lavapipe repeats dispatches cut
// short by its loop budget, so two renders with one seed see different splits and orders, yet
// are promised the same bits (the stress suite's position group and `compare --exact` between
// same-seed renders depend on it). The resolve pass (shaders/resolve.comp) keeps that promise.
#include "gpu_harness.h"

#include "render/sampler.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "shared/rng.h"
#include "vulkan_rt/compute_mode/compute_renderer.h"
#include "vulkan_rt/present/progressive_renderer.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace tp;

namespace {

// The film after `spp` samples traced `per_frame` at a time.
Film accumulated(const FlatScene& scene, uint32_t sampler, uint32_t spp, uint32_t per_frame) {
    ProgressiveOptions o;
    o.seed = 5;
    o.sampler = sampler;
    o.max_spp = spp;
    o.samples_per_frame = per_frame;
    ProgressiveRenderer r(test::gpu_context(), scene, o);
    while (r.frame()) {
    }
    REQUIRE(r.spp() == spp);
    return r.result().film;
}

} // namespace

TEST_CASE("a pixel's sums do not depend on how its samples are split into batches", "[gpu]") {
    std::vector<std::string> warnings;
    Scene s = load_scene("cornell", warnings);
    s.settings.width = 16;
    s.settings.height = 16;
    const FlatScene scene = flatten(s);
    // 6 samples as 6 + 0, 3 + 3 and 1 + 1 + ... : sums of doubles in another grouping round
    // differently (the variance, a difference of two such sums, shows it in most pixels).
    for (uint32_t sampler : {SAMPLER_RANDOM, SAMPLER_SOBOL}) {
        CAPTURE(sampler);
        const Film whole = accumulated(scene, sampler, 6, 6);
        for (uint32_t per_frame : {1u, 3u}) {
            CAPTURE(per_frame);
            const Film split = accumulated(scene, sampler, 6, per_frame);
            uint32_t differ = 0;
            for (uint32_t p = 0; p < 16 * 16; ++p)
                differ += whole.mean(p) != split.mean(p) ||
                          whole.variance_of_mean(p) != split.variance_of_mean(p);
            CHECK(differ == 0);
        }
    }
    CHECK(test::validation_messages() == 0);
}

// The same film whether every sample has its own invocation (lavapipe's default: it reports no
// resident count, so the shader is specialized to the strided schedule) or 64 invocations share
// all of a launch's samples, each tracing hundreds in whatever order the counter hands them out
// (the counter schedule with path regeneration: the persistent launches of a GPU that reports its
// resident count). On lavapipe the long-lived invocations also run out of loop budget, so
// launches are cut short and repeated (each repetition tracing only what is left).
TEST_CASE("a pixel's sums do not depend on which invocations traced its samples", "[gpu]") {
    std::vector<std::string> warnings;
    Scene s = load_scene("cornell_spheres", warnings);
    s.settings.width = 40;
    s.settings.height = 30;
    s.settings.spp = 40;
    const FlatScene scene = flatten(s);
    for (uint32_t sampler : {SAMPLER_RANDOM, SAMPLER_SOBOL}) {
        CAPTURE(sampler);
        RenderOptions o;
        o.seed = 3;
        o.sampler = sampler;
        const RenderResult one_each =
            render_compute(test::gpu_context(), scene, o, BvhLayout::binary);
        o.gpu_invocations = 64;
        const RenderResult shared =
            render_compute(test::gpu_context(), scene, o, BvhLayout::binary);
        CHECK(shared.stats.extra.at("render_invocations") == "64");
        CHECK(shared.stats.rays.camera == one_each.stats.rays.camera);
        uint32_t differ = 0;
        for (uint32_t p = 0; p < 40 * 30; ++p)
            differ += one_each.film.mean(p) != shared.film.mean(p) ||
                      one_each.film.variance_of_mean(p) != shared.film.variance_of_mean(p);
        CHECK(differ == 0);
    }
    CHECK(test::validation_messages() == 0);
}
