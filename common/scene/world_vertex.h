// A mesh vertex placed in world space by its instance, for the one-level acceleration structures
// that hold world-space triangles instead of instancing an object-space mesh: the CPU engine's
// Embree scene (cpu_ref/embree_accel.cpp, a mesh that one instance uses) and compute mode's
// one-level BVH (vulkan_rt/compute_mode/bvh_builder.cpp, a scene without instancing). Both get
// their vertices here, so that same-seed CPU and compute renders intersect the same float
// triangles.
#pragma once

#include "shared/types.h"

namespace tp {

// M p + T computed in double and rounded to float once. The products of floats are exact in
// double and its sums round at 2^-53, so each coordinate is the float nearest the exact value
// (but within 2^-29 ulp of a halfway case): |error| <= u |w_c|, u = 2^-24, the rounding that
// the ray-offset bound allows for a world-space triangle (shared/offset.h). Being a function of
// the vertex alone, a vertex that two triangles share stays one point, so the watertight
// triangle test stays watertight after the transform.
vec3 world_vertex(const Instance& inst, vec3 p);

} // namespace tp
