#include "vulkan_rt/compute_mode/bvh_builder.h"

#include "scene/world_vertex.h"
#include "shared/surface.h"
#include "util/error.h"

#include "vulkan_rt/compute_mode/bvh_estimate.h"
#include "vulkan_rt/compute_mode/embree_tree.h"
#include "vulkan_rt/compute_mode/wide_collapse.h"

#include <algorithm>

namespace tp {
namespace {

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

BvhNode empty_node() {
    BvhNode n{};
    n.ref0 = BVH_EMPTY;
    n.ref1 = BVH_EMPTY;
    return n;
}

// Copies Embree's binary trees into the node layout of shared/intersect.h.
class BinaryWriter {
  public:
    explicit BinaryWriter(std::vector<BvhNode>& nodes) : nodes_(&nodes) {}

    // Appends the tree and returns its root node index and depth. A tree of one leaf gets a
    // root node with that leaf and an absent second child; an empty one (root null), a root
    // with no children.
    uint32_t write(const TreeNode* top, const RTCBounds& all, const LeafEmitter& emit_leaf,
                   uint32_t& depth) {
        depth = 1;
        const uint32_t root = uint32_t(nodes_->size());
        nodes_->push_back(empty_node());
        if (!top) return root;
        if (top->count > 0) {
            set_child(root, 0, all, static_cast<const TreeLeaf*>(top), emit_leaf, depth, 1);
        } else {
            flatten_inner(root, static_cast<const TreeInner*>(top), emit_leaf, depth, 1);
        }
        return root;
    }

  private:
    void flatten_inner(uint32_t index, const TreeInner* n, const LeafEmitter& emit_leaf,
                       uint32_t& depth, uint32_t level) {
        depth = std::max(depth, level);
        for (uint32_t c = 0; c < n->children; ++c) {
            if (n->child[c]->count > 0) {
                set_child(index, int(c), n->bounds[c], static_cast<const TreeLeaf*>(n->child[c]),
                          emit_leaf, depth, level);
            } else {
                const uint32_t child = uint32_t(nodes_->size());
                nodes_->push_back(empty_node());
                flatten_inner(child, static_cast<const TreeInner*>(n->child[c]), emit_leaf, depth,
                              level + 1);
                write_child(index, int(c), n->bounds[c], child, 0);
            }
        }
    }

    void set_child(uint32_t index, int c, const RTCBounds& b, const TreeLeaf* leaf,
                   const LeafEmitter& emit_leaf, uint32_t& depth, uint32_t level) {
        depth = std::max(depth, level);
        write_child(index, c, b, emit_leaf(leaf->items, leaf->count), leaf->count);
    }

    void write_child(uint32_t index, int c, const RTCBounds& b, uint32_t ref, uint32_t count) {
        BvhNode& n = (*nodes_)[index];
        const vec3 lo(b.lower_x, b.lower_y, b.lower_z), hi(b.upper_x, b.upper_y, b.upper_z);
        if (c == 0) {
            n.lo0 = lo;
            n.hi0 = hi;
            n.ref0 = ref;
            n.count0 = count;
        } else {
            n.lo1 = lo;
            n.hi1 = hi;
            n.ref1 = ref;
            n.count1 = count;
        }
    }

    std::vector<BvhNode>* nodes_;
};

// Builds the trees of one BvhBuild in its layout: Embree's binary tree as it is, or, from a
// binary tree with leaves of one item, its SAH-optimal collapse into the compressed wide nodes
// (wide_collapse.h, wide_bvh.h).
class Builder {
  public:
    explicit Builder(BvhBuild& out) : out_(out) {}

