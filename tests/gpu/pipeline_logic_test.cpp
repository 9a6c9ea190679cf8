// Pipeline mode's host logic, without a device (lavapipe cannot run it; CI tests it here):
// the shader binding table's layout for several handle sizes and alignments, the TLAS instance
// records, the bottom-level build inputs and the scene limits, which mode a device and a
// --vk-mode request lead to, and the words of the modes.
#include "scene/flatten.h"
#include "scene/generators.h"
#include "scene/load.h"
#include "shaders/rt_interface.h"
#include "shared/surface.h"
#include "util/error.h"
#include "vulkan_rt/device/device_info.h"
#include "vulkan_rt/device/vk_mode.h"
#include "vulkan_rt/pipeline_mode/accel_inputs.h"
#include "vulkan_rt/pipeline_mode/sbt_layout.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

using namespace tp;

namespace {

// The rules vkCmdTraceRaysKHR states for the regions (VUIDs 03682, 04023, 03685/03686/04029,
// 03689/03690/04035), and that the records fit and do not overlap.
void check_regions(const SbtProperties& p, const SbtLayout& l, uint32_t miss, uint32_t hit) {
    INFO("handle " << p.handle_size << ", handle alignment " << p.handle_alignment
                   << ", base alignment " << p.base_alignment);
    for (const SbtRegion* r : {&l.raygen, &l.miss, &l.hit}) {
        CHECK(r->offset % p.base_alignment == 0);
        CHECK(r->stride >= p.handle_size);
        CHECK(r->stride <= p.max_stride);
    }
    CHECK(l.raygen.size == l.raygen.stride);
    CHECK(l.miss.stride % p.handle_alignment == 0);
    CHECK(l.hit.stride % p.handle_alignment == 0);
    CHECK(l.miss.size >= miss * l.miss.stride);
    CHECK(l.hit.size >= hit * l.hit.stride);
    CHECK(l.raygen.offset == 0);
    CHECK(l.miss.offset >= l.raygen.offset + l.raygen.size);
    CHECK(l.hit.offset >= l.miss.offset + l.miss.size);
    CHECK(l.bytes >= l.hit.offset + l.hit.size);
}

DeviceCaps compute_caps() {
    DeviceCaps caps;
    caps.api_version = VK_API_VERSION_1_2;
    caps.float64 = caps.scalar_layout = caps.subgroup_arithmetic = caps.subgroup_ballot =
        caps.compute_queue = true;
    caps.max_storage_buffers = 32;
    caps.max_sampled_images = caps.max_stage_resources = 128; // lavapipe's
    return caps;
}

DeviceCaps pipeline_caps() {
    DeviceCaps caps = compute_caps();
    for (const char* e : pipeline_extensions()) caps.extensions.push_back(e);
    caps.acceleration_structure = caps.ray_tracing_pipeline = caps.buffer_device_address = true;
    caps.subgroup_arithmetic_raygen = caps.subgroup_ballot_raygen = true;
    return caps;
}

DeviceInfo device_with(const DeviceCaps& caps) {
    DeviceInfo d;
    d.name = "GPU";
    d.caps = caps;
    d.compute_missing = compute_mode_missing(caps);
    d.pipeline_missing = pipeline_mode_missing(caps);
    return d;
}

} // namespace

TEST_CASE("SBT regions follow the device's handle size and alignments", "[gpu]") {
    // NVIDIA (32, 32, 64), AMD RDNA (32, 32, 64 / 32), and sizes and alignments that do not
    // divide each other, so that every rounding step matters.
    const SbtProperties props[] = {
        {32, 32, 64, 4096}, {32, 32, 32, 4096}, {16, 16, 64, 4096},  {32, 8, 256, 4096},
        {48, 32, 64, 4096}, {64, 64, 64, 4096}, {32, 32, 128, 4096}, {24, 16, 48, 4096},
    };
    for (const SbtProperties& p : props)
        for (uint32_t miss : {1u, 2u, 5u})
            for (uint32_t hit : {1u, 3u}) check_regions(p, sbt_layout(p, miss, hit), miss, hit);

    // NVIDIA's numbers with twinpath's groups (2 miss shaders, 1 hit group), worked by hand.
    const SbtLayout nv = sbt_layout({32, 32, 64, 4096}, 2, 1);
    CHECK((nv.raygen.offset == 0 && nv.raygen.stride == 64 && nv.raygen.size == 64));
    CHECK((nv.miss.offset == 64 && nv.miss.stride == 32 && nv.miss.size == 64));
    CHECK((nv.hit.offset == 128 && nv.hit.stride == 32 && nv.hit.size == 64));
    CHECK(nv.bytes == 192);
    // A 48-byte handle with 32-byte alignment needs 64-byte records.
    const SbtLayout odd = sbt_layout({48, 32, 64, 4096}, 2, 1);
    CHECK((odd.miss.stride == 64 && odd.miss.size == 128 && odd.hit.offset == 192));

    CHECK_THROWS_AS(sbt_layout({64, 64, 64, 32}, 2, 1), RuntimeError); // stride over the limit
}

