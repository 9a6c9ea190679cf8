#include "vulkan_rt/accel/wide_bvh.h"

#include "util/error.h"
#include "vulkan_rt/accel/embree_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace tp {
namespace {

struct Child {
    const TreeNode* node;
    RTCBounds bounds;
};

glm::dvec3 lower(const RTCBounds& b) {
    return {b.lower_x, b.lower_y, b.lower_z};
}
glm::dvec3 upper(const RTCBounds& b) {
    return {b.upper_x, b.upper_y, b.upper_z};
}

// Slot of each child by the octant ordering of Ylitie et al. sec. 3.2: slot s is first for rays
// of direction D_s = (s & 4 ? -1 : 1, s & 2 ? -1 : 1, s & 1 ? -1 : 1) (octant code s ^ 7, bit
// set for a positive component, shaders/trace_cwbvh.glsl), and such a ray meets first the child
// whose centre lies farthest against D_s from the node's centre: least dot(c - centre, D_s),
// the cost of (child, s). The paper solves the assignment with an auction; this takes the
// cheapest free (child, slot) pair until every child has a slot.
std::array<int, 8> assign_slots(const std::vector<Child>& children, glm::dvec3 centre) {
    double cost[8][8];
    for (size_t c = 0; c < children.size(); ++c) {
        const glm::dvec3 d = 0.5 * (lower(children[c].bounds) + upper(children[c].bounds)) - centre;
        for (int s = 0; s < 8; ++s)
            cost[c][s] = ((s & 4) ? -d.x : d.x) + ((s & 2) ? -d.y : d.y) + ((s & 1) ? -d.z : d.z);
    }
    std::array<int, 8> child_of_slot;
    child_of_slot.fill(-1);
    std::array<bool, 8> placed{};
    for (size_t k = 0; k < children.size(); ++k) {
        int best_c = -1, best_s = -1;
        for (size_t c = 0; c < children.size(); ++c) {
            if (placed[c]) continue;
            for (int s = 0; s < 8; ++s)
                if (child_of_slot[s] < 0 && (best_c < 0 || cost[c][s] < cost[best_c][best_s])) {
                    best_c = int(c);
                    best_s = s;
                }
        }
        placed[best_c] = true;
        child_of_slot[best_s] = best_c;
    }
    return child_of_slot;
}

// One axis of the quantization frame: p and the scale's exponent k (scale 2^k). E is the
// exponent of the axis's largest magnitude in the node; p is the node's low bound rounded down
// to a multiple of 2^(E - 23) (a float: at most 24 significant bits below 2^(E + 1)), and k the
// least exponent >= E - 31 with p + 255 * 2^k >= hi. Every p + 2^k q then is a multiple of
// 2^(E - 31) below 2^(E + 2): 33 bits, exact in double, which makes the containment checks of
// quantize() exact. The lower bound on k costs nothing: a float box that is not flat is at least
// one ulp, 2^(E - 23) = 256 * 2^(E - 31), wide.
struct AxisFrame {
    double p;
    int k;
};

AxisFrame axis_frame(double lo, double hi) {
    const double m = std::max(std::abs(lo), std::abs(hi));
    const int E = m >= 0x1p-126 ? std::ilogb(m) : -126;
    const double grid = std::ldexp(1.0, E - 23);
    AxisFrame f{std::floor(lo / grid) * grid, std::max(E - 31, -126)};
    while (f.p + 255.0 * std::ldexp(1.0, f.k) < hi) ++f.k;
    return f;
}

// q_lo = the largest q with p + 2^k q <= lo, q_hi = the least with p + 2^k q >= hi: the
// decoded box contains [lo, hi] exactly (the sums are exact in double, see axis_frame).
void quantize(const AxisFrame& f, double lo, double hi, uint8_t& qlo, uint8_t& qhi) {
    const double scale = std::ldexp(1.0, f.k);
    double q = std::clamp(std::floor((lo - f.p) / scale), 0.0, 255.0);
    while (q > 0.0 && f.p + scale * q > lo) q -= 1.0;
    qlo = uint8_t(q);
    q = std::clamp(std::ceil((hi - f.p) / scale), 0.0, 255.0);
    while (q < 255.0 && f.p + scale * q < hi) q += 1.0;
    qhi = uint8_t(q);
}

class WideWriter {
  public:
    WideWriter(std::vector<WideBvhNode>& nodes, const LeafEmitter& emit_leaf)
        : nodes_(nodes), emit_leaf_(emit_leaf) {}

