#include "view/overlay.h"

#include "vulkan_rt/device/vk_error.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

namespace tp {
namespace {

void check(VkResult r) {
    vk_check(r, "drawing the overlay");
}

} // namespace

Overlay::Overlay(const VulkanContext& ctx, const ViewWindow& window, const Presenter& presenter)
    : device_(ctx.device()) {
    // The back end needs one combined image sampler (the font atlas).
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo pci{};
    pci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    pci.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pci.maxSets = 1;
    pci.poolSizeCount = 1;
    pci.pPoolSizes = &size;
    vk_check(vkCreateDescriptorPool(device_, &pci, nullptr, &pool_), "creating a descriptor pool");

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini in the user's directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window.handle(), true);
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance().handle();
    info.PhysicalDevice = ctx.physical();
    info.Device = ctx.device();
    info.QueueFamily = ctx.queue_family();
    info.Queue = ctx.queue();
    info.DescriptorPool = pool_;
    info.MinImageCount = presenter.image_count();
    info.ImageCount = presenter.image_count();
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = check;
    ImGui_ImplVulkan_Init(&info, presenter.render_pass());
    ctx.submit_and_wait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Overlay::~Overlay() {
    vkDeviceWaitIdle(device_);
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(device_, pool_, nullptr);
}

bool Overlay::wants_mouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}

void Overlay::build(const OverlayText& t, bool visible) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (visible) {
        ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
        ImGui::SetNextWindowBgAlpha(0.6f);
        ImGui::Begin("twinpath", nullptr,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                         ImGuiWindowFlags_NoSavedSettings);
        ImGui::Text("%s", t.scene.c_str());
        ImGui::Text("%u spp   %.1f ms/frame   %.1f Mrays/s", t.spp, t.frame_ms, t.mrays_per_s);
        ImGui::Text("%s (%s)", t.device.c_str(), t.mode.c_str());
        ImGui::TextWrapped("features: %s", t.features.c_str());
        for (const std::string& line : t.status) ImGui::TextWrapped("%s", line.c_str());
        ImGui::TextDisabled("P flags  Ctrl+S save  C compare  Esc leave  H hide");
        ImGui::End();
    }
    ImGui::Render();
}

void Overlay::record(VkCommandBuffer cmd) const {
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

} // namespace tp
