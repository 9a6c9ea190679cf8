// Pipeline mode's acceleration structures (VK_KHR_acceleration_structure): one bottom-level
// structure (BLAS) per mesh with triangles (accel_inputs.h), built for fast tracing and then
// compacted (built with ALLOW_COMPACTION, compacted size queried, copied into a structure of
// that size, as nvpro-samples' BLAS builder does), and one top-level structure (TLAS) over the
// instances.
#pragma once

#include "scene/flatten.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/pipeline_mode/rt_functions.h"
#include "vulkan_rt/render_loop/scene_buffers.h"

#include <vector>

namespace tp {

// Added to the usage of the buffers that a build reads (vertices, indices, instances).
constexpr VkBufferUsageFlags kAccelInputUsage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

// One acceleration structure and the buffer that holds it.
class Accel {
  public:
    Accel() = default;
    Accel(const VulkanContext& ctx, const RtFunctions& rt, VkAccelerationStructureTypeKHR type,
          VkDeviceSize size);
    ~Accel();
    Accel(Accel&& o) noexcept;
    Accel& operator=(Accel&& o) noexcept;

    VkAccelerationStructureKHR handle() const { return handle_; }
    VkDeviceSize size() const { return buffer_.size(); }
    VkDeviceAddress device_address() const;

  private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    const RtFunctions* rt_ = nullptr;
    Buffer buffer_;
    VkAccelerationStructureKHR handle_ = VK_NULL_HANDLE;
};

class AccelStructures {
  public:
    // Reads the geometry from the scene's position and triangle buffers, uploaded with
    // kAccelInputUsage. Throws RuntimeError when the scene exceeds the device's limits.
    AccelStructures(const VulkanContext& ctx, const RtFunctions& rt, const FlatScene& scene,
                    const SceneBuffers& sb);

    VkAccelerationStructureKHR tlas() const { return tlas_.handle(); }
    uint64_t bytes() const; // the compacted BLAS and the TLAS
    uint64_t uncompacted_blas_bytes() const { return uncompacted_blas_bytes_; }
    size_t blas_count() const { return blas_.size(); }
    // Meshes built from triangle boxes (accel_inputs.h, exact_triangle_meshes); with any, the
    // pipeline needs the procedural hit group (rt_program.h).
    size_t exact_count() const;

  private:
    void build_blas(const FlatScene& scene, const SceneBuffers& sb);
    void build_tlas(const FlatScene& scene);

    const VulkanContext& ctx_;
    const RtFunctions& rt_;
    VkDeviceSize scratch_alignment_ = 1;
    std::vector<Accel> blas_;            // compacted, one per blas_geometries() entry
    std::vector<uint64_t> blas_address_; // per FlatScene mesh; 0 for a mesh without triangles
    std::vector<uint8_t> exact_;         // per FlatScene mesh: exact_triangle_meshes()
    uint64_t uncompacted_blas_bytes_ = 0;
    Accel tlas_;
};

} // namespace tp
