// What pipeline mode's acceleration structures are built from (pure, unit tested): one
// bottom-level structure (BLAS) per mesh that has triangles, over that mesh's slice of the
// position and triangle buffers that the shaders read too, and one top-level instance record
// per FlatScene instance of such a mesh. An instanced mesh is built once. A mesh whose
// triangles dwarf the rest of the scene (exact_triangle_meshes) is built from one box per
// triangle instead, and its hits come from the intersection shader's exact test.
#pragma once

#include "scene/flatten.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace tp {

struct BlasGeometry {
    uint32_t mesh;
    bool exact;             // boxes (triangle_boxes) and shaders/exact_triangle.rint
    uint64_t vertex_offset; // bytes into the position buffer (vec3: 12 bytes per vertex)
    uint64_t index_offset;  // bytes into the triangle buffer (uvec3: three uint32 indices)
    uint32_t max_vertex;    // highest mesh-local vertex index a triangle may use
    uint32_t triangle_count;
};

// Which meshes pipeline mode intersects with shared/intersect.h rather than the driver's
// triangle test (1: exact), as the compute mode does everywhere. The driver's distance to a
// triangle errs by ~u times the triangle's size, not the distance (docs/gpu.md, "Exact meshes";
// docs/stress.md, "Floor at ±1e8"); the offsets of shared/offset.h assume errors of ~u times
// the distance. A mesh is exact when its longest world-space edge, over its instances, exceeds
// kExactEdgeRatio times the scene's content scale: the lower median of the instances' world
// bounding-box diagonals.
constexpr float kExactEdgeRatio = 1024.0f;
std::vector<uint8_t> exact_triangle_meshes(const FlatScene& scene);

// In mesh order. The triangles keep their order, so gl_PrimitiveID is the mesh-local triangle
// index that the shaders and the CPU engine use. `exact`: exact_triangle_meshes(), one entry
// per mesh.
std::vector<BlasGeometry> blas_geometries(const FlatScene& scene,
                                          const std::vector<uint8_t>& exact);

// The object-space bounding box of each triangle of an exact geometry, in triangle order.
std::vector<VkAabbPositionsKHR> triangle_boxes(const FlatScene& scene, const BlasGeometry& g);

struct AccelLimits {
    uint64_t max_instances;  // VkPhysicalDeviceAccelerationStructurePropertiesKHR
    uint64_t max_primitives; // per bottom-level geometry
};

// instanceCustomIndex has 24 bits (VkAccelerationStructureInstanceKHR).
constexpr uint64_t kMaxCustomIndex = (1u << 24) - 1;

// Throws RuntimeError (naming the limit and suggesting compute mode) when the scene has more
// instances than the device or the 24-bit custom index allow, or a mesh more triangles than a
// geometry may have.
void check_accel_limits(const FlatScene& scene, const AccelLimits& limits);

// The TLAS record of FlatScene instance `index`: the transform rows are Instance::to_world0..2
// (both are the rows of the 3x4 object-to-world matrix); the custom index is `index`, which
// the closest-hit shader reports (gl_InstanceCustomIndexEXT) and the shaders use to read
// Instance[index] (mesh, material, lights); mask 0xFF (every ray sees every instance);
// hit group RT_HIT_GROUP_EXACT for an exact mesh, else RT_HIT_GROUP_TRIANGLES
// (shaders/rt_interface.h); no face culling; opaque, unless `alpha` (its material has alpha
// as coverage: the hit groups' any-hit shader, shaders/alpha_test.rahit, then tests it).
VkAccelerationStructureInstanceKHR instance_record(const Instance& inst, uint32_t index,
                                                   uint64_t blas_address, bool exact, bool alpha);

// One record per instance whose mesh has a BLAS, in instance order. mesh_blas_address[m] is the
// device address of mesh m's BLAS, 0 for a mesh without triangles; `exact` as in
// blas_geometries.
std::vector<VkAccelerationStructureInstanceKHR>
instance_records(const FlatScene& scene, const std::vector<uint64_t>& mesh_blas_address,
                 const std::vector<uint8_t>& exact);

} // namespace tp
