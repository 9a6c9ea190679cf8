// Closest-hit and occlusion queries on the CPU reference's acceleration structure
// (embree_accel.h: Embree with the exact-triangle filter), for checks that aim rays at a scene
// directly.
#pragma once

#include "render/closest_hits.h"
#include "scene/flatten.h"
#include "shared/path.h"

#include <vector>

namespace tp {

// With FEATURE_ALPHA in `features`, a surface is there only where its alpha covers the hit
// (shared/alpha.h), as in a render and in the GPU's ray queries.
ClosestHits closest_hits_cpu(const FlatScene& scene, const std::vector<Ray>& rays,
                             uint32_t features);

} // namespace tp
