// Random triangle soups for the BVH tests: scenes whose trees have every shape and scale.
#pragma once

#include "scene/flatten.h"

#include <cstdint>

namespace tp::test {

// `count` random triangles of size about `size` around points uniform in [-extent, extent]^3
// shifted by `centre`, under `instances` random placements (scale and translation), then with
// every `degenerate`-th triangle collapsed: to a point, or onto a line through its first vertex.
FlatScene soup(uint32_t seed, uint32_t count, double centre, double extent, double size,
               uint32_t instances, uint32_t degenerate);

} // namespace tp::test
