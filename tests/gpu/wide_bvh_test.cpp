// The compressed 8-wide BVH (vulkan_rt/compute_mode/wide_bvh.h) as the host builds it, checked node
// by node against the triangles it holds: every slot's decoded box p + 2^(e - 127) q, in exact
// arithmetic, contains the exact bounds of everything below that slot (the quantization must
// round outward: a box that cut off a sliver of a triangle would lose hits), every triangle is
// reached exactly once, its record holds the binary layout's floats for the primitive and
// instance its IDs name, top-level leaves hold one instance each, and the meta bytes, imask and
// child indices follow the format of shaders/cwbvh.h. Over the bundled scenes, the bunny and the
// Buddha, and random triangle soups with degenerate, tiny-far-away and range-rule-sized triangles.
// Host only: no device needed.
#include "scene/flatten.h"
#include "scene/load.h"
#include "scene/world_vertex.h"
#include "shared/features.h"
#include "shared/surface.h"
#include "support/test_paths.h"
#include "triangle_soup.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <random>
#include <set>

namespace tp {
namespace {

struct Box {
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
    void add(glm::dvec3 p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void add(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
};

// Walks one tree, checking each node against its content; returns the exact bounds of the
// node's content and collects the triangle-array items reached.
class Walk {
  public:
    Walk(const BvhBuild& bvh, const FlatScene& scene) : bvh_(bvh), scene_(scene) {}

    // `top`: the node is in the top tree of two levels, whose items are instance records.
    Box node(uint32_t index, bool top, uint32_t level) {
        REQUIRE(index < bvh_.wide_nodes.size());
        depth = std::max(depth, level);
        ++nodes;
        const WideBvhNode& n = bvh_.wide_nodes[index];
        Box all;
        uint32_t inner_seen = 0, offset = 0;
        for (uint32_t s = 0; s < 8; ++s) {
            const uint8_t m = n.meta[s];
            const bool inner = (n.imask >> s) & 1u;
            if (m == 0) {
                REQUIRE_FALSE(inner);
                continue;
            }
            Box content;
            if (inner) {
                REQUIRE(m == (CWBVH_META_INNER | s));
                content = node(n.child_base + inner_seen++, top, level + 1);
            } else {
                const uint32_t o = m & 0x1fu, bits = m >> 5;
                REQUIRE((bits == 1 || bits == 3 || bits == 7));
                const uint32_t count = bits == 1 ? 1 : bits == 3 ? 2 : 3;
                // One instance per top-level leaf: each is entered behind its own box.
                if (top) REQUIRE(count == 1);
                // Leaves of one node are stored back to back in slot order and fit 24 bits.
                REQUIRE(o == offset);
                offset += count;
                REQUIRE(offset <= 24);
                for (uint32_t k = 0; k < count; ++k)
                    content.add(item(n.triangle_base + o + k, top));
            }
            glm::dvec3 lo, hi;
            wide_child_box(n, s, lo, hi);
            INFO("node " << index << " slot " << s << ": decoded [" << lo.x << ' ' << lo.y << ' '
                         << lo.z << "] .. [" << hi.x << ' ' << hi.y << ' ' << hi.z << "], content ["
                         << content.lo.x << ' ' << content.lo.y << ' ' << content.lo.z << "] .. ["
                         << content.hi.x << ' ' << content.hi.y << ' ' << content.hi.z << "]");
            REQUIRE(glm::all(glm::lessThanEqual(lo, content.lo)));
            REQUIRE(glm::all(glm::greaterThanEqual(hi, content.hi)));
            all.add(content);
        }
        return all;
    }

    std::multiset<uint32_t> items; // triangle-array indices reached
    std::multiset<uint32_t> instances;
    uint32_t depth = 0, nodes = 0;

  private:
    Box item(uint32_t i, bool top) {
        REQUIRE(i < bvh_.wide_triangles.records());
        Box b;
        if (!top) {
            items.insert(i);
            const WideTriangle t = bvh_.wide_triangles.triangle(i);
            check_record(i, t);
            b.add(t.v0);
            b.add(t.v1);
            b.add(t.v2);
            return b;
        }
        // An instance record: the box must hold the instance's world-space vertices.
        const uint32_t instance = bvh_.wide_triangles.instance_item(i);
        REQUIRE(instance < scene_.instances.size());
        instances.insert(instance);
        const Instance& inst = scene_.instances[instance];
        const MeshInfo& m = scene_.meshes[inst.mesh];
        for (uint32_t v = 0; v < m.vertex_count; ++v)
            b.add(instance_point_to_world(inst, scene_.positions[m.first_vertex + v]));
        return b;
    }

    // The record holds, bit for bit, the vertices and plane normal of the binary layout's
    // BvhTriangle for the primitive (and instance) its IDs name: object-space vertices with
    // two levels, world_vertex's with one.
    void check_record(uint32_t i, const WideTriangle& t) {
        const uint32_t primitive = bvh_.wide_triangles.primitive(i);
        const uint32_t instance = bvh_.one_level ? bvh_.wide_triangles.instance(i) : 0;
        REQUIRE(instance < scene_.instances.size());
        const Instance& inst = scene_.instances[instance];
        const MeshInfo& m = scene_.meshes[bvh_.one_level ? inst.mesh : mesh_];
        REQUIRE(primitive < m.triangle_count);
        const uvec3 tri = scene_.triangles[m.first_triangle + primitive];
        auto place = [&](uint32_t v) {
            const vec3 p = scene_.positions[m.first_vertex + v];
            return bvh_.one_level ? world_vertex(inst, p) : p;
        };
        const vec3 v0 = place(tri.x), v1 = place(tri.y), v2 = place(tri.z);
        const vec3 n = triangle_plane_normal(v0, v1, v2);
        CHECK(same_bits(t.v0, v0));
        CHECK(same_bits(t.v1, v1));
        CHECK(same_bits(t.v2, v2));
        CHECK(same_bits(t.normal, n));
        if (bvh_.one_level) one_level_items.insert({instance, primitive});
    }

    static bool same_bits(vec3 a, vec3 b) { return std::memcmp(&a, &b, sizeof(vec3)) == 0; }

  public:
    uint32_t mesh_ = 0;                                      // two levels: the mesh walked
    std::set<std::pair<uint32_t, uint32_t>> one_level_items; // (instance, primitive)

  private:
    const BvhBuild& bvh_;
    const FlatScene& scene_;
};

// Both shapes of the wide BVH of `scene` pass the walk; the one-level tree holds every
// instance's triangles once, the two-level trees every mesh's once and the top every instance
// (with triangles) once.
void check_wide(const FlatScene& scene) {
    INFO(scene.name);
    {
        const BvhBuild bvh = build_bvh(scene, FEATURES_ALL & ~FEATURE_INSTANCING, BvhLayout::wide);
        REQUIRE(bvh.nodes.empty());
        REQUIRE(bvh.triangles.empty());
        Walk w(bvh, scene);
        w.node(bvh.top_root, false, 1);
        size_t triangles = 0;
        for (const Instance& inst : scene.instances)
            triangles += scene.meshes[inst.mesh].triangle_count;
        CHECK(w.items.size() == triangles);
        CHECK(std::set<uint32_t>(w.items.begin(), w.items.end()).size() == triangles);
        CHECK(w.one_level_items.size() == triangles);
        CHECK(bvh.wide_triangles.records() == triangles);
        CHECK(w.nodes == bvh.wide_nodes.size());
        CHECK(w.depth == bvh.bottom_depth);
        CHECK(bvh.bottom_depth + 2 <= CWBVH_STACK_SIZE);
    }
    const BvhBuild bvh = build_bvh(scene, FEATURES_ALL, BvhLayout::wide);
    Walk w(bvh, scene);
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        w.mesh_ = m;
        w.node(bvh.mesh_roots[m], false, 1);
    }
    size_t stored = 0, with_triangles = 0;
    for (const MeshInfo& m : scene.meshes) stored += m.triangle_count;
    for (const Instance& inst : scene.instances)
        with_triangles += scene.meshes[inst.mesh].triangle_count > 0;
    CHECK(w.items.size() == stored);
    CHECK(std::set<uint32_t>(w.items.begin(), w.items.end()).size() == stored);
    Walk top(bvh, scene);
    top.node(bvh.top_root, true, 1);
    CHECK(top.instances.size() == with_triangles);
    CHECK(std::set<uint32_t>(top.instances.begin(), top.instances.end()).size() == with_triangles);
    CHECK(bvh.wide_triangles.records() == stored + with_triangles);
    CHECK(w.nodes + top.nodes == bvh.wide_nodes.size());
    CHECK(bvh.top_depth + bvh.bottom_depth + 2 <= CWBVH_STACK_SIZE);
}

FlatScene load(const std::string& path) {
    std::vector<std::string> warnings;
    return flatten(load_scene(path, warnings));
}

} // namespace

TEST_CASE("wide BVH: decoded boxes contain their content on the bundled scenes", "[wide_bvh]") {
    for (const auto& entry : std::filesystem::directory_iterator(test::scenes_dir()))
        if (entry.path().extension() == ".json") check_wide(load(entry.path().string()));
}

TEST_CASE("wide BVH: decoded boxes contain their content on the bunny and the Buddha",
          "[wide_bvh]") {
    const std::string dir = test::assets_dir();
    for (const char* file : {"bunny/stanford-bunny.obj", "buddha/happy_buddha_112k.obj"}) {
        const std::string path = dir + "/" + file;
        if (!std::filesystem::exists(path)) {
            WARN("skipped: " << path << " is missing (../shared/assets)");
            continue;
        }
        check_wide(load(path));
    }
}

TEST_CASE("wide BVH: decoded boxes contain their content on random soups", "[wide_bvh]") {
    // Ordinary triangles; every 7th one degenerate.
    check_wide(test::soup(1, 3000, 0.0, 10.0, 0.5, 3, 7));
    // Triangles far smaller than the ulp of their coordinates' distance from the origin
    // (1e-4 at 1e6, where floats are 0.0625 apart): boxes narrower than one step of any scale.
    check_wide(test::soup(2, 2000, 1e6, 1.0, 1e-4, 2, 5));
    // Coordinates up to the range rule's 2^36 (scene/flatten.h): a mesh just under 2^36 wide,
    // stored relative to its lowest corner; mixed sizes, many degenerate.
    check_wide(test::soup(3, 2000, 0.0, 0x1p35 - 0x1p29, 0x1p29, 1, 3));
    // All triangles degenerate, half of them single points.
    check_wide(test::soup(4, 500, -3.0, 2.0, 1.0, 1, 1));
    // A few triangles: a tree that is one leaf.
    check_wide(test::soup(5, 2, 0.0, 1.0, 1.0, 1, 0));
}

} // namespace tp
