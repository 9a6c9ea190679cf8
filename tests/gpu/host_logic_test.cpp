// The Vulkan backend's host-side logic, without a device: VkResult -> error mapping (device
// lost and out of memory become RuntimeError, exit code 3), device selection, compute mode's
// requirements (pipeline mode's and mode selection: pipeline_logic_test.cpp), batch planning,
// the BVH builder's invariants and the watertightness of the triangle test.
#include "scene/flatten.h"
#include "scene/generators.h"
#include "scene/world_vertex.h"
#include "shared/features.h"
#include "shared/intersect.h"
#include "shared/surface.h"
#include "util/error.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/device/device_info.h"
#include "vulkan_rt/device/vk_error.h"
#include "vulkan_rt/render_loop/batch_planner.h"
#include "vulkan_rt/render_loop/batch_session.h"
#include "vulkan_rt/render_loop/item_schedule.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <random>
#include <set>
#include <tuple>

using namespace tp;

TEST_CASE("VkResult errors become RuntimeError with a clear message", "[gpu]") {
    CHECK_NOTHROW(vk_check(VK_SUCCESS, "x"));
    CHECK_NOTHROW(vk_check(VK_INCOMPLETE, "x")); // success codes are not errors
    CHECK_THROWS_AS(vk_check(VK_ERROR_DEVICE_LOST, "submitting"), RuntimeError);
    CHECK_THROWS_WITH(vk_check(VK_ERROR_DEVICE_LOST, "submitting"),
                      Catch::Contains("VK_ERROR_DEVICE_LOST") &&
                          Catch::Contains("device was lost") && Catch::Contains("submitting"));
    CHECK_THROWS_AS(vk_check(VK_ERROR_OUT_OF_DEVICE_MEMORY, "allocating"), RuntimeError);
    CHECK_THROWS_WITH(vk_check(VK_ERROR_OUT_OF_DEVICE_MEMORY, "allocating"),
                      Catch::Contains("out of GPU memory"));
    CHECK_THROWS_WITH(vk_check(VK_ERROR_OUT_OF_HOST_MEMORY, "mapping"),
                      Catch::Contains("out of host memory"));
    CHECK_THROWS_WITH(vk_check(VK_ERROR_INCOMPATIBLE_DRIVER, "creating the instance"),
                      Catch::Contains("no usable Vulkan driver"));
    CHECK_THROWS_WITH(vk_check(VkResult(-12345), "x"), Catch::Contains("VkResult -12345"));
}

namespace {

DeviceInfo device(uint32_t index, const char* name, const char* type, bool compute = true) {
    DeviceInfo d;
    d.index = index;
    d.name = name;
    d.type = type;
    if (!compute) d.compute_missing = "shaderFloat64";
    return d;
}

} // namespace

TEST_CASE("device selection by index or name substring or best type", "[gpu]") {
    const std::vector<DeviceInfo> devices = {device(0, "llvmpipe (LLVM 15)", "cpu"),
                                             device(1, "NVIDIA H100 PCIe", "discrete"),
                                             device(2, "Old GPU", "integrated", false)};
    CHECK(select_device(devices, "").index == 1); // discrete first
    CHECK(select_device(devices, "0").index == 0);
    CHECK(select_device(devices, "h100").index == 1); // case-insensitive
    CHECK(select_device(devices, "LLVMPIPE").index == 0);
    CHECK_THROWS_AS(select_device(devices, "99"), InputError);
    CHECK_THROWS_WITH(select_device(devices, "99"),
                      Catch::Contains("no Vulkan device with that index") &&
                          Catch::Contains("1: NVIDIA H100 PCIe"));
    CHECK_THROWS_AS(select_device(devices, "radeon"), InputError);
    CHECK_THROWS_AS(select_device(devices, "2"), RuntimeError); // cannot run compute mode
    CHECK_THROWS_WITH(select_device(devices, "old"), Catch::Contains("shaderFloat64"));
    CHECK_THROWS_AS(select_device({}, ""), RuntimeError);
    CHECK_THROWS_WITH(select_device({}, ""), Catch::Contains("no Vulkan device"));
}

