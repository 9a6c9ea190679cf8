// How many render invocations a launch keeps resident, and so which loop the render shader
// runs (shaders/render_items.glsl; a specialization constant, fixed per pipeline): the counter
// with path regeneration where a launch is sized to a resident count (fewer invocations than
// items, each taking items until none is left); invocation i of n tracing items i, i + n, ...
// where the count is unknown and a launch has one invocation per item, so that no invocation
// pays for votes and atomics that would never hand it a second item (docs/gpu.md, "Item
// schedule"). BatchSession sizes its launches from the same resident count.
#pragma once

#include "shaders/interface.h"
#include "vulkan_rt/device/device_info.h"

#include <cstdint>

namespace tp {

// `asked`: RenderOptions::gpu_invocations (0: the device's count, 0 where it does not say).
inline uint64_t resident_invocations(const DeviceInfo& device, uint32_t asked) {
    return asked > 0 ? asked : device.caps.resident_invocations;
}

inline uint32_t item_schedule(uint64_t resident) {
    return resident > 0 ? ITEM_SCHEDULE_COUNTER : ITEM_SCHEDULE_STRIDED;
}

// The schedule of a render on `device` with RenderOptions::gpu_invocations `asked`.
inline uint32_t render_item_schedule(const DeviceInfo& device, uint32_t asked) {
    return item_schedule(resident_invocations(device, asked));
}

} // namespace tp
