#include "vulkan_rt/device/context.h"

#include "util/error.h"
#include "util/leak_check.h"
#include "vulkan_rt/device/device_query.h"
#include "vulkan_rt/device/vk_error.h"

#include <fmt/core.h>

#include <cstdlib>
#include <cstring>
#include <string>

namespace tp {
namespace {

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// vk_check for the loader's calls before an instance exists: the loader also answers
// VK_ERROR_OUT_OF_HOST_MEMORY when a driver manifest (ICD JSON) cannot be parsed, far more often
// the cause at start-up than memory, so the message says both and where the manifests are.
void loader_check(VkResult r, const char* what) {
    if (r != VK_ERROR_OUT_OF_HOST_MEMORY) return vk_check(r, what);
    const char* listed = std::getenv("VK_DRIVER_FILES");
    if (!listed || !*listed) listed = std::getenv("VK_ICD_FILENAMES");
    const std::string where =
        listed && *listed
            ? fmt::format("the manifests listed in VK_DRIVER_FILES/VK_ICD_FILENAMES ({})", listed)
            : "the manifests in /usr/share/vulkan/icd.d and /etc/vulkan/icd.d";
    runtime_error("Vulkan call failed while {}: VK_ERROR_OUT_OF_HOST_MEMORY, which the Vulkan "
                  "loader also reports for a malformed driver manifest: check {} "
                  "(VK_LOADER_DEBUG=error names the file)",
                  what, where);
}

bool layer_available(const char* name) {
    uint32_t n = 0;
    loader_check(vkEnumerateInstanceLayerProperties(&n, nullptr), "listing instance layers");
    std::vector<VkLayerProperties> layers(n);
    loader_check(vkEnumerateInstanceLayerProperties(&n, layers.data()), "listing instance layers");
    for (const VkLayerProperties& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

bool instance_extension_available(const char* name) {
    uint32_t n = 0;
    loader_check(vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr),
                 "listing instance extensions");
    std::vector<VkExtensionProperties> exts(n);
    loader_check(vkEnumerateInstanceExtensionProperties(nullptr, &n, exts.data()),
                 "listing instance extensions");
    for (const VkExtensionProperties& e : exts)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

} // namespace

VulkanInstance::VulkanInstance(const std::vector<std::string>& extra_extensions) {
    const ValidationRequest request = validation_request();
    if (request != ValidationRequest::Off) {
        validation_ = layer_available(kValidationLayer);
        if (!validation_ && request == ValidationRequest::Required)
            runtime_error("TWINPATH_VALIDATION=1 but the Vulkan validation layer {} is not "
                          "installed (Debian: vulkan-validationlayers)",
                          kValidationLayer);
        if (!validation_)
            fmt::print(stderr,
                       "twinpath: warning: {} is not installed; running without "
                       "Vulkan validation\n",
                       kValidationLayer);
    }

    std::vector<const char*> extensions, layers;
    VkInstanceCreateFlags flags = 0;
    // Portability drivers (MoltenVK) are only listed when the application asks for them.
    if (instance_extension_available(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }
    for (const std::string& e : extra_extensions) extensions.push_back(e.c_str());
    VkDebugUtilsMessengerCreateInfoEXT messenger_ci{};
    if (validation_) {
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        layers.push_back(kValidationLayer);
        messenger_ci = messenger_.create_info();
    }

    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "twinpath";
    app.pEngineName = "twinpath";
    app.apiVersion = VK_API_VERSION_1_2;
    VkInstanceCreateInfo ci{};
    ci.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ci.pNext = validation_ ? &messenger_ci : nullptr;
    ci.flags = flags;
    ci.pApplicationInfo = &app;
    ci.enabledExtensionCount = uint32_t(extensions.size());
    ci.ppEnabledExtensionNames = extensions.data();
    ci.enabledLayerCount = uint32_t(layers.size());
    ci.ppEnabledLayerNames = layers.data();
    {
        // The driver's one-time set-up (Mesa lavapipe) keeps 128 bytes it never frees; they are
        // not twinpath's to free, so the debug preset's leak check leaves them out.
        const LeakCheckPause driver_setup;
        loader_check(vkCreateInstance(&ci, nullptr, &instance_), "creating the Vulkan instance");
    }
    if (validation_) messenger_.attach(instance_);

    uint32_t n = 0;
    vk_check(vkEnumeratePhysicalDevices(instance_, &n, nullptr), "listing Vulkan devices");
    physical_.resize(n);
    vk_check(vkEnumeratePhysicalDevices(instance_, &n, physical_.data()), "listing Vulkan devices");
    physical_.resize(n);
}

VulkanInstance::~VulkanInstance() {
    messenger_.detach();
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::vector<DeviceInfo> VulkanInstance::devices() const {
    std::vector<DeviceInfo> list;
    for (uint32_t i = 0; i < physical_.size(); ++i) list.push_back(query_device(physical_[i], i));
    return list;
}

VulkanContext::VulkanContext(const std::string& selector, VkModeRequest vk_mode,
                             bool pipeline_statistics, const PresentationRequest* presentation)
    : instance_(std::make_unique<VulkanInstance>(presentation ? presentation->instance_extensions
                                                              : std::vector<std::string>{})),
      statistics_requested_(pipeline_statistics) {
    const std::vector<DeviceInfo> devices = instance_->devices();
    info_ = select_device(devices, selector);
    mode_ = resolve_vk_mode(vk_mode, info_);
    const bool ray_tracing = mode_ == VkMode::pipeline;
    physical_ = instance_->physical_devices()[info_.index];

    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(physical_, &props);
    limits_ = props.limits;
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);

    uint32_t nq = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &nq, nullptr);
    std::vector<VkQueueFamilyProperties> queues(nq);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &nq, queues.data());
    // Prefer a compute family that can also write timestamps; for a window, one that can also
    // draw (the overlay) and present to its surface.
    if (presentation) surface_ = presentation->create_surface(instance_->handle());
    bool found = false;
    for (uint32_t i = 0; i < nq; ++i) {
        if (!(queues[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) continue;
        if (surface_) {
            VkBool32 present = VK_FALSE;
            vkGetPhysicalDeviceSurfaceSupportKHR(physical_, i, surface_, &present);
            if (!present || !(queues[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
        }
        if (!found || (timestamp_bits_ == 0 && queues[i].timestampValidBits > 0)) {
            queue_family_ = i;
            timestamp_bits_ = queues[i].timestampValidBits;
            found = true;
        }
    }

    if (!found) {
        release();
        runtime_error("Vulkan device {} has no queue that can compute, draw and present to the "
                      "window",
                      info_.name);
    }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{};
    qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    qci.queueFamilyIndex = queue_family_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as{};
    as.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR;
    as.accelerationStructure = VK_TRUE;
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{};
    rt.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR;
    rt.pNext = &as;
    rt.rayTracingPipeline = VK_TRUE;
    // Statistics make the driver keep what it would otherwise discard (and some drivers bypass
    // their caches), so they are enabled only on request.
    pipeline_statistics_ = pipeline_statistics && info_.caps.pipeline_executable_info;
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR exec{};
    exec.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR;
    exec.pNext = ray_tracing ? &rt : nullptr;
    exec.pipelineExecutableInfo = VK_TRUE;
    VkPhysicalDeviceVulkan12Features f12{};
    f12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    f12.pNext = pipeline_statistics_ ? &exec : exec.pNext;
    f12.scalarBlockLayout = VK_TRUE;
    f12.bufferDeviceAddress = ray_tracing ? VK_TRUE : VK_FALSE;
    VkPhysicalDeviceFeatures2 features{};
    features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features.pNext = &f12;
    features.features.shaderFloat64 = VK_TRUE;
    std::vector<const char*> extensions;
    if (ray_tracing) extensions = pipeline_extensions();
    // Core in Vulkan 1.3, but the instance asks for 1.2: enabled as the extension.
    creation_feedback_ = info_.caps.has(VK_EXT_PIPELINE_CREATION_FEEDBACK_EXTENSION_NAME);
    if (creation_feedback_) extensions.push_back(VK_EXT_PIPELINE_CREATION_FEEDBACK_EXTENSION_NAME);
    if (pipeline_statistics_)
        extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
    if (surface_) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    VkDeviceCreateInfo dci{};
    dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    dci.pNext = &features;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.enabledExtensionCount = uint32_t(extensions.size());
    dci.ppEnabledExtensionNames = extensions.data();
    vk_check(vkCreateDevice(physical_, &dci, nullptr, &device_), "creating the Vulkan device");
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
    try {
        VkCommandPoolCreateInfo pci{};
        pci.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
        pci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
        pci.queueFamilyIndex = queue_family_;
        vk_check(vkCreateCommandPool(device_, &pci, nullptr, &pool_), "creating a command pool");
        VkFenceCreateInfo fci{};
        fci.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        vk_check(vkCreateFence(device_, &fci, nullptr, &fence_), "creating a fence");
    } catch (...) {
        release();
        throw;
    }
}

VulkanContext::~VulkanContext() {
    release();
}

void VulkanContext::release() {
    if (device_) {
        vkDeviceWaitIdle(device_); // best effort: a lost device cannot be waited for
        if (fence_) vkDestroyFence(device_, fence_, nullptr);
        if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (surface_) vkDestroySurfaceKHR(instance_->handle(), surface_, nullptr);
    surface_ = VK_NULL_HANDLE;
}

uint32_t VulkanContext::memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                                    VkMemoryPropertyFlags preferred) const {
    int fallback = -1;
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
        if (!(type_bits & (1u << i))) continue;
        const VkMemoryPropertyFlags f = memory_.memoryTypes[i].propertyFlags;
        if ((f & required) != required) continue;
        if ((f & preferred) == preferred) return i;
        if (fallback < 0) fallback = int(i);
    }
    if (fallback < 0)
        runtime_error("the Vulkan device has no memory type with the properties {:#x}",
                      uint32_t(required));
    return uint32_t(fallback);
}

bool VulkanContext::counts_as_device_memory(uint32_t memory_type) const {
    const uint32_t heap = memory_.memoryTypes[memory_type].heapIndex;
    return (memory_.memoryHeaps[heap].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) != 0;
}

void VulkanContext::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const {
    VkCommandBufferAllocateInfo ai{};
    ai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    ai.commandPool = pool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    vk_check(vkAllocateCommandBuffers(device_, &ai, &cmd), "allocating a command buffer");
    struct Release {
        VkDevice d;
        VkCommandPool p;
        VkCommandBuffer c;
        ~Release() { vkFreeCommandBuffers(d, p, 1, &c); }
    } release{device_, pool_, cmd};

    VkCommandBufferBeginInfo bi{};
    bi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk_check(vkBeginCommandBuffer(cmd, &bi), "recording commands");
    record(cmd);
    vk_check(vkEndCommandBuffer(cmd), "recording commands");

    VkSubmitInfo si{};
    si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    vk_check(vkResetFences(device_, 1, &fence_), "resetting a fence");
    vk_check(vkQueueSubmit(queue_, 1, &si, fence_), "submitting work to the GPU");
    vk_check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "waiting for the GPU");
}

} // namespace tp
