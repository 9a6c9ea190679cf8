// The SAH-optimal collapse of a binary BVH into an 8-wide one
// (vulkan_rt/compute_mode/wide_collapse.h, Ylitie, Karras & Laine, HPG 2017, sec. 3) against an
// exhaustive search: on random binary trees, the least cost over every wide tree whose nodes are
// unions of binary subtrees (every choice of up to 8 slot roots below each node, each a leaf of at
// most max_leaf items or a node of its own) must equal the cost the dynamic program reports, and
// the tree it chose must have that cost when evaluated from its boxes, hold every item once in
// leaves of at most max_leaf, give each slot the box of its binary subtree and have the node,
// item and level counts the program reports. Host only: no device needed.
#include "shaders/cwbvh.h"
#include "vulkan_rt/compute_mode/wide_collapse.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>

namespace tp {
namespace {

// A binary tree built by hand, in the shape Embree hands over (embree_tree.h).
class Forest {
  public:
    // A random tree over `leaves` items with random boxes; every `flat`-th item is a point.
    TreeNode* random(std::mt19937& rng, uint32_t leaves, uint32_t flat, RTCBounds& box) {
        return split(rng, 0, leaves, flat, box);
    }

    // A balanced tree of 2^levels point items at the origin: every cost is 0.
    TreeNode* points(uint32_t levels, uint32_t& next, RTCBounds& box) {
        box = RTCBounds{};
        if (levels == 0) return leaf(next++);
        RTCBounds a, b;
        TreeNode* l = points(levels - 1, next, a);
        TreeNode* r = points(levels - 1, next, b);
        return inner(l, a, r, b);
    }

  private:
    TreeNode* split(std::mt19937& rng, uint32_t first, uint32_t count, uint32_t flat,
                    RTCBounds& box) {
        if (count == 1) {
            std::uniform_real_distribution<float> u(-10.0f, 10.0f), size(0.0f, 3.0f);
            const float x = u(rng), y = u(rng), z = u(rng);
            const bool point = flat > 0 && first % flat == 0;
            const float sx = point ? 0.0f : size(rng), sy = point ? 0.0f : size(rng),
                        sz = point ? 0.0f : size(rng);
            box = RTCBounds{x, y, z, 0.0f, x + sx, y + sy, z + sz, 0.0f};
            return leaf(first);
        }
        const uint32_t left = std::uniform_int_distribution<uint32_t>(1, count - 1)(rng);
        RTCBounds a, b;
        TreeNode* l = split(rng, first, left, flat, a);
        TreeNode* r = split(rng, first + left, count - left, flat, b);
        box = RTCBounds{std::min(a.lower_x, b.lower_x), std::min(a.lower_y, b.lower_y),
                        std::min(a.lower_z, b.lower_z), 0.0f,
                        std::max(a.upper_x, b.upper_x), std::max(a.upper_y, b.upper_y),
                        std::max(a.upper_z, b.upper_z), 0.0f};
        return inner(l, a, r, b);
    }

    TreeNode* leaf(uint32_t item) {
        items_.push_back(item);
        TreeLeaf& l = leaves_.emplace_back();
        l.count = 1;
        l.items = &items_.back();
        return &l;
    }

    TreeNode* inner(TreeNode* l, const RTCBounds& a, TreeNode* r, const RTCBounds& b) {
        TreeInner& n = inners_.emplace_back();
        n.children = 2;
        n.child[0] = l;
        n.child[1] = r;
        n.bounds[0] = a;
        n.bounds[1] = b;
        return &n;
    }

    std::deque<uint32_t> items_;
    std::deque<TreeLeaf> leaves_;
    std::deque<TreeInner> inners_;
};

uint32_t items_below(const TreeNode* n) {
    if (n->count > 0) return n->count;
    const auto* i = static_cast<const TreeInner*>(n);
    return items_below(i->child[0]) + items_below(i->child[1]);
}

// The exhaustive search: every set of at most `budget` slot roots that covers a subtree, and
// the least cost of a node over every such set below it.
class Exhaustive {
  public:
    explicit Exhaustive(uint32_t max_leaf) : max_leaf_(max_leaf) {}

    // The least cost of the whole tree with the root as a wide node.
    double tree(const TreeNode* root, const RTCBounds& box) {
        const double area = half_area(box);
        double best = kCollapseNodeCost * area;
        if (root->count > 0) return best + kCollapsePrimitiveCost * area * root->count;
        double below = forest_cost(root);
        const uint32_t items = items_below(root);
        if (items <= max_leaf_) below = std::min(below, kCollapsePrimitiveCost * area * items);
        return best + below;
    }

