// One dispatch of a small compute shader over plain storage buffers, for the shaders that check
// the shared code on a device: the GPU tests (tests/gpu) and the stress suite's edge-aimed rays
// and BRDF sweeps (stress), which `twinpath bench --stress` also runs on the GPU machine.
#pragma once

#include "shared/features.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/context.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace tp {

struct HostBytes {
    const void* data;
    size_t bytes;
};

template <typename T>
HostBytes bytes_of(const std::vector<T>& v) {
    return {v.data(), v.size() * sizeof(T)};
}

// An array of sampled images at one binding (views in VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL).
struct ImageArrayBinding {
    uint32_t binding;
    std::vector<VkImageView> views;
    uint32_t count; // how many of the views are the scene's images (SPEC_IMAGE_COUNT)
};

// Dispatches `groups` workgroups of `spirv` with storage buffers bound in order: first
// `device` (buffers already on the device; a null entry leaves its binding to `images`), then
// the inputs (uploaded), then outputs of the given sizes (zero-filled), and returns the outputs.
// `constants` specialize a shader that includes the render shaders' features.glsl (with
// trace_bvh.glsl: the BVH's shape) or scene_access.glsl (the scene's image count); `images`, a
// shader that reads the scene's images.
std::vector<std::vector<uint8_t>>
run_compute_shader(const VulkanContext& ctx, const uint32_t* spirv, size_t spirv_bytes,
                   const std::vector<HostBytes>& inputs, const std::vector<size_t>& output_bytes,
                   const void* push, uint32_t push_bytes, uint32_t groups,
                   const std::vector<const Buffer*>& device = {}, uint32_t features = FEATURES_ALL,
                   const ImageArrayBinding* images = nullptr);

// The output as an array of T.
template <typename T>
std::vector<T> as_vector(const std::vector<uint8_t>& bytes) {
    std::vector<T> v(bytes.size() / sizeof(T));
    std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
    return v;
}

} // namespace tp
