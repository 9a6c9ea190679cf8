// The compute mode's compressed 8-wide BVH (Ylitie, Karras & Laine, HPG 2017, sec. 3.1; word
// layouts: shaders/cwbvh.h): the node, and the triangle buffer of 48-byte records with the hits'
// IDs in a table of their own. The tree is the SAH-optimal collapse of a binary Embree tree
// (wide_collapse.h); this file stores it: quantized boxes, octant-ordered slots, leaf records.
//
// A record holds the triangle's vertices and its plane normal, the floats of the binary
// layout's BvhTriangle (shared/intersect.h), so that the same watertight test gives the same
// hits; the primitive (and with one level the instance) it reports is read from the ID table
// once per closest-hit query, not in the leaf loop. Two levels: the top tree's leaf items are
// records whose first word names an instance, one per leaf.
#pragma once

#include "shaders/cwbvh.h"
#include "shared/math.h"
#include "vulkan_rt/compute_mode/wide_collapse.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tp {

struct WideBvhNode {
    float p[3];          // the quantization origin
    uint8_t e[3];        // per axis: the scale 2^(e - 127), a normal float's exponent byte
    uint8_t imask;       // bit i: slot i holds an inner child
    uint32_t child_base; // node index of the first inner child
    uint32_t triangle_base;
    uint8_t meta[8];   // per slot (cwbvh.h)
    uint8_t qlo[3][8]; // per axis, per slot: the box's low corner in steps of the scale
    uint8_t qhi[3][8];
};
static_assert(sizeof(WideBvhNode) == 16 * CWBVH_NODE_WORDS, "WideBvhNode is 80 bytes");

// Slot `slot`'s box, p + 2^(e - 127) q in exact arithmetic (the builder places p and the
// scales so that double holds these sums exactly).
void wide_child_box(const WideBvhNode& node, uint32_t slot, glm::dvec3& lo, glm::dvec3& hi);

// Writes the tree that collapse_to_wide chose over the binary tree `root` (nullptr: empty; box
// `bounds`) as nodes[node_base .. node_base + c.nodes), the root first, with its leaf items at
// item_base .. item_base + c.items (written by `write_leaf`; the items of one node back to back).
// Depth first, as a serial writer would append: a node, then the block of its inner children,
// then each child's subtree in slot order; the subtrees are written in parallel at offsets from
// their sizes (TreeScratch). An empty tree is a root without slots, which no ray enters.
void write_wide_tree(const TreeNode* root, const RTCBounds& bounds, const WideCollapse& c,
                     WideBvhNode* nodes, uint32_t node_base, uint32_t item_base,
                     const LeafWriter& write_leaf);

// A triangle record as the traversal reads it.
struct WideTriangle {
    vec3 v0, v1, v2;
    vec3 normal; // (v1 - v0) x (v2 - v0), as triangle_plane_normal gives it
};

// The triangle buffer (BINDING_BVH_TRIS) of the wide layout, 16-byte words (cwbvh.h); empty
// until sized (a binary build holds none).
class WideTriangleBuffer {
  public:
    // Makes room for `records` records, before any is set.
    void resize(uint32_t records);
    // Sets record `record`; different records may be set at once.
    void set_triangle(uint32_t record, vec3 v0, vec3 v1, vec3 v2, uint32_t primitive,
                      uint32_t instance);
    void set_instance(uint32_t record, uint32_t instance); // a top-level item
    // Appends the ID table (cwbvh.h); no record may be set after.
    void finish(bool one_level);

    const std::vector<glm::uvec4>& words() const { return words_; }
    uint32_t records() const { return records_; }

    // Reading back, for the tests.
    WideTriangle triangle(uint32_t record) const;
    uint32_t instance_item(uint32_t record) const; // the instance a top-level record names
    uint32_t primitive(uint32_t record) const;
    uint32_t instance(uint32_t record) const; // one level

  private:
    uint32_t id(uint32_t index) const; // uint `index` of the ID table
    std::vector<glm::uvec4> words_;
    std::vector<uint32_t> primitive_, instance_; // until finish()
    uint32_t records_ = 0;
};

} // namespace tp
