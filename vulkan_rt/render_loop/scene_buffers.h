// The scene on the device: FlatScene's arrays uploaded as they are (the shared structs have the
// same bytes on both sides, shared/types.h), and its images (scene_images.h). A feature the
// scene does not use (vertex normals, uvs, textures, an environment map, lights) gets a 16-byte
// placeholder buffer instead of its array, because the descriptor set always has every
// binding. Arrays only a feature outside the render's feature mask reads (shared/features.h) are
// not uploaded either: uvs without textures, images without textures or an environment map.
// The acceleration structure's slots belong to the mode: the BVH arrays of compute mode
// (compute_mode/bvh_buffers.h) or the TLAS of pipeline mode (pipeline_mode/accel_structures.h).
#pragma once

#include "scene/flatten.h"
#include "shaders/interface.h"
#include "shared/features.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/pipeline_bindings.h"
#include "vulkan_rt/render_loop/scene_images.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tp {

struct SceneBuffers {
    // Indexed by the scene's BINDING_* slots of shaders/interface.h, 0 .. BINDING_SCENE_COUNT - 1.
    std::array<Buffer, BINDING_SCENE_COUNT> slots;
    SceneImages images; // BINDING_IMAGES
    uint64_t bytes = 0; // device memory of the real (non-placeholder) arrays and images
};

// Descriptor set 0 of the render interface (shaders/interface.h) for the shaders that include
// bindings.glsl: every slot below `count` a storage buffer, except BINDING_IMAGES, the
// IMAGE_SLOTS sampled images (left out where `images` is false: a shader that reads no scene
// image, the resolve pass), and BINDING_TLAS, an acceleration structure where `tlas`.
std::vector<BindingSlot> interface_slots(uint32_t count, bool images, bool tlas = false);

// `params` is the scene's RenderParams with the render's seed. `mesh_bvh_roots` (compute mode)
// fills MeshInfo::bvh_root; empty leaves it as it is. `geometry_usage` is added to the usage of
// the position and triangle buffers (pipeline mode: acceleration-structure build input).
SceneBuffers upload_scene(const VulkanContext& ctx, const FlatScene& scene,
                          const RenderParams& params, const std::vector<uint32_t>& mesh_bvh_roots,
                          VkBufferUsageFlags geometry_usage, uint32_t features = FEATURES_ALL);

} // namespace tp
