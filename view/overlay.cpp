#include "view/overlay.h"

#include "vulkan_rt/device/vk_error.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <fmt/core.h>

#include <algorithm>

namespace tp {
namespace {

void check(VkResult r) {
    vk_check(r, "drawing the overlay");
}

// Below this window size the full panel (title, device, features, keys: some 360 x 140 pixels
// in ImGui's 13-pixel font) would cover most of the image: the panel is the compact one.
constexpr float kFullPanelMinWidth = 480, kFullPanelMinHeight = 360;
constexpr float kCompactFontScale = 0.8f;
// The panel's margin from the window's edges, and the most of the window's height it takes.
constexpr float kMargin = 8;
constexpr float kMaxHeightShare = 0.4f;

std::string spp_text(const OverlayText& t) {
    if (t.pass_fraction <= 0) return fmt::format("{} spp", t.spp);
    return fmt::format("{} spp (+{:.0f}%)", t.spp, 100.0 * t.pass_fraction);
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
        const ImVec2 window = ImGui::GetIO().DisplaySize;
        const bool full = window.x >= kFullPanelMinWidth && window.y >= kFullPanelMinHeight;
        const float max_width = std::max(window.x - 2 * kMargin, 1.0f);
        ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin), ImGuiCond_Always);
        ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                            ImVec2(max_width, kMaxHeightShare * window.y));
        ImGui::SetNextWindowBgAlpha(0.6f);
        ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings;
        if (!full) flags |= ImGuiWindowFlags_NoTitleBar;
        ImGui::Begin("twinpath", nullptr, flags);
        if (!full) ImGui::SetWindowFontScale(kCompactFontScale);
        // Lines wrap at the panel's widest, not at an auto-sized panel's last width.
        ImGui::PushTextWrapPos(max_width - 2 * ImGui::GetStyle().WindowPadding.x);
        const std::string spp = spp_text(t);
        if (full) {
            ImGui::TextUnformatted(t.scene.c_str());
            ImGui::TextWrapped("%s   %.1f ms/frame   %.1f Mrays/s   exposure %+.1f", spp.c_str(),
                               t.frame_ms, t.mrays_per_s, t.exposure);
            ImGui::TextWrapped("%s (%s)", t.device.c_str(), t.mode.c_str());
            ImGui::TextWrapped("features: %s", t.features.c_str());
        } else {
            ImGui::TextWrapped("%s  %.0f ms", spp.c_str(), t.frame_ms);
        }
        for (const std::string& line : t.status) ImGui::TextWrapped("%s", line.c_str());
        if (full)
            ImGui::TextDisabled(
                "P flags  Ctrl+S save  C compare  Esc leave  H hide  [ ] X exposure");
        ImGui::PopTextWrapPos();
        ImGui::End();
    }
    ImGui::Render();
}

void Overlay::record(VkCommandBuffer cmd) const {
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

} // namespace tp