    // Appends a tree over `prims` in the chosen layout; returns its root node index and depth.
    // Leaves hold up to `max_leaf` items (binary; wide: at most CWBVH_MAX_LEAF).
    uint32_t build(std::vector<RTCBuildPrimitive> prims, uint32_t max_leaf, uint32_t max_depth,
                   uint32_t& depth, const LeafEmitter& emit_leaf) {
        const bool wide = out_.layout == BvhLayout::wide;
        const TreeNode* top =
            prims.empty() ? nullptr : embree_.build(prims, wide ? 1 : max_leaf, max_depth);
        const RTCBounds all = bounds_of(prims);
        if (wide)
            return write_wide_tree(out_.wide_nodes,
                                   collapse_to_wide(top, all, std::min(max_leaf, CWBVH_MAX_LEAF)),
                                   emit_leaf, depth);
        return BinaryWriter(out_.nodes).write(top, all, emit_leaf, depth);
    }

  private:
    BvhBuild& out_;
    EmbreeTreeBuilder embree_;
};

// Appends a leaf triangle to the layout's triangle array and returns its index there.
uint32_t add_triangle(BvhBuild& out, const BvhTriangle& t) {
    if (out.layout == BvhLayout::wide)
        return out.wide_triangles.add_triangle(t.v0, t.v1, t.v2, t.primitive, t.instance);
    out.triangles.push_back(t);
    return uint32_t(out.triangles.size() - 1);
}

// Binary leaves of at most 4 triangles: a leaf is then at most 192 contiguous bytes. The wide
// layout's leaves hold at most CWBVH_MAX_LEAF, as the collapse chooses.
constexpr uint32_t kMaxTrianglesPerLeaf = 4;
// Depth limits of Embree's binary trees that keep depth(top) + depth(bottom) + 2 within the
// binary traversal's stack (BVH_STACK_SIZE); Embree makes its last levels balanced when a
// branch approaches the limit. A wide tree has at most the levels of the binary tree it
// collapses, in practice a third; build_bvh checks it against CWBVH_STACK_SIZE.
constexpr uint32_t kMaxBottomDepth = 40;
constexpr uint32_t kMaxTopDepth = 22;

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
// its instance, since no instance marker leads to it.
void build_one_level(const FlatScene& scene, Builder& builder, BvhBuild& out) {
    size_t count = 0;
    for (const Instance& inst : scene.instances) count += scene.meshes[inst.mesh].triangle_count;
    std::vector<BvhTriangle> world;
    std::vector<RTCBuildPrimitive> prims;
    world.reserve(count);
    prims.reserve(count);
    std::vector<vec3> v;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        const MeshInfo& mesh = scene.meshes[inst.mesh];
        v.resize(mesh.vertex_count);
        for (uint32_t k = 0; k < mesh.vertex_count; ++k)
            v[k] = world_vertex(inst, scene.positions[mesh.first_vertex + k]);
        for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
            const uvec3 tri = scene.triangles[mesh.first_triangle + t];
            const BvhTriangle bt = leaf_triangle(v[tri.x], v[tri.y], v[tri.z], t, i);
            prims.push_back(make_primitive(glm::min(bt.v0, glm::min(bt.v1, bt.v2)),
                                           glm::max(bt.v0, glm::max(bt.v1, bt.v2)),
                                           uint32_t(world.size())));
            world.push_back(bt);
        }
    }
    out.top_root = builder.build(std::move(prims), kMaxTrianglesPerLeaf, kMaxBottomDepth,
                                 out.bottom_depth, [&](const uint32_t* ids, uint32_t n) {
                                     const uint32_t first = add_triangle(out, world[ids[0]]);
                                     for (uint32_t k = 1; k < n; ++k)
                                         add_triangle(out, world[ids[k]]);
                                     return first;
                                 });
    out.one_level = true;
}

