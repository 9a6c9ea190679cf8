#include "vulkan_rt/pipeline_mode/accel_structures.h"

#include "shaders/interface.h"
#include "util/error.h"
#include "vulkan_rt/device/align.h"
#include "vulkan_rt/device/vk_error.h"
#include "vulkan_rt/pipeline_mode/accel_inputs.h"

#include <algorithm>
#include <utility>

namespace tp {
namespace {

// A build's device address inputs must be aligned (vertices and indices to their 4-byte
// components, instances to 16 bytes). Buffers get memory of their own, so their addresses sit at
// the start of an allocation, aligned far beyond that; this only confirms it.
VkDeviceAddress aligned_address(const Buffer& b, uint64_t alignment, const char* what) {
    const VkDeviceAddress address = b.device_address();
    if (address % alignment != 0)
        runtime_error("the Vulkan driver placed the {} at address {:#x}, not a multiple of {} "
                      "bytes as acceleration-structure builds require",
                      what, address, alignment);
    return address;
}

// Scratch memory must start at a multiple of minAccelerationStructureScratchOffsetAlignment,
// which need not divide the buffer's own alignment: the buffer gets alignment - 1 bytes of
// slack and the build uses its first aligned address.
struct Scratch {
    Buffer buffer;
    VkDeviceAddress address;
};
Scratch make_scratch(const VulkanContext& ctx, VkDeviceSize size, VkDeviceSize alignment) {
    Buffer b(ctx, size + alignment - 1,
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, false);
    const VkDeviceAddress address = align_up(b.device_address(), alignment);
    return {std::move(b), address};
}

// Acceleration-structure writes before it (builds and compacting copies, scratch included: all
// in the build stage) visible to the next builds, copies and size queries, which read and
// write structures and scratch in the build stage ...
void record_build_barrier(VkCommandBuffer cmd) {
    VkMemoryBarrier b{};
    b.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    b.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    b.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                      VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                         VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0, 1, &b, 0,
                         nullptr, 0, nullptr);
}

// ... or to traceRayEXT, which only reads them.
void record_trace_barrier(VkCommandBuffer cmd) {
    VkMemoryBarrier b{};
    b.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    b.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    b.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                         VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 1, &b, 0, nullptr, 0,
                         nullptr);
}

const VkBuildAccelerationStructureFlagsKHR kBuildFlags =
    VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;

} // namespace

Accel::Accel(const VulkanContext& ctx, const RtFunctions& rt, VkAccelerationStructureTypeKHR type,
             VkDeviceSize size)
    : device_(ctx.device()), rt_(&rt),
      buffer_(ctx, size,
              VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                  VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
              false) {
    VkAccelerationStructureCreateInfoKHR ci{};
    ci.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR;
    ci.buffer = buffer_.handle();
    ci.size = size;
    ci.type = type;
    vk_check(rt.vkCreateAccelerationStructureKHR(device_, &ci, nullptr, &handle_),
             "creating an acceleration structure");
}

Accel::~Accel() {
    release();
}

Accel::Accel(Accel&& o) noexcept {
    *this = std::move(o);
}

Accel& Accel::operator=(Accel&& o) noexcept {
    if (this != &o) {
        release();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        rt_ = std::exchange(o.rt_, nullptr);
        buffer_ = std::move(o.buffer_);
        handle_ = std::exchange(o.handle_, VK_NULL_HANDLE);
    }
    return *this;
}