TEST_CASE("what compute mode needs", "[gpu]") {
    DeviceCaps caps;
    caps.api_version = VK_API_VERSION_1_2;
    caps.float64 = caps.scalar_layout = caps.subgroup_arithmetic = caps.subgroup_ballot =
        caps.compute_queue = true;
    caps.max_storage_buffers = 32;
    caps.max_sampled_images = caps.max_stage_resources = 128; // lavapipe's
    CHECK(compute_mode_missing(caps).empty());
    caps.float64 = false;
    caps.api_version = VK_API_VERSION_1_1;
    CHECK(compute_mode_missing(caps) == "Vulkan 1.2, shaderFloat64");
}

TEST_CASE("batches cover every pixel-sample exactly once in passes", "[gpu]") {
    const uint32_t W = 37, H = 23, spp = 300;
    BatchPlanner plan(W, H, spp, 0.1);
    std::vector<uint32_t> samples(W * H, 0);
    uint64_t last_work = plan.work();
    double last_fraction = 0.0;
    int batch_count = 0;
    std::mt19937 rng(3);
    while (!plan.done()) {
        const Batch b = plan.next();
        REQUIRE(b.sample_count >= 1);
        REQUIRE(b.sample_count <= BatchPlanner::kMaxSamplesPerBatch);
        REQUIRE(b.row_begin < b.row_end);
        REQUIRE(b.row_end <= H);
        for (uint32_t y = b.row_begin; y < b.row_end; ++y)
            for (uint32_t x = 0; x < W; ++x) {
                REQUIRE(samples[y * W + x] == b.sample_begin); // in order, no gap, no overlap
                samples[y * W + x] += b.sample_count;
            }
        // Simulated submissions: a throughput that varies by 2x between batches.
        const double work = double(W) * (b.row_end - b.row_begin) * b.sample_count;
        plan.completed(b, work / (1e5 * (1.0 + std::uniform_real_distribution<>(0, 1)(rng))));
        CHECK(plan.work() <= 4 * last_work); // adapts by at most 4x per submission
        CHECK(4 * plan.work() >= last_work);
        CHECK(plan.fraction_done() >= last_fraction);
        last_work = plan.work();
        last_fraction = plan.fraction_done();
        ++batch_count;
    }
    for (uint32_t s : samples) CHECK(s == spp);
    CHECK(plan.samples_done() == spp);
    CHECK(plan.fraction_done() == Approx(1.0));
    CHECK(plan.at_pass_boundary());
    CHECK(batch_count > 1);
}

TEST_CASE("a batch cut short halves the samples per pixel of the next ones", "[gpu]") {
    BatchPlanner plan(8, 8, 1000, 0.1);
    Batch b = plan.next();
    plan.completed(b, 1e-6); // fast: the next batch takes many samples
    b = plan.next();
    REQUIRE(b.sample_count > 8);
    plan.completed(b, 1e-6, true);
    CHECK(plan.max_samples() == b.sample_count / 2);
    CHECK(plan.next().sample_count <= b.sample_count / 2);
}

TEST_CASE("a slow device gets bands of rows and a fast one several samples per pixel", "[gpu]") {
    BatchPlanner slow(1000, 1000, 4, 0.1);
    Batch b = slow.next();
    CHECK(b.sample_count == 1);
    CHECK(b.row_end - b.row_begin < 1000); // 16384 pixel-samples: 16 rows
    BatchPlanner fast(64, 64, 1000, 0.1);
    for (int i = 0; i < 10; ++i) { // 10^9 pixel-samples per second
        b = fast.next();
        fast.completed(b, double(64 * (b.row_end - b.row_begin) * b.sample_count) * 1e-9);
    }
    CHECK(fast.next().sample_count ==
          std::min(BatchPlanner::kMaxSamplesPerBatch, 1000 - fast.samples_done()));
}

