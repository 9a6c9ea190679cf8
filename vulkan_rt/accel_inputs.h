// What pipeline mode's acceleration structures are built from (pure, unit tested): one
// bottom-level structure (BLAS) per mesh that has triangles, over that mesh's slice of the
// position and triangle buffers that the shaders read too, and one top-level instance record
// per FlatScene instance of such a mesh. An instanced mesh is built once.
#pragma once

#include "scene/flatten.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace tp {

struct BlasGeometry {
    uint32_t mesh;
    uint64_t vertex_offset; // bytes into the position buffer (vec3: 12 bytes per vertex)
    uint64_t index_offset;  // bytes into the triangle buffer (uvec3: three uint32 indices)
    uint32_t max_vertex;    // highest mesh-local vertex index a triangle may use
    uint32_t triangle_count;
};

// In mesh order. The triangles keep their order, so gl_PrimitiveID is the mesh-local triangle
// index that the shaders and the CPU engine use.
std::vector<BlasGeometry> blas_geometries(const FlatScene& scene);

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
// hit group 0; no face culling, opaque.
VkAccelerationStructureInstanceKHR instance_record(const Instance& inst, uint32_t index,
                                                   uint64_t blas_address);

// One record per instance whose mesh has a BLAS, in instance order. mesh_blas_address[m] is the
// device address of mesh m's BLAS, 0 for a mesh without triangles.
std::vector<VkAccelerationStructureInstanceKHR>
instance_records(const FlatScene& scene, const std::vector<uint64_t>& mesh_blas_address);

} // namespace tp
