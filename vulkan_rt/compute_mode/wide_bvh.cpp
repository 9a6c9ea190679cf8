#include "vulkan_rt/compute_mode/wide_bvh.h"

#include "shared/intersect.h"
#include "util/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include <tbb/parallel_for.h>

namespace tp {
namespace {

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
std::array<int, 8> assign_slots(const WideSlot* children, uint32_t count, glm::dvec3 centre) {
    double cost[8][8];
    for (size_t c = 0; c < count; ++c) {
        const glm::dvec3 d = 0.5 * (lower(children[c].bounds) + upper(children[c].bounds)) - centre;
        for (int s = 0; s < 8; ++s)
            cost[c][s] = ((s & 4) ? -d.x : d.x) + ((s & 2) ? -d.y : d.y) + ((s & 1) ? -d.z : d.z);
    }
    std::array<int, 8> child_of_slot;
    child_of_slot.fill(-1);
    std::array<bool, 8> placed{};
    for (size_t k = 0; k < count; ++k) {
        int best_c = -1, best_s = -1;
        for (size_t c = 0; c < count; ++c) {
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
    explicit WideWriter(WideBvhNode* nodes, const LeafWriter& write_leaf)
        : nodes_(nodes), write_leaf_(write_leaf) {}

    // Writes the wide node of `slots` as nodes_[index], its inner children at `child_base` on,
    // their subtrees after them, and its leaves' items from `item_base`.
    void write(const WideSlot* slots, uint32_t count, uint32_t index, uint32_t child_base,
               uint32_t item_base, uint32_t level) const {
        glm::dvec3 lo(FLOAT_MAX), hi(-FLOAT_MAX);
        for (uint32_t s = 0; s < count; ++s) {
            lo = glm::min(lo, lower(slots[s].bounds));
            hi = glm::max(hi, upper(slots[s].bounds));
        }
        const std::array<int, 8> child_of_slot = assign_slots(slots, count, 0.5 * (lo + hi));
        WideBvhNode n{};
        AxisFrame frame[3];
        for (int a = 0; a < 3; ++a) {
            frame[a] = axis_frame(lo[a], hi[a]);
            n.p[a] = float(frame[a].p);
            n.e[a] = uint8_t(frame[a].k + 127);
        }
        n.child_base = child_base;
        uint32_t inner = 0, offset = 0;
        const TreeInner* pending[8]; // inner children in slot order
        for (uint32_t s = 0; s < 8; ++s) {
            if (child_of_slot[s] < 0) continue;
            const WideSlot& c = slots[child_of_slot[s]];
            for (int a = 0; a < 3; ++a)
                quantize(frame[a], lower(c.bounds)[a], upper(c.bounds)[a], n.qlo[a][s],
                         n.qhi[a][s]);
            if (c.count == 0) {
                n.meta[s] = uint8_t(CWBVH_META_INNER | s);
                n.imask = uint8_t(n.imask | (1u << s));
                pending[inner++] = static_cast<const TreeInner*>(c.node);
                continue;
            }
            // A leaf fits the 3 bits of its meta's hit mask; a node's leaves, the 24 triangle bits.
            if (c.count > CWBVH_MAX_LEAF) runtime_error("wide BVH: a leaf holds too many items");
            uint32_t items[CWBVH_MAX_LEAF];
            wide_leaf_items(c.node, items);
            write_leaf_(items, c.count, item_base + offset);
            if (offset == 0) n.triangle_base = item_base;
            n.meta[s] = uint8_t(((1u << c.count) - 1u) << 5 | offset);
            offset += c.count;
        }
        nodes_[index] = n;
        // Child k's subtree: its node at child_base + k, its descendants after the block of
        // children and the earlier children's descendants; its items after theirs.
        uint32_t descendants[8], items[8];
        uint32_t next_node = child_base + inner, next_item = item_base + offset;
        for (uint32_t k = 0; k < inner; ++k) {
            descendants[k] = next_node;
            items[k] = next_item;
            next_node += pending[k]->scratch.nodes - 1;
            next_item += pending[k]->scratch.items;
        }
        auto child = [&](uint32_t k) {
            WideSlot child_slots[kWideSlots];
            const uint32_t count = wide_node_slots(pending[k], child_slots);
            write(child_slots, count, child_base + k, descendants[k], items[k], level + 1);
        };
        if (level < kParallelLevels && inner > 1) {
            tbb::parallel_for(uint32_t(0), inner, child);
        } else {
            for (uint32_t k = 0; k < inner; ++k) child(k);
        }
    }

  private:
    WideBvhNode* nodes_;
    const LeafWriter& write_leaf_;
};

// The bits that hold v: 0 for 0.
uint32_t bit_width(uint32_t v) {
    uint32_t n = 0;
    while (v >> n) ++n;
    return n;
}

// The records' words: (v0, n.x), (v1, n.y), (v2, n.z) (cwbvh.h).
glm::uvec4 record_word(vec3 v, float n) {
    return glm::uvec4(glm::floatBitsToUint(v.x), glm::floatBitsToUint(v.y),
                      glm::floatBitsToUint(v.z), glm::floatBitsToUint(n));
}

} // namespace

void write_wide_tree(const TreeNode* root, const RTCBounds& bounds, const WideCollapse& c,
                     WideBvhNode* nodes, uint32_t node_base, uint32_t item_base,
                     const LeafWriter& write_leaf) {
    nodes[node_base] = WideBvhNode{};
    if (!root) return;
    WideSlot slots[kWideSlots];
    const uint32_t count = wide_root_slots(root, bounds, c, slots);
    WideWriter(nodes, write_leaf).write(slots, count, node_base, node_base + 1, item_base, 0);
}

void wide_child_box(const WideBvhNode& node, uint32_t slot, glm::dvec3& lo, glm::dvec3& hi) {
    for (int a = 0; a < 3; ++a) {
        const double scale = std::ldexp(1.0, int(node.e[a]) - 127);
        lo[a] = double(node.p[a]) + scale * node.qlo[a][slot];
        hi[a] = double(node.p[a]) + scale * node.qhi[a][slot];
    }
}

void WideTriangleBuffer::resize(uint32_t records) {
    records_ = records;
    words_.assign(1 + size_t(CWBVH_TRIANGLE_WORDS) * records, glm::uvec4(0u)); // header first
    primitive_.assign(records, 0u);
    instance_.assign(records, 0u);
}

void WideTriangleBuffer::set_triangle(uint32_t record, vec3 v0, vec3 v1, vec3 v2,
                                      uint32_t primitive, uint32_t instance) {
    const vec3 n = triangle_plane_normal(v0, v1, v2);
    glm::uvec4* w = &words_[1 + size_t(CWBVH_TRIANGLE_WORDS) * record];
    w[0] = record_word(v0, n.x);
    w[1] = record_word(v1, n.y);
    w[2] = record_word(v2, n.z);
    primitive_[record] = primitive;
    instance_[record] = instance;
}

void WideTriangleBuffer::set_instance(uint32_t record, uint32_t instance) {
    words_[1 + size_t(CWBVH_TRIANGLE_WORDS) * record] = glm::uvec4(instance, 0u, 0u, 0u);
    instance_[record] = instance;
}

void WideTriangleBuffer::finish(bool one_level) {
    if (words_.empty()) resize(0);
    // One uint per record, primitive << bits | instance, where the instance's bits and the
    // primitive's fit 32 (always with two levels, whose IDs are primitives alone); else two.
    uint32_t bits = 0, primitive_bits = 0;
    for (uint32_t i = 0; i < records_; ++i) {
        if (one_level) bits = std::max(bits, bit_width(instance_[i]));
        primitive_bits = std::max(primitive_bits, bit_width(primitive_[i]));
    }
    if (bits + primitive_bits > 32) bits = CWBVH_ID_PAIRS;
    words_[0] = glm::uvec4(uint32_t(words_.size()), bits, 0u, 0u);
    std::vector<uint32_t> ids;
    ids.reserve(bits == CWBVH_ID_PAIRS ? 2 * size_t(records_) : records_);
    for (uint32_t i = 0; i < records_; ++i) {
        if (bits == CWBVH_ID_PAIRS) {
            ids.push_back(primitive_[i]);
            ids.push_back(instance_[i]);
        } else {
            ids.push_back(bits == 0 ? primitive_[i] : primitive_[i] << bits | instance_[i]);
        }
    }
    ids.resize((ids.size() + 3) / 4 * 4, 0u);
    for (size_t i = 0; i < ids.size(); i += 4)
        words_.push_back(glm::uvec4(ids[i], ids[i + 1], ids[i + 2], ids[i + 3]));
    primitive_.clear();
    primitive_.shrink_to_fit();
    instance_.clear();
    instance_.shrink_to_fit();
}

WideTriangle WideTriangleBuffer::triangle(uint32_t record) const {
    const glm::uvec4* w = &words_[1 + size_t(CWBVH_TRIANGLE_WORDS) * record];
    auto v = [](glm::uvec4 u) { return glm::uintBitsToFloat(glm::uvec3(u)); };
    WideTriangle t;
    t.v0 = v(w[0]);
    t.v1 = v(w[1]);
    t.v2 = v(w[2]);
    t.normal = glm::uintBitsToFloat(glm::uvec3(w[0].w, w[1].w, w[2].w));
    return t;
}

uint32_t WideTriangleBuffer::instance_item(uint32_t record) const {
    return words_[1 + size_t(CWBVH_TRIANGLE_WORDS) * record].x;
}

uint32_t WideTriangleBuffer::id(uint32_t index) const {
    return words_[words_[0].x + index / 4][index % 4];
}

uint32_t WideTriangleBuffer::primitive(uint32_t record) const {
    const uint32_t bits = words_[0].y;
    return bits == CWBVH_ID_PAIRS ? id(2 * record) : id(record) >> bits;
}

uint32_t WideTriangleBuffer::instance(uint32_t record) const {
    const uint32_t bits = words_[0].y;
    return bits == CWBVH_ID_PAIRS ? id(2 * record + 1) : id(record) & ((1u << bits) - 1u);
}

} // namespace tp
