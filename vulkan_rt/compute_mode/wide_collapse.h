// The SAH-optimal collapse of a binary BVH into an 8-wide one (Ylitie, Karras & Laine,
// "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs", HPG 2017, sec. 3):
// a dynamic program over (binary node n, number of slots i) finds, among all 8-wide trees whose
// nodes are unions of subtrees of the binary tree, the one of least SAH cost
//
//   C = sum over wide inner nodes N of c_node A(N) + sum over leaves L of c_prim A(L) |L|,
//
// A the surface area. cost(n, i) is the least cost of covering n's primitives with a forest of
// at most i roots taken from n's subtree:
//
//   cost(n, 1) = min(leaf: c_prim A(n) P(n) if P(n) <= max_leaf, inner: c_node A(n) + dist(n, 8))
//   cost(n, i) = min(cost(n, i - 1), dist(n, i))                      for 1 < i < 8
//   dist(n, j) = min over 0 < k < j of cost(left(n), k) + cost(right(n), j - k)
//
// with P(n) the primitives below n. The binary tree comes from Embree (embree_tree.h: binned SAH,
// the binary layout's builder) with leaves of one item, so that the program, not Embree,
// chooses how triangles group into leaves.
#pragma once

#include "vulkan_rt/compute_mode/embree_tree.h"

#include <cstdint>
#include <vector>

namespace tp {

// The paper's constants (sec. 5.1): a node visit costs one unit, a primitive test 0.3.
constexpr double kCollapseNodeCost = 1.0;
constexpr double kCollapsePrimitiveCost = 0.3;
constexpr uint32_t kWideSlots = 8;

// One child of a wide node: an inner node or a leaf of `count` items.
struct WideSlot {
    RTCBounds bounds;
    uint32_t count = 0; // 0: inner child `node`; > 0: a leaf, items[first .. first + count)
    uint32_t node = 0;
    uint32_t first = 0;
};

struct WideTreeNode {
    uint32_t slots = 0;
    WideSlot slot[kWideSlots];
};

struct WideTree {
    std::vector<WideTreeNode> nodes; // nodes[0] is the root; an empty tree has a root of 0 slots
    std::vector<uint32_t> items;     // leaf items (the binary leaves' primitive IDs)
    RTCBounds bounds;                // the root's box
    double cost = 0.0;               // the program's C for the returned tree
};

// The surface area of a box over 2 (0 for an empty or flat-enough box).
double half_area(const RTCBounds& b);

// The least-cost 8-wide tree over the binary tree `root` (nullptr: empty), whose box is
// `bounds`, with at most `max_leaf` items per leaf (Embree's leaves must not hold more). The
// root is always a wide node: a single leaf slot where one leaf is cheapest. Where costs tie
// the program takes the choice with fewer wide nodes, which keeps flat (zero-area) subtrees
// shallow. Throws RuntimeError when the tree is not binary.
WideTree collapse_to_wide(const TreeNode* root, const RTCBounds& bounds, uint32_t max_leaf);

// C of a wide tree evaluated from its boxes: what the program minimized.
double wide_tree_cost(const WideTree& tree);

} // namespace tp