// One tree per mesh in object space and, behind them, the top tree over the instances' world
// boxes.
void build_two_level(const FlatScene& scene, Builder& builder, BvhBuild& out) {
    std::vector<vec3> mesh_lo(scene.meshes.size(), vec3(FLOAT_MAX)),
        mesh_hi(scene.meshes.size(), vec3(-FLOAT_MAX));
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const MeshInfo& mesh = scene.meshes[m];
        std::vector<RTCBuildPrimitive> prims;
        prims.reserve(mesh.triangle_count);
        for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
            const uvec3 tri = scene.triangles[mesh.first_triangle + t];
            const vec3 a = scene.positions[mesh.first_vertex + tri.x];
            const vec3 b = scene.positions[mesh.first_vertex + tri.y];
            const vec3 c = scene.positions[mesh.first_vertex + tri.z];
            const vec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
            prims.push_back(make_primitive(lo, hi, t));
            mesh_lo[m] = glm::min(mesh_lo[m], lo);
            mesh_hi[m] = glm::max(mesh_hi[m], hi);
        }
        uint32_t depth = 0;
        out.mesh_roots.push_back(builder.build(
            std::move(prims), kMaxTrianglesPerLeaf, kMaxBottomDepth, depth,
            [&](const uint32_t* ids, uint32_t n) {
                uint32_t first = 0;
                for (uint32_t i = 0; i < n; ++i) {
                    const uvec3 tri = scene.triangles[mesh.first_triangle + ids[i]];
                    const vec3* p = &scene.positions[mesh.first_vertex];
                    const uint32_t k =
                        add_triangle(out, leaf_triangle(p[tri.x], p[tri.y], p[tri.z], ids[i], 0));
                    if (i == 0) first = k;
                }
                return first;
            }));
        out.bottom_depth = std::max(out.bottom_depth, depth);
    }

    std::vector<RTCBuildPrimitive> instances;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (scene.meshes[inst.mesh].triangle_count == 0) continue;
        vec3 lo, hi;
        world_box(inst, mesh_lo[inst.mesh], mesh_hi[inst.mesh], lo, hi);
        instances.push_back(make_primitive(lo, hi, i));
    }
    // One instance per leaf in both layouts, so that every instance is entered behind its own
    // box: a binary leaf names it directly (count 1), a wide leaf by a record (wide_bvh.h).
    const bool wide = out.layout == BvhLayout::wide;
    out.top_root = builder.build(std::move(instances), 1, kMaxTopDepth, out.top_depth,
                                 [&](const uint32_t* ids, uint32_t) {
                                     return wide ? out.wide_triangles.add_instance(ids[0]) : ids[0];
                                 });
}

// The trees of one layout, not yet checked against the traversal stack.
BvhBuild build_layout(const FlatScene& scene, uint32_t features, BvhLayout layout) {
    BvhBuild out;
    out.layout = layout;
    out.requested = layout;
    Builder builder(out);
    if (feature_on(features, FEATURE_INSTANCING))
        build_two_level(scene, builder, out);
    else
        build_one_level(scene, builder, out);
    if (layout == BvhLayout::wide) out.wide_triangles.finish(out.one_level);
    out.estimate = estimate_bvh_work(out, scene);
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

} // namespace

BvhBuild build_bvh(const FlatScene& scene, uint32_t features, BvhLayout layout) {
    if (layout != BvhLayout::automatic) return checked(build_layout(scene, features, layout));
    BvhBuild binary = build_layout(scene, features, BvhLayout::binary);
    BvhBuild wide = build_layout(scene, features, BvhLayout::wide);
    const bool pick_wide =
        fits_stack(wide) && (!fits_stack(binary) || auto_prefers_wide(binary.estimate));
    BvhBuild& pick = pick_wide ? wide : binary;
    pick.requested = BvhLayout::automatic;
    pick.other_estimate = (pick_wide ? binary : wide).estimate;
    return checked(std::move(pick));
}

std::map<std::string, std::string> bvh_stats(const BvhBuild& bvh) {
    std::map<std::string, std::string> s;
    s["bvh_layout"] = bvh_layout_name(bvh.layout);
    s["bvh_requested"] = bvh_layout_name(bvh.requested);
    s["bvh_levels"] = bvh.one_level ? "1" : "2";
    s["bvh_estimate"] = describe(bvh.estimate);
    if (bvh.requested == BvhLayout::automatic) {
        const BvhLayout other = bvh.layout == BvhLayout::wide ? BvhLayout::binary : BvhLayout::wide;
        s[std::string("bvh_estimate_") + bvh_layout_name(other)] = describe(bvh.other_estimate);
    }
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
