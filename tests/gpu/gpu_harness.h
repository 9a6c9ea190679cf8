// Runs test compute shaders on the Vulkan device the suite uses (lavapipe in CI). One context
// per test process; CTest sets TWINPATH_VALIDATION=1, so the validation layer watches every
// call and validation_messages() must stay 0.
#pragma once

#include "vulkan_rt/device/shader_dispatch.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tp::test {

VulkanContext& gpu_context();
uint64_t validation_messages();

using tp::as_vector;
using tp::bytes_of;
using tp::HostBytes;

// run_compute_shader (vulkan_rt/device/shader_dispatch.h) on gpu_context().
std::vector<std::vector<uint8_t>> run_shader(const uint32_t* spirv, size_t spirv_bytes,
                                             const std::vector<HostBytes>& inputs,
                                             const std::vector<size_t>& output_bytes,
                                             const void* push, uint32_t push_bytes, uint32_t groups,
                                             const std::vector<const Buffer*>& device = {},
                                             uint32_t features = FEATURES_ALL);

} // namespace tp::test