// The viewer's rule (progressive_renderer.h): frames of 1/60 s, but a pass that takes at most
// 0.1 s at the measured throughput is one frame rather than bands of rows.
TEST_CASE("a pass within the whole-pass time is one batch, a longer one bands", "[gpu]") {
    const auto frames_of_first_passes = [](double pixel_samples_per_s) {
        BatchPlanner plan(512, 512, 100, 1.0 / 60, 16384, 1 << 20, 0.1);
        std::vector<Batch> batches;
        for (int i = 0; i < 40 && plan.samples_done() < 3; ++i) {
            const Batch b = plan.next();
            batches.push_back(b);
            plan.completed(b, double(512 * (b.row_end - b.row_begin) * b.sample_count) /
                                  pixel_samples_per_s);
        }
        return batches;
    };
    // 512x512 at 4 Mpixel-samples/s: a pass takes 66 ms. The first batch is planned before any
    // measurement (16384 pixel-samples: a band), the passes after it are whole.
    std::vector<Batch> b = frames_of_first_passes(4e6);
    CHECK(b.front().row_end - b.front().row_begin < 512);
    const Batch& last = b.back();
    CHECK(last.row_begin == 0);
    CHECK(last.row_end == 512);
    CHECK(last.sample_count == 1);
    // At 1 Mpixel-samples/s a pass takes 262 ms: bands of about 1/60 s each.
    b = frames_of_first_passes(1e6);
    for (size_t i = 1; i < b.size(); ++i)
        CHECK(b[i].row_end - b[i].row_begin <= 2 * (1e6 / 60 / 512) + 1);
    // Without the rule (render's planner) the 66 ms pass is cut into 1/60 s bands.
    BatchPlanner render(512, 512, 100, 1.0 / 60, 16384, 1 << 20);
    for (int i = 0; i < 10; ++i) {
        const Batch r = render.next();
        CHECK(r.row_end - r.row_begin < 512);
        render.completed(r, double(512 * (r.row_end - r.row_begin) * r.sample_count) / 4e6);
    }
}

TEST_CASE("the planner never plans more than the largest submission it is given", "[gpu]") {
    BatchPlanner plan(1920, 1080, 4096, 0.1, 1 << 20, 1 << 22);
    for (int i = 0; i < 20 && !plan.done(); ++i) {
        const Batch b = plan.next();
        CHECK(uint64_t(1920) * (b.row_end - b.row_begin) * b.sample_count <= (1u << 22));
        plan.completed(b, 1e-9); // infinitely fast: it would grow without the bound
    }
    CHECK(plan.work() == (1u << 22));
}

// Work items (shaders/interface.h): every pixel of the rows once per sample, items without a
// pixel only where a tile overhangs, and pixel_item the inverse of item_pixel.
TEST_CASE("a batch's work items are its pixel-samples, each once", "[gpu]") {
    struct Case {
        uint32_t width, row_begin, row_end, samples;
    };
    for (const Case c :
         {Case{16, 0, 8, 3}, Case{13, 5, 12, 2}, Case{1, 0, 1, 4}, Case{37, 3, 4, 1}}) {
        CAPTURE(c.width, c.row_begin, c.row_end, c.samples);
        const uint32_t items = batch_item_count(c.width, c.row_begin, c.row_end, c.samples);
        const uint32_t tiles_x = (c.width + ITEM_TILE_X - 1) / ITEM_TILE_X;
        const uint32_t tiles_y = (c.row_end - c.row_begin + ITEM_TILE_Y - 1) / ITEM_TILE_Y;
        CHECK(items == tiles_x * tiles_y * ITEM_TILE_PIXELS * c.samples);
        std::set<std::tuple<uint32_t, uint32_t, uint32_t>> seen;
        uint32_t without_pixel = 0;
        for (uint32_t i = 0; i < items; ++i) {
            const uvec3 p = item_pixel(i, c.width, c.row_begin, c.row_end);
            if (p.x >= c.width) {
                ++without_pixel;
                continue;
            }
            REQUIRE(p.y >= c.row_begin);
            REQUIRE(p.y < c.row_end);
            REQUIRE(p.z < c.samples);
            CHECK(seen.insert({p.x, p.y, p.z}).second);
            CHECK(pixel_item(p.x, p.y, p.z, c.width, c.row_begin, c.row_end) == i);
        }
        CHECK(seen.size() == size_t(c.width) * (c.row_end - c.row_begin) * c.samples);
        CHECK(without_pixel == items - seen.size());
    }
}

