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
// chooses how triangles group into leaves. The program runs over subtrees in parallel and
// leaves its choices in the binary tree's inner nodes (TreeScratch): the wide tree is read from
// them slot by slot (wide_root_slots, wide_node_slots) by its writer (wide_bvh.h).
#pragma once

#include "vulkan_rt/compute_mode/embree_tree.h"

#include <cstdint>

namespace tp {

// The paper's constants (sec. 5.1): a node visit costs one unit, a primitive test 0.3.
constexpr double kCollapseNodeCost = 1.0;
constexpr double kCollapsePrimitiveCost = 0.3;
constexpr uint32_t kWideSlots = 8;

// The chosen wide tree as a whole.
struct WideCollapse {
    double cost = 0.0;         // the program's C for it
    uint32_t nodes = 0;        // wide nodes (an empty tree: one node without slots)
    uint32_t items = 0;        // leaf items
    uint32_t depth = 0;        // node levels
    bool root_as_leaf = false; // the root holds a single leaf slot with every item
};

// One child of a wide node: the binary subtree `node` with its box, as a leaf of `count` items
// (those below node, left to right: wide_leaf_items) or, with count 0, as a wide node of its
// own whose slots wide_node_slots lists (node is then a TreeInner; its scratch holds the wide
// nodes, items and levels of its wide subtree).
struct WideSlot {
    const TreeNode* node = nullptr;
    RTCBounds bounds{};
    uint32_t count = 0;
};

// The surface area of a box over 2 (0 for an empty or flat-enough box).
double half_area(const RTCBounds& b);

// Runs the program over the binary tree `root` (nullptr: empty), whose box is `bounds`, with at
// most `max_leaf` items per leaf (Embree's leaves must not hold more). The root is always a wide
// node: a single leaf slot where one leaf is cheapest. Where costs tie the program takes the
// choice with fewer wide nodes, which keeps flat (zero-area) subtrees shallow. Throws
// RuntimeError when the tree is not binary.
WideCollapse collapse_to_wide(TreeNode* root, const RTCBounds& bounds, uint32_t max_leaf);

// The slots of the chosen tree's root (root not null), and of the wide node an inner slot
// stands for; each returns the number of slots (1 to 8).
uint32_t wide_root_slots(const TreeNode* root, const RTCBounds& bounds, const WideCollapse& c,
                         WideSlot slots[kWideSlots]);
uint32_t wide_node_slots(const TreeInner* n, WideSlot slots[kWideSlots]);

// The items of the binary leaves below n, left to right.
void wide_leaf_items(const TreeNode* n, uint32_t* out);

} // namespace tp