  private:
    struct Root {
        const TreeNode* node;
        RTCBounds box;
    };

    // Every cover of `n` (box `box`) by at most `budget` subtree roots.
    void covers(const TreeNode* n, const RTCBounds& box, uint32_t budget,
                std::vector<std::vector<Root>>& out) {
        out.push_back({{n, box}});
        if (n->count > 0 || budget < 2) return;
        const auto* i = static_cast<const TreeInner*>(n);
        std::vector<std::vector<Root>> left, right;
        covers(i->child[0], i->bounds[0], budget - 1, left);
        covers(i->child[1], i->bounds[1], budget - 1, right);
        for (const auto& l : left)
            for (const auto& r : right) {
                if (l.size() + r.size() > budget) continue;
                std::vector<Root> both = l;
                both.insert(both.end(), r.begin(), r.end());
                out.push_back(both);
            }
    }

    // The least cost of the slots of a wide node made from inner binary node n.
    double forest_cost(const TreeNode* n) {
        const auto* i = static_cast<const TreeInner*>(n);
        std::vector<std::vector<Root>> left, right;
        covers(i->child[0], i->bounds[0], kWideSlots - 1, left);
        covers(i->child[1], i->bounds[1], kWideSlots - 1, right);
        double best = std::numeric_limits<double>::infinity();
        for (const auto& l : left)
            for (const auto& r : right) {
                if (l.size() + r.size() > kWideSlots) continue;
                double c = 0.0;
                for (const Root& root : l) c += slot_cost(root);
                for (const Root& root : r) c += slot_cost(root);
                best = std::min(best, c);
            }
        return best;
    }

    // The least cost of one slot: a leaf, or a wide node of its own.
    double slot_cost(const Root& r) {
        const auto memo = memo_.find(r.node);
        if (memo != memo_.end()) return memo->second;
        const double area = half_area(r.box);
        const uint32_t items = items_below(r.node);
        double best = items <= max_leaf_ ? kCollapsePrimitiveCost * area * items
                                         : std::numeric_limits<double>::infinity();
        if (r.node->count == 0)
            best = std::min(best, kCollapseNodeCost * area + forest_cost(r.node));
        memo_[r.node] = best;
        return best;
    }

