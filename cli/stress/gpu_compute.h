// Runs the stress suite's own compute shaders (shaders/stress_*.comp) on a Vulkan context: the
// same pattern as the GPU test harness (tests/gpu/gpu_harness.h), here for a context the
// caller owns, so that `twinpath bench --stress` can run them on the GPU machine.
#pragma once

#include "vulkan_rt/buffer.h"
#include "vulkan_rt/context.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace tp::stress {

struct HostBytes {
    const void* data;
    size_t bytes;
};

template <typename T>
HostBytes bytes_of(const std::vector<T>& v) {
    return {v.data(), v.size() * sizeof(T)};
}

// Binds `device` buffers first, then the uploaded inputs, then zero-filled outputs of the given
// sizes, dispatches `groups` workgroups and returns the outputs.
std::vector<std::vector<uint8_t>> run_shader(const VulkanContext& ctx, const uint32_t* spirv,
                                             size_t spirv_bytes,
                                             const std::vector<HostBytes>& inputs,
                                             const std::vector<size_t>& output_bytes,
                                             const void* push, uint32_t push_bytes, uint32_t groups,
                                             const std::vector<const Buffer*>& device = {});

template <typename T>
std::vector<T> as_vector(const std::vector<uint8_t>& bytes) {
    std::vector<T> v(bytes.size() / sizeof(T));
    std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
    return v;
}

} // namespace tp::stress
