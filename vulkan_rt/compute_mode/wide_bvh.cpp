#include "vulkan_rt/compute_mode/wide_bvh.h"

#include "shared/intersect.h"
#include "util/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace tp {
namespace {

struct Child {
    const WideSlot* slot;
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
    WideWriter(std::vector<WideBvhNode>& nodes, const WideTree& tree, const LeafEmitter& emit_leaf)
        : nodes_(nodes), tree_(tree), emit_leaf_(emit_leaf) {}

    // Writes tree node `t` as nodes_[index]; its inner children go to the end of nodes_.
    void write(uint32_t index, uint32_t t, uint32_t level) {
        depth = std::max(depth, level);
        const WideTreeNode& node = tree_.nodes[t];
        std::vector<Child> children;
        glm::dvec3 lo(FLOAT_MAX), hi(-FLOAT_MAX);
        for (uint32_t s = 0; s < node.slots; ++s) {
            children.push_back({&node.slot[s], node.slot[s].bounds});
            lo = glm::min(lo, lower(node.slot[s].bounds));
            hi = glm::max(hi, upper(node.slot[s].bounds));
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
        std::vector<std::pair<uint32_t, uint32_t>> pending; // (node index, tree node)
        for (uint32_t s = 0; s < 8; ++s) {
            if (child_of_slot[s] < 0) continue;
            const Child& c = children[size_t(child_of_slot[s])];
            for (int a = 0; a < 3; ++a)
                quantize(frame[a], lower(c.bounds)[a], upper(c.bounds)[a], n.qlo[a][s],
                         n.qhi[a][s]);
            if (c.slot->count == 0) {
                n.meta[s] = uint8_t(CWBVH_META_INNER | s);
                n.imask = uint8_t(n.imask | (1u << s));
                pending.push_back({n.child_base + inner++, c.slot->node});
                continue;
            }
            const uint32_t first = emit_leaf_(&tree_.items[c.slot->first], c.slot->count);
            if (offset == 0) n.triangle_base = first;
            // The leaves of one node are stored back to back (the emitters append) and fit the
            // 24 triangle bits of a hit mask.
            if (first != n.triangle_base + offset || c.slot->count > CWBVH_MAX_LEAF)
                runtime_error("wide BVH: leaf items out of order");
            n.meta[s] = uint8_t(((1u << c.slot->count) - 1u) << 5 | offset);
            offset += c.slot->count;
        }
        nodes_.resize(nodes_.size() + inner);
        nodes_[index] = n;
        for (const auto& [child_index, tree_node] : pending)
            write(child_index, tree_node, level + 1);
    }

    uint32_t depth = 0;

  private:
    std::vector<WideBvhNode>& nodes_;
    const WideTree& tree_;
    const LeafEmitter& emit_leaf_;
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

uint32_t write_wide_tree(std::vector<WideBvhNode>& nodes, const WideTree& tree,
                         const LeafEmitter& emit_leaf, uint32_t& depth) {
    const uint32_t index = uint32_t(nodes.size());
    nodes.push_back(WideBvhNode{}); // no slots: an empty tree, which no ray enters
    depth = 1;
    if (tree.nodes[0].slots == 0) return index;
    WideWriter writer(nodes, tree, emit_leaf);
    writer.write(index, 0, 1);
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

void WideTriangleBuffer::start() {
    if (words_.empty()) words_.push_back(glm::uvec4(0u)); // the header, set by finish()
}

uint32_t WideTriangleBuffer::add_triangle(vec3 v0, vec3 v1, vec3 v2, uint32_t primitive,
                                          uint32_t instance) {
    start();
    const vec3 n = triangle_plane_normal(v0, v1, v2);
    words_.push_back(record_word(v0, n.x));
    words_.push_back(record_word(v1, n.y));
    words_.push_back(record_word(v2, n.z));
    primitive_.push_back(primitive);
    instance_.push_back(instance);
    return records_++;
}

uint32_t WideTriangleBuffer::add_instance(uint32_t instance) {
    start();
    words_.push_back(glm::uvec4(instance, 0u, 0u, 0u));
    words_.push_back(glm::uvec4(0u));
    words_.push_back(glm::uvec4(0u));
    primitive_.push_back(0u);
    instance_.push_back(instance);
    return records_++;
}

void WideTriangleBuffer::finish(bool one_level) {
    start();
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
