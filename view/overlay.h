// The viewer's overlay (Dear ImGui, Debian's libimgui-dev, with its GLFW and Vulkan back ends):
// a panel with what the accumulation has done and on what, drawn inside the Presenter's render
// pass over the displayed image. The panel keeps to the top of the window, within its width and
// a share of its height; in a small window it shows only the samples, the frame time and the
// status lines, in a smaller font, so that the image (or the compare map) stays in view.
#pragma once

#include "view/window.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/present/presenter.h"

#include <string>
#include <vector>

namespace tp {

struct OverlayText {
    uint32_t spp = 0;
    double pass_fraction = 0; // the share of the rows that have one sample more than spp
    double frame_ms = 0;
    double mrays_per_s = 0;
    float exposure = 0; // the display's exposure in stops
    std::string device, mode, scene, features;
    std::vector<std::string> status; // compare and path-diff results, saved files
};

class Overlay {
  public:
    Overlay(const VulkanContext& ctx, const ViewWindow& window, const Presenter& presenter);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    bool wants_mouse() const; // the pointer is over the panel
    // Lays out this frame's panel; `visible` false lays out nothing.
    void build(const OverlayText& text, bool visible);
    void record(VkCommandBuffer cmd) const; // inside the render pass

  private:
    VkDevice device_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

} // namespace tp