TEST_CASE("the SBT holds each group's handle at its record", "[gpu]") {
    for (const SbtProperties& p :
         {SbtProperties{32, 32, 64, 4096}, SbtProperties{48, 32, 256, 4096},
          SbtProperties{16, 16, 32, 4096}}) {
        const SbtLayout l = sbt_layout(p, 2, 1);
        // Handle g is filled with the byte g + 1.
        std::vector<uint8_t> handles;
        for (uint8_t g = 0; g < 4; ++g)
            handles.insert(handles.end(), p.handle_size, uint8_t(g + 1));
        const std::vector<uint8_t> table = sbt_table(l, handles);
        REQUIRE(table.size() == l.bytes);
        const uint64_t starts[4] = {l.raygen.offset, l.miss.offset, l.miss.offset + l.miss.stride,
                                    l.hit.offset};
        size_t handle_bytes = 0;
        for (uint8_t g = 0; g < 4; ++g)
            for (uint32_t i = 0; i < p.handle_size; ++i) CHECK(table[starts[g] + i] == g + 1);
        for (uint8_t b : table) handle_bytes += b != 0;
        CHECK(handle_bytes == 4 * p.handle_size); // the rest is zero
    }
    // The table goes to the buffer's first multiple of the base alignment.
    CHECK(sbt_placement(0x10000, 64) == 0);
    CHECK(sbt_placement(0x10001, 64) == 63);
    CHECK(sbt_placement(0x1003f, 64) == 1);
    CHECK(sbt_placement(0x10040, 256) == 0xc0);
}

TEST_CASE("TLAS instance records carry the instance's transform and its index", "[gpu]") {
    Instance inst{};
    inst.to_world0 = vec4(0.5f, -1.0f, 2.0f, 3.0f);
    inst.to_world1 = vec4(0.25f, 4.0f, -0.5f, -7.0f);
    inst.to_world2 = vec4(1.5f, 0.0f, 3.0f, 11.0f);
    const uint64_t blas = 0x0000123456789a00ull;
    for (uint32_t index : {0u, 5u, 4095u, uint32_t(kMaxCustomIndex)}) {
        const VkAccelerationStructureInstanceKHR r =
            instance_record(inst, index, blas, false, false);
        const vec4 rows[3] = {inst.to_world0, inst.to_world1, inst.to_world2};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) CHECK(r.transform.matrix[i][j] == rows[i][j]);
        CHECK(r.instanceCustomIndex == index);
        CHECK(r.mask == 0xFF);
        CHECK(r.instanceShaderBindingTableRecordOffset == 0);
        CHECK(r.flags == (VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR |
                          VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR));
        CHECK(r.accelerationStructureReference == blas);

        // The bytes the device reads (the spec's layout: 48 bytes of matrix, then 24-bit index
        // and 8-bit mask in one little-endian word, 24-bit record offset and 8-bit flags, and
        // the 64-bit reference), independent of how this compiler packs bit-fields.
        static_assert(sizeof(VkAccelerationStructureInstanceKHR) == 64, "instance record size");
        uint32_t words[2];
        uint64_t reference;
        std::memcpy(words, reinterpret_cast<const uint8_t*>(&r) + 48, 8);
        std::memcpy(&reference, reinterpret_cast<const uint8_t*>(&r) + 56, 8);
        CHECK(words[0] == (index | 0xFF000000u));
        CHECK(words[1] == uint32_t(r.flags) << 24);
        CHECK(reference == blas);
    }

    // The record's matrix maps points as the shaders' instance transform does.
    const VkAccelerationStructureInstanceKHR r = instance_record(inst, 0, blas, false, false);
    const vec3 p(0.3f, -2.0f, 5.0f);
    const vec3 expected = instance_point_to_world(inst, p);
    for (int i = 0; i < 3; ++i) {
        const float* m = r.transform.matrix[i];
        CHECK(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3] == Approx(expected[i]));
    }
}

