#include "view/window.h"

#include "util/error.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdlib>

namespace tp {
namespace {

std::string glfw_error() {
    const char* text = nullptr;
    glfwGetError(&text);
    return text ? text : "no detail";
}

bool set(const char* name) {
    const char* v = std::getenv(name);
    return v && *v;
}

// A press and release closer than this many pixels is a click, not a drag.
constexpr double kClickSlop = 3.0;

} // namespace

ViewWindow::ViewWindow(uint32_t width, uint32_t height, const std::string& title) {
    if (!set("DISPLAY") && !set("WAYLAND_DISPLAY"))
        runtime_error("no display: neither DISPLAY nor WAYLAND_DISPLAY is set (run it under X11 "
                      "or Wayland, under xvfb-run, or use --headless)");
    if (!glfwInit())
        runtime_error("cannot open the display (DISPLAY={}, WAYLAND_DISPLAY={}): {}",
                      set("DISPLAY") ? std::getenv("DISPLAY") : "",
                      set("WAYLAND_DISPLAY") ? std::getenv("WAYLAND_DISPLAY") : "", glfw_error());
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        runtime_error("GLFW finds no Vulkan loader that can present to the display");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string why = glfw_error();
        glfwTerminate();
        runtime_error("cannot create a {}x{} window: {}", width, height, why);
    }
    glfwSetWindowUserPointer(window_, this);
    glfwSetMouseButtonCallback(window_, on_button);
    glfwSetCursorPosCallback(window_, on_motion);
    glfwSetScrollCallback(window_, on_scroll);
    glfwSetKeyCallback(window_, on_key);
}

ViewWindow::~ViewWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

PresentationRequest ViewWindow::presentation() const {
    PresentationRequest p;
    uint32_t n = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&n);
    for (uint32_t i = 0; i < n; ++i) p.instance_extensions.emplace_back(names[i]);
    GLFWwindow* w = window_;
    p.create_surface = [w](VkInstance instance) {
        VkSurfaceKHR surface = VK_NULL_HANDLE;
        const VkResult r = glfwCreateWindowSurface(instance, w, nullptr, &surface);
        if (r != VK_SUCCESS)
            runtime_error("cannot create a Vulkan surface for the window (VkResult {})", int(r));
        return surface;
    };
    return p;
}

bool ViewWindow::closed() const {
    return glfwWindowShouldClose(window_);
}

std::vector<ViewAction> ViewWindow::poll(bool ui_has_mouse) {
    ui_has_mouse_ = ui_has_mouse;
    glfwPollEvents();
    // Fly keys act for as long as they are held.
    for (char k : {'W', 'A', 'S', 'D', 'Q', 'E'})
        if (glfwGetKey(window_, GLFW_KEY_A + (k - 'A')) == GLFW_PRESS &&
            !(k == 'S' && glfwGetKey(window_, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS))
            pending_.push_back({ViewAction::Key, char(k - 'A' + 'a'), 0, 0});
    std::vector<ViewAction> out;
    out.swap(pending_);
    return out;
}

void ViewWindow::on_button(GLFWwindow* w, int button, int action, int) {
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(w));
    double x, y;
    glfwGetCursorPos(w, &x, &y);
    if (action == GLFW_PRESS && !self->ui_has_mouse_ && self->dragging_ < 0) {
        self->dragging_ = button;
        self->press_x_ = self->last_x_ = x;
        self->press_y_ = self->last_y_ = y;
        self->moved_ = false;
    } else if (action == GLFW_RELEASE && button == self->dragging_) {
        if (button == GLFW_MOUSE_BUTTON_LEFT && !self->moved_)
            self->pending_.push_back({ViewAction::Click, 0, std::floor(x), std::floor(y)});
        self->dragging_ = -1;
    }
}

void ViewWindow::on_motion(GLFWwindow* w, double x, double y) {
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(w));
    if (self->dragging_ < 0) return;
    if (std::hypot(x - self->press_x_, y - self->press_y_) > kClickSlop) self->moved_ = true;
    if (!self->moved_) return;
    const ViewAction::Kind kind =
        self->dragging_ == GLFW_MOUSE_BUTTON_LEFT ? ViewAction::Orbit : ViewAction::Pan;
    self->pending_.push_back({kind, 0, x - self->last_x_, y - self->last_y_});
    self->last_x_ = x;
    self->last_y_ = y;
}

void ViewWindow::on_scroll(GLFWwindow* w, double, double dy) {
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(w));
    if (self->ui_has_mouse_) return;
    const bool modifier = glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                          glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    self->pending_.push_back({modifier ? ViewAction::Fov : ViewAction::Wheel, 0, 0, dy});
}

void ViewWindow::on_key(GLFWwindow* w, int key, int, int action, int mods) {
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(w));
    if (action != GLFW_PRESS) return;
    // Ctrl+S saves (plain S flies backwards); P, C, H; X, [ and ] set the exposure; Esc.
    char k = 0;
    if (key == GLFW_KEY_ESCAPE) k = 27;
    if (key == GLFW_KEY_P || key == GLFW_KEY_C || key == GLFW_KEY_H)
        k = char('A' + key - GLFW_KEY_A);
    if (key == GLFW_KEY_S && (mods & GLFW_MOD_CONTROL)) k = 'S';
    if (key == GLFW_KEY_X) k = 'X';
    if (key == GLFW_KEY_LEFT_BRACKET) k = '[';
    if (key == GLFW_KEY_RIGHT_BRACKET) k = ']';
    if (k) self->pending_.push_back({ViewAction::Key, k, 0, 0});
}

} // namespace tp