    void write(uint32_t index, const std::vector<Child>& children, uint32_t level) {
        depth = std::max(depth, level);
        glm::dvec3 lo(FLOAT_MAX), hi(-FLOAT_MAX);
        for (const Child& c : children) {
            lo = glm::min(lo, lower(c.bounds));
            hi = glm::max(hi, upper(c.bounds));
        }
        const std::array<int, 8> child_of_slot = assign_slots(children, 0.5 * (lo + hi));
        WideBvhNode n{};
        AxisFrame frame[3];
        for (int a = 0; a < 3; ++a) {
            frame[a] = axis_frame(lo[a], hi[a]);
            n.p[a] = float(frame[a].p);
            n.e[a] = uint8_t(frame[a].k + 127);
        }
        n.child_base = uint32_t(nodes_.size());
        uint32_t inner = 0, offset = 0;
        std::vector<std::pair<uint32_t, const TreeInner*>> pending;
        for (uint32_t s = 0; s < 8; ++s) {
            if (child_of_slot[s] < 0) continue;
            const Child& c = children[size_t(child_of_slot[s])];
            for (int a = 0; a < 3; ++a)
                quantize(frame[a], lower(c.bounds)[a], upper(c.bounds)[a], n.qlo[a][s],
                         n.qhi[a][s]);
            if (c.node->count == 0) {
                n.meta[s] = uint8_t(CWBVH_META_INNER | s);
                n.imask = uint8_t(n.imask | (1u << s));
                pending.push_back({n.child_base + inner++, static_cast<const TreeInner*>(c.node)});
                continue;
            }
            const auto* leaf = static_cast<const TreeLeaf*>(c.node);
            const uint32_t first = emit_leaf_(leaf->items, leaf->count);
            if (offset == 0) n.triangle_base = first;
            // The leaves of one node are stored back to back (the emitters append) and fit the
            // 24 triangle bits of a hit mask; Embree's leaves respect CWBVH_MAX_LEAF.
            if (first != n.triangle_base + offset || leaf->count > CWBVH_MAX_LEAF)
                runtime_error("wide BVH: leaf items out of order");
            n.meta[s] = uint8_t(((1u << leaf->count) - 1u) << 5 | offset);
            offset += leaf->count;
        }
        nodes_.resize(nodes_.size() + inner);
        nodes_[index] = n;
        for (const auto& [child_index, node] : pending) {
            std::vector<Child> grandchildren;
            for (uint32_t i = 0; i < node->children; ++i)
                grandchildren.push_back({node->child[i], node->bounds[i]});
            write(child_index, grandchildren, level + 1);
        }
    }

    uint32_t depth = 0;

  private:
    std::vector<WideBvhNode>& nodes_;
    const LeafEmitter& emit_leaf_;
};

} // namespace

uint32_t write_wide_tree(std::vector<WideBvhNode>& nodes, const TreeNode* root,
                         const RTCBounds& root_bounds, const LeafEmitter& emit_leaf,
                         uint32_t& depth) {
    const uint32_t index = uint32_t(nodes.size());
    nodes.push_back(WideBvhNode{});
    depth = 1;
    if (!root) return index; // no children: no slot is ever hit
    std::vector<Child> children;
    if (root->count > 0) {
        children.push_back({root, root_bounds}); // a tree of one leaf
    } else {
        const auto* inner = static_cast<const TreeInner*>(root);
        for (uint32_t i = 0; i < inner->children; ++i)
            children.push_back({inner->child[i], inner->bounds[i]});
    }
    WideWriter writer(nodes, emit_leaf);
    writer.write(index, children, 1);
    depth = writer.depth;
    return index;
}

void wide_child_box(const WideBvhNode& node, uint32_t slot, glm::dvec3& lo, glm::dvec3& hi) {
    for (int a = 0; a < 3; ++a) {
        const double scale = std::ldexp(1.0, int(node.e[a]) - 127);
        lo[a] = double(node.p[a]) + scale * node.qlo[a][slot];
        hi[a] = double(node.p[a]) + scale * node.qhi[a][slot];
    }
}

} // namespace tp
