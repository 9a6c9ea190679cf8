// The compute mode's acceleration structure, built on the host: one binary SAH BVH per mesh
// in object space (Embree's BVH builder API, rtcBuildBVH) and one over the instances' world
// boxes, flattened into the node layout of shared/intersect.h. An instanced mesh is stored
// once; shaders/trace_bvh.glsl traverses both levels.
#pragma once

#include "scene/flatten.h"
#include "shared/intersect.h"

#include <cstdint>
#include <vector>

namespace tp {

struct BvhBuild {
    std::vector<BvhNode> nodes;         // top level first, then each mesh's tree
    std::vector<BvhTriangle> triangles; // bottom-level leaf items, in leaf order
    std::vector<uint32_t> mesh_roots;   // per FlatScene mesh: its root node (MeshInfo::bvh_root)
    uint32_t top_root = 0;
    uint32_t top_depth = 0;    // inner-node levels of the top tree
    uint32_t bottom_depth = 0; // the deepest mesh tree

    uint64_t bytes() const {
        return nodes.size() * sizeof(BvhNode) + triangles.size() * sizeof(BvhTriangle);
    }
};

// Throws RuntimeError when Embree fails and InputError when the scene's trees are too deep for
// the shader's traversal stack (BVH_STACK_SIZE).
BvhBuild build_bvh(const FlatScene& scene);

} // namespace tp
