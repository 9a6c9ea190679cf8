#include "vulkan_rt/compute_mode/wide_collapse.h"

#include "util/error.h"

#include <algorithm>
#include <array>
#include <limits>

namespace tp {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr uint32_t kNone = 0xFFFFFFFFu;

// A cost and, to break its ties, the wide nodes it takes: where subtrees are flat (zero area)
// every choice costs 0, and the fewest nodes are the fullest, which keeps the tree shallow.
struct Cost {
    double sah = 0.0;
    uint32_t nodes = 0;
    Cost operator+(const Cost& o) const { return {sah + o.sah, nodes + o.nodes}; }
    bool operator<(const Cost& o) const { return sah < o.sah || (sah == o.sah && nodes < o.nodes); }
};

// A node of the binary tree in an array, parents before children.
struct BinaryNode {
    RTCBounds bounds;
    const TreeNode* node;
    uint32_t left = kNone, right = kNone; // inner nodes
    uint32_t primitives = 0;              // items below
};

class Collapse {
  public:
    Collapse(const TreeNode* root, const RTCBounds& bounds, uint32_t max_leaf)
        : max_leaf_(max_leaf) {
        flatten(root, bounds);
        solve();
    }

    WideTree tree() {
        WideTree out;
        out.bounds = bins_[0].bounds;
        out.nodes.emplace_back();
        const BinaryNode& root = bins_[0];
        const double area = half_area(root.bounds);
        out.cost = kCollapseNodeCost * area;
        if (root.left == kNone || root_as_leaf_) {
            add_slot(out, 0, 0);
            out.cost += kCollapsePrimitiveCost * area * root.primitives;
        } else {
            const double inner = fill(out, 0, 0);
            out.cost += inner;
        }
        return out;
    }

  private:
    void flatten(const TreeNode* n, const RTCBounds& bounds) {
        const uint32_t index = uint32_t(bins_.size());
        bins_.push_back({bounds, n});
        if (n->count > 0) {
            if (n->count > max_leaf_) runtime_error("wide BVH: a binary leaf holds too many items");
            bins_[index].primitives = n->count;
            return;
        }
        const auto* inner = static_cast<const TreeInner*>(n);
        if (inner->children != 2) runtime_error("wide BVH: the tree to collapse is not binary");
        const uint32_t left = uint32_t(bins_.size());
        flatten(inner->child[0], inner->bounds[0]);
        const uint32_t right = uint32_t(bins_.size());
        flatten(inner->child[1], inner->bounds[1]);
        BinaryNode& b = bins_[index];
        b.left = left;
        b.right = right;
        b.primitives = bins_[left].primitives + bins_[right].primitives;
    }

    // cost_[n][i - 1] = cost(n, i) for i = 1..7; split_[n][j - 1] = the k of dist(n, j) when
    // cost(n, j) distributes (j = 2..7) or of the inner node's dist(n, 8) (j = 8), 0 when
    // cost(n, j) = cost(n, j - 1); leaf_[n]: cost(n, 1) is the leaf.
    void solve() {
        const Cost none{kInfinity, 0};
        cost_.resize(bins_.size());
        split_.resize(bins_.size());
        leaf_.resize(bins_.size());
        for (size_t n = bins_.size(); n-- > 0;) {
            const BinaryNode& b = bins_[n];
            const double area = half_area(b.bounds);
            auto& cost = cost_[n];
            auto& split = split_[n];
            split.fill(0);
            if (b.left == kNone) {
                cost.fill({kCollapsePrimitiveCost * area * b.primitives, 0});
                leaf_[n] = true;
                continue;
            }
            const auto& l = cost_[b.left];
            const auto& r = cost_[b.right];
            // dist(n, j) and its best k.
            auto dist = [&](uint32_t j, uint8_t& best) {
                Cost d = none;
                for (uint32_t k = j > 7 ? j - 7 : 1; k < j && k <= 7; ++k) {
                    const Cost c = l[k - 1] + r[j - k - 1];
                    if (c < d) {
                        d = c;
                        best = uint8_t(k);
                    }
                }
                return d;
            };
            const Cost leaf = b.primitives <= max_leaf_
                                  ? Cost{kCollapsePrimitiveCost * area * b.primitives, 0}
                                  : none;
            const Cost forest = dist(kWideSlots, split[kWideSlots - 1]);
            const Cost inner = Cost{kCollapseNodeCost * area, 1} + forest;
            leaf_[n] = !(inner < leaf);
            cost[0] = leaf_[n] ? leaf : inner;
            for (uint32_t i = 2; i < kWideSlots; ++i) {
                uint8_t k = 0;
                const Cost d = dist(i, k);
                if (d < cost[i - 2]) {
                    cost[i - 1] = d;
                    split[i - 1] = k;
                } else {
                    cost[i - 1] = cost[i - 2];
                }
            }
            if (n == 0) root_as_leaf_ = !(forest < leaf);
        }
    }

