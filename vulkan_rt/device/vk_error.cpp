#include "vulkan_rt/device/vk_error.h"

#include "util/error.h"

#include <fmt/format.h>

namespace tp {

const char* vk_result_name(VkResult r) {
    switch (r) {
    case VK_SUCCESS:
        return "VK_SUCCESS";
    case VK_NOT_READY:
        return "VK_NOT_READY";
    case VK_TIMEOUT:
        return "VK_TIMEOUT";
    case VK_INCOMPLETE:
        return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY:
        return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
        return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED:
        return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST:
        return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_MEMORY_MAP_FAILED:
        return "VK_ERROR_MEMORY_MAP_FAILED";
    case VK_ERROR_LAYER_NOT_PRESENT:
        return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT:
        return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT:
        return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER:
        return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_TOO_MANY_OBJECTS:
        return "VK_ERROR_TOO_MANY_OBJECTS";
    case VK_ERROR_FORMAT_NOT_SUPPORTED:
        return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    case VK_ERROR_FRAGMENTED_POOL:
        return "VK_ERROR_FRAGMENTED_POOL";
    case VK_ERROR_OUT_OF_POOL_MEMORY:
        return "VK_ERROR_OUT_OF_POOL_MEMORY";
    case VK_ERROR_INVALID_EXTERNAL_HANDLE:
        return "VK_ERROR_INVALID_EXTERNAL_HANDLE";
    case VK_ERROR_FRAGMENTATION:
        return "VK_ERROR_FRAGMENTATION";
    case VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS:
        return "VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS";
    case VK_ERROR_UNKNOWN:
        return "VK_ERROR_UNKNOWN";
    default:
        return nullptr;
    }
}

std::string vk_error_message(VkResult r, const char* what) {
    const char* name = vk_result_name(r);
    const std::string code = name ? std::string(name) : fmt::format("VkResult {}", int(r));
    const char* hint = "";
    switch (r) {
    case VK_ERROR_DEVICE_LOST:
        hint = ": the Vulkan device was lost (driver reset, hang or GPU fault); rerun, or pick "
               "another device with --device";
        break;
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
        hint = ": out of GPU memory; lower --width/--height, use a smaller scene or a device "
               "with more memory";
        break;
    case VK_ERROR_OUT_OF_HOST_MEMORY:
        hint = ": out of host memory";
        break;
    case VK_ERROR_INCOMPATIBLE_DRIVER:
    case VK_ERROR_INITIALIZATION_FAILED:
        hint = ": no usable Vulkan driver (install one, e.g. mesa-vulkan-drivers for lavapipe)";
        break;
    default:
        break;
    }
    return fmt::format("Vulkan call failed while {}: {}{}", what, code, hint);
}

void vk_fail(VkResult r, const char* what) {
    throw RuntimeError(vk_error_message(r, what));
}

} // namespace tp
