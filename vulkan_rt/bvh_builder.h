// The compute mode's acceleration structure, built on the host with Embree's BVH builder API
// (rtcBuildBVH, binned SAH) and flattened into the node layout of shared/intersect.h, in the
// shape that shaders/trace_bvh.glsl traverses for the render's feature mask (issue 9):
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

#include <cstdint>
#include <vector>

namespace tp {

struct BvhBuild {
    std::vector<BvhNode> nodes;         // two levels: the top level first, then each mesh's tree
    std::vector<BvhTriangle> triangles; // leaf items, in leaf order
    // Two levels, per FlatScene mesh: its root node (MeshInfo::bvh_root); one level: empty.
    std::vector<uint32_t> mesh_roots;
    uint32_t top_root = 0;     // where traversal starts (BatchParams::bvh_top_root)
    uint32_t top_depth = 0;    // inner-node levels of the top tree; 0 with one level
    uint32_t bottom_depth = 0; // the deepest mesh tree, or the one-level tree
    bool one_level = false;

    uint64_t bytes() const {
        return nodes.size() * sizeof(BvhNode) + triangles.size() * sizeof(BvhTriangle);
    }
};

// Two levels when `features` (shared/features.h) has FEATURE_INSTANCING, else one level: the
// shape that the render shader specialized to `features` traverses. Throws RuntimeError when
// Embree fails and InputError when the trees are too deep for the shader's traversal stack
// (BVH_STACK_SIZE).
BvhBuild build_bvh(const FlatScene& scene, uint32_t features = FEATURES_ALL);

} // namespace tp
