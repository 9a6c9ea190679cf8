#include "vulkan_rt/bvh_builder.h"

#include "scene/world_vertex.h"
#include "shared/surface.h"
#include "util/error.h"

#include <embree3/rtcore.h>
#include <embree3/rtcore_builder.h>

#include <algorithm>
#include <cmath>
#include <new>

namespace tp {
namespace {

// Embree builds into nodes that we allocate through its thread-local allocator (the memory
// belongs to the RTCBVH object) and hands back the root; flatten() then copies the tree into
// the shader's layout.
struct BuildNode {
    uint32_t count; // 0: BuildInner; > 0: BuildLeaf with that many items
};
struct BuildInner : BuildNode {
    BuildNode* child[2] = {nullptr, nullptr};
    RTCBounds bounds[2] = {};
};
struct BuildLeaf : BuildNode {
    uint32_t* items; // primitive IDs
};

void* create_node(RTCThreadLocalAllocator alloc, unsigned int, void*) {
    void* p = rtcThreadLocalAlloc(alloc, sizeof(BuildInner), 16);
    auto* n = new (p) BuildInner();
    n->count = 0;
    return n;
}

void set_children(void* node, void** children, unsigned int n, void*) {
    for (unsigned int i = 0; i < n && i < 2; ++i)
        static_cast<BuildInner*>(node)->child[i] = static_cast<BuildNode*>(children[i]);
}

void set_bounds(void* node, const RTCBounds** bounds, unsigned int n, void*) {
    for (unsigned int i = 0; i < n && i < 2; ++i)
        static_cast<BuildInner*>(node)->bounds[i] = *bounds[i];
}

void* create_leaf(RTCThreadLocalAllocator alloc, const RTCBuildPrimitive* prims, size_t n, void*) {
    auto* leaf = new (rtcThreadLocalAlloc(alloc, sizeof(BuildLeaf), 16)) BuildLeaf();
    leaf->count = uint32_t(n);
    leaf->items = static_cast<uint32_t*>(rtcThreadLocalAlloc(alloc, n * sizeof(uint32_t), 4));
    for (size_t i = 0; i < n; ++i) leaf->items[i] = prims[i].primID;
    return leaf;
}

RTCBuildPrimitive make_primitive(vec3 lo, vec3 hi, uint32_t id) {
    RTCBuildPrimitive p;
    p.lower_x = lo.x;
    p.lower_y = lo.y;
    p.lower_z = lo.z;
    p.geomID = 0;
    p.upper_x = hi.x;
    p.upper_y = hi.y;
    p.upper_z = hi.z;
    p.primID = id;
    return p;
}

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

class Builder {
  public:
    Builder() {
        device_ = rtcNewDevice(nullptr);
        if (!device_) runtime_error("cannot create an Embree device for the GPU BVH");
    }
    ~Builder() { rtcReleaseDevice(device_); }
    Builder(const Builder&) = delete;
    Builder& operator=(const Builder&) = delete;

    // Builds a tree over `prims` and appends it to `nodes`; returns the root node index and
    // its depth. Leaf items go through emit_leaf: (first item, count) of the child reference.
    // A tree of one leaf gets a root node with that leaf and an absent second child.
    template <typename EmitLeaf>
    uint32_t build(std::vector<BvhNode>& nodes, std::vector<RTCBuildPrimitive> prims,
                   uint32_t max_leaf, uint32_t max_depth, uint32_t& depth, EmitLeaf emit_leaf) {
        nodes_ = &nodes;
        depth = 1;
        const uint32_t root = uint32_t(nodes.size());
        nodes.push_back(empty_node());
        if (prims.empty()) return root;

        RTCBounds all{prims[0].lower_x, prims[0].lower_y, prims[0].lower_z, 0.0f,
                      prims[0].upper_x, prims[0].upper_y, prims[0].upper_z, 0.0f};
        for (const RTCBuildPrimitive& p : prims) {
            all.lower_x = std::min(all.lower_x, p.lower_x);
            all.lower_y = std::min(all.lower_y, p.lower_y);
            all.lower_z = std::min(all.lower_z, p.lower_z);
            all.upper_x = std::max(all.upper_x, p.upper_x);
            all.upper_y = std::max(all.upper_y, p.upper_y);
            all.upper_z = std::max(all.upper_z, p.upper_z);
        }

        RTCBVH bvh = rtcNewBVH(device_);
        RTCBuildArguments args = rtcDefaultBuildArguments();
        args.buildQuality = RTC_BUILD_QUALITY_MEDIUM; // binned SAH, no spatial splits
        args.maxBranchingFactor = 2;
        args.maxDepth = max_depth;
        args.minLeafSize = 1;
        args.maxLeafSize = max_leaf;
        args.traversalCost = 1.0f;
        args.intersectionCost = 1.0f;
        args.bvh = bvh;
        args.primitives = prims.data();
        args.primitiveCount = prims.size();
        args.primitiveArrayCapacity = prims.size();
        args.createNode = create_node;
        args.setNodeChildren = set_children;
        args.setNodeBounds = set_bounds;
        args.createLeaf = create_leaf;
        auto* top = static_cast<BuildNode*>(rtcBuildBVH(&args));
        const RTCError error = rtcGetDeviceError(device_);
        if (!top || error != RTC_ERROR_NONE) {
            rtcReleaseBVH(bvh);
            if (error == RTC_ERROR_OUT_OF_MEMORY)
                runtime_error("out of host memory while building the GPU BVH");
            runtime_error("Embree could not build the GPU BVH");
        }
        if (top->count > 0) {
            set_child(root, 0, all, static_cast<BuildLeaf*>(top), emit_leaf, depth, 1);
        } else {
            flatten_inner(root, static_cast<BuildInner*>(top), emit_leaf, depth, 1);
        }
        rtcReleaseBVH(bvh);
        return root;
    }

