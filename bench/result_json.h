// Small pieces of the bench result's JSON (run_sections.h), shared by the sections that write it
// (ladder.cpp, sweep.cpp, sizes.cpp) and the lab's report that reads it back (tools/lab/).
#pragma once

#include "render/stats.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace tp::bench {

// A measurement that may be absent: null in JSON (and an empty CSV cell, a dash in markdown)
// when not finite, so that "not measured" never reads as a number.
nlohmann::json number_or_null(double v);
nlohmann::json number_or_null(const std::optional<double>& v);

// GPU time is negative when the backend has no timestamp queries (RenderStats::gpu_time_s).
nlohmann::json gpu_seconds(double gpu_s);

// Compute mode's BVH build, seconds per stage ({"primitives": s, "embree": s, ...}) from the
// render's extra.bvh_build_stages (vulkan_rt/compute_mode/bvh_builder.h, bvh_stats: "name
// seconds" pairs); null for a render without it (pipeline mode, the CPU).
nlohmann::json build_stages_json(const RenderStats& stats);

// {"camera": n, "extension": n, "shadow": n}
nlohmann::json rays_json(const RayCounts& rays);

// Sum of the three kinds of rays_json.
double total_rays(const nlohmann::json& rays);

// Rays of one kind ("camera", "extension", "shadow"; nullptr: all) per second, in millions;
// null without a positive time.
nlohmann::json mrays_per_s(const nlohmann::json& rays, const char* kind, double seconds);

} // namespace tp::bench