TEST_CASE("render launches: one invocation per item unless the device keeps fewer resident",
          "[gpu]") {
    CHECK(BatchSession::render_invocations(1000, 0) == 1000);
    CHECK(BatchSession::render_invocations(1000, 270336) == 1000);
    CHECK(BatchSession::render_invocations(1u << 24, 270336) == 270336);
    CHECK(BatchSession::render_invocations(uint64_t(1) << 30, 0) == BatchSession::kMaxInvocations);
    CHECK(BatchSession::render_invocations(0, 0) == 1);
}

TEST_CASE("item schedule: regeneration where a launch keeps a resident count, else strided",
          "[gpu]") {
    DeviceInfo lavapipe; // says nothing of residency
    DeviceInfo h200;
    h200.caps.resident_invocations = 270336;
    CHECK(resident_invocations(lavapipe, 0) == 0);
    CHECK(resident_invocations(lavapipe, 64) == 64);
    CHECK(resident_invocations(h200, 0) == 270336);
    CHECK(resident_invocations(h200, 1024) == 1024);
    CHECK(item_schedule(0) == ITEM_SCHEDULE_STRIDED);
    CHECK(item_schedule(64) == ITEM_SCHEDULE_COUNTER);
    CHECK(item_schedule(270336) == ITEM_SCHEDULE_COUNTER);
    CHECK(render_item_schedule(lavapipe, 0) == ITEM_SCHEDULE_STRIDED);
    CHECK(render_item_schedule(lavapipe, 64) == ITEM_SCHEDULE_COUNTER);
    CHECK(render_item_schedule(h200, 0) == ITEM_SCHEDULE_COUNTER);
}

namespace {

// Two meshes (an icosphere and a box, the box unused twice) and instances of both, one mesh
// without triangles.
FlatScene bvh_scene() {
    Scene s;
    s.path = "bvh";
    Material m = default_material();
    s.materials = {m};
    s.material_names = {"m"};
    s.meshes = {make_icosphere(3, false), make_box()};
    for (int i = 0; i < 40; ++i) {
        Object o;
        o.mesh = uint32_t(i % 3 == 0);
        o.transform = glm::scale(
            glm::translate(glm::mat4(1.0f), vec3(float(i % 7), float(i / 7), 0.0f)), vec3(0.3f));
        s.objects.push_back(o);
    }
    s.camera.given = true;
    s.camera.eye = vec3(3, 3, 20);
    s.camera.target = vec3(3, 3, 0);
    s.settings.width = s.settings.height = 4;
    return flatten(s);
}

bool contains(vec3 lo, vec3 hi, vec3 p) {
    return glm::all(glm::lessThanEqual(lo, p)) && glm::all(glm::lessThanEqual(p, hi));
}

struct Walk {
    const BvhBuild& bvh;
    const FlatScene& scene;
    std::multiset<std::pair<uint32_t, uint32_t>> items; // (instance word, primitive) of leaves
    // Visits the triangle tree below node `n`, checking that every child's box holds its
    // content and that each leaf triangle has the vertices of primitive `primitive` of `mesh`
    // (two levels, object space), or of its instance's mesh placed by world_vertex (mesh
    // NO_INDEX: one level).
    void bottom(uint32_t n, uint32_t mesh) {
        const BvhNode& node = bvh.nodes[n];
        for (int c = 0; c < 2; ++c) {
            const uint32_t ref = c ? node.ref1 : node.ref0, count = c ? node.count1 : node.count0;
            const vec3 lo = c ? node.lo1 : node.lo0, hi = c ? node.hi1 : node.hi0;
            if (ref == BVH_EMPTY) continue;
            if (count == 0) {
                const BvhNode& child = bvh.nodes[ref];
                for (int k = 0; k < 2; ++k) {
                    if ((k ? child.ref1 : child.ref0) == BVH_EMPTY) continue;
                    REQUIRE(contains(lo, hi, k ? child.lo1 : child.lo0));
                    REQUIRE(contains(lo, hi, k ? child.hi1 : child.hi0));
                }
                bottom(ref, mesh);
                continue;
            }
            REQUIRE(count <= 4);
            for (uint32_t i = ref; i < ref + count; ++i) {
                const BvhTriangle& t = bvh.triangles[i];
                const bool world = mesh == NO_INDEX;
                REQUIRE((world ? t.instance < scene.instances.size() : t.instance == 0));
                const MeshInfo& m = scene.meshes[world ? scene.instances[t.instance].mesh : mesh];
                REQUIRE(t.primitive < m.triangle_count);
                const uvec3 tri = scene.triangles[m.first_triangle + t.primitive];
                const auto place = [&](uint32_t v) {
                    const vec3 p = scene.positions[m.first_vertex + v];
                    return world ? world_vertex(scene.instances[t.instance], p) : p;
                };
                REQUIRE(t.v0 == place(tri.x));
                REQUIRE(t.v1 == place(tri.y));
                REQUIRE(t.v2 == place(tri.z));
                REQUIRE(t.normal == glm::cross(t.v1 - t.v0, t.v2 - t.v0));
                REQUIRE(
                    (contains(lo, hi, t.v0) && contains(lo, hi, t.v1) && contains(lo, hi, t.v2)));
                items.insert({t.instance, t.primitive});
            }
        }
    }
};

} // namespace

