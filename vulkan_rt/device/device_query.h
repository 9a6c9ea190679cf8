// Reads a physical device's properties, features and extensions into a DeviceInfo.
#pragma once

#include "vulkan_rt/device/device_info.h"

#include <vulkan/vulkan.h>

namespace tp {

DeviceInfo query_device(VkPhysicalDevice device, uint32_t index);

} // namespace tp
