// The per-ray work a compute-mode BVH (bvh_builder.h) is expected to cost, from its boxes
// alone: the surface area heuristic's probability that a ray through the root's box meets a
// box, A(box) / A(root) (MacDonald & Booth 1990), summed over what meeting it costs. With two
// levels a mesh tree's work is counted once per instance, weighted by the probability of
// meeting the instance's world box; its boxes' probabilities are taken relative to the mesh's
// root in object space (an affine map keeps the ratios of a uniform ray distribution's
// hitting probabilities only approximately; they serve to compare layouts, not to predict).
//
// `--bvh auto` builds both layouts and chooses by their estimates (auto_prefers_wide); the rule
// and where its threshold comes from are in docs/gpu.md ("Choosing a layout: --bvh auto").
#pragma once

#include <string>

namespace tp {

struct BvhBuild;
struct FlatScene;

struct BvhEstimate {
    double nodes = 0;     // node visits per ray
    double boxes = 0;     // child boxes evaluated: 2 per binary node visit, 8 per wide one
    double triangles = 0; // triangle tests
    double instances = 0; // instance entries (two levels)
};

// `scene`: the scene the BVH was built for (its instances' meshes).
BvhEstimate estimate_bvh_work(const BvhBuild& bvh, const FlatScene& scene);

// Wide where the binary tree's traversal is long: at least kAutoWideMinBinaryNodes node visits
// per ray. A wide node replaces about three binary visits (a dependent load and a stack entry
// each) with eight box tests; the saved visits pay for the tests only in a deep tree, and on
// the H200, whose traversal is bound by instructions, not in one of a few dozen triangles or a
// handful of instances. A heuristic fitted to fifteen scenes (docs/gpu.md, "Choosing a layout").
constexpr double kAutoWideMinBinaryNodes = 20;
bool auto_prefers_wide(const BvhEstimate& binary);

// "nodes N boxes B triangles T instances I", for the render statistics.
std::string describe(const BvhEstimate& e);

} // namespace tp
