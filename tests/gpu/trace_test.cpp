// The compute mode's ray queries (vulkan_rt/renderer/gpu_ray_queries.h: the BVH built by
// vulkan_rt/compute_mode/bvh_builder.cpp, traversed by shaders/trace_bvh.glsl, or in the compressed
// 8-wide layout by shaders/trace_cwbvh.glsl) against Embree's on the same scenes: every bundled
// scene and a generated one with hundreds of instances, each in both layouts and with both shapes
// of the BVH: two levels (the all-features shader) and one level (the shader specialized to a mask
// without instancing, which the builder then gives one world-space tree). Closest hit
// (instance, primitive, distance, barycentrics) and occlusion must agree for random rays. Rays
// that meet two surfaces at the same distance (coplanar faces, a shared edge) may name either:
// such a tie passes when the GPU's triangle lies at Embree's distance along the ray. Up to 0.1 %
// may differ otherwise: float rounding decides grazing rays, and a tie of the two-level shader
// is re-tested in world space, not in the object space where it was found. A hit that named the
// wrong instance or primitive, or gave the wrong vertex its weight, would fail on every ray.
#include "gpu_harness.h"

#include "cpu_ref/embree_accel.h"
#include "cpu_ref/ray_queries.h"
#include "scene/flatten.h"
#include "scene/generators.h"
#include "scene/load.h"
#include "scene/world_vertex.h"
#include "shared/features.h"
#include "shared/intersect.h"
#include "shared/surface.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/renderer/gpu_ray_queries.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <random>

namespace tp::test {
namespace {

// Two hundred instances of an icosphere and a box under random similarity transforms.
FlatScene instanced_scene() {
    Scene s;
    s.path = "generated: 200 instances";
    Material m = default_material();
    m.kd = vec3(0.5f);
    s.materials = {m};
    s.material_names = {"grey"};
    s.meshes = {make_icosphere(2, false), make_box()};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 200; ++i) {
        Object o;
        o.name = fmt::format("object {}", i);
        o.mesh = uint32_t(i % 4 == 0);
        glm::mat4 t = glm::translate(glm::mat4(1.0f),
                                     vec3(20 * u(rng) - 10, 20 * u(rng) - 10, 20 * u(rng) - 10));
        t = glm::rotate(t, 6.28f * u(rng), glm::normalize(vec3(u(rng), u(rng), u(rng)) + 0.1f));
        o.transform = glm::scale(t, vec3(0.2f + u(rng)));
        s.objects.push_back(o);
    }
    s.camera.given = true;
    s.camera.eye = vec3(0, 0, 30);
    s.settings.width = s.settings.height = 8;
    return flatten(s);
}

// A sphere of 81,920 triangles among 32,768 small quads, each its own mesh: with one level the
// wide layout's hits name primitives of 17 bits and instances of 16, which do not share one
// 32-bit ID (wide_bvh.h), so its ID table holds pairs.
FlatScene many_objects_scene() {
    Scene s;
    s.path = "generated: a sphere among 32768 quads";
    s.materials = {default_material()};
    s.material_names = {"grey"};
    s.meshes.push_back(make_icosphere(6, false));
    s.objects.push_back(Object{});
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 32768; ++i) {
        s.meshes.push_back(make_quad());
        Object o;
        o.name = fmt::format("quad {}", i);
        o.mesh = uint32_t(s.meshes.size() - 1);
        glm::mat4 t = glm::translate(glm::mat4(1.0f), vec3(10 * u(rng), 10 * u(rng), 10 * u(rng)));
        t = glm::rotate(t, 3.14f * u(rng), glm::normalize(vec3(u(rng), u(rng), u(rng)) + 0.1f));
        o.transform = glm::scale(t, vec3(0.4f));
        s.objects.push_back(o);
    }
    s.camera.given = true;
    s.camera.eye = vec3(0, 0, 30);
    s.settings.width = s.settings.height = 8;
    return flatten(s);
}

FlatScene bundled(const char* name) {
    std::vector<std::string> warnings;
    return flatten(load_scene(name, warnings));
}

std::vector<Ray> random_rays(const FlatScene& scene, size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<double> g;
    const vec3 lo = scene.bounds_min, hi = scene.bounds_max, pad = 0.1f * (hi - lo);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.origin = lo - pad + (hi - lo + 2.0f * pad) * vec3(u(rng), u(rng), u(rng));
        r.dir = vec3(glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))));
        // Half the rays unbounded, half ending somewhere inside the scene (shadow rays).
        r.tmax = u(rng) < 0.5f ? FLOAT_MAX : u(rng) * glm::length(hi - lo);
        r.tag = 0;
    }
    return rays;
}

