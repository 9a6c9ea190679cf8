// The numerical stress suite (docs/stress.md): cases whose expected outcome follows
// from the mathematics of the estimator, each run on one backend/mode and reduced to a verdict
// and the NaN/Inf counts it met. The CI tests (tests/stress, label `stress`) run them at a small
// size; `twinpath bench --stress` runs them larger on every backend and mode and writes a report.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tp {
class VulkanContext;
struct VkBackend;
} // namespace tp

namespace tp::stress {

struct CaseResult {
    std::string group;    // scale, position, watertight, brdf, dielectric, degenerate, ...
    std::string name;     // the case within its group
    std::string backend;  // cpu, vulkan, c++, glsl
    std::string mode;     // embree, compute, pipeline, or "-" for function tests
    std::string expected; // the expected outcome, in words
    std::string measured; // what was measured, in words
    uint64_t nan = 0;     // NaN values met (for renders: samples dropped as NaN or Inf)
    uint64_t inf = 0;     // Inf values met (renders count both in `nan`: the film cannot tell)
    uint64_t checked = 0; // rays, samples or function evaluations behind the verdict
    bool pass = false;
    bool skipped = false; // could not run here (the reason is in `measured`)
    double seconds = 0;
};

std::string describe(const CaseResult& r); // one line for logs and test failures

// A renderer: CPU (Embree) or Vulkan in one mode.
struct Engine {
    std::string backend; // cpu, vulkan
    std::string mode;    // embree, or the Vulkan backend's word (vk_backend_name)
    std::function<RenderResult(const FlatScene&, const RenderOptions&)> render;
};

Engine cpu_engine(uint32_t threads = 0);
Engine vulkan_engine(const VkBackend& backend, const std::string& device = "");

// How large each case is: the CI tests use small(), the bench large().
struct Size {
    uint32_t image = 24;                 // square renders of image x image pixels
    uint32_t spp = 128;                  // samples per pixel of the comparison renders
    uint32_t furnace_spp = 64;           // the dielectric and shading-normal furnaces
    uint64_t watertight_rays = 1000000;  // per mesh and backend, at least
    uint32_t brdf_samples = 1000;        // per configuration of the BRDF sweep
    uint64_t accumulation_spp = 1000000; // the constant pixel
    uint32_t point_lights = 10000;
    // Both renders of the IOR 1.0 sphere and of the lit closed box, whose variants' pixels get a
    // large part of their value from events of probability ~1 % per sample (docs/stress.md,
    // "Rare events and the per-pixel test"): enough samples that each pixel sees ~50 or more.
    uint32_t rare_spp = 2048;
    double alpha = 1e-3; // per comparison; see compare_consistent()
};
Size small_size();
Size large_size();

// ---- the cases (cases_*.cpp) ----------------------------------------------------------------
std::vector<CaseResult> scale_cases(const Engine& e, const Size& s);
// The reference scene moved with its camera by 1e2, 1e4 and 1e6: the same image for the same
// seed (position_cases.cpp).
std::vector<CaseResult> position_cases(const Engine& e, const Size& s);
// Far objects inside and beyond the float32 range rule (range_cases.cpp).
std::vector<CaseResult> range_cases(const Engine& e, const Size& s);
std::vector<CaseResult> dielectric_cases(const Engine& e, const Size& s);
// Two cases of the lists, alone (their regression test runs them at full size).
CaseResult ior1_sphere_case(const Engine& e, const Size& s);
CaseResult closed_box_lights_case(const Engine& e, const Size& s);
std::vector<CaseResult> degenerate_cases(const Engine& e, const Size& s);
std::vector<CaseResult> light_cases(const Engine& e, const Size& s);
std::vector<CaseResult> shading_normal_cases(const Engine& e, const Size& s);
std::vector<CaseResult> accumulation_render_cases(const Engine& e, const Size& s);
// Same-seed renders on two engines (twin_cases.cpp): both follow the same paths, so every pixel
// must agree up to float rounding; a pixel that does not is a bug in one of them.
std::vector<CaseResult> twin_cases(const Engine& a, const Engine& b, const Size& s);
std::vector<CaseResult> film_accumulation_cases(const Size& s); // the double film itself

// The BRDF sweep of the C++ functions, and of the same functions compiled as GLSL on `ctx`.
std::vector<CaseResult> brdf_cases_cpp(const Size& s);
std::vector<CaseResult> brdf_cases_glsl(const VulkanContext& ctx, const Size& s);
// The glTF material's sweep (roughness at the smooth limit, grazing views, degenerate normal
// maps; pbr_cases.cpp) in C++, and compiled as GLSL on `ctx`.
std::vector<CaseResult> pbr_cases_cpp(const Size& s);
std::vector<CaseResult> pbr_cases_glsl(const VulkanContext& ctx, const Size& s);

// Rays aimed exactly at the shared edges and vertices of closed meshes: the icosphere, and the
// bunny when `assets_dir` holds it (skipped otherwise). CPU: Embree; GPU: the compute mode's
// BVH traversals, binary and wide (shaders/trace_bvh.glsl, trace_cwbvh.glsl), on `ctx`;
// pipeline: the driver's traversal of the render's TLAS (shaders/trace_rtx.glsl), on a `ctx`
// made for pipeline mode.
std::vector<CaseResult> watertight_cases_cpu(const Size& s, const std::string& assets_dir);
std::vector<CaseResult> watertight_cases_gpu(const VulkanContext& ctx, const Size& s,
                                             const std::string& assets_dir);
std::vector<CaseResult> watertight_cases_pipeline(const VulkanContext& ctx, const Size& s,
                                                  const std::string& assets_dir);

// NaN vertices are rejected at load: `twinpath render` on such an OBJ exits 2 with an error.
CaseResult nan_vertex_case(const std::string& twinpath_binary, const std::string& temp_dir);

// ---- `twinpath bench --stress` --------------------------------------------------------------
struct StressOptions {
    std::string out_dir = "out/stress";
    std::string assets_dir;
    std::vector<std::string> backends{"cpu", "vulkan"}; // vulkan: every mode of the device
    std::string device;
    uint32_t threads = 0;
    bool quick = false; // small() sizes
    std::string self;   // the twinpath executable (for the load-time NaN case)
    std::string command;
};
// Runs every case on every backend/mode that exists here, writes stress.md and stress.json into
// out_dir; returns 0 when every case that ran passed, 1 otherwise, 3 when a backend failed.
int run_stress(const StressOptions& o);

} // namespace tp::stress
