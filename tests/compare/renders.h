// Real renderings for compare's tests: in-process CPU renders (fast, no files) for the null
// and power trials, and renders through the twinpath executable for the command-line tests
// and the cross-backend check.
#pragma once

#include "compare/rgb_image.h"
#include "shared/lang.h"
#include "shared/rng.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace tp::test {

struct RenderSpec {
    std::string scene = "cornell"; // bundled name or path
    uint32_t width = 64, height = 64, spp = 16;
    uint32_t seed = 1;
    uint32_t sampler = SAMPLER_SOBOL; // SAMPLER_* (shared/rng.h); the renderer's default
    uint32_t threads = 0;             // 0: all cores
    std::optional<uint32_t> max_depth;
    std::optional<vec3> eye, target;
    std::optional<float> fov;
};

// Renders on the CPU backend in this process; twinpath:spp set as the CLI sets it.
RgbImage render_cpu_image(const RenderSpec& spec);

// Same, written to an OpenEXR file (what `twinpath render` writes).
void render_cpu_file(const RenderSpec& spec, const std::string& path);

// A copy of a bundled scene's JSON with material `material`'s Kd multiplied by `factor`,
// written into `dir`; returns its path.
std::string scene_with_scaled_albedo(const std::string& scene, const std::string& material,
                                     double factor, const std::string& dir);

// A copy of a bundled scene's JSON with each material named in `replacements` (an object of
// material objects as docs/scene-format.md spells them) replaced, written into `dir` as
// `scene`_`tag`.json; returns its path.
std::string scene_with_materials(const std::string& scene, const nlohmann::json& replacements,
                                 const std::string& tag, const std::string& dir);

// ---- Cross-backend hook --------------------------------------------------------------------
// One rendering through `twinpath render`: backend "cpu" or "vulkan" (vk_mode "auto",
// "compute" or "pipeline"), seed and thread count. Until the Vulkan backend lands only
// CPU-vs-CPU pairs are called (test_render_null.cpp); a CPU-vs-Vulkan test calls
// compare_backends with {"vulkan", ...} for `b`.
struct BackendRun {
    std::string backend = "cpu";
    std::string vk_mode = "auto";
    uint32_t seed = 1;
    uint32_t threads = 0;
};

struct BackendComparison {
    int render_exit_a = -1, render_exit_b = -1;
    int compare_exit = -1; // 0 consistent, 1 different, 2 bad input
    std::string output;    // everything the three commands printed
    nlohmann::json result; // compare --json
};

// Renders `scene` at width x height x spp with both runs and compares A against B at alpha.
BackendComparison compare_backends(const std::string& scene, uint32_t width, uint32_t height,
                                   uint32_t spp, const BackendRun& a, const BackendRun& b,
                                   double alpha);

} // namespace tp::test
