#include "vulkan_rt/accel_inputs.h"

#include "util/error.h"

#include <algorithm>

namespace tp {

std::vector<BlasGeometry> blas_geometries(const FlatScene& scene) {
    std::vector<BlasGeometry> out;
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const MeshInfo& mesh = scene.meshes[m];
        if (mesh.triangle_count == 0) continue;
        out.push_back({m, uint64_t(mesh.first_vertex) * sizeof(vec3),
                       uint64_t(mesh.first_triangle) * sizeof(uvec3), mesh.vertex_count - 1,
                       mesh.triangle_count});
    }
    return out;
}

void check_accel_limits(const FlatScene& scene, const AccelLimits& limits) {
    const uint64_t instances = scene.instances.size();
    if (instances > limits.max_instances || instances > kMaxCustomIndex + 1)
        runtime_error("the scene has {} instances; the ray-tracing pipeline mode allows at most "
                      "{} on this device (use --vk-mode compute)",
                      instances, std::min(limits.max_instances, kMaxCustomIndex + 1));
    for (const MeshInfo& m : scene.meshes)
        if (m.triangle_count > limits.max_primitives)
            runtime_error("a mesh has {} triangles; the ray-tracing pipeline mode allows at most "
                          "{} per mesh on this device (use --vk-mode compute)",
                          m.triangle_count, limits.max_primitives);
}

VkAccelerationStructureInstanceKHR instance_record(const Instance& inst, uint32_t index,
                                                   uint64_t blas_address) {
    VkAccelerationStructureInstanceKHR r{};
    const vec4 rows[3] = {inst.to_world0, inst.to_world1, inst.to_world2};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) r.transform.matrix[i][j] = rows[i][j];
    r.instanceCustomIndex = index;
    r.mask = 0xFF;
    r.instanceShaderBindingTableRecordOffset = 0;
    r.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR |
              VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR;
    r.accelerationStructureReference = blas_address;
    return r;
}

std::vector<VkAccelerationStructureInstanceKHR>
instance_records(const FlatScene& scene, const std::vector<uint64_t>& mesh_blas_address) {
    std::vector<VkAccelerationStructureInstanceKHR> out;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const uint64_t blas = mesh_blas_address[scene.instances[i].mesh];
        if (blas != 0) out.push_back(instance_record(scene.instances[i], i, blas));
    }
    return out;
}

} // namespace tp
