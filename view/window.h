// The viewer's GLFW window: no client API (Vulkan draws into it through the context's surface,
// PresentationRequest), not resizable (the film has the window's size), and its mouse and keys
// turned into ViewActions (view_input.h).
#pragma once

#include "view/view_input.h"
#include "vulkan_rt/device/context.h"

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace tp {

class ViewWindow {
  public:
    // Throws RuntimeError (exit code 3) naming DISPLAY and WAYLAND_DISPLAY when there is no
    // display to open the window on.
    ViewWindow(uint32_t width, uint32_t height, const std::string& title);
    ~ViewWindow();
    ViewWindow(const ViewWindow&) = delete;
    ViewWindow& operator=(const ViewWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    PresentationRequest presentation() const;
    bool closed() const;

    // Processes the window system's events; returns what the user did since the last call.
    // `ui_has_mouse`: the overlay is under the pointer, so drags and clicks are its own.
    std::vector<ViewAction> poll(bool ui_has_mouse);

  private:
    static void on_button(GLFWwindow* w, int button, int action, int mods);
    static void on_motion(GLFWwindow* w, double x, double y);
    static void on_scroll(GLFWwindow* w, double dx, double dy);
    static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);

    GLFWwindow* window_ = nullptr;
    std::vector<ViewAction> pending_;
    bool ui_has_mouse_ = false;
    int dragging_ = -1; // the mouse button held, or -1
    double press_x_ = 0, press_y_ = 0, last_x_ = 0, last_y_ = 0;
    bool moved_ = false;
};

} // namespace tp
