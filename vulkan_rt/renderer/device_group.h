// One render on several Vulkan devices at once (--device all, or a list; docs/farm.md): every
// device renders disjoint sample ranges of the render's range, taken as it goes from one
// SampleShare (sample_share.h) in proportion to its measured rate, into its own accumulator;
// the films are merged in memory (Film::merge) and the statistics summed (GPU time too; the
// wall time is the slowest device's), with each device's share in RenderStats::devices.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

namespace tp {

// vk.device is "all" or a list (selects_several). Every device opens its own instance and
// device, and runs in its own thread; all run one mode (resolve_common_mode). The debug
// outputs, checkpoints and --time-limit are for one device: InputError when asked for. A
// device that fails stops the others, and its error is thrown.
RenderResult render_on_devices(const FlatScene& scene, const RenderOptions& options,
                               const VulkanOptions& vk);

} // namespace tp
