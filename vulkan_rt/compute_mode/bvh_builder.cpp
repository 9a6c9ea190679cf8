#include "vulkan_rt/compute_mode/bvh_builder.h"

#include "scene/world_vertex.h"
#include "shared/surface.h"
#include "util/clock.h"
#include "util/error.h"

#include "vulkan_rt/compute_mode/binary_writer.h"
#include "vulkan_rt/compute_mode/bvh_estimate.h"
#include "vulkan_rt/compute_mode/embree_tree.h"
#include "vulkan_rt/compute_mode/wide_collapse.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>

namespace tp {
namespace {

using Clock = std::chrono::steady_clock;

// A leaf item with its plane normal, which intersect_triangle_normal takes from the buffer
// (shared/intersect.h).
BvhTriangle leaf_triangle(vec3 v0, vec3 v1, vec3 v2, uint32_t primitive, uint32_t instance) {
    BvhTriangle t{};
    t.v0 = v0;
    t.v1 = v1;
    t.v2 = v2;
    t.primitive = primitive;
    t.instance = instance;
    t.normal = triangle_plane_normal(v0, v1, v2);
    return t;
}

// Sets leaf item `item` of the layout's triangle array.
void set_triangle(BvhBuild& out, uint32_t item, vec3 v0, vec3 v1, vec3 v2, uint32_t primitive,
                  uint32_t instance) {
    if (out.layout == BvhLayout::wide)
        out.wide_triangles.set_triangle(item, v0, v1, v2, primitive, instance);
    else
        out.triangles[item] = leaf_triangle(v0, v1, v2, primitive, instance);
}

RTCBuildPrimitive triangle_primitive(vec3 a, vec3 b, vec3 c, uint32_t id) {
    return make_primitive(glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)), id);
}

// Builds the trees of one BvhBuild in its layout, appending each to the layout's arrays: Embree's
// binary tree as it is, or, from a binary tree with leaves of one item, its SAH-optimal collapse
// into the compressed wide nodes (wide_collapse.h, wide_bvh.h). The leaf items' array is sized
// by the caller; the trees' items follow each other in it.
class Builder {
  public:
    explicit Builder(BvhBuild& out) : out_(out) {}

    // Appends a tree over `prims` and returns its root node index; `depth`: its levels. Leaves
    // hold up to `max_leaf` items (binary; wide: at most CWBVH_MAX_LEAF). `instances`: every
    // leaf holds one instance, which a binary node names itself (`write_leaf` is then called
    // only for the wide layout's records).
    uint32_t build(std::vector<RTCBuildPrimitive> prims, uint32_t max_leaf, uint32_t max_depth,
                   bool instances, uint32_t& depth, const LeafWriter& write_leaf) {
        const bool wide = out_.layout == BvhLayout::wide;
        auto t = Clock::now();
        TreeNode* top =
            prims.empty() ? nullptr : embree_.build(prims, wide ? 1 : max_leaf, max_depth);
        const RTCBounds all = bounds_of(prims);
        prims = {};
        out_.times.embree_s += seconds_since(t);
        t = Clock::now();
        uint32_t root = 0, items = 0;
        if (wide) {
            const WideCollapse c = collapse_to_wide(top, all, std::min(max_leaf, CWBVH_MAX_LEAF));
            out_.times.layout_s += seconds_since(t);
            t = Clock::now();
            root = uint32_t(out_.wide_nodes.size());
            out_.wide_nodes.resize(root + c.nodes);
            write_wide_tree(top, all, c, out_.wide_nodes.data(), root, next_item_, write_leaf);
            depth = c.depth;
            items = c.items;
        } else {
            const TreeSize size = size_binary_tree(top, !instances);
            out_.times.layout_s += seconds_since(t);
            t = Clock::now();
            root = uint32_t(out_.nodes.size());
            out_.nodes.resize(root + size.nodes);
            write_binary_tree(top, all, !instances, out_.nodes.data(), root, next_item_,
                              write_leaf);
            depth = size.depth;
            items = size.items;
        }
        out_.times.write_s += seconds_since(t);
        next_item_ += items;
        return root;
    }