    // The roots of the forest of at most i trees that cost(n, i) stands for.
    void forest(uint32_t n, uint32_t i, std::vector<uint32_t>& roots) const {
        const BinaryNode& b = bins_[n];
        while (i > 1 && split_[n][i - 1] == 0) --i;
        if (b.left == kNone || i == 1) {
            roots.push_back(n);
            return;
        }
        const uint32_t k = split_[n][i - 1];
        forest(b.left, k, roots);
        forest(b.right, i - k, roots);
    }

    // Fills wide node `w` with the 8-slot forest of binary node n's children and returns its
    // cost without n's own node term.
    double fill(WideTree& out, uint32_t w, uint32_t n) {
        std::vector<uint32_t> roots;
        const uint32_t k = split_[n][kWideSlots - 1];
        forest(bins_[n].left, k, roots);
        forest(bins_[n].right, kWideSlots - k, roots);
        double cost = 0.0;
        for (const uint32_t r : roots) cost += add_slot(out, w, r);
        return cost;
    }

    // Appends binary node n to wide node w as a leaf or a new inner node; returns cost(n, 1).
    double add_slot(WideTree& out, uint32_t w, uint32_t n) {
        const BinaryNode& b = bins_[n];
        WideSlot s;
        s.bounds = b.bounds;
        const double area = half_area(b.bounds);
        double cost;
        if (leaf_[n]) {
            s.count = b.primitives;
            s.first = uint32_t(out.items.size());
            collect(n, out.items);
            cost = kCollapsePrimitiveCost * area * b.primitives;
        } else {
            s.node = uint32_t(out.nodes.size());
            out.nodes.emplace_back();
            cost = kCollapseNodeCost * area + fill(out, s.node, n);
        }
        WideTreeNode& node = out.nodes[w];
        node.slot[node.slots++] = s;
        return cost;
    }

    void collect(uint32_t n, std::vector<uint32_t>& items) const {
        const BinaryNode& b = bins_[n];
        if (b.left == kNone) {
            const auto* leaf = static_cast<const TreeLeaf*>(b.node);
            items.insert(items.end(), leaf->items, leaf->items + leaf->count);
            return;
        }
        collect(b.left, items);
        collect(b.right, items);
    }

    uint32_t max_leaf_;
    std::vector<BinaryNode> bins_;
    std::vector<std::array<Cost, kWideSlots - 1>> cost_;
    std::vector<std::array<uint8_t, kWideSlots>> split_;
    std::vector<bool> leaf_;
    bool root_as_leaf_ = false;
};

} // namespace

double half_area(const RTCBounds& b) {
    const double dx = std::max(0.0, double(b.upper_x) - double(b.lower_x));
    const double dy = std::max(0.0, double(b.upper_y) - double(b.lower_y));
    const double dz = std::max(0.0, double(b.upper_z) - double(b.lower_z));
    return dx * dy + dy * dz + dz * dx;
}

WideTree collapse_to_wide(const TreeNode* root, const RTCBounds& bounds, uint32_t max_leaf) {
    if (!root) {
        WideTree empty;
        empty.nodes.emplace_back();
        empty.bounds = bounds;
        return empty;
    }
    return Collapse(root, bounds, max_leaf).tree();
}

double wide_tree_cost(const WideTree& tree) {
    if (tree.nodes.empty() || tree.nodes[0].slots == 0) return 0.0;
    double cost = kCollapseNodeCost * half_area(tree.bounds);
    for (const WideTreeNode& n : tree.nodes)
        for (uint32_t s = 0; s < n.slots; ++s) {
            const WideSlot& slot = n.slot[s];
            const double area = half_area(slot.bounds);
            cost += slot.count > 0 ? kCollapsePrimitiveCost * area * slot.count
                                   : kCollapseNodeCost * area;
        }
    return cost;
}

} // namespace tp