TEST_CASE("BVH holds every triangle once per mesh in boxes that enclose their content", "[gpu]") {
    const FlatScene scene = bvh_scene();
    const BvhBuild bvh = build_bvh(scene);
    REQUIRE(bvh.mesh_roots.size() == scene.meshes.size());
    CHECK_FALSE(bvh.one_level);
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        Walk w{bvh, scene, {}};
        w.bottom(bvh.mesh_roots[m], m);
        std::multiset<std::pair<uint32_t, uint32_t>> expected;
        for (uint32_t t = 0; t < scene.meshes[m].triangle_count; ++t) expected.insert({0, t});
        CHECK(w.items == expected);
    }
    // Instanced meshes are stored once.
    uint64_t stored = 0;
    for (const MeshInfo& m : scene.meshes) stored += m.triangle_count;
    CHECK(bvh.triangles.size() == stored);
    // The top level holds each instance once, in a box around its transformed triangles.
    std::multiset<uint32_t> instances;
    std::vector<uint32_t> stack = {bvh.top_root};
    while (!stack.empty()) {
        const BvhNode n = bvh.nodes[stack.back()];
        stack.pop_back();
        for (int c = 0; c < 2; ++c) {
            const uint32_t ref = c ? n.ref1 : n.ref0, count = c ? n.count1 : n.count0;
            if (ref == BVH_EMPTY) continue;
            if (count == 0) {
                stack.push_back(ref);
                continue;
            }
            REQUIRE(count == 1);
            instances.insert(ref);
            const Instance& inst = scene.instances[ref];
            const MeshInfo& m = scene.meshes[inst.mesh];
            for (uint32_t v = 0; v < m.vertex_count; ++v)
                REQUIRE(
                    contains(c ? n.lo1 : n.lo0, c ? n.hi1 : n.hi0,
                             instance_point_to_world(inst, scene.positions[m.first_vertex + v])));
        }
    }
    CHECK(instances.size() == scene.instances.size());
    CHECK(std::set<uint32_t>(instances.begin(), instances.end()).size() == instances.size());
    CHECK(bvh.top_depth + bvh.bottom_depth + 2 <= BVH_STACK_SIZE);
}

TEST_CASE("one-level BVH holds every instance's triangles once, in world space", "[gpu]") {
    // Built for a mask without instancing (what a scene without it renders with); bvh_scene()
    // has instancing, so this also checks that each instance gets its own copy.
    const FlatScene scene = bvh_scene();
    const BvhBuild bvh = build_bvh(scene, FEATURES_ALL & ~FEATURE_INSTANCING);
    CHECK(bvh.one_level);
    CHECK(bvh.mesh_roots.empty()); // no mesh trees, no top level
    CHECK(bvh.top_depth == 0);
    Walk w{bvh, scene, {}};
    w.bottom(bvh.top_root, NO_INDEX);
    std::multiset<std::pair<uint32_t, uint32_t>> expected;
    for (uint32_t i = 0; i < scene.instances.size(); ++i)
        for (uint32_t t = 0; t < scene.meshes[scene.instances[i].mesh].triangle_count; ++t)
            expected.insert({i, t});
    CHECK(w.items == expected);
    CHECK(bvh.triangles.size() == expected.size());
    CHECK(bvh.bottom_depth + 2 <= BVH_STACK_SIZE);
}