    uint32_t max_leaf_;
    std::map<const TreeNode*, double> memo_;
};

bool contains(const RTCBounds& a, const RTCBounds& b) {
    return a.lower_x <= b.lower_x && a.lower_y <= b.lower_y && a.lower_z <= b.lower_z &&
           a.upper_x >= b.upper_x && a.upper_y >= b.upper_y && a.upper_z >= b.upper_z;
}

// Every binary subtree's box, by the items below it, to check the slots' boxes.
void subtree_boxes(const TreeNode* n, const RTCBounds& box,
                   std::map<std::set<uint32_t>, RTCBounds>& out, std::set<uint32_t>& items) {
    items.clear();
    if (n->count > 0) {
        const auto* l = static_cast<const TreeLeaf*>(n);
        items.insert(l->items, l->items + l->count);
    } else {
        const auto* i = static_cast<const TreeInner*>(n);
        std::set<uint32_t> a, b;
        subtree_boxes(i->child[0], i->bounds[0], out, a);
        subtree_boxes(i->child[1], i->bounds[1], out, b);
        items = a;
        items.insert(b.begin(), b.end());
    }
    out[items] = box;
}

// Checks the chosen tree's structure against the binary tree and the program's counts; returns
// its cost evaluated from its boxes.
double check_tree(const WideCollapse& c, const TreeNode* root, const RTCBounds& box,
                  uint32_t max_leaf) {
    std::map<std::set<uint32_t>, RTCBounds> boxes;
    std::set<uint32_t> all;
    subtree_boxes(root, box, boxes, all);
    std::multiset<uint32_t> seen;
    uint32_t nodes = 0, depth = 0;
    double cost = kCollapseNodeCost * half_area(box);
    std::function<std::set<uint32_t>(const WideSlot*, uint32_t, uint32_t)> walk =
        [&](const WideSlot* slots, uint32_t count, uint32_t level) {
            ++nodes;
            depth = std::max(depth, level);
            REQUIRE(count >= 1);
            REQUIRE(count <= kWideSlots);
            std::set<uint32_t> below;
            for (uint32_t s = 0; s < count; ++s) {
                const WideSlot& slot = slots[s];
                const double area = half_area(slot.bounds);
                std::set<uint32_t> items;
                if (slot.count > 0) {
                    REQUIRE(slot.count <= max_leaf);
                    std::vector<uint32_t> leaf(slot.count);
                    wide_leaf_items(slot.node, leaf.data());
                    items.insert(leaf.begin(), leaf.end());
                    seen.insert(leaf.begin(), leaf.end());
                    cost += kCollapsePrimitiveCost * area * slot.count;
                } else {
                    const auto* inner = static_cast<const TreeInner*>(slot.node);
                    WideSlot child[kWideSlots];
                    const uint32_t n = wide_node_slots(inner, child);
                    items = walk(child, n, level + 1);
                    CHECK(inner->scratch.items == items.size());
                    cost += kCollapseNodeCost * area;
                }
                // A slot is a binary subtree, with that subtree's box.
                const auto sub = boxes.find(items);
                REQUIRE(sub != boxes.end());
                CHECK(std::memcmp(&sub->second, &slot.bounds, sizeof(RTCBounds)) == 0);
                CHECK(contains(box, slot.bounds));
                below.insert(items.begin(), items.end());
            }
            return below;
        };
    WideSlot slots[kWideSlots];
    const uint32_t n = wide_root_slots(root, box, c, slots);
    CHECK(walk(slots, n, 1) == all);
    CHECK(seen.size() == all.size());
    CHECK(c.nodes == nodes);
    CHECK(c.items == all.size());
    CHECK(c.depth == depth);
    return cost;
}

} // namespace

TEST_CASE("wide collapse: the dynamic program finds the least SAH cost of any collapse",
          "[wide_bvh]") {
    std::mt19937 rng(3);
    for (int trial = 0; trial < 60; ++trial) {
        const uint32_t leaves = 1 + trial % 23;
        const uint32_t max_leaf = trial % 3 == 0 ? 1 : CWBVH_MAX_LEAF;
        const uint32_t flat = trial % 4 == 1 ? 3 : 0;
        Forest forest;
        RTCBounds box;
        TreeNode* root = forest.random(rng, leaves, flat, box);
        INFO("trial " << trial << ": " << leaves << " items, leaves of at most " << max_leaf);
        const WideCollapse c = collapse_to_wide(root, box, max_leaf);
        const double exhaustive = Exhaustive(max_leaf).tree(root, box);
        // The program sums the same terms in another order: relative rounding of a few ulp.
        CHECK(c.cost == Approx(exhaustive).epsilon(1e-12));
        CHECK(check_tree(c, root, box, max_leaf) == Approx(c.cost).epsilon(1e-12));
    }
}

TEST_CASE("wide collapse: flat subtrees, where every cost ties at 0, stay shallow", "[wide_bvh]") {
    // 2^9 points: with ties going to the wider forest, 8 slots take 3 binary levels, so 9
    // levels need 3 wide ones over leaves of 1; 4 allows leaves formed one level higher.
    Forest forest;
    RTCBounds box;
    uint32_t next = 0;
    TreeNode* root = forest.points(9, next, box);
    const WideCollapse c = collapse_to_wide(root, box, CWBVH_MAX_LEAF);
    CHECK(c.cost == 0.0);
    CHECK(check_tree(c, root, box, CWBVH_MAX_LEAF) == 0.0);
    CHECK(c.depth <= 4);
}

TEST_CASE("wide collapse: an empty tree and a tree of one leaf", "[wide_bvh]") {
    const RTCBounds box{0, 0, 0, 0, 1, 2, 3, 0};
    const WideCollapse empty = collapse_to_wide(nullptr, box, CWBVH_MAX_LEAF);
    CHECK(empty.nodes == 1);
    CHECK(empty.items == 0);
    CHECK(empty.cost == 0.0);
    uint32_t item = 7;
    TreeLeaf leaf;
    leaf.count = 1;
    leaf.items = &item;
    const WideCollapse one = collapse_to_wide(&leaf, box, CWBVH_MAX_LEAF);
    CHECK(one.nodes == 1);
    WideSlot slots[kWideSlots];
    REQUIRE(wide_root_slots(&leaf, box, one, slots) == 1);
    CHECK(slots[0].count == 1);
    uint32_t got = 0;
    wide_leaf_items(slots[0].node, &got);
    CHECK(got == 7);
    // The root node and its one triangle: (1 + 0.3) x half the area, 2 + 6 + 3.
    CHECK(one.cost == Approx(1.3 * 11.0));
}

} // namespace tp