TEST_CASE("bottom-level inputs are each mesh's slice of the shared buffers", "[gpu]") {
    std::vector<std::string> warnings;
    const FlatScene scene = flatten(load_scene("cornell", warnings));
    // The box's walls (5.6 long) and blocks are of one scale: no mesh needs the exact test.
    const std::vector<uint8_t> exact = exact_triangle_meshes(scene);
    CHECK(std::count(exact.begin(), exact.end(), 1) == 0);
    const std::vector<BlasGeometry> geoms = blas_geometries(scene, exact);
    REQUIRE(geoms.size() == scene.meshes.size());
    for (const BlasGeometry& g : geoms) {
        CHECK(!g.exact);
        const MeshInfo& m = scene.meshes[g.mesh];
        CHECK(g.vertex_offset == uint64_t(m.first_vertex) * 12);
        CHECK(g.index_offset == uint64_t(m.first_triangle) * 12);
        CHECK(g.triangle_count == m.triangle_count);
        CHECK(g.max_vertex + 1 == m.vertex_count);
        for (uint32_t t = 0; t < m.triangle_count; ++t) {
            const uvec3 tri = scene.triangles[m.first_triangle + t];
            CHECK(std::max(tri.x, std::max(tri.y, tri.z)) <= g.max_vertex);
        }
    }

    // Every instance gets a record with its own index, pointing at its mesh's BLAS.
    std::vector<uint64_t> address(scene.meshes.size());
    for (size_t m = 0; m < address.size(); ++m) address[m] = 0x100000 * (m + 1);
    const auto records = instance_records(scene, address, exact);
    REQUIRE(records.size() == scene.instances.size());
    for (uint32_t i = 0; i < records.size(); ++i) {
        CHECK(records[i].instanceCustomIndex == i);
        CHECK(records[i].instanceShaderBindingTableRecordOffset == RT_HIT_GROUP_TRIANGLES);
        CHECK(records[i].accelerationStructureReference == address[scene.instances[i].mesh]);
    }
}

// A floor quad of half-size `half` under a unit box and a unit icosphere (shared/stress: the floor
// at +-1e8, docs/stress.md); the quad's edges are 2 half sqrt(2) long at the diagonal.
FlatScene floor_scene(float half, float floor_scale_in_instance = 1.0f) {
    Scene s;
    s.materials = {default_material()};
    s.material_names = {"grey"};
    s.meshes = {make_quad(), make_box(), make_icosphere(2, false)};
    const float mesh_half = half / floor_scale_in_instance;
    for (glm::dvec3& p : s.meshes[0].positions) p *= double(mesh_half);
    s.objects = {{"floor", 0, 0, glm::scale(glm::mat4(1.0f), vec3(floor_scale_in_instance))},
                 {"box", 1, 0, glm::mat4(1.0f)},
                 {"sphere", 2, 0, glm::mat4(1.0f)}};
    s.camera.given = true;
    return flatten(s);
}