TEST_CASE("watertight triangle test: no ray slips between triangles sharing an edge", "[gpu]") {
    // A jittered grid of 16 x 16 quads, two triangles each, in a tilted plane; rays aimed at
    // the shared vertices and at points of the shared edges (computed in float, so they lie
    // on the edge up to rounding) must hit at least one triangle. A non-watertight test loses
    // a fraction of these (Woop et al. 2013, fig. 1).
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-0.3f, 0.3f);
    const int N = 16;
    std::vector<vec3> grid((N + 1) * (N + 1));
    const glm::mat3 tilt =
        glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(vec3(1, 2, 3))));
    for (int j = 0; j <= N; ++j)
        for (int i = 0; i <= N; ++i)
            grid[j * (N + 1) + i] = tilt * vec3(float(i) + u(rng), float(j) + u(rng), 0.0f) * 0.37f;
    std::vector<std::array<vec3, 3>> tris;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const vec3 a = grid[j * (N + 1) + i], b = grid[j * (N + 1) + i + 1];
            const vec3 c = grid[(j + 1) * (N + 1) + i], d = grid[(j + 1) * (N + 1) + i + 1];
            tris.push_back({a, b, d});
            tris.push_back({a, d, c});
        }
    const vec3 normal = tilt * vec3(0, 0, 1);
    int misses = 0, rays = 0;
    std::uniform_real_distribution<float> t01(0.0f, 1.0f);
    for (int j = 1; j < N; ++j)
        for (int i = 1; i < N; ++i) {
            const vec3 v = grid[j * (N + 1) + i];
            const vec3 nb[3] = {grid[j * (N + 1) + i + 1], grid[(j + 1) * (N + 1) + i],
                                grid[(j + 1) * (N + 1) + i + 1]};
            std::vector<vec3> targets = {v};
            for (const vec3& w : nb) targets.push_back(v + t01(rng) * (w - v));
            for (const vec3& target : targets) {
                const vec3 org =
                    target + 5.0f * glm::normalize(normal + 0.4f * vec3(u(rng), u(rng), u(rng)));
                const vec3 dir = glm::normalize(target - org);
                const WatertightRay wr = watertight_ray(dir);
                bool hit = false;
                for (const auto& t : tris) {
                    vec3 tuv;
                    hit = hit || intersect_triangle(org, wr, t[0], t[1], t[2], FLOAT_MAX, tuv);
                }
                misses += !hit;
                ++rays;
            }
        }
    INFO(misses << " of " << rays << " rays through shared vertices and edges missed");
    CHECK(misses == 0);
}

TEST_CASE("slab test never rejects a box the exact test accepts", "[gpu]") {
    // Rays grazing boxes: the exact (double) slab interval is compared with the float test;
    // the float test may accept a few extra boxes (conservative) but must never miss one.
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int missed = 0, exact_hits = 0;
    for (int i = 0; i < 200000; ++i) {
        vec3 lo(u(rng), u(rng), u(rng)),
            hi = lo + vec3(0.5f + u(rng), 0.5f + u(rng), 0.5f + u(rng));
        const vec3 org = 10.0f * vec3(u(rng), u(rng), u(rng));
        const vec3 corner = vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        vec3 dir = glm::normalize(corner + 1e-6f * vec3(u(rng), u(rng), u(rng)) - org);
        if (i % 5 == 0) dir[i % 3] = 0.0f;
        const glm::dvec3 o(org), d(dir);
        double tn = 0.0, tf = 1e300;
        for (int k = 0; k < 3; ++k) {
            if (d[k] == 0.0) {
                if (o[k] < double(lo[k]) || o[k] > double(hi[k])) tf = -1.0;
                continue;
            }
            const double a = (double(lo[k]) - o[k]) / d[k], b = (double(hi[k]) - o[k]) / d[k];
            tn = std::max(tn, std::min(a, b));
            tf = std::min(tf, std::max(a, b));
        }
        if (!(tn <= tf)) continue;
        ++exact_hits;
        float t_enter;
        missed += !intersect_aabb(org, ray_inverse_direction(dir), lo, hi, FLOAT_MAX, t_enter);
    }
    INFO(missed << " of " << exact_hits << " boxes the exact test accepts were rejected");
    CHECK(exact_hits > 10000);
    CHECK(missed == 0);
}
