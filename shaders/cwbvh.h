// The compressed 8-wide BVH node of compute mode (Ylitie, Karras & Laine, "Efficient Incoherent
// Ray Traversal on GPUs Through Compressed Wide BVHs", HPG 2017, sec. 3.1), as the host writes it
// (vulkan_rt/compute_mode/wide_bvh.h) and shaders/trace_cwbvh.glsl reads it: 80 bytes, five
// 16-byte words.
//
//   word 0  p.x, p.y, p.z (float)    e.x | e.y << 8 | e.z << 16 | imask << 24
//   word 1  child_base  triangle_base  meta[0..3]  meta[4..7]
//   word 2  qlo_x[0..7]              qlo_y[0..7]
//   word 3  qlo_z[0..7]              qhi_x[0..7]
//   word 4  qhi_y[0..7]              qhi_z[0..7]
//
// Slot i's box is p + 2^(e - 127) * (qlo[i], qhi[i]) per axis, the 8-bit q rounded outward so
// that this box, in exact arithmetic, contains the child's. meta[i]: 0 for an empty slot;
// CWBVH_META_INNER | i for an inner child, which is node child_base + (the inner children in the
// slots below i: popcount of imask below bit i); for a leaf of k <= 3 triangles
// (2^k - 1) << 5 | o, its items being triangle_base + o .. + k - 1 with o < 24. The children sit
// in the slots by the direction they lie in from the node's centre (host: octant order), so that
// visiting the hit slots in the order slot ^ (the ray's octant) visits them roughly front to back.
//
// The triangle buffer, in 16-byte words:
//
//   word 0            x: the first word of the ID table, y: b, the instance's bits in an ID
//   words 1 + 3 i ..  record i: (v0, n.x), (v1, n.y), (v2, n.z), floats, n = (v1 - v0) x (v2 - v0)
//                     (shared/intersect.h); a top-level item: x of its first word = the instance
//   the ID table      what a hit on record i reports, as uints: uint i = primitive << b | instance
//                     (two levels: b = 0, the primitive, the instance being the one entered), or
//                     where the two do not fit 32 bits, b = CWBVH_ID_PAIRS and uints 2 i, 2 i + 1
//                     = primitive, instance
#ifndef TP_SHADERS_CWBVH_H
#define TP_SHADERS_CWBVH_H

#include "shared/lang.h"

TP_NAMESPACE_BEGIN

const uint CWBVH_NODE_WORDS = 5u;    // 16-byte words per node
const uint CWBVH_TRIANGLE_WORDS = 3u; // 16-byte words per triangle record
const uint CWBVH_ID_PAIRS = 32u;      // the ID table's b for (primitive, instance) pairs
const uint CWBVH_MAX_LEAF = 3u;      // triangles per leaf: 8 slots x 3 = the 24 triangle bits
const uint CWBVH_META_INNER = 0x38u; // 001 (one hit bit) << 5 | 24: bit 24 + slot of a hit mask
const uint CWBVH_STACK_SIZE = 32u;   // traversal stack entries; the builder checks the depth

TP_NAMESPACE_END

#endif // TP_SHADERS_CWBVH_H
