// Compute mode: the path tracer of shaders/render_compute.comp with software BVH traversal,
// run in progressive batches (batch_planner.h) on an open VulkanContext.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "vulkan_rt/context.h"

namespace tp {

RenderResult render_compute(const VulkanContext& ctx, const FlatScene& scene,
                            const RenderOptions& options);

} // namespace tp
