// Every VkResult is checked (vk_check); failures become tp::RuntimeError (exit code 3) with a
// message that says what was being done and, for the failures a user can act on (device lost,
// out of memory, no driver), what to try.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace tp {

// "VK_ERROR_DEVICE_LOST" etc.; "VkResult <n>" for codes this build does not know.
const char* vk_result_name(VkResult r);

// The message vk_check throws for a failed call made while doing `what`.
std::string vk_error_message(VkResult r, const char* what);

[[noreturn]] void vk_fail(VkResult r, const char* what);

// Success codes (>= 0: VK_SUCCESS, VK_INCOMPLETE, ...) pass; error codes throw RuntimeError.
inline void vk_check(VkResult r, const char* what) {
    if (r < 0) vk_fail(r, what);
}

} // namespace tp
