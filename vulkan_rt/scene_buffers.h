// The scene on the device: FlatScene's arrays uploaded as they are (the shared structs have the
// same bytes on both sides, shared/types.h), plus the BVH. A feature the scene does not use
// (vertex normals, uvs, textures, an environment map, lights) gets a 16-byte placeholder
// buffer instead of its array, because the descriptor set always has every binding.
#pragma once

#include "scene/flatten.h"
#include "vulkan_rt/buffer.h"
#include "vulkan_rt/bvh_builder.h"

#include <array>

namespace tp {

struct SceneBuffers {
    // Indexed by the BINDING_* slots of shaders/interface.h, BINDING_PARAMS..BINDING_BVH_TRIS.
    std::array<Buffer, 15> slots;
    uint64_t bytes = 0; // device memory of the real (non-placeholder) arrays
};

// `params` is the scene's RenderParams with the render's seed.
SceneBuffers upload_scene(const VulkanContext& ctx, const FlatScene& scene,
                          const RenderParams& params, const BvhBuild& bvh);

} // namespace tp
