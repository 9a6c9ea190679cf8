#include "vulkan_rt/compute_mode/binary_writer.h"

#include <algorithm>

namespace tp {
namespace {

BvhNode empty_node() {
    BvhNode n{};
    n.ref0 = BVH_EMPTY;
    n.ref1 = BVH_EMPTY;
    return n;
}

void set_child(BvhNode& n, uint32_t c, const RTCBounds& b, uint32_t ref, uint32_t count) {
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

// Post-order: an inner node's scratch gets its subtree's nodes (itself included), items and
// inner-node levels.
void size_inner(TreeInner* n, bool store_items, uint32_t level) {
    auto side = [&](uint32_t c) {
        if (c < n->children && n->child[c]->count == 0)
            size_inner(static_cast<TreeInner*>(n->child[c]), store_items, level + 1);
    };
    fork(
        level, [&] { side(0); }, [&] { side(1); });
    TreeScratch& s = n->scratch;
    s.nodes = 1;
    s.items = 0;
    s.depth = 1;
    for (uint32_t c = 0; c < n->children; ++c) {
        const TreeNode* child = n->child[c];
        if (child->count > 0) {
            s.items += store_items ? child->count : 0;
            continue;
        }
        const TreeScratch& cs = static_cast<const TreeInner*>(child)->scratch;
        s.nodes += cs.nodes;
        s.items += cs.items;
        s.depth = std::max(s.depth, cs.depth + 1);
    }
}

struct Writer {
    bool store_items;
    BvhNode* nodes;
    const LeafWriter& write_leaf;

    // A leaf's reference: its first item where the items are stored, else the item itself.
    uint32_t leaf_ref(const TreeLeaf* leaf, uint32_t first) const {
        if (!store_items) return leaf->items[0];
        write_leaf(leaf->items, leaf->count, first);
        return first;
    }

    void inner(const TreeInner* n, uint32_t index, uint32_t first_item, uint32_t level) const {
        BvhNode node = empty_node();
        uint32_t next_node = index + 1, next_item = first_item;
        uint32_t child_index[2] = {0, 0}, child_item[2] = {0, 0};
        for (uint32_t c = 0; c < n->children; ++c) {
            const TreeNode* child = n->child[c];
            if (child->count > 0) {
                const auto* leaf = static_cast<const TreeLeaf*>(child);
                set_child(node, c, n->bounds[c], leaf_ref(leaf, next_item), leaf->count);
                next_item += store_items ? leaf->count : 0;
                continue;
            }
            const TreeScratch& s = static_cast<const TreeInner*>(child)->scratch;
            set_child(node, c, n->bounds[c], next_node, 0);
            child_index[c] = next_node;
            child_item[c] = next_item;
            next_node += s.nodes;
            next_item += s.items;
        }
        nodes[index] = node;
        auto side = [&](uint32_t c) {
            if (c < n->children && n->child[c]->count == 0)
                inner(static_cast<const TreeInner*>(n->child[c]), child_index[c], child_item[c],
                      level + 1);
        };
        fork(
            level, [&] { side(0); }, [&] { side(1); });
    }
};

} // namespace

TreeSize size_binary_tree(TreeNode* root, bool store_items) {
    if (!root) return {1, 0, 1};
    if (root->count > 0) return {1, store_items ? root->count : 0, 1};
    auto* inner = static_cast<TreeInner*>(root);
    size_inner(inner, store_items, 0);
    return {inner->scratch.nodes, inner->scratch.items, inner->scratch.depth};
}

void write_binary_tree(const TreeNode* root, const RTCBounds& bounds, bool store_items,
                       BvhNode* nodes, uint32_t node_base, uint32_t item_base,
                       const LeafWriter& write_leaf) {
    const Writer w{store_items, nodes, write_leaf};
    if (!root) {
        nodes[node_base] = empty_node();
    } else if (root->count > 0) {
        BvhNode node = empty_node();
        const auto* leaf = static_cast<const TreeLeaf*>(root);
        set_child(node, 0, bounds, w.leaf_ref(leaf, item_base), leaf->count);
        nodes[node_base] = node;
    } else {
        w.inner(static_cast<const TreeInner*>(root), node_base, item_base, 0);
    }
}

} // namespace tp
