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

// Wide where its child-box evaluations per ray are at most kAutoBoxRatio times binary's: on the
// H200 the traversal is bound by instructions, and the box evaluations are what the wide
// layout adds (docs/gpu.md).
constexpr double kAutoBoxRatio = 1.5;
bool auto_prefers_wide(const BvhEstimate& wide, const BvhEstimate& binary);

// "nodes N boxes B triangles T instances I", for the render statistics.
std::string describe(const BvhEstimate& e);

} // namespace tp