  private:
    BvhBuild& out_;
    EmbreeTreeBuilder embree_;
    uint32_t next_item_ = 0;
};

// Binary leaves of at most 4 triangles: a leaf is then at most 192 contiguous bytes. The wide
// layout's leaves hold at most CWBVH_MAX_LEAF, as the collapse chooses.
constexpr uint32_t kMaxTrianglesPerLeaf = 4;
// Depth limits of Embree's binary trees that keep depth(top) + depth(bottom) + 2 within the
// binary traversal's stack (BVH_STACK_SIZE); Embree makes its last levels balanced when a
// branch approaches the limit. A wide tree has at most the levels of the binary tree it
// collapses, in practice a third; build_bvh checks it against CWBVH_STACK_SIZE.
constexpr uint32_t kMaxBottomDepth = 40;
constexpr uint32_t kMaxTopDepth = 22;
// Triangles of one task where a mesh's triangles or vertices are visited in parallel.
constexpr size_t kGrain = 4096;

// World box of an object box under an instance transform: the 8 corners transformed, padded by
// 2^-20 of the largest coordinate so that the float rounding of the transform (a few ulp)
// cannot make the box miss what the object-space test then hits.
void world_box(const Instance& inst, vec3 lo, vec3 hi, vec3& wlo, vec3& whi) {
    wlo = vec3(FLOAT_MAX);
    whi = vec3(-FLOAT_MAX);
    for (int i = 0; i < 8; ++i) {
        const vec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
        const vec3 w = instance_point_to_world(inst, p);
        wlo = glm::min(wlo, w);
        whi = glm::max(whi, w);
    }
    const vec3 m = glm::max(glm::abs(wlo), glm::abs(whi));
    const float pad = std::max(m.x, std::max(m.y, m.z)) * (1.0f / 1048576.0f);
    wlo -= vec3(pad);
    whi += vec3(pad);
}

// The tree over every instance's triangles in world space (one level): each leaf item carries
// its instance, since no instance marker leads to it. A triangle's primitive ID is its index in
// the instances' triangles one after another; the world vertices are computed once per vertex
// and the leaf items are written from them.
void build_one_level(const FlatScene& scene, Builder& builder, BvhBuild& out) {
    auto t = Clock::now();
    const size_t n = scene.instances.size();
    std::vector<uint32_t> first_triangle(n + 1, 0), first_vertex(n + 1, 0);
    for (size_t i = 0; i < n; ++i) {
        const MeshInfo& mesh = scene.meshes[scene.instances[i].mesh];
        first_triangle[i + 1] = first_triangle[i] + mesh.triangle_count;
        first_vertex[i + 1] = first_vertex[i] + mesh.vertex_count;
    }
    std::vector<vec3> world(first_vertex[n]);
    std::vector<RTCBuildPrimitive> prims(first_triangle[n]);
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
        const Instance& inst = scene.instances[i];
        const MeshInfo& mesh = scene.meshes[inst.mesh];
        vec3* v = &world[first_vertex[i]];
        tbb::parallel_for(tbb::blocked_range<uint32_t>(0, mesh.vertex_count, kGrain), [&](auto r) {
            for (uint32_t k = r.begin(); k != r.end(); ++k)
                v[k] = world_vertex(inst, scene.positions[mesh.first_vertex + k]);
        });
        tbb::parallel_for(
            tbb::blocked_range<uint32_t>(0, mesh.triangle_count, kGrain), [&](auto r) {
                for (uint32_t k = r.begin(); k != r.end(); ++k) {
                    const uvec3 tri = scene.triangles[mesh.first_triangle + k];
                    prims[first_triangle[i] + k] =
                        triangle_primitive(v[tri.x], v[tri.y], v[tri.z], first_triangle[i] + k);
                }
            });
    });
    if (out.layout == BvhLayout::wide)
        out.wide_triangles.resize(first_triangle[n]);
    else
        out.triangles.resize(first_triangle[n]);
    out.times.primitives_s += seconds_since(t);
    out.top_root = builder.build(
        std::move(prims), kMaxTrianglesPerLeaf, kMaxBottomDepth, false, out.bottom_depth,
        [&](const uint32_t* ids, uint32_t count, uint32_t first) {
            for (uint32_t k = 0; k < count; ++k) {
                const uint32_t i = uint32_t(
                    std::upper_bound(first_triangle.begin(), first_triangle.end(), ids[k]) -
                    first_triangle.begin() - 1);
                const uint32_t primitive = ids[k] - first_triangle[i];
                const MeshInfo& mesh = scene.meshes[scene.instances[i].mesh];
                const uvec3 tri = scene.triangles[mesh.first_triangle + primitive];
                const vec3* v = &world[first_vertex[i]];
                set_triangle(out, first + k, v[tri.x], v[tri.y], v[tri.z], primitive, i);
            }
        });
    out.one_level = true;
}

