// The compute mode's acceleration structure, built on the host with Embree's BVH builder API
// (rtcBuildBVH, binned SAH, embree_tree.h) in one of two layouts: binary nodes (shared/intersect.h,
// traversed by shaders/trace_bvh.glsl) or compressed 8-wide nodes, the SAH-optimal collapse of a
// binary tree (wide_collapse.h, wide_bvh.h, traversed by shaders/trace_cwbvh.glsl). Either comes in
// the shape that the render's feature mask asks for (scene features: docs/gpu.md,
// "Specialization to the scene's features"):
//   two levels (FEATURE_INSTANCING set): one BVH per mesh in object space, an instanced mesh
//     stored once, and one over the instances' world boxes;
//   one level (FEATURE_INSTANCING clear): one BVH over the triangles of every instance in world
//     space (scene/world_vertex.h, the vertices of the CPU engine's one-level Embree scene),
//     each leaf triangle naming its instance; no top level, no instance markers, no transform
//     of the ray. It renders any scene, but copies an instanced mesh once per instance: the
//     renderers use it where the scene's mask has no instancing, so nothing is copied.
#pragma once

#include "scene/flatten.h"
#include "shared/features.h"
#include "shared/intersect.h"
#include "vulkan_rt/compute_mode/bvh_estimate.h"
#include "vulkan_rt/compute_mode/wide_bvh.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tp {

// `automatic` (--bvh auto) builds the binary layout, and the wide one only where its rule
// prefers it from the binary tree's estimated work per ray (bvh_estimate.h); the build it
// returns has the layout it chose.
enum class BvhLayout { binary, wide, automatic };

// "binary", "wide" or "auto" (the --bvh option); InputError for anything else.
BvhLayout parse_bvh_layout(const std::string& name);
const char* bvh_layout_name(BvhLayout layout);

// Seconds a build spent in each stage, summed over its trees (and with auto over the layouts it
// built).
struct BvhBuildTimes {
    double primitives_s = 0; // the items' boxes (and with one level the world vertices)
    double embree_s = 0;     // Embree's binary trees
    double layout_s = 0;     // the binary tree's sizes, or the wide collapse's program
    double write_s = 0;      // the nodes and leaf items at their offsets; the wide ID table
    double estimate_s = 0;   // estimate_bvh_work
};

struct BvhBuild {
    BvhLayout layout = BvhLayout::binary;    // binary or wide
    BvhLayout requested = BvhLayout::binary; // the layout asked for, or automatic
    BvhEstimate estimate;                    // the per-ray work of these trees
    BvhEstimate binary_estimate;             // automatic: the binary layout's, which chose
    BvhBuildTimes times;
    // The nodes of the layout (the other array stays empty); two levels: each mesh's tree,
    // then the top level.
    std::vector<BvhNode> nodes;
    std::vector<WideBvhNode> wide_nodes;
    // Leaf items, in leaf order: the binary layout's BvhTriangles, or the wide layout's records
    // and ID table (wide_bvh.h), with two levels also the top tree's instance records.
    std::vector<BvhTriangle> triangles;
    WideTriangleBuffer wide_triangles;
    // Two levels, per FlatScene mesh: its root node (MeshInfo::bvh_root); one level: empty.
    std::vector<uint32_t> mesh_roots;
    uint32_t top_root = 0;     // where traversal starts (BatchParams::bvh_top_root)
    uint32_t top_depth = 0;    // inner-node levels of the top tree; 0 with one level
    uint32_t bottom_depth = 0; // the deepest mesh tree, or the one-level tree
    bool one_level = false;

    uint64_t bytes() const {
        return nodes.size() * sizeof(BvhNode) + wide_nodes.size() * sizeof(WideBvhNode) +
               triangles.size() * sizeof(BvhTriangle) +
               wide_triangles.words().size() * sizeof(glm::uvec4);
    }
};

// Two levels when `features` (shared/features.h) has FEATURE_INSTANCING, else one level: the
// shape that the render shader specialized to `features` traverses. Throws RuntimeError when
// Embree fails and InputError when the trees are too deep for the shader's traversal stack
// (BVH_STACK_SIZE, CWBVH_STACK_SIZE); `automatic` keeps a layout that fits where one does.
BvhBuild build_bvh(const FlatScene& scene, uint32_t features = FEATURES_ALL,
                   BvhLayout layout = BvhLayout::binary);

// The render statistics' words about the build (RenderStats::extra): bvh_layout (the one
// built), bvh_requested, bvh_levels (1 or 2), bvh_estimate (bvh_estimate.h), with auto the
// binary layout's estimate that chose (bvh_estimate_binary), and bvh_build_stages (seconds per
// stage, BvhBuildTimes).
std::map<std::string, std::string> bvh_stats(const BvhBuild& bvh);

} // namespace tp