// Two hits tie when their distances agree to 1e-6 (max|origin| + t) (~17 ulp of the coordinates
// involved): coplanar surfaces (the cubes standing on cornell_glossy's floor) meet the ray at the
// same t to the rounding of their planes, and the two triangles of a shared edge at one point
// to a few ulp. Both round at the size of the origin and the hit point, not of t: rays starting
// near the floor met it at t ~ 1e-3 with the engines 2e-8 apart (2.5e-5 t), ties all the same.
const double kTieDistance = 1e-6;

// The hit point's error, in units of max|origin| + t: ~170 ulp. The object-space ray M^-1 o of
// an instance adds a few ulp of |M^-1| |o|, which the scaled instances of these scenes (x0.045
// to x4) magnify.
const double kHitPointError = 1e-5;

double tie_scale(const Ray& ray, float t) {
    const vec3 o = glm::abs(ray.origin);
    return double(std::max(o.x, std::max(o.y, o.z))) + double(t);
}

// Whether the ray meets the triangle `primitive` of `instance`, placed in world space as the
// one-level structures place it (scene/world_vertex.h), at distance t.
bool meets_at(const FlatScene& scene, const Ray& ray, uint32_t instance, uint32_t primitive,
              float t) {
    if (instance >= scene.instances.size()) return false;
    const Instance& inst = scene.instances[instance];
    const MeshInfo& m = scene.meshes[inst.mesh];
    if (primitive >= m.triangle_count) return false;
    const uvec3 tri = scene.triangles[m.first_triangle + primitive];
    const auto place = [&](uint32_t v) {
        return world_vertex(inst, scene.positions[m.first_vertex + v]);
    };
    vec3 tuv;
    return intersect_triangle(ray.origin, watertight_ray(ray.dir), place(tri.x), place(tri.y),
                              place(tri.z), FLOAT_MAX, tuv) &&
           std::abs(double(tuv.x) - double(t)) <= kTieDistance * tie_scale(ray, t);
}

