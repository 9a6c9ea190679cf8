// Compute mode: the path tracer of shaders/render_compute.comp with software traversal of a
// BVH built on the host in the given layout (bvh_builder.h), run by the shared render loop
// (render_loop.h).
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/render_loop/render_loop.h"

namespace tp {

// The BVH, the scene buffers and the compute tracer, ready for batches.
ModeSetup prepare_compute(const VulkanContext& ctx, const FlatScene& scene,
                          const RenderOptions& options, BvhLayout layout);

RenderResult render_compute(const VulkanContext& ctx, const FlatScene& scene,
                            const RenderOptions& options, BvhLayout layout);

} // namespace tp