void Accel::release() {
    // The structure goes before the buffer that holds it.
    if (handle_) rt_->vkDestroyAccelerationStructureKHR(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
    buffer_ = Buffer();
}

VkDeviceAddress Accel::device_address() const {
    VkAccelerationStructureDeviceAddressInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR;
    info.accelerationStructure = handle_;
    return rt_->vkGetAccelerationStructureDeviceAddressKHR(device_, &info);
}

AccelStructures::AccelStructures(const VulkanContext& ctx, const RtFunctions& rt,
                                 const FlatScene& scene, const SceneBuffers& sb)
    : ctx_(ctx), rt_(rt) {
    VkPhysicalDeviceAccelerationStructurePropertiesKHR props{};
    props.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR;
    VkPhysicalDeviceProperties2 p2{};
    p2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    p2.pNext = &props;
    vkGetPhysicalDeviceProperties2(ctx.physical(), &p2);
    scratch_alignment_ =
        std::max<VkDeviceSize>(props.minAccelerationStructureScratchOffsetAlignment, 1);
    check_accel_limits(scene, {props.maxInstanceCount, props.maxPrimitiveCount});
    build_blas(scene, sb);
    build_tlas(scene);
}

size_t AccelStructures::exact_count() const {
    return size_t(std::count(exact_.begin(), exact_.end(), 1));
}

uint64_t AccelStructures::bytes() const {
    uint64_t n = tlas_.size();
    for (const Accel& a : blas_) n += a.size();
    return n;
}

void AccelStructures::build_blas(const FlatScene& scene, const SceneBuffers& sb) {
    exact_ = exact_triangle_meshes(scene);
    const std::vector<BlasGeometry> geoms = blas_geometries(scene, exact_);
    blas_address_.assign(scene.meshes.size(), 0);
    if (geoms.empty()) return;
    const VkDevice device = ctx_.device();
    const VkDeviceAddress positions =
        aligned_address(sb.slots[BINDING_POSITIONS], sizeof(float), "vertex buffer");
    const VkDeviceAddress indices =
        aligned_address(sb.slots[BINDING_TRIANGLES], sizeof(uint32_t), "index buffer");
    // The exact meshes' triangle boxes, one buffer each (8-byte aligned, as AABB data must be).
    std::vector<Buffer> boxes(geoms.size());
    Uploader up(ctx_);
    for (size_t i = 0; i < geoms.size(); ++i)
        if (geoms[i].exact) boxes[i] = up.add(triangle_boxes(scene, geoms[i]), kAccelInputUsage);
    up.flush();

    // Sizes, the uncompacted structures and one scratch buffer that every build reuses in turn.
    const size_t n = geoms.size();
    std::vector<VkAccelerationStructureGeometryKHR> geometry(n);
    std::vector<VkAccelerationStructureBuildGeometryInfoKHR> info(n);
    std::vector<Accel> built;
    VkDeviceSize scratch_size = 0;
    for (size_t i = 0; i < n; ++i) {
        const BlasGeometry& g = geoms[i];
        VkAccelerationStructureGeometryKHR& geom = geometry[i];
        geom.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
        geom.flags = VK_GEOMETRY_OPAQUE_BIT_KHR; // no any-hit shader: every hit counts
        if (g.exact) {
            geom.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
            VkAccelerationStructureGeometryAabbsDataKHR& a = geom.geometry.aabbs;
            a.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
            a.data.deviceAddress = aligned_address(boxes[i], 8, "triangle box buffer");
            a.stride = sizeof(VkAabbPositionsKHR);
        } else {
            geom.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
            VkAccelerationStructureGeometryTrianglesDataKHR& t = geom.geometry.triangles;
            t.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
            t.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
            t.vertexData.deviceAddress = positions + g.vertex_offset;
            t.vertexStride = sizeof(vec3);
            t.maxVertex = g.max_vertex;
            t.indexType = VK_INDEX_TYPE_UINT32;
            t.indexData.deviceAddress = indices + g.index_offset;
        }

        VkAccelerationStructureBuildGeometryInfoKHR& bi = info[i];
        bi.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR;
        bi.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
        bi.flags = kBuildFlags | VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
        bi.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
        bi.geometryCount = 1;
        bi.pGeometries = &geom;
        VkAccelerationStructureBuildSizesInfoKHR sizes{};
        sizes.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR;
        rt_.vkGetAccelerationStructureBuildSizesKHR(device,
                                                    VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                                    &bi, &g.triangle_count, &sizes);
        built.emplace_back(ctx_, rt_, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                           sizes.accelerationStructureSize);
        bi.dstAccelerationStructure = built.back().handle();
        uncompacted_blas_bytes_ += sizes.accelerationStructureSize;
        scratch_size = std::max(scratch_size, sizes.buildScratchSize);
    }
    const Scratch scratch = make_scratch(ctx_, scratch_size, scratch_alignment_);

    // Build one after another (the scratch buffer is shared), then query the compacted sizes.
    VkQueryPoolCreateInfo qi{};
    qi.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    qi.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
    qi.queryCount = uint32_t(n);
    VkQueryPool pool = VK_NULL_HANDLE;
    vk_check(vkCreateQueryPool(device, &qi, nullptr, &pool), "creating a query pool");
    struct PoolGuard {
        VkDevice d;
        VkQueryPool p;
        ~PoolGuard() { vkDestroyQueryPool(d, p, nullptr); }
    } guard{device, pool};
    std::vector<VkAccelerationStructureKHR> handles;
    for (const Accel& a : built) handles.push_back(a.handle());
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        vkCmdResetQueryPool(cmd, pool, 0, uint32_t(n));
        for (size_t i = 0; i < n; ++i) {
            info[i].scratchData.deviceAddress = scratch.address;
            VkAccelerationStructureBuildRangeInfoKHR range{};
            range.primitiveCount = geoms[i].triangle_count;
            const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
            rt_.vkCmdBuildAccelerationStructuresKHR(cmd, 1, &info[i], &ranges);
            record_build_barrier(cmd);
        }
        rt_.vkCmdWriteAccelerationStructuresPropertiesKHR(
            cmd, uint32_t(n), handles.data(),
            VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, pool, 0);
    });
    std::vector<VkDeviceSize> compacted(n);
    vk_check(vkGetQueryPoolResults(device, pool, 0, uint32_t(n), n * sizeof(VkDeviceSize),
                                   compacted.data(), sizeof(VkDeviceSize),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
             "reading compacted acceleration-structure sizes");

    // Copy each into a structure of its compacted size; the uncompacted ones go at the end.
    for (size_t i = 0; i < n; ++i) {
        blas_.emplace_back(ctx_, rt_, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                           compacted[i]);
        blas_address_[geoms[i].mesh] = blas_.back().device_address();
    }
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        for (size_t i = 0; i < n; ++i) {
            VkCopyAccelerationStructureInfoKHR copy{};
            copy.sType = VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR;
            copy.src = built[i].handle();
            copy.dst = blas_[i].handle();
            copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
            rt_.vkCmdCopyAccelerationStructureKHR(cmd, &copy);
        }
        record_build_barrier(cmd);
    });
}

