#include "vulkan_rt/compute_mode/wide_collapse.h"

#include "util/error.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <limits>

namespace tp {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A cost and, to break its ties, the wide nodes it takes: where subtrees are flat (zero area)
// every choice costs 0, and the fewest nodes are the fullest, which keeps the tree shallow.
struct Cost {
    double sah = 0.0;
    uint32_t nodes = 0;
    Cost operator+(const Cost& o) const { return {sah + o.sah, nodes + o.nodes}; }
    bool operator<(const Cost& o) const { return sah < o.sah || (sah == o.sah && nodes < o.nodes); }
};

using Costs = std::array<Cost, kWideSlots - 1>; // cost(n, i) for i = 1..7

// Adds the roots of the forest of at most i trees that cost(n, i) stands for (n's box: b).
void forest(const TreeNode* n, const RTCBounds& b, uint32_t i, WideSlot* roots, uint32_t& count) {
    if (n->count == 0) {
        const auto* inner = static_cast<const TreeInner*>(n);
        const uint8_t* split = inner->scratch.split;
        while (i > 1 && split[i - 1] == 0) --i;
        if (i > 1) {
            const uint32_t k = split[i - 1];
            forest(inner->child[0], inner->bounds[0], k, roots, count);
            forest(inner->child[1], inner->bounds[1], i - k, roots, count);
            return;
        }
    }
    WideSlot& s = roots[count++];
    s.node = n;
    s.bounds = b;
    s.count = 0;
    if (n->count > 0)
        s.count = n->count;
    else if (static_cast<const TreeInner*>(n)->scratch.as_leaf)
        s.count = static_cast<const TreeInner*>(n)->scratch.items;
}

// The 8-slot forest of inner node n's children: the slots of the wide node n stands for.
uint32_t node_slots(const TreeInner* n, WideSlot slots[kWideSlots]) {
    uint32_t count = 0;
    const uint32_t k = n->scratch.split[kWideSlots - 1];
    forest(n->child[0], n->bounds[0], k, slots, count);
    forest(n->child[1], n->bounds[1], kWideSlots - k, slots, count);
    return count;
}

class Program {
  public:
    explicit Program(uint32_t max_leaf) : max_leaf_(max_leaf) {}

    // cost(n, i) for i = 1..7 of n (box `b`). Inner nodes keep in their scratch: split[j - 1],
    // the k of dist(n, j) when cost(n, j) distributes (j = 2..7) or of the inner node's
    // dist(n, 8) (j = 8), 0 when cost(n, j) = cost(n, j - 1); as_leaf: cost(n, 1) is the leaf;
    // items; and the wide nodes and levels below n as a wide node. `forest_cost`: dist(n, 8).
    Costs solve(TreeNode* n, const RTCBounds& b, uint32_t level, Cost* forest_cost = nullptr) {
        const double area = half_area(b);
        Costs cost;
        if (n->count > 0) {
            if (n->count > max_leaf_) runtime_error("wide BVH: a binary leaf holds too many items");
            cost.fill({kCollapsePrimitiveCost * area * n->count, 0});
            return cost;
        }
        auto* inner = static_cast<TreeInner*>(n);
        if (inner->children != 2) runtime_error("wide BVH: the tree to collapse is not binary");
        Costs l, r;
        fork(
            level, [&] { l = solve(inner->child[0], inner->bounds[0], level + 1); },
            [&] { r = solve(inner->child[1], inner->bounds[1], level + 1); });
        TreeScratch& s = inner->scratch;
        s.items = items(inner->child[0]) + items(inner->child[1]);
        std::fill(std::begin(s.split), std::end(s.split), uint8_t(0));
        // dist(n, j) and its best k.
        auto dist = [&](uint32_t j, uint8_t& best) {
            Cost d{kInfinity, 0};
            for (uint32_t k = j > 7 ? j - 7 : 1; k < j && k <= 7; ++k) {
                const Cost c = l[k - 1] + r[j - k - 1];
                if (c < d) {
                    d = c;
                    best = uint8_t(k);
                }
            }
            return d;
        };
        const Cost leaf = s.items <= max_leaf_ ? Cost{kCollapsePrimitiveCost * area * s.items, 0}
                                               : Cost{kInfinity, 0};
        const Cost forest = dist(kWideSlots, s.split[kWideSlots - 1]);
        const Cost as_inner = Cost{kCollapseNodeCost * area, 1} + forest;
        s.as_leaf = !(as_inner < leaf);
        cost[0] = s.as_leaf ? leaf : as_inner;
        for (uint32_t i = 2; i < kWideSlots; ++i) {
            uint8_t k = 0;
            const Cost d = dist(i, k);
            if (d < cost[i - 2]) {
                cost[i - 1] = d;
                s.split[i - 1] = k;
            } else {
                cost[i - 1] = cost[i - 2];
            }
        }
        WideSlot slots[kWideSlots];
        const uint32_t count = node_slots(inner, slots);
        s.nodes = 1;
        s.depth = 1;
        for (uint32_t i = 0; i < count; ++i) {
            if (slots[i].count > 0) continue;
            const TreeScratch& c = static_cast<const TreeInner*>(slots[i].node)->scratch;
            s.nodes += c.nodes;
            s.depth = std::max(s.depth, c.depth + 1);
        }
        if (forest_cost) *forest_cost = forest;
        return cost;
    }

