// The twinpath:* header attributes of a render's EXR (docs/design.md, "Files"; docs/farm.md): what
// was rendered, how, and which samples, so that `twinpath merge` can combine parts and refuse
// parts that are not of one render.
#pragma once

#include "image/exr_io.h"
#include "render/render_options.h"
#include "scene/flatten.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

namespace header {
constexpr const char* kSpp = "twinpath:spp";   // int: samples per pixel in all
constexpr const char* kSeed = "twinpath:seed"; // int: when every range has one seed
constexpr const char* kSampleRanges = "twinpath:sample_ranges"; // string, format_sample_ranges
constexpr const char* kBackend = "twinpath:backend";      // "cpu/embree", "vulkan/compute", ...
constexpr const char* kDevice = "twinpath:device";        // devices, "; "-separated
constexpr const char* kScene = "twinpath:scene";          // the scene's path
constexpr const char* kSceneHash = "twinpath:scene_hash"; // scene_hash() of the FlatScene
constexpr const char* kCamera = "twinpath:camera";        // camera_description()
constexpr const char* kSettings = "twinpath:settings";    // settings_description()
constexpr const char* kSampler = "twinpath:sampler";      // random, sobol
constexpr const char* kVarianceEstimator = "twinpath:variance_estimator"; // Film::to_exr
constexpr const char* kVarianceDof = "twinpath:variance_dof";             // batches: K' - 1
constexpr const char* kFilm = "twinpath:film"; // "lean" or "full": render/film.h, FilmLayout
constexpr const char* kRenderTime = "twinpath:render_time_s"; // double; merged: the parts' sum
constexpr const char* kParts = "twinpath:parts";              // merge: one line per part
constexpr const char* kIntegrator = "twinpath:integrator";    // debug views only
} // namespace header

// How variance.R/G/B was estimated (render/film.h). "samples": the unbiased sample variance of
// the pixel's samples divided by their count, valid when the samples of a pixel are independent
// (the random sampler, shared/rng.h); "batches" (the Sobol sampler): from the means of
// independent batches, with twinpath:variance_dof degrees of freedom.
constexpr const char* kVarianceFromSamples = "samples";
constexpr const char* kVarianceFromBatches = "batches";

// "SEED:BEGIN-END" entries joined by ",", sorted by seed then begin, with touching ranges of one
// seed joined into one ("0:0-64,0:64-128" is written "0:0-128").
std::string format_sample_ranges(std::vector<SampleRange> ranges);
// The inverse; InputError naming `where` (file and attribute) when the text is not that format.
std::vector<SampleRange> parse_sample_ranges(const std::string& text, const std::string& where);

// The camera as the engines see it: the eye in scene coordinates, the unit frame, the field of
// view and the aspect ratio, every number in the shortest text that reads back to it.
std::string camera_description(const FlatScene& scene);
// Everything else that changes what a sample estimates: the depths and the integrator (not the
// path-loop variant, --features: both variants compute the same samples).
std::string settings_description(const FlatScene& scene, const DebugRequest& debug);

// The EXR of a finished render: Film::to_exr, the header attributes above, and the AOV layers
// when they were asked for. `options` gives the sample offset and the debug request.
ExrImage render_exr(const RenderResult& result, const FlatScene& scene,
                    const RenderOptions& options);

// The header of a render's path log (docs/debugging.md): its backend, seed, size, depths, the
// logged pixel and the origin its positions are relative to. `scene_path` names the scene file.
PathLogInfo path_log_info(const RenderResult& result, const FlatScene& scene,
                          const std::string& scene_path, const DebugRequest& debug);

} // namespace tp
