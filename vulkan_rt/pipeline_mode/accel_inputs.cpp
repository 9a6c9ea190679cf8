#include "vulkan_rt/pipeline_mode/accel_inputs.h"

#include "shaders/rt_interface.h"
#include "shared/math.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>

namespace tp {
namespace {

vec3 mesh_vertex(const FlatScene& scene, const MeshInfo& mesh, uint32_t triangle, int k) {
    return scene.positions[mesh.first_vertex + scene.triangles[mesh.first_triangle + triangle][k]];
}

// The largest factor by which the instance's linear part stretches a length: bounded by the
// Frobenius norm, which is exact for a uniform scale times a rotation.
float instance_stretch(const Instance& t) {
    const vec3 r0(t.to_world0), r1(t.to_world1), r2(t.to_world2);
    return std::sqrt(glm::dot(r0, r0) + glm::dot(r1, r1) + glm::dot(r2, r2));
}

} // namespace

std::vector<uint8_t> exact_triangle_meshes(const FlatScene& scene) {
    const size_t n = scene.meshes.size();
    std::vector<float> edge(n, 0.0f), diagonal_of(n, 0.0f);
    for (size_t m = 0; m < n; ++m) {
        const MeshInfo& mesh = scene.meshes[m];
        float edge2 = 0.0f;
        for (uint32_t t = 0; t < mesh.triangle_count; ++t)
            for (int k = 0; k < 3; ++k) {
                const vec3 e =
                    mesh_vertex(scene, mesh, t, (k + 1) % 3) - mesh_vertex(scene, mesh, t, k);
                edge2 = std::max(edge2, glm::dot(e, e));
            }
        edge[m] = std::sqrt(edge2);
        vec3 lo(FLOAT_MAX), hi(-FLOAT_MAX);
        for (uint32_t v = 0; v < mesh.vertex_count; ++v) {
            lo = glm::min(lo, scene.positions[mesh.first_vertex + v]);
            hi = glm::max(hi, scene.positions[mesh.first_vertex + v]);
        }
        if (mesh.vertex_count > 0) diagonal_of[m] = glm::length(hi - lo);
    }
    std::vector<float> diagonal, world_edge(n, 0.0f);
    for (const Instance& inst : scene.instances) {
        if (scene.meshes[inst.mesh].triangle_count == 0) continue;
        const float stretch = instance_stretch(inst);
        diagonal.push_back(diagonal_of[inst.mesh] * stretch);
        world_edge[inst.mesh] = std::max(world_edge[inst.mesh], edge[inst.mesh] * stretch);
    }
    std::vector<uint8_t> exact(n, 0);
    if (diagonal.empty()) return exact;
    const auto median = diagonal.begin() + (diagonal.size() - 1) / 2;
    std::nth_element(diagonal.begin(), median, diagonal.end());
    for (size_t m = 0; m < n; ++m) exact[m] = world_edge[m] > kExactEdgeRatio * *median;
    return exact;
}

std::vector<BlasGeometry> blas_geometries(const FlatScene& scene,
                                          const std::vector<uint8_t>& exact) {
    std::vector<BlasGeometry> out;
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const MeshInfo& mesh = scene.meshes[m];
        if (mesh.triangle_count == 0) continue;
        out.push_back({m, exact[m] != 0, uint64_t(mesh.first_vertex) * sizeof(vec3),
                       uint64_t(mesh.first_triangle) * sizeof(uvec3), mesh.vertex_count - 1,
                       mesh.triangle_count});
    }
    return out;
}

std::vector<VkAabbPositionsKHR> triangle_boxes(const FlatScene& scene, const BlasGeometry& g) {
    const MeshInfo& mesh = scene.meshes[g.mesh];
    std::vector<VkAabbPositionsKHR> out(mesh.triangle_count);
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const vec3 a = mesh_vertex(scene, mesh, t, 0), b = mesh_vertex(scene, mesh, t, 1),
                   c = mesh_vertex(scene, mesh, t, 2);
        const vec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
        out[t] = {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z};
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
                                                   uint64_t blas_address, bool exact, bool alpha) {
    VkAccelerationStructureInstanceKHR r{};
    const vec4 rows[3] = {inst.to_world0, inst.to_world1, inst.to_world2};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) r.transform.matrix[i][j] = rows[i][j];
    r.instanceCustomIndex = index;
    r.mask = 0xFF;
    r.instanceShaderBindingTableRecordOffset = exact ? RT_HIT_GROUP_EXACT : RT_HIT_GROUP_TRIANGLES;
    r.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR |
              (alpha ? VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR
                     : VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR);
    r.accelerationStructureReference = blas_address;
    return r;
}

std::vector<VkAccelerationStructureInstanceKHR>
instance_records(const FlatScene& scene, const std::vector<uint64_t>& mesh_blas_address,
                 const std::vector<uint8_t>& exact) {
    std::vector<VkAccelerationStructureInstanceKHR> out;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const uint32_t m = scene.instances[i].mesh;
        const uint64_t blas = mesh_blas_address[m];
        const bool alpha = scene.material_of(i).alpha_mode != ALPHA_OPAQUE;
        if (blas != 0)
            out.push_back(instance_record(scene.instances[i], i, blas, exact[m] != 0, alpha));
    }
    return out;
}

} // namespace tp
