#include "vulkan_rt/device/validation.h"

#include "vulkan_rt/device/vk_error.h"

#include <fmt/core.h>

#include <cstdlib>
#include <cstring>

namespace tp {

ValidationRequest validation_request() {
    const char* env = std::getenv("TWINPATH_VALIDATION");
    if (env && std::strcmp(env, "1") == 0) return ValidationRequest::Required;
    if (env && std::strcmp(env, "0") == 0) return ValidationRequest::Off;
#ifdef NDEBUG
    return ValidationRequest::Off;
#else
    return ValidationRequest::Optional;
#endif
}

ValidationMessenger::~ValidationMessenger() {
    detach();
}

VkDebugUtilsMessengerCreateInfoEXT ValidationMessenger::create_info() {
    VkDebugUtilsMessengerCreateInfoEXT ci{};
    ci.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    ci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    ci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    ci.pfnUserCallback = &ValidationMessenger::callback;
    ci.pUserData = this;
    return ci;
}

void ValidationMessenger::attach(VkInstance instance) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) vk_fail(VK_ERROR_EXTENSION_NOT_PRESENT, "loading vkCreateDebugUtilsMessengerEXT");
    const VkDebugUtilsMessengerCreateInfoEXT ci = create_info();
    vk_check(create(instance, &ci, nullptr, &messenger_), "creating the validation messenger");
    instance_ = instance;
}

void ValidationMessenger::detach() {
    if (messenger_ == VK_NULL_HANDLE) return;
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
    instance_ = VK_NULL_HANDLE;
}

VkBool32 ValidationMessenger::callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                       VkDebugUtilsMessageTypeFlagsEXT,
                                       const VkDebugUtilsMessengerCallbackDataEXT* data,
                                       void* self) {
    static_cast<ValidationMessenger*>(self)->messages_++;
    const char* level =
        severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
    fmt::print(stderr, "twinpath: vulkan validation {}: {}\n", level,
               data && data->pMessage ? data->pMessage : "(no message)");
    return VK_FALSE; // never abort the call that triggered the message
}

} // namespace tp
