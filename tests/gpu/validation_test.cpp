// The validation plumbing itself: under TWINPATH_VALIDATION=1 (set by CTest) the Khronos layer
// is on and every message it reports is counted, so that "zero messages" in the other tests
// means something. The messages this test provokes on purpose are printed to its output.
#include "vulkan_rt/device/context.h"

#include <catch2/catch.hpp>

using namespace tp;

TEST_CASE("validation layer is on and the messenger counts its messages", "[gpu]") {
    REQUIRE(validation_request() == ValidationRequest::Required);
    const VulkanContext ctx("");
    REQUIRE(ctx.instance().validation_enabled());
    CHECK(ctx.instance().validation_messages() == 0);

    // A message submitted through the debug-utils extension reaches the counter...
    auto submit = reinterpret_cast<PFN_vkSubmitDebugUtilsMessageEXT>(
        vkGetInstanceProcAddr(ctx.instance().handle(), "vkSubmitDebugUtilsMessageEXT"));
    REQUIRE(submit);
    VkDebugUtilsMessengerCallbackDataEXT data{};
    data.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CALLBACK_DATA_EXT;
    data.pMessage = "test message (expected)";
    submit(ctx.instance().handle(), VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
           VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT, &data);
    CHECK(ctx.instance().validation_messages() == 1);

    // ... and so does a real invalid call: a buffer of size 0 (VUID-VkBufferCreateInfo-size-00912).
    VkBufferCreateInfo bi{};
    bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    bi.size = 0;
    bi.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    if (vkCreateBuffer(ctx.device(), &bi, nullptr, &buffer) == VK_SUCCESS && buffer)
        vkDestroyBuffer(ctx.device(), buffer, nullptr);
    CHECK(ctx.instance().validation_messages() >= 2);
}