TEST_CASE("meshes far larger than the scene's content get the exact triangle test", "[gpu]") {
    // Content scale: the lower median of the instances' diagonals, the box's and the sphere's
    // 2 sqrt(3) = 3.46; the threshold is 1024 times that, 3547, for the longest edge.
    const float content = 2.0f * std::sqrt(3.0f);
    const float just_below = kExactEdgeRatio * content / (2.0f * std::sqrt(2.0f)) * 0.99f;
    CHECK(exact_triangle_meshes(floor_scene(1e8f)) == std::vector<uint8_t>{1, 0, 0});
    CHECK(exact_triangle_meshes(floor_scene(1e4f)) == std::vector<uint8_t>{1, 0, 0});
    CHECK(exact_triangle_meshes(floor_scene(just_below)) == std::vector<uint8_t>{0, 0, 0});
    CHECK(exact_triangle_meshes(floor_scene(just_below / 0.99f * 1.01f)) ==
          std::vector<uint8_t>{1, 0, 0});
    // The instance's scale counts: the same world floor from a small mesh scaled up.
    CHECK(exact_triangle_meshes(floor_scene(1e8f, 1e6f)) == std::vector<uint8_t>{1, 0, 0});

    const FlatScene scene = floor_scene(1e8f);
    const std::vector<uint8_t> exact = exact_triangle_meshes(scene);
    const std::vector<BlasGeometry> geoms = blas_geometries(scene, exact);
    REQUIRE(geoms.size() == 3);
    CHECK((geoms[0].exact && !geoms[1].exact && !geoms[2].exact));
    // One box per triangle, in triangle order: the quad's triangles (0, 1, 2) and (0, 2, 3), in
    // the mesh's stored coordinates, relative to its lowest corner (-1e8, 0, -1e8) (flatten.h).
    const std::vector<VkAabbPositionsKHR> boxes = triangle_boxes(scene, geoms[0]);
    REQUIRE(boxes.size() == 2);
    CHECK((boxes[0].minX == 0.0f && boxes[0].maxX == 2e8f && boxes[0].minZ == 0.0f &&
           boxes[0].maxZ == 2e8f && boxes[0].minY == 0.0f && boxes[0].maxY == 0.0f));
    CHECK((boxes[1].minX == 0.0f && boxes[1].maxX == 2e8f));
    // Its instance selects the procedural hit group; the others the triangle group.
    const auto records = instance_records(scene, {0xA00, 0xB00, 0xC00}, exact);
    REQUIRE(records.size() == 3);
    CHECK(records[0].instanceShaderBindingTableRecordOffset == RT_HIT_GROUP_EXACT);
    CHECK(records[1].instanceShaderBindingTableRecordOffset == RT_HIT_GROUP_TRIANGLES);
    CHECK(records[2].instanceShaderBindingTableRecordOffset == RT_HIT_GROUP_TRIANGLES);
}

TEST_CASE("meshes without triangles get no BLAS and their instances no record", "[gpu]") {
    FlatScene scene;
    scene.meshes.resize(3);
    scene.meshes[0] = {0, 0, 2, 4, 0, 0, 0, 0};
    scene.meshes[1] = {2, 4, 0, 0, 0, 0, 0, 0}; // empty
    scene.meshes[2] = {2, 4, 1, 3, 0, 0, 0, 0};
    scene.materials.resize(1); // every instance's material 0: opaque
    scene.instances.resize(4);
    for (uint32_t i = 0; i < 4; ++i) scene.instances[i].mesh = i % 3; // 0, 1, 2, 0
    const std::vector<BlasGeometry> geoms = blas_geometries(scene, {0, 0, 0});
    REQUIRE(geoms.size() == 2);
    CHECK((geoms[0].mesh == 0 && geoms[1].mesh == 2));
    CHECK(
        (geoms[1].vertex_offset == 48 && geoms[1].index_offset == 24 && geoms[1].max_vertex == 2));
    const auto records = instance_records(scene, {0xA00, 0, 0xC00}, {0, 0, 0});
    REQUIRE(records.size() == 3);
    CHECK((records[0].instanceCustomIndex == 0 && records[1].instanceCustomIndex == 2 &&
           records[2].instanceCustomIndex == 3));
    CHECK(records[1].accelerationStructureReference == 0xC00);

    // Limits: instances (device, or the 24-bit custom index) and triangles per geometry.
    CHECK_NOTHROW(check_accel_limits(scene, {4, 2}));
    CHECK_THROWS_AS(check_accel_limits(scene, {3, 2}), RuntimeError);
    CHECK_THROWS_WITH(check_accel_limits(scene, {3, 2}),
                      Catch::Contains("4 instances") && Catch::Contains("--vk-mode compute"));
    CHECK_THROWS_WITH(check_accel_limits(scene, {4, 1}), Catch::Contains("2 triangles"));
}

TEST_CASE("pipeline mode needs its extensions and features and compute mode's", "[gpu]") {
    CHECK(pipeline_mode_missing(pipeline_caps()).empty());
    DeviceCaps caps = compute_caps(); // lavapipe 22: no ray-tracing extensions
    CHECK(pipeline_mode_missing(caps) == "VK_KHR_acceleration_structure, "
                                         "VK_KHR_ray_tracing_pipeline, "
                                         "VK_KHR_deferred_host_operations");
    caps = pipeline_caps();
    caps.subgroup_arithmetic_raygen = false;
    CHECK(pipeline_mode_missing(caps) == "subgroup arithmetic in ray-generation shaders");
    caps = pipeline_caps();
    caps.ray_tracing_pipeline = caps.buffer_device_address = false;
    CHECK(pipeline_mode_missing(caps) == "rayTracingPipeline, bufferDeviceAddress");
    caps = pipeline_caps();
    caps.float64 = false; // the shared shading code accumulates in double precision
    CHECK(pipeline_mode_missing(caps) == "shaderFloat64");
    CHECK(caps.has("VK_KHR_ray_tracing_pipeline"));
    CHECK_FALSE(caps.has("VK_KHR_ray_query"));
}