  private:
    template <typename EmitLeaf>
    void flatten_inner(uint32_t index, const BuildInner* n, EmitLeaf& emit_leaf, uint32_t& depth,
                       uint32_t level) {
        depth = std::max(depth, level);
        for (int c = 0; c < 2; ++c) {
            if (!n->child[c]) continue;
            if (n->child[c]->count > 0) {
                set_child(index, c, n->bounds[c], static_cast<const BuildLeaf*>(n->child[c]),
                          emit_leaf, depth, level);
            } else {
                const uint32_t child = uint32_t(nodes_->size());
                nodes_->push_back(empty_node());
                flatten_inner(child, static_cast<const BuildInner*>(n->child[c]), emit_leaf, depth,
                              level + 1);
                write_child(index, c, n->bounds[c], child, 0);
            }
        }
    }

    template <typename EmitLeaf>
    void set_child(uint32_t index, int c, const RTCBounds& b, const BuildLeaf* leaf,
                   EmitLeaf& emit_leaf, uint32_t& depth, uint32_t level) {
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

    std::vector<BvhNode>* nodes_ = nullptr;
    RTCDevice device_ = nullptr;
};

// Leaves of at most 4 triangles: a leaf is then at most 192 contiguous bytes.
constexpr uint32_t kMaxTrianglesPerLeaf = 4;
// Depth limits that keep depth(top) + depth(bottom) + 2 <= BVH_STACK_SIZE (64); Embree makes
// its last levels balanced when a branch approaches the limit.
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
    out.top_root = builder.build(out.nodes, std::move(prims), kMaxTrianglesPerLeaf, kMaxBottomDepth,
                                 out.bottom_depth, [&](const uint32_t* ids, uint32_t n) {
                                     const uint32_t first = uint32_t(out.triangles.size());
                                     for (uint32_t k = 0; k < n; ++k)
                                         out.triangles.push_back(world[ids[k]]);
                                     return first;
                                 });
    out.one_level = true;
}

// One tree per mesh in object space and the top tree over the instances' world boxes.
void build_two_level(const FlatScene& scene, Builder& builder, BvhBuild& out) {
    // Node 0 is the top root; it is filled once the meshes' boxes are known.
    out.nodes.push_back(empty_node());
    out.top_root = 0;
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
            out.nodes, std::move(prims), kMaxTrianglesPerLeaf, kMaxBottomDepth, depth,
            [&](const uint32_t* ids, uint32_t n) {
                const uint32_t first = uint32_t(out.triangles.size());
                for (uint32_t i = 0; i < n; ++i) {
                    const uvec3 tri = scene.triangles[mesh.first_triangle + ids[i]];
                    const vec3* p = &scene.positions[mesh.first_vertex];
                    out.triangles.push_back(leaf_triangle(p[tri.x], p[tri.y], p[tri.z], ids[i], 0));
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
    // The top tree is built into a scratch array and copied over node 0 and onwards: node 0
    // must be its root so that the shader starts there.
    std::vector<BvhNode> top;
    builder.build(top, std::move(instances), 1, kMaxTopDepth, out.top_depth,
                  [](const uint32_t* ids, uint32_t) { return ids[0]; });
    // Re-base the top tree's inner references behind the mesh trees.
    const uint32_t base = uint32_t(out.nodes.size()) - 1;
    for (size_t k = 0; k < top.size(); ++k) {
        BvhNode n = top[k];
        if (n.count0 == 0 && n.ref0 != BVH_EMPTY) n.ref0 += base;
        if (n.count1 == 0 && n.ref1 != BVH_EMPTY) n.ref1 += base;
        if (k == 0)
            out.nodes[0] = n;
        else
            out.nodes.push_back(n);
    }
}

} // namespace

BvhBuild build_bvh(const FlatScene& scene, uint32_t features) {
    BvhBuild out;
    Builder builder;
    if (feature_on(features, FEATURE_INSTANCING))
        build_two_level(scene, builder, out);
    else
        build_one_level(scene, builder, out);
    if (out.top_depth + out.bottom_depth + 2 > BVH_STACK_SIZE)
        input_error("the scene's BVH is too deep for the GPU traversal stack ({} + {} levels)",
                    out.top_depth, out.bottom_depth);
    return out;
}

} // namespace tp
