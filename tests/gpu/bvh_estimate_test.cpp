// The per-ray work estimate of a compute-mode BVH (vulkan_rt/compute_mode/bvh_estimate.h) against a
// Monte Carlo count, and the `--bvh auto` choice that rests on it. The surface area heuristic's
// A(box) / A(root) is the probability that a uniformly distributed line meeting the root's box
// also meets a box inside it (Cauchy-Crofton: the measure of the lines meeting a convex body is
// proportional to its surface area), so the estimate's node visits, box evaluations and
// triangle tests are the mean numbers of inner nodes and leaf items whose boxes such a line
// meets, counted here over random lines with the slab test, independently of the estimator's
// walk. Host only: no device needed.
#include "scene/flatten.h"
#include "scene/load.h"
#include "shared/features.h"
#include "shared/intersect.h"
#include "support/test_paths.h"
#include "triangle_soup.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/compute_mode/bvh_estimate.h"

#include <catch2/catch.hpp>

#include <bitset>
#include <cmath>
#include <cstring>
#include <random>

namespace tp {
namespace {

struct Box {
    glm::dvec3 lo, hi;
};

struct Line {
    vec3 origin, dir;
};

bool meets(const Line& l, const Box& b) {
    const vec3 inv = ray_inverse_direction(l.dir);
    float t;
    return intersect_aabb(l.origin, inv, vec3(b.lo), vec3(b.hi), FLOAT_MAX, t);
}

// A line uniformly distributed among those meeting `box`: a uniform direction, and a point
// uniform on the plane through the box's centre normal to it, taken from a square that holds
// the box's shadow and kept when the line meets the box. The origin is set back along the
// line beyond the box so that the slab test (t >= 0) sees the whole of it.
Line random_line(std::mt19937& rng, const Box& box) {
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dvec3 c = 0.5 * (box.lo + box.hi);
    const double r = 0.5 * glm::length(box.hi - box.lo);
    for (;;) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        const glm::dvec3 e1 = glm::normalize(
            glm::cross(d, std::abs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
        const glm::dvec3 e2 = glm::cross(d, e1);
        const glm::dvec3 p = c + r * (u(rng) * e1 + u(rng) * e2) - 2.0 * r * d;
        const Line l{vec3(p), vec3(d)};
        if (meets(l, box)) return l;
    }
}

struct Node {
    Box box;
    bool inner;
    uint32_t ref, count;
};

// The children of a node of either layout, with the boxes the estimator and the traversal use.
std::vector<Node> children(const BvhBuild& bvh, uint32_t node) {
    std::vector<Node> out;
    if (bvh.layout == BvhLayout::binary) {
        const BvhNode& n = bvh.nodes[node];
        if (!(n.count0 == 0 && n.ref0 == BVH_EMPTY))
            out.push_back(
                {{glm::dvec3(n.lo0), glm::dvec3(n.hi0)}, n.count0 == 0, n.ref0, n.count0});
        if (!(n.count1 == 0 && n.ref1 == BVH_EMPTY))
            out.push_back(
                {{glm::dvec3(n.lo1), glm::dvec3(n.hi1)}, n.count1 == 0, n.ref1, n.count1});
        return out;
    }
    const WideBvhNode& n = bvh.wide_nodes[node];
    uint32_t inner = 0;
    for (uint32_t s = 0; s < 8; ++s) {
        if (n.meta[s] == 0) continue;
        Node c;
        wide_child_box(n, s, c.box.lo, c.box.hi);
        c.inner = (n.imask >> s) & 1u;
        c.ref = c.inner ? n.child_base + inner++ : 0;
        c.count = c.inner ? 0 : uint32_t(std::bitset<3>(n.meta[s] >> 5).count());
        out.push_back(c);
    }
    return out;
}

// Inner nodes and leaf items whose boxes the line meets, below `node` (met).
void count(const BvhBuild& bvh, uint32_t node, const Line& l, double& nodes, double& items) {
    nodes += 1;
    for (const Node& c : children(bvh, node)) {
        if (!meets(l, c.box)) continue;
        if (c.inner)
            count(bvh, c.ref, l, nodes, items);
        else
            items += c.count;
    }
}

FlatScene load(const std::string& name) {
    std::vector<std::string> warnings;
    return flatten(load_scene(name, warnings));
}

const uint32_t kOneLevel = FEATURES_ALL & ~FEATURE_INSTANCING;

} // namespace

TEST_CASE("BVH estimate: node visits and triangle tests are what random lines meet", "[wide_bvh]") {
    for (const char* name : {"cornell", "furnace"})
        for (BvhLayout layout : {BvhLayout::binary, BvhLayout::wide}) {
            const FlatScene scene = load(name);
            const BvhBuild bvh = build_bvh(scene, kOneLevel, layout);
            const BvhEstimate e = estimate_bvh_work(bvh, scene);
            Box root{glm::dvec3(std::numeric_limits<double>::max()),
                     glm::dvec3(-std::numeric_limits<double>::max())};
            for (const Node& c : children(bvh, bvh.top_root)) {
                root.lo = glm::min(root.lo, c.box.lo);
                root.hi = glm::max(root.hi, c.box.hi);
            }
            std::mt19937 rng(9);
            const int n = 20000;
            double nodes = 0, nodes2 = 0, items = 0, items2 = 0;
            for (int i = 0; i < n; ++i) {
                double a = 0, b = 0;
                count(bvh, bvh.top_root, random_line(rng, root), a, b);
                nodes += a;
                nodes2 += a * a;
                items += b;
                items2 += b * b;
            }
            nodes /= n;
            items /= n;
            // Five standard errors of the means: a wrong walk or a wrong area ratio misses by
            // far more (a box's probability off by its own size, a leaf counted twice).
            const double se_nodes = std::sqrt((nodes2 / n - nodes * nodes) / n);
            const double se_items = std::sqrt((items2 / n - items * items) / n);
            INFO(name << ' ' << bvh_layout_name(layout) << ": estimate " << describe(e)
                      << ", lines meet " << nodes << " nodes, " << items << " triangles");
            CHECK(std::abs(e.nodes - nodes) <= 5.0 * se_nodes + 1e-9);
            CHECK(std::abs(e.triangles - items) <= 5.0 * se_items + 1e-9);
            CHECK(e.boxes == Approx(e.nodes * (layout == BvhLayout::wide ? 8.0 : 2.0)));
            CHECK(e.instances == 0.0);
        }
}

TEST_CASE("bvh auto keeps the layout its rule prefers and says why", "[wide_bvh]") {
    // The bundled scenes' trees are shallow (binary); a soup of 20000 triangles in a cube is
    // deep enough for the wide layout.
    bool chose_wide = false;
    for (const char* name : {"cornell", "cornell_spheres", "furnace", "soup"}) {
        const FlatScene scene =
            std::string(name) == "soup" ? test::soup(6, 20000, 0.0, 10.0, 0.3, 1, 0) : load(name);
        for (uint32_t features : {FEATURES_ALL, kOneLevel}) {
            const BvhBuild binary = build_bvh(scene, features, BvhLayout::binary);
            const BvhBuild wide = build_bvh(scene, features, BvhLayout::wide);
            const BvhBuild chosen = build_bvh(scene, features, BvhLayout::automatic);
            const bool prefers_wide = binary.estimate.nodes >= kAutoWideMinBinaryNodes;
            INFO(name << ": binary " << describe(binary.estimate) << "; wide "
                      << describe(wide.estimate));
            CHECK(chosen.layout == (prefers_wide ? BvhLayout::wide : BvhLayout::binary));
            chose_wide = chose_wide || prefers_wide;
            CHECK(chosen.requested == BvhLayout::automatic);
            // The tree kept is the one the layout builds when asked for by name.
            const BvhBuild& same = prefers_wide ? wide : binary;
            CHECK(chosen.bytes() == same.bytes());
            CHECK(chosen.nodes.size() == same.nodes.size());
            CHECK(std::memcmp(chosen.nodes.data(), same.nodes.data(),
                              same.nodes.size() * sizeof(BvhNode)) == 0);
            CHECK(std::memcmp(chosen.wide_nodes.data(), same.wide_nodes.data(),
                              same.wide_nodes.size() * sizeof(WideBvhNode)) == 0);
            CHECK(chosen.wide_triangles.words() == same.wide_triangles.words());
            const auto stats = bvh_stats(chosen);
            CHECK(stats.at("bvh_layout") == bvh_layout_name(chosen.layout));
            CHECK(stats.at("bvh_requested") == "auto");
            CHECK(stats.at("bvh_estimate") == describe(chosen.estimate));
            CHECK(stats.at("bvh_estimate_binary") == describe(binary.estimate));
            CHECK(stats.count("bvh_build_stages") == 1);
        }
    }
    CHECK(chose_wide);
    CHECK(parse_bvh_layout("auto") == BvhLayout::automatic);
    CHECK(std::string(bvh_layout_name(BvhLayout::automatic)) == "auto");
}

} // namespace tp