// One tree per mesh in object space and, behind them, the top tree over the instances' world
// boxes.
void build_two_level(const FlatScene& scene, Builder& builder, BvhBuild& out) {
    const bool wide = out.layout == BvhLayout::wide;
    size_t triangles = 0, instances = 0;
    for (const MeshInfo& mesh : scene.meshes) triangles += mesh.triangle_count;
    for (const Instance& inst : scene.instances)
        instances += scene.meshes[inst.mesh].triangle_count > 0 ? 1 : 0;
    // The wide layout's top-level items are records too, after the meshes' triangles.
    if (wide)
        out.wide_triangles.resize(uint32_t(triangles + instances));
    else
        out.triangles.resize(triangles);

    std::vector<RTCBounds> mesh_box(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const auto t = Clock::now();
        const MeshInfo& mesh = scene.meshes[m];
        const vec3* p = &scene.positions[mesh.first_vertex];
        const uvec3* tris = &scene.triangles[mesh.first_triangle];
        std::vector<RTCBuildPrimitive> prims(mesh.triangle_count);
        tbb::parallel_for(
            tbb::blocked_range<uint32_t>(0, mesh.triangle_count, kGrain), [&](auto r) {
                for (uint32_t k = r.begin(); k != r.end(); ++k)
                    prims[k] = triangle_primitive(p[tris[k].x], p[tris[k].y], p[tris[k].z], k);
            });
        mesh_box[m] = bounds_of(prims);
        out.times.primitives_s += seconds_since(t);
        uint32_t depth = 0;
        out.mesh_roots.push_back(builder.build(
            std::move(prims), kMaxTrianglesPerLeaf, kMaxBottomDepth, false, depth,
            [&](const uint32_t* ids, uint32_t count, uint32_t first) {
                for (uint32_t k = 0; k < count; ++k) {
                    const uvec3 tri = tris[ids[k]];
                    set_triangle(out, first + k, p[tri.x], p[tri.y], p[tri.z], ids[k], 0);
                }
            }));
        out.bottom_depth = std::max(out.bottom_depth, depth);
    }

    const auto t = Clock::now();
    std::vector<RTCBuildPrimitive> boxes;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (scene.meshes[inst.mesh].triangle_count == 0) continue;
        const RTCBounds& b = mesh_box[inst.mesh];
        vec3 lo, hi;
        world_box(inst, vec3(b.lower_x, b.lower_y, b.lower_z),
                  vec3(b.upper_x, b.upper_y, b.upper_z), lo, hi);
        boxes.push_back(make_primitive(lo, hi, i));
    }
    out.times.primitives_s += seconds_since(t);
    // One instance per leaf in both layouts, so that every instance is entered behind its own
    // box: a binary leaf names it directly (count 1), a wide leaf by a record (wide_bvh.h).
    out.top_root = builder.build(std::move(boxes), 1, kMaxTopDepth, true, out.top_depth,
                                 [&](const uint32_t* ids, uint32_t, uint32_t first) {
                                     out.wide_triangles.set_instance(first, ids[0]);
                                 });
}

