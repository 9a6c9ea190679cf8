// Embree's BVH builder API (rtcBuildBVH, binned SAH) driven into a plain binary tree that the
// compute mode's layouts then store: as binary nodes (bvh_builder.cpp), or collapsed into
// compressed 8-wide nodes (wide_collapse.h, wide_bvh.h). Internal to vulkan_rt: the one place
// that includes Embree's builder.
#pragma once

#include "shared/math.h"

#include <embree3/rtcore.h>
#include <embree3/rtcore_builder.h>

#include <tbb/parallel_invoke.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace tp {

// A node of the built tree: an inner node with `children` (2) children
// or a leaf with `count` > 0 primitive IDs. The memory belongs to the EmbreeTreeBuilder.
struct TreeNode {
    uint32_t count = 0; // 0: TreeInner; > 0: TreeLeaf with that many items
};

// What the passes of a layout (the binary writer, the wide collapse) record at an inner node
// about the subtree below it, so that the layout's arrays can be sized and then written by
// subtrees in parallel at offsets known in advance.
struct TreeScratch {
    uint32_t items = 0;   // leaf items below
    uint32_t nodes = 0;   // layout nodes of the subtree rooted here
    uint32_t depth = 0;   // their levels
    uint8_t split[8]{};   // wide collapse: the program's choices (wide_collapse.cpp)
    bool as_leaf = false; // wide collapse: one leaf is this subtree's cheapest slot
};

struct TreeInner : TreeNode {
    uint32_t children = 0;
    TreeNode* child[2]{};
    RTCBounds bounds[2]{}; // child[i]'s box
    TreeScratch scratch;
};
struct TreeLeaf : TreeNode {
    uint32_t* items = nullptr; // RTCBuildPrimitive::primID of each item
};

// Writes a leaf's items (primitive IDs) at positions first .. first + count of the layout's item
// array. The layouts' writers call it for different leaves at once.
using LeafWriter = std::function<void(const uint32_t* ids, uint32_t count, uint32_t first)>;

// The levels of a tree below which the layouts' passes stop handing the two subtrees of a node
// to separate tasks: 2^12 tasks keep any core count busy, and a deeper split only adds overhead.
constexpr uint32_t kParallelLevels = 12;

// Runs a and b, at once when `level` < kParallelLevels.
template <class A, class B>
void fork(uint32_t level, A&& a, B&& b) {
    if (level < kParallelLevels) {
        tbb::parallel_invoke(a, b);
    } else {
        a();
        b();
    }
}

RTCBuildPrimitive make_primitive(vec3 lo, vec3 hi, uint32_t id);

// The box around every primitive's box (a parallel reduction).
RTCBounds bounds_of(const std::vector<RTCBuildPrimitive>& prims);

// The box around two boxes.
RTCBounds merge_bounds(const RTCBounds& a, const RTCBounds& b);

class EmbreeTreeBuilder {
  public:
    EmbreeTreeBuilder();
    ~EmbreeTreeBuilder();
    EmbreeTreeBuilder(const EmbreeTreeBuilder&) = delete;
    EmbreeTreeBuilder& operator=(const EmbreeTreeBuilder&) = delete;

    // Builds a binary tree over `prims` (not empty) with at most `max_leaf` items per leaf and
    // `max_depth` levels, in parallel (Embree's TBB tasks); valid until the next build or the
    // builder's end. The root may be a leaf. `prims` is reordered. Throws RuntimeError when
    // Embree fails.
    TreeNode* build(std::vector<RTCBuildPrimitive>& prims, uint32_t max_leaf, uint32_t max_depth);

  private:
    RTCDevice device_ = nullptr;
    RTCBVH bvh_ = nullptr;
};

} // namespace tp
