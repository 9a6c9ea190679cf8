// The Vulkan instance (with the validation layer when requested, validation.h) and, for
// rendering, one logical device with one compute queue; in pipeline mode with the ray-tracing
// extensions and features enabled; with VK_EXT_pipeline_creation_feedback where the device has
// it, and VK_KHR_pipeline_executable_properties when pipeline statistics are asked for.
#pragma once

#include "vulkan_rt/device/device_info.h"
#include "vulkan_rt/device/memory_tally.h"
#include "vulkan_rt/device/validation.h"

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tp {

// What a window needs from the context (vulkan_rt/present/presenter.h): the instance extensions of
// its window system (GLFW's glfwGetRequiredInstanceExtensions) and the function that creates its
// surface on the instance. The context then opens a queue that can also draw and present there,
// with VK_KHR_swapchain, and owns the surface.
struct PresentationRequest {
    std::vector<std::string> instance_extensions;
    std::function<VkSurfaceKHR(VkInstance)> create_surface;
};

class VulkanInstance {
  public:
    // Throws RuntimeError when there is no Vulkan loader/driver, or when validation is
    // required (TWINPATH_VALIDATION=1) and the Khronos layer is not installed.
    explicit VulkanInstance(const std::vector<std::string>& extra_extensions = {});
    ~VulkanInstance();
    VulkanInstance(const VulkanInstance&) = delete;
    VulkanInstance& operator=(const VulkanInstance&) = delete;

    VkInstance handle() const { return instance_; }
    const std::vector<VkPhysicalDevice>& physical_devices() const { return physical_; }
    std::vector<DeviceInfo> devices() const;

    bool validation_enabled() const { return validation_; }
    uint64_t validation_messages() const { return messenger_.messages(); }

  private:
    VkInstance instance_ = VK_NULL_HANDLE;
    ValidationMessenger messenger_;
    bool validation_ = false;
    std::vector<VkPhysicalDevice> physical_;
};

class VulkanContext {
  public:
    // Opens the device that `selector` names (device_info.h, select_device) for the mode that
    // `vk_mode` (--vk-mode) resolves to there (resolve_vk_mode). `pipeline_statistics`
    // (--pipeline-stats): enable VK_KHR_pipeline_executable_properties where the device has it.
    // `presentation`: also open the device for a window's swapchain (PresentationRequest).
    explicit VulkanContext(const std::string& selector, VkModeRequest vk_mode = VkMode::compute,
                           bool pipeline_statistics = false,
                           const PresentationRequest* presentation = nullptr);
    ~VulkanContext();
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    const VulkanInstance& instance() const { return *instance_; }
    const DeviceInfo& info() const { return info_; }
    VkMode mode() const { return mode_; }
    VkPhysicalDevice physical() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queue_family() const { return queue_family_; }
    VkSurfaceKHR surface() const { return surface_; } // VK_NULL_HANDLE without a window
    const VkPhysicalDeviceLimits& limits() const { return limits_; }
    uint32_t timestamp_valid_bits() const { return timestamp_bits_; }
    // VK_EXT_pipeline_creation_feedback is enabled (pipeline_report.h).
    bool creation_feedback() const { return creation_feedback_; }
    // Pipeline statistics were asked for, and VK_KHR_pipeline_executable_properties is enabled
    // to give them (pipeline_report.h).
    bool statistics_requested() const { return statistics_requested_; }
    bool pipeline_statistics() const { return pipeline_statistics_; }

    // A memory type allowed by `type_bits` with all of `required`, preferring one that also
    // has `preferred`; throws RuntimeError when there is none.
    uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                         VkMemoryPropertyFlags preferred = 0) const;
    // Whether allocations of `memory_type` count as device memory: those of a device-local heap,
    // the memory a GPU runs out of. A discrete GPU's staging buffers in host memory do not count;
    // on lavapipe the one heap is device-local, so everything does.
    bool counts_as_device_memory(uint32_t memory_type) const;
    // The device memory held through this context (memory_tally.h). Bookkeeping, not state of
    // the device: the buffers of a const context add to it.
    MemoryTally& memory_tally() const { return memory_tally_; }

    // Records commands into a fresh primary command buffer, submits it and waits.
    void submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const;

  private:
    void release();
    std::unique_ptr<VulkanInstance> instance_;
    DeviceInfo info_;
    VkMode mode_ = VkMode::compute;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkPhysicalDeviceLimits limits_{};
    VkPhysicalDeviceMemoryProperties memory_{};
    VkDevice device_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    uint32_t timestamp_bits_ = 0;
    bool creation_feedback_ = false;
    bool statistics_requested_ = false;
    bool pipeline_statistics_ = false;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    mutable MemoryTally memory_tally_;
};

} // namespace tp