void AccelStructures::build_tlas(const FlatScene& scene) {
    const std::vector<VkAccelerationStructureInstanceKHR> records =
        instance_records(scene, blas_address_, exact_);
    Uploader up(ctx_);
    const Buffer instances = up.add(records, kAccelInputUsage);
    up.flush();

    VkAccelerationStructureGeometryKHR geom{};
    geom.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
    geom.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    geom.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
    geom.geometry.instances.sType =
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    geom.geometry.instances.arrayOfPointers = VK_FALSE;
    geom.geometry.instances.data.deviceAddress = aligned_address(instances, 16, "instance buffer");
    VkAccelerationStructureBuildGeometryInfoKHR bi{};
    bi.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR;
    bi.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
    bi.flags = kBuildFlags;
    bi.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    bi.geometryCount = 1;
    bi.pGeometries = &geom;
    const uint32_t count = uint32_t(records.size());
    VkAccelerationStructureBuildSizesInfoKHR sizes{};
    sizes.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR;
    rt_.vkGetAccelerationStructureBuildSizesKHR(
        ctx_.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &bi, &count, &sizes);
    tlas_ = Accel(ctx_, rt_, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                  sizes.accelerationStructureSize);
    const Scratch scratch = make_scratch(ctx_, sizes.buildScratchSize, scratch_alignment_);
    bi.dstAccelerationStructure = tlas_.handle();
    bi.scratchData.deviceAddress = scratch.address;
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        VkAccelerationStructureBuildRangeInfoKHR range{};
        range.primitiveCount = count;
        const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
        rt_.vkCmdBuildAccelerationStructuresKHR(cmd, 1, &bi, &ranges);
        record_trace_barrier(cmd);
    });
}

} // namespace tp
