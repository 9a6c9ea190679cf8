// The Khronos validation layer and a debug-utils messenger that prints every warning and
// error it reports and counts them. On in debug builds and whenever TWINPATH_VALIDATION=1
// (TWINPATH_VALIDATION=0 turns it off in a debug build). A render that drew any message
// fails with exit code 3 (vulkan_renderer.cpp), so the tests, which set the variable, fail
// on any validation message.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>

namespace tp {

enum class ValidationRequest {
    Off,      // not asked for
    Optional, // debug build: use the layer when it is installed
    Required, // TWINPATH_VALIDATION=1: fail when it is not installed
};

// From TWINPATH_VALIDATION and the build type.
ValidationRequest validation_request();

class ValidationMessenger {
  public:
    ValidationMessenger() = default;
    ~ValidationMessenger();
    ValidationMessenger(const ValidationMessenger&) = delete;
    ValidationMessenger& operator=(const ValidationMessenger&) = delete;

    // Chained into VkInstanceCreateInfo::pNext so that instance creation is covered too.
    VkDebugUtilsMessengerCreateInfoEXT create_info();
    void attach(VkInstance instance);
    void detach();

    uint64_t messages() const { return messages_.load(); }

  private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* self);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::atomic<uint64_t> messages_{0};
};

} // namespace tp