// `features`: the mask the trace shader is specialized to, and so the shape of the BVH.
void compare_with_embree(const FlatScene& scene, uint32_t features, BvhLayout layout) {
    const BvhBuild bvh = build_bvh(scene, features, layout);
    REQUIRE(bvh.one_level == !feature_on(features, FEATURE_INSTANCING));
    const std::vector<Ray> rays = random_rays(scene, 20000, 11);
    const ClosestHits gpu = closest_hits_compute(gpu_context(), scene, rays, layout, features);

    // Embree with the same alpha test (a scene with alpha MASK or BLEND: gltf_materials).
    const ClosestHits cpu = closest_hits_cpu(scene, rays, features);
    size_t hits = 0, hit_mismatch = 0, ties = 0, occl_mismatch = 0, bary_mismatch = 0;
    double worst_t = 0.0, worst_bary = 0.0;
    for (size_t i = 0; i < rays.size(); ++i) {
        Hit h;
        h.found = cpu.found[i] != 0;
        h.t = cpu.t[i];
        h.instance = cpu.instance[i];
        h.primitive = cpu.primitive[i];
        h.bary = cpu.bary[i];
        hits += h.found;
        occl_mismatch += (cpu.occluded[i] != 0) != (gpu.occluded[i] != 0);
        if (h.found != (gpu.found[i] != 0)) {
            ++hit_mismatch;
            continue;
        }
        if (!h.found) continue;
        const double dt = std::abs(double(gpu.t[i]) - double(h.t));
        if (gpu.instance[i] != h.instance || gpu.primitive[i] != h.primitive) {
            // A tie (coplanar surfaces, a shared edge): the distance must still agree, and the
            // triangle the GPU names must be there.
            ++ties;
            if (dt > kTieDistance * tie_scale(rays[i], h.t) ||
                !meets_at(scene, rays[i], gpu.instance[i], gpu.primitive[i], h.t))
                ++hit_mismatch;
            continue;
        }
        // Both engines find the hit point to within a few ulp of the coordinates involved
        // (origin and hit point); along the ray that is an error in t of that over
        // cos(incidence), so the error is measured in units of max|origin| + t after
        // multiplying by the cosine.
        const Instance& inst = scene.instances[h.instance];
        const MeshInfo& m = scene.meshes[inst.mesh];
        const uvec3 tri = scene.triangles[m.first_triangle + h.primitive];
        const vec3 a = scene.positions[m.first_vertex + tri.x];
        const vec3 b = scene.positions[m.first_vertex + tri.y];
        const vec3 c = scene.positions[m.first_vertex + tri.z];
        const vec3 ng = glm::normalize(instance_normal_to_world(inst, glm::cross(b - a, c - a)));
        const double cos_i = std::abs(double(glm::dot(ng, rays[i].dir)));
        worst_t = std::max(worst_t, dt * cos_i / tie_scale(rays[i], h.t));
        // The barycentrics place the hit point on the triangle: a difference (du, dv) moves it
        // by du (B - A) + dv (C - A) in world space, measured in the units of t's error and
        // held to the same bound. Weights given to the wrong vertices move it by a fraction of
        // the triangle's size on almost every ray.
        const glm::dvec3 wa = world_vertex(inst, a), wb = world_vertex(inst, b),
                         wc = world_vertex(inst, c);
        const glm::dvec2 db = glm::dvec2(gpu.bary[i]) - glm::dvec2(h.bary);
        const double moved =
            glm::length(db.x * (wb - wa) + db.y * (wc - wa)) / tie_scale(rays[i], h.t);
        worst_bary = std::max(worst_bary, moved);
        bary_mismatch += moved >= kHitPointError;
    }
    const size_t allowed = rays.size() / 1000;
    INFO(scene.name << ": " << hits << " of " << rays.size() << " rays hit; hit mismatches "
                    << hit_mismatch << ", primitive ties " << ties << ", occlusion mismatches "
                    << occl_mismatch << ", worst t error x cos(incidence) / (max|origin| + t) "
                    << worst_t << ", worst hit point moved by the barycentrics / (max|origin| + t) "
                    << worst_bary << " (" << bary_mismatch << " rays above the bound, "
                    << gpu.truncated << " traversals cut by the loop budget), BVH "
                    << bvh_layout_name(layout) << ", "
                    << (bvh.one_level ? "one level, " : "two levels, ")
                    << bvh.nodes.size() + bvh.wide_nodes.size() << " nodes, depth " << bvh.top_depth
                    << " + " << bvh.bottom_depth);
    CHECK(hits > rays.size() / 10);
    CHECK(hit_mismatch <= allowed);
    CHECK(occl_mismatch <= allowed);
    CHECK(gpu.truncated == 0);
    CHECK(worst_t < kHitPointError);
    CHECK(bary_mismatch <= allowed);
    CHECK(validation_messages() == 0);
}

// The two shapes: two levels (every feature) and one level (no instancing).
const uint32_t kTwoLevels = FEATURES_ALL;
const uint32_t kOneLevel = FEATURES_ALL & ~FEATURE_INSTANCING;

} // namespace

TEST_CASE("GPU BVH traversal agrees with Embree on the bundled scenes", "[gpu]") {
    for (const char* name :
         {"cornell", "cornell_glossy", "cornell_spheres", "spheres", "furnace", "gltf_materials"})
        for (BvhLayout layout : {BvhLayout::binary, BvhLayout::wide}) {
            const std::string label = std::string(name) + ", " + bvh_layout_name(layout);
            SECTION(label + ", two levels") {
                compare_with_embree(bundled(name), kTwoLevels, layout);
            }
            SECTION(label + ", one level") {
                compare_with_embree(bundled(name), kOneLevel, layout);
            }
        }
}

TEST_CASE("GPU BVH traversal agrees with Embree with hundreds of instances", "[gpu]") {
    for (BvhLayout layout : {BvhLayout::binary, BvhLayout::wide}) {
        SECTION(std::string(bvh_layout_name(layout)) + ", two levels") {
            compare_with_embree(instanced_scene(), kTwoLevels, layout);
        }
        SECTION(std::string(bvh_layout_name(layout)) + ", one level") {
            compare_with_embree(instanced_scene(), kOneLevel, layout);
        }
    }
}

TEST_CASE("GPU wide BVH traversal agrees with Embree where its IDs do not fit 32 bits", "[gpu]") {
    const FlatScene scene = many_objects_scene();
    REQUIRE(build_bvh(scene, kOneLevel, BvhLayout::wide).wide_triangles.words()[0].y ==
            CWBVH_ID_PAIRS);
    compare_with_embree(scene, kOneLevel, BvhLayout::wide);
}

} // namespace tp::test
