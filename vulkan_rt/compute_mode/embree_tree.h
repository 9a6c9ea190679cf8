// Embree's BVH builder API (rtcBuildBVH, binned SAH) driven into a plain binary tree that the
// compute mode's layouts then store: as binary nodes (bvh_builder.cpp), or collapsed into
// compressed 8-wide nodes (wide_collapse.h, wide_bvh.h). Internal to vulkan_rt: the one place
// that includes Embree's builder.
#pragma once

#include "shared/math.h"

#include <embree3/rtcore.h>
#include <embree3/rtcore_builder.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace tp {

// A node of the built tree: an inner node with `children` (2) children
// or a leaf with `count` > 0 primitive IDs. The memory belongs to the EmbreeTreeBuilder.
struct TreeNode {
    uint32_t count = 0; // 0: TreeInner; > 0: TreeLeaf with that many items
};
struct TreeInner : TreeNode {
    uint32_t children = 0;
    const TreeNode** child = nullptr;
    RTCBounds* bounds = nullptr; // child[i]'s box
};
struct TreeLeaf : TreeNode {
    uint32_t* items = nullptr; // RTCBuildPrimitive::primID of each item
};

// Stores a leaf's items (primitive IDs) where the layout keeps them and returns the index of
// the first; the items of one leaf are stored consecutively.
using LeafEmitter = std::function<uint32_t(const uint32_t* ids, uint32_t count)>;

RTCBuildPrimitive make_primitive(vec3 lo, vec3 hi, uint32_t id);

// The box around every primitive's box.
RTCBounds bounds_of(const std::vector<RTCBuildPrimitive>& prims);

class EmbreeTreeBuilder {
  public:
    EmbreeTreeBuilder();
    ~EmbreeTreeBuilder();
    EmbreeTreeBuilder(const EmbreeTreeBuilder&) = delete;
    EmbreeTreeBuilder& operator=(const EmbreeTreeBuilder&) = delete;

    // Builds a binary tree over `prims` (not empty) with at most `max_leaf` items per leaf and
    // `max_depth` levels; valid until the next build. The root may be a leaf. Throws
    // RuntimeError when Embree fails.
    const TreeNode* build(std::vector<RTCBuildPrimitive>& prims, uint32_t max_leaf,
                          uint32_t max_depth);

  private:
    RTCDevice device_ = nullptr;
    RTCBVH bvh_ = nullptr;
};

} // namespace tp
