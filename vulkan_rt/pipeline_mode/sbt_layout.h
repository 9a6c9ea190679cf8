// The shader binding table's layout, from the device's handle size and alignments (pure, unit
// tested). Groups, in pipeline order: one ray generation, `miss_count` miss shaders, `hit_count`
// hit groups (shaders/rt_interface.h); no callables. The rules (Vulkan spec, vkCmdTraceRaysKHR):
//   - every region starts at a multiple of shaderGroupBaseAlignment;
//   - a record stride is a multiple of shaderGroupHandleAlignment, at least the handle size and
//     at most maxShaderGroupStride;
//   - the ray-generation region's size equals its stride.
// Records hold only the handle (no shader record data). The regions follow one another from
// offset 0; the table must be placed at a multiple of the base alignment (sbt_placement).
#pragma once

#include <cstdint>
#include <vector>

namespace tp {

struct SbtProperties {
    uint32_t handle_size;      // shaderGroupHandleSize
    uint32_t handle_alignment; // shaderGroupHandleAlignment
    uint32_t base_alignment;   // shaderGroupBaseAlignment
    uint32_t max_stride;       // maxShaderGroupStride
};

struct SbtRegion {
    uint64_t offset; // from the start of the table
    uint64_t stride;
    uint64_t size;
};

struct SbtLayout {
    SbtRegion raygen, miss, hit;
    uint32_t handle_size;
    uint32_t miss_count, hit_count;
    uint64_t bytes; // the whole table
};

// Throws RuntimeError when a record stride would exceed maxShaderGroupStride.
SbtLayout sbt_layout(const SbtProperties& p, uint32_t miss_count, uint32_t hit_count);

// The table's bytes: `handles` holds the groups' handles in pipeline order (handle_size bytes
// each, from vkGetRayTracingShaderGroupHandlesKHR); each lands at the start of its record.
std::vector<uint8_t> sbt_table(const SbtLayout& layout, const std::vector<uint8_t>& handles);

// Where the table goes in a buffer at device address `address` with base_alignment - 1 bytes
// of slack beyond layout.bytes: the offset of the first multiple of the base alignment.
uint64_t sbt_placement(uint64_t address, uint32_t base_alignment);

} // namespace tp
