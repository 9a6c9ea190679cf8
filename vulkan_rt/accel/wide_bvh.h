// The compute mode's compressed 8-wide BVH node (Ylitie, Karras & Laine, HPG 2017, sec. 3.1;
// word layout and meta encoding: shaders/cwbvh.h). The host builds an 8-ary tree with Embree
// (embree_tree.h: rtcBuildBVH with maxBranchingFactor 8, leaves of at most 3 triangles) and
// stores every inner node as one of these; triangles stay BvhTriangle (shared/intersect.h), so
// the triangle test and what a hit reports are those of the binary layout.
//
// Two levels: the top tree's leaf items are records of the triangle array whose `instance`
// names the instance (the other fields zero); one level and mesh trees: triangles as in the
// binary layout.
#pragma once

#include "shaders/cwbvh.h"

#include <glm/glm.hpp>

#include <cstdint>

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

} // namespace tp
