// Compute mode's BVH on the device: the arrays of a host build (bvh_builder.h) in the layout it
// was built in, for the render interface's slots BINDING_BVH_NODES and BINDING_BVH_TRIS
// (shaders/interface.h). The other slots hold the scene (render_loop/scene_buffers.h).
#pragma once

#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/context.h"

namespace tp {

// For slots BINDING_BVH_NODES (the nodes of the build's layout) and BINDING_BVH_TRIS.
struct BvhBuffers {
    Buffer nodes, triangles;
};
BvhBuffers upload_bvh(const VulkanContext& ctx, const BvhBuild& bvh);

} // namespace tp
