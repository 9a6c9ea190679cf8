// Watertight triangles for Embree: Embree finds the candidates, shared/intersect.h decides.
//
// Embree's robust (Pluecker) test passes rays aimed exactly at a vertex (RenderKit/embree
// issues #174, #181; docs/stress.md, "Embree at vertices"): each triangle computes its own edge
// functions, and around a vertex they are all rounding noise. Compute mode's test (Woop et al.
// 2013, shared/intersect.h) does not, and an Embree user geometry running it costs 1.5x Embree's
// time per ray. Instead, Embree gets each triangle grown by delta in its plane (every edge moved
// out by delta, the corners mitred), with delta far above Embree's rounding for any ray of the
// scene, so every ray that meets the exact triangle meets the grown one; an intersection filter
// then keeps a candidate only where the exact triangle is hit. Where Embree's own barycentrics put
// the candidate more than 2 delta inside the grown triangle, it is inside the exact one beyond
// doubt and no exact test is needed (about 9 candidates in 10 on the bunny); the rest run
// intersect_triangle. The hit's distance is then the exact triangle's plane distance as
// intersect_triangle computes it, and its barycentrics those of the exact triangle (exact_hit),
// so Embree and compute mode decide every edge and vertex alike and agree on t and the
// barycentrics to rounding.
#pragma once

#include "shared/intersect.h"
#include "shared/path.h"

#include <embree3/rtcore.h>

#include <vector>

namespace tp {

// One Embree geometry's exact triangles, in the space Embree traces it in (world for a mesh
// placed in world space, object space for an instanced one).
struct ExactMesh {
    std::vector<vec3> vertices;
    std::vector<uvec3> triangles;
    float margin = 0.0f; // 2 delta times the longest grown edge (grow_triangles)
};

// Alpha coverage (shared/alpha.h), asked of every candidate the exact test keeps where a query
// carries one: the engine's test with the world-space ray and the candidate's instance, triangle
// and exact barycentrics.
struct CoverageTest {
    bool (*covers)(const void* engine, uint32_t instance, uint32_t primitive, vec2 bary,
                   const Ray& ray);
    const void* engine;
    Ray ray; // in world space, as the engine traced it
};

// What the filters below keep of the candidate they accepted last for one ray (the nearest, since
// Embree offers only candidates nearer than the current hit): the ray as its geometry saw it, and
// the exact test's result where they ran it.
struct ExactRecord {
    const ExactMesh* mesh = nullptr;
    vec3 org{0.0f}, dir{0.0f};
    bool tested = false;
    vec3 tuv{0.0f};
};

// An Embree query context that the filters below fill in: one record per ray of the query (a
// single ray, or the lanes of a packet, indexed as Embree indexes them in the filter's arguments).
struct ExactQuery {
    RTCIntersectContext context; // first: Embree passes &context to the filters
    ExactRecord* records = nullptr;
    const CoverageTest* coverage = nullptr; // none: every surface is opaque
};

// delta for rays whose origins and vertices lie within `extent` of the origin in every
// coordinate: 2^-17 extent, 128 float ulps of the largest coordinate. Embree's Moeller test
// rounds its edge tests by about 10 ulps of |origin - vertex| <= 2 extent.
double exact_delta(double extent);

// The extent a mesh's delta covers: its own vertices and the camera (`camera_extent`, the largest
// coordinate of the eye in the mesh's space), so every camera ray and every ray between two
// points of the mesh's neighbourhood. Never the scene's whole extent: a far object would grow
// every near triangle by 2^-17 of its distance (at 1e24 the grown triangles' normals overflow
// float and Embree misses them all). A ray that starts farther away than that carries a
// rounding of its own direction, 2^-24 of its length, of the order of Embree's error for it.
double mesh_extent(const ExactMesh& mesh, double camera_extent);

// The triangles grown by delta, three unshared vertices each (out: 3 per triangle); returns the
// mesh's margin. Corners are mitred: a corner of angle theta moves by delta / sin(theta / 2),
// at most 1024 delta (below 0.11 degrees the growth covers the corner's edges only up to that
// distance); a zero-area triangle stays as it is (the exact test never accepts it).
float grow_triangles(const ExactMesh& mesh, double delta, vec3* out);

// The intersection and occlusion filters of a geometry whose user data is its ExactMesh. These
// and exact_hit run once or more per query: they are compiled in both instruction-set copies
// (isa_clones.h).
void exact_intersect_filter(const RTCFilterFunctionNArguments* args);
void exact_occluded_filter(const RTCFilterFunctionNArguments* args);

// The exact distance and barycentrics (weights of vertices 1 and 2) of the hit a ray's query
// ended with, triangle `primitive` of record.mesh.
vec3 exact_hit(const ExactRecord& record, uint32_t primitive);

// The same for a ray (org, dir) and triangle `primitive` of `mesh`, where the margin accepted the
// hit (exact_hit's arithmetic).
vec3 exact_margin_hit(const ExactMesh& mesh, uint32_t primitive, vec3 org, vec3 dir);

} // namespace tp