  private:
    static uint32_t items(const TreeNode* n) {
        return n->count > 0 ? n->count : static_cast<const TreeInner*>(n)->scratch.items;
    }

    uint32_t max_leaf_;
};

void collect(const TreeNode* n, uint32_t*& out) {
    if (n->count > 0) {
        const auto* leaf = static_cast<const TreeLeaf*>(n);
        out = std::copy(leaf->items, leaf->items + leaf->count, out);
        return;
    }
    const auto* inner = static_cast<const TreeInner*>(n);
    collect(inner->child[0], out);
    collect(inner->child[1], out);
}

} // namespace

double half_area(const RTCBounds& b) {
    const double dx = std::max(0.0, double(b.upper_x) - double(b.lower_x));
    const double dy = std::max(0.0, double(b.upper_y) - double(b.lower_y));
    const double dz = std::max(0.0, double(b.upper_z) - double(b.lower_z));
    return dx * dy + dy * dz + dz * dx;
}

WideCollapse collapse_to_wide(TreeNode* root, const RTCBounds& bounds, uint32_t max_leaf) {
    WideCollapse c;
    c.nodes = 1;
    c.depth = 1;
    if (!root) return c;
    const double area = half_area(bounds);
    c.cost = kCollapseNodeCost * area;
    if (root->count > 0) {
        if (root->count > max_leaf) runtime_error("wide BVH: a binary leaf holds too many items");
        c.items = root->count;
        c.root_as_leaf = true;
        c.cost += kCollapsePrimitiveCost * area * c.items;
        return c;
    }
    Cost forest;
    Program(max_leaf).solve(root, bounds, 0, &forest);
    const TreeScratch& s = static_cast<const TreeInner*>(root)->scratch;
    c.items = s.items;
    c.root_as_leaf =
        s.items <= max_leaf && !(forest < Cost{kCollapsePrimitiveCost * area * s.items, 0});
    if (c.root_as_leaf) {
        c.cost += kCollapsePrimitiveCost * area * s.items;
    } else {
        c.cost += forest.sah;
        c.nodes = s.nodes;
        c.depth = s.depth;
    }
    return c;
}

uint32_t wide_root_slots(const TreeNode* root, const RTCBounds& bounds, const WideCollapse& c,
                         WideSlot slots[kWideSlots]) {
    if (root->count > 0 || c.root_as_leaf) {
        slots[0].node = root;
        slots[0].bounds = bounds;
        slots[0].count = c.items;
        return 1;
    }
    return node_slots(static_cast<const TreeInner*>(root), slots);
}

uint32_t wide_node_slots(const TreeInner* n, WideSlot slots[kWideSlots]) {
    return node_slots(n, slots);
}

void wide_leaf_items(const TreeNode* n, uint32_t* out) {
    collect(n, out);
}

} // namespace tp