TEST_CASE("auto picks pipeline where supported and pipeline elsewhere is a clear error", "[gpu]") {
    const DeviceInfo rt = device_with(pipeline_caps());
    CHECK(rt.modes() == std::vector<VkMode>{VkMode::compute, VkMode::pipeline});
    CHECK(resolve_vk_mode(std::nullopt, rt) == VkMode::pipeline);
    CHECK(resolve_vk_mode(VkMode::compute, rt) == VkMode::compute);
    CHECK(resolve_vk_mode(VkMode::pipeline, rt) == VkMode::pipeline);

    const DeviceInfo plain = device_with(compute_caps());
    CHECK(plain.modes() == std::vector<VkMode>{VkMode::compute});
    CHECK(resolve_vk_mode(std::nullopt, plain) == VkMode::compute);
    CHECK(resolve_vk_mode(VkMode::compute, plain) == VkMode::compute);
    CHECK_THROWS_AS(resolve_vk_mode(VkMode::pipeline, plain), RuntimeError); // exit code 3
    CHECK_THROWS_WITH(resolve_vk_mode(VkMode::pipeline, plain),
                      Catch::Contains("cannot run the ray-tracing pipeline mode") &&
                          Catch::Contains("VK_KHR_ray_tracing_pipeline") &&
                          Catch::Contains("--vk-mode compute"));
}

// The words are what the command line reads and the outputs write (RenderStats::mode in the
// stats JSON, the bench and stress reports): saved files and the other tests depend on them.
TEST_CASE("the mode and backend words read back as what they name, other words are refused",
          "[gpu]") {
    CHECK(std::string(vk_mode_name(VkMode::compute)) == "compute");
    CHECK(std::string(vk_mode_name(VkMode::pipeline)) == "pipeline");
    CHECK(std::string(vk_mode_request_name(std::nullopt)) == "auto");
    for (const VkMode m : {VkMode::compute, VkMode::pipeline}) {
        CHECK(parse_vk_mode(vk_mode_name(m)) == m);
        CHECK(parse_vk_mode_request(vk_mode_name(m)) == VkModeRequest(m));
        CHECK(std::string(vk_mode_request_name(m)) == vk_mode_name(m));
    }
    CHECK(parse_vk_mode_request("auto") == std::nullopt);
    CHECK_FALSE(parse_vk_mode("auto")); // a request, not a mode that runs
    CHECK_FALSE(parse_vk_mode("Compute"));
    CHECK_FALSE(parse_vk_mode(""));
    CHECK_THROWS_AS(parse_vk_mode_request("rtx"), InputError); // exit code 2
    CHECK_THROWS_WITH(parse_vk_mode_request("rtx"),
                      "--vk-mode rtx: expected auto, compute or pipeline");

    for (const std::string word : {"compute", "compute-wide", "compute-auto", "pipeline"}) {
        const std::optional<VkBackend> b = parse_vk_backend(word);
        REQUIRE(b);
        CHECK(vk_backend_name(*b) == word);
    }
    CHECK(parse_vk_backend("compute")->bvh == BvhLayout::binary);
    CHECK(parse_vk_backend("compute-wide")->mode == VkMode::compute);
    CHECK(parse_vk_backend("compute-wide")->bvh == BvhLayout::wide);
    CHECK(parse_vk_backend("compute-auto")->bvh == BvhLayout::automatic);
    CHECK(parse_vk_backend("compute-auto")->mode == VkMode::compute);
    CHECK(parse_vk_backend("pipeline")->mode == VkMode::pipeline);
    CHECK_FALSE(parse_vk_backend("pipeline-wide"));
    CHECK_FALSE(parse_vk_backend("auto"));
    CHECK_FALSE(parse_vk_backend("compute/wide"));
}
