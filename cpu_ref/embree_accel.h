// Embree 3 acceleration structure for the CPU reference: one Embree geometry per mesh. A mesh that
// several instances share is one Embree scene, built once and placed by Embree instance
// geometries; a mesh that one instance uses is a triangle geometry of the top-level scene in world
// space. Either way the top-level geometry ID is the FlatScene instance index. Embree traces the
// triangles grown by a little and an intersection filter keeps the exact hits
// (cpu_ref/exact_triangles.h): watertight at edges and vertices, as compute mode.
#pragma once

#include "cpu_ref/exact_triangles.h"
#include "scene/flatten.h"
#include "shared/path.h"

#include <embree3/rtcore.h>

#include <atomic>
#include <deque>
#include <vector>

namespace tp {

struct Hit {
    bool found = false;
    float t = 0.0f;
    uint32_t instance = 0;
    uint32_t primitive = 0;
    vec2 bary{0.0f}; // weights of vertices 1 and 2, as surface_point() expects
};

class EmbreeAccel {
  public:
    explicit EmbreeAccel(const FlatScene& scene);
    ~EmbreeAccel();
    EmbreeAccel(const EmbreeAccel&) = delete;
    EmbreeAccel& operator=(const EmbreeAccel&) = delete;

    // `coverage`: the alpha test every candidate must pass (exact_triangles.h); null: opaque.
    Hit intersect(const Ray& ray, const CoverageTest* coverage) const;
    bool occluded(const Ray& ray, const CoverageTest* coverage) const;

    // The closest hits of up to kPacket opaque rays (no alpha) traced together as one of Embree's
    // packets (rtcIntersect8): for coherent rays, such as the camera rays of one pixel, its
    // traversal visits each node once for all of them. Each hit is the one intersect() finds,
    // except where two triangles are hit at the same distance, which the packet may order
    // differently.
    static constexpr uint32_t kPacket = 8;
    void intersect_packet(const Ray* rays, uint32_t count, Hit* hits) const;

    // Bytes Embree holds for the acceleration structures (its memory monitor).
    uint64_t memory_bytes() const { return uint64_t(std::max<int64_t>(bytes_.load(), 0)); }

  private:
    static Hit exact_result(const ExactRecord& record, uint32_t geom, uint32_t inst, uint32_t prim);
    RTCDevice device_ = nullptr;
    RTCScene top_ = nullptr;
    std::vector<RTCScene> meshes_; // per mesh; null for a mesh placed in world space
    std::deque<ExactMesh> exact_;  // per Embree geometry, its user data (stable addresses)
    std::atomic<int64_t> bytes_{0};
    static bool monitor(void* self, ssize_t bytes, bool post);
    RTCScene new_scene() const;
    // Adds mesh m to s as geometry `id`, in object space, or in world space when to_world is set,
    // grown by the delta of its vertices and the camera_extent (exact_triangles.h, mesh_extent).
    void attach_mesh(RTCScene s, uint32_t id, const FlatScene& scene, const MeshInfo& m,
                     const Instance* to_world, double camera_extent);
    void check(const char* what) const;
};

} // namespace tp
