// The stress suite on the Vulkan compute mode (lavapipe in CI) and the GLSL shared functions,
// at CI size; expectations as in stress_cpu_test.cpp. Pipeline mode runs in
// `twinpath bench --stress` on a device that has it.
#define CATCH_CONFIG_EXTERNAL_INTERFACES // Catch2 v2: the event listener below
#include "stress_common.h"

#include "support/test_paths.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/device/validation.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

namespace tp::stress {
namespace {

// The stress runner renders through render_vulkan, which keeps its device open; like the
// command line (cli/main.cpp), close it before the process exits, while the driver is whole
// (vulkan_renderer.h). Destroyed at exit instead, on lavapipe it leaves 6 KB that the debug
// preset's leak check reports.
struct CloseVulkanDeviceAtEnd : Catch::TestEventListenerBase {
    using TestEventListenerBase::TestEventListenerBase;
    void testRunEnded(const Catch::TestRunStats&) override { close_vulkan_device(); }
};
CATCH_REGISTER_LISTENER(CloseVulkanDeviceAtEnd)

VulkanContext& context() {
    static VulkanContext ctx("", VkMode::compute);
    return ctx;
}

Engine gpu() {
    return vulkan_engine(VkBackend{VkMode::compute});
}

// The GPU renders are slower on lavapipe: a smaller image, the same expectations.
Size gpu_size() {
    Size s = small_size();
    s.image = 16;
    s.spp = 64;
    s.furnace_spp = 16;
    s.point_lights = 2000;
    return s;
}

// Cases lavapipe cannot run, left out below and checked in a [!shouldfail] test case: the IOR 3
// furnaces' 512 bounces exceed its 65535-iteration loop budget (on the H200 they pass, bench
// --stress; docs/stress.md, "IOR 3 furnaces: truncated at the depth cap").
const std::vector<std::string> kOpenDielectric = {"glass furnace IOR 3", "total internal"};

} // namespace

TEST_CASE("stress GPU: watertight icosphere and bunny in the compute traversal", "[stress][gpu]") {
    require_all(watertight_cases_gpu(context(), small_size(), tp::test::assets_dir()));
    CHECK(context().instance().validation_messages() == 0);
}

TEST_CASE("stress GPU: Phong extremes in GLSL", "[stress][gpu]") {
    require_all(brdf_cases_glsl(context(), small_size()));
    CHECK(context().instance().validation_messages() == 0);
}

TEST_CASE("stress GPU: glTF material extremes in GLSL", "[stress][gpu]") {
    require_all(pbr_cases_glsl(context(), small_size()));
    CHECK(context().instance().validation_messages() == 0);
}

TEST_CASE("stress GPU: scale in compute mode", "[stress][gpu]") {
    require_all(scale_cases(gpu(), gpu_size()));
}

// Regression (docs/stress.md, "Scale and position"): see stress_cpu_test.cpp.
TEST_CASE("stress GPU: a scene moved by 1e2 to 1e6 in compute mode", "[stress][gpu]") {
    require_all(position_cases(gpu(), gpu_size()));
}

TEST_CASE("stress GPU: far and huge objects in compute mode", "[stress][gpu]") {
    require_all(range_cases(gpu(), gpu_size()));
}

TEST_CASE("stress GPU: dielectrics in compute mode", "[stress][gpu]") {
    require_all(dielectric_cases(gpu(), gpu_size()), kOpenDielectric);
}

TEST_CASE("stress GPU (open): IOR 3 furnaces in compute mode", "[stress][gpu][!shouldfail]") {
    require_open(dielectric_cases(gpu(), gpu_size()), kOpenDielectric);
}

// Includes the floor at +-1e8, which passes since intersect_triangle takes t from the plane
// (shared/intersect.h).
TEST_CASE("stress GPU: degenerate geometry in compute mode", "[stress][gpu]") {
    require_all(degenerate_cases(gpu(), gpu_size()));
}

TEST_CASE("stress GPU: accumulation in compute mode", "[stress][gpu]") {
    require_all(accumulation_render_cases(gpu(), small_size()));
}

// At the CPU's size: the same-seed test below shows that compute mode renders these scenes pixel
// for pixel as the CPU does, and at gpu_size() (64 spp, 16 furnace spp) the closed-box
// comparison (p = 9e-5) and the furnace's per-pixel 4-SE bound (variance estimates from 16
// heavy-tailed samples) failed on both backends alike: the statistics, not the GPU.
TEST_CASE("stress GPU: lights in compute mode", "[stress][gpu]") {
    require_all(light_cases(gpu(), small_size()));
}

TEST_CASE("stress GPU: shading normals in compute mode", "[stress][gpu]") {
    require_all(shading_normal_cases(gpu(), small_size()));
}

// Same seed, same spp: the compute mode follows the CPU's paths pixel for pixel.
TEST_CASE("stress GPU: same-seed renders match the CPU", "[stress][gpu]") {
    require_all(twin_cases(cpu_engine(), gpu(), gpu_size()));
}

// The geometry cases and the same-seed replay again over the compressed 8-wide BVH (--bvh wide):
// its quantized boxes must not lose the far, huge, flat and degenerate triangles either.
TEST_CASE("stress GPU: geometry and same-seed renders with the wide BVH", "[stress][gpu]") {
    const Engine wide = vulkan_engine(VkBackend{VkMode::compute, BvhLayout::wide});
    require_all(range_cases(wide, gpu_size()));
    require_all(degenerate_cases(wide, gpu_size()));
    require_all(twin_cases(cpu_engine(), wide, gpu_size()));
}

} // namespace tp::stress