// The trees of one layout, not yet checked against the traversal stack.
BvhBuild build_layout(const FlatScene& scene, uint32_t features, BvhLayout layout) {
    BvhBuild out;
    out.layout = layout;
    out.requested = layout;
    {
        Builder builder(out);
        if (feature_on(features, FEATURE_INSTANCING))
            build_two_level(scene, builder, out);
        else
            build_one_level(scene, builder, out);
    }
    auto t = Clock::now();
    if (layout == BvhLayout::wide) out.wide_triangles.finish(out.one_level);
    out.times.write_s += seconds_since(t);
    t = Clock::now();
    out.estimate = estimate_bvh_work(out, scene);
    out.times.estimate_s += seconds_since(t);
    return out;
}

bool fits_stack(const BvhBuild& b) {
    const uint32_t stack = b.layout == BvhLayout::wide ? CWBVH_STACK_SIZE : BVH_STACK_SIZE;
    return b.top_depth + b.bottom_depth + 2 <= stack;
}

BvhBuild checked(BvhBuild b) {
    if (!fits_stack(b))
        input_error("the scene's BVH is too deep for the GPU traversal stack ({} + {} levels)",
                    b.top_depth, b.bottom_depth);
    return b;
}

void add_times(BvhBuildTimes& to, const BvhBuildTimes& t) {
    to.primitives_s += t.primitives_s;
    to.embree_s += t.embree_s;
    to.layout_s += t.layout_s;
    to.write_s += t.write_s;
    to.estimate_s += t.estimate_s;
}

} // namespace

BvhBuild build_bvh(const FlatScene& scene, uint32_t features, BvhLayout layout) {
    if (layout != BvhLayout::automatic) return checked(build_layout(scene, features, layout));
    // The rule reads the binary tree alone (auto_prefers_wide): the wide tree is built only when
    // it is chosen, after the binary one is released, so that the host holds one layout at once.
    BvhBuild binary = build_layout(scene, features, BvhLayout::binary);
    binary.requested = BvhLayout::automatic;
    binary.binary_estimate = binary.estimate;
    const bool binary_fits = fits_stack(binary);
    if (binary_fits && !auto_prefers_wide(binary.estimate)) return binary;
    const BvhEstimate binary_estimate = binary.estimate;
    const BvhBuildTimes times = binary.times;
    binary = BvhBuild{};
    BvhBuild pick = build_layout(scene, features, BvhLayout::wide);
    if (!fits_stack(pick) && binary_fits) pick = build_layout(scene, features, BvhLayout::binary);
    pick.requested = BvhLayout::automatic;
    pick.binary_estimate = binary_estimate;
    add_times(pick.times, times);
    return checked(std::move(pick));
}

std::map<std::string, std::string> bvh_stats(const BvhBuild& bvh) {
    std::map<std::string, std::string> s;
    s["bvh_layout"] = bvh_layout_name(bvh.layout);
    s["bvh_requested"] = bvh_layout_name(bvh.requested);
    s["bvh_levels"] = bvh.one_level ? "1" : "2";
    s["bvh_estimate"] = describe(bvh.estimate);
    if (bvh.requested == BvhLayout::automatic)
        s["bvh_estimate_binary"] = describe(bvh.binary_estimate);
    const BvhBuildTimes& t = bvh.times;
    s["bvh_build_stages"] =
        fmt::format("primitives {:.4f} embree {:.4f} layout {:.4f} write {:.4f} estimate {:.4f}",
                    t.primitives_s, t.embree_s, t.layout_s, t.write_s, t.estimate_s);
    return s;
}

BvhLayout parse_bvh_layout(const std::string& name) {
    if (name == "binary") return BvhLayout::binary;
    if (name == "wide") return BvhLayout::wide;
    if (name == "auto") return BvhLayout::automatic;
    input_error("unknown BVH layout '{}' (expected binary, wide or auto)", name);
}

const char* bvh_layout_name(BvhLayout layout) {
    switch (layout) {
    case BvhLayout::wide:
        return "wide";
    case BvhLayout::automatic:
        return "auto";
    default:
        return "binary";
    }
}

} // namespace tp
