// What an engine answers for a batch of rays aimed directly rather than rendered (the stress
// suite's watertightness check, the GPU traversal test): per ray the closest hit (distance,
// instance, triangle and barycentrics) and the occlusion query's answer, and how many traversals
// a loop budget cut short (compute mode on lavapipe), whose answers are not final.
#pragma once

#include "shared/lang.h"

#include <cstdint>
#include <vector>

namespace tp {

struct ClosestHits {
    std::vector<float> t;
    std::vector<uint8_t> found;
    // Where found: the FlatScene instance, the triangle within its mesh, and the weights of the
    // triangle's vertices 1 and 2 at the hit (as surface_point() expects them).
    std::vector<uint32_t> instance, primitive;
    std::vector<vec2> bary;
    // Whether anything lies on the ray up to tmax: the shadow ray's query.
    std::vector<uint8_t> occluded;
    uint64_t truncated = 0;

    explicit ClosestHits(size_t rays = 0)
        : t(rays), found(rays), instance(rays), primitive(rays), bary(rays), occluded(rays) {}
};

} // namespace tp
