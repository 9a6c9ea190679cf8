// The binary layout's writer: an Embree tree (embree_tree.h) stored as the nodes of
// shared/intersect.h, depth first (a node, then its first child's subtree, then its second's)
// with the leaves' items in the order the traversal meets them. Two passes, each over subtrees in
// parallel: size_binary_tree records every subtree's node and item counts, from which
// write_binary_tree places each subtree at an offset known in advance, so that the arrays are
// the same as a serial depth-first walk's.
#pragma once

#include "shared/intersect.h"
#include "vulkan_rt/compute_mode/embree_tree.h"

#include <cstdint>

namespace tp {

struct TreeSize {
    uint32_t nodes = 0; // nodes the layout stores
    uint32_t items = 0; // leaf items the layout stores
    uint32_t depth = 0; // inner-node levels (1 for a tree of one leaf or none)
};

// The sizes of `root`'s tree (nullptr: empty) in the binary layout, recorded in its inner nodes'
// scratch for write_binary_tree. `store_items`: leaves keep their items in the item array; else
// every leaf holds one item that its node names itself (a top level's instance).
TreeSize size_binary_tree(TreeNode* root, bool store_items);

// Writes the tree sized by size_binary_tree, whose root's box is `bounds`, as
// nodes[node_base ...] with its leaf items at item_base ... (written by `write_leaf`). A tree of
// one leaf gets a root node with that leaf and an absent second child; an empty one, a root with
// no children.
void write_binary_tree(const TreeNode* root, const RTCBounds& bounds, bool store_items,
                       BvhNode* nodes, uint32_t node_base, uint32_t item_base,
                       const LeafWriter& write_leaf);

} // namespace tp
