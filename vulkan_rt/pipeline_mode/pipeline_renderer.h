// Pipeline mode: the same path tracer as compute mode (shaders/integrator.glsl) in a
// ray-generation shader that traces with traceRayEXT against hardware acceleration structures
// (VK_KHR_ray_tracing_pipeline, VK_KHR_acceleration_structure), run by the shared render loop
// (render_loop.h). The context must have been opened for pipeline mode.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/render_loop/render_loop.h"

namespace tp {

// The scene buffers, acceleration structures and ray-tracing pipeline, ready for batches.
ModeSetup prepare_pipeline(const VulkanContext& ctx, const FlatScene& scene,
                           const RenderOptions& options);

RenderResult render_pipeline(const VulkanContext& ctx, const FlatScene& scene,
                             const RenderOptions& options);

} // namespace tp
