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

// Appends the nodes of `tree` to `nodes` and returns the root's index; `depth`: node levels.
// `emit_leaf` stores a leaf's items as records (the items of one node back to back).
uint32_t write_wide_tree(std::vector<WideBvhNode>& nodes, const WideTree& tree,
                         const LeafEmitter& emit_leaf, uint32_t& depth);

// A triangle record as the traversal reads it.
struct WideTriangle {
    vec3 v0, v1, v2;
    vec3 normal; // (v1 - v0) x (v2 - v0), as triangle_plane_normal gives it
};

// The triangle buffer (BINDING_BVH_TRIS) of the wide layout, 16-byte words (cwbvh.h); empty
// until the first record (a binary build holds none).
class WideTriangleBuffer {
  public:
    // Appends a record and returns its index.
    uint32_t add_triangle(vec3 v0, vec3 v1, vec3 v2, uint32_t primitive, uint32_t instance);
    uint32_t add_instance(uint32_t instance); // a top-level item
    // Appends the ID table (cwbvh.h); no record may be added after.
    void finish(bool one_level);

    const std::vector<glm::uvec4>& words() const { return words_; }
    uint32_t records() const { return records_; }

    // Reading back, for the tests.
    WideTriangle triangle(uint32_t record) const;
    uint32_t instance_item(uint32_t record) const; // the instance a top-level record names
    uint32_t primitive(uint32_t record) const;
    uint32_t instance(uint32_t record) const; // one level

  private:
    void start();                      // the header word, before the first record
    uint32_t id(uint32_t index) const; // uint `index` of the ID table
    std::vector<glm::uvec4> words_;
    std::vector<uint32_t> primitive_, instance_; // until finish()
    uint32_t records_ = 0;
};

} // namespace tp
