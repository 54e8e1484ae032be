#pragma once
// A GLFW window without a client API (Vulkan draws into it) and the source of its input events.
// One per process: GLFW is initialised by the first Window and terminated by its destructor.
#include "engine/viewer/input_event.h"

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

struct GLFWwindow;

namespace globe {

class Window {
 public:
  // Throws std::runtime_error with one line when there is no display or GLFW cannot open a window.
  Window(uint32_t width_px, uint32_t height_px, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // True when an X display is configured ($DISPLAY); GLFW 3.3 on Debian talks X11 only.
  static bool displayAvailable();

  // Instance extensions the surface needs (VK_KHR_surface and the platform's).
  std::vector<std::string> requiredInstanceExtensions() const;
  // Creates the window's surface on `instance`; the caller owns it (Device destroys it).
  VkSurfaceKHR createSurface(VkInstance instance) const;

  // Processes pending window-system events and returns the input received since the last call.
  std::vector<InputEvent> pollEvents();
  bool shouldClose() const;
  void requestClose();
  void setSize(uint32_t width_px, uint32_t height_px);
  // Framebuffer size in pixels (0 x 0 while minimised).
  VkExtent2D framebufferExtent() const;
  // True once after the framebuffer changed size.
  bool takeResized();
  void setTitle(const std::string& title);

  GLFWwindow* handle() const { return window_; }

 private:
  static void onKey(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void onMouseButton(GLFWwindow* w, int button, int action, int mods);
  static void onCursor(GLFWwindow* w, double x, double y);
  static void onChar(GLFWwindow* w, unsigned int codepoint);
  static void onFramebufferSize(GLFWwindow* w, int width, int height);

  GLFWwindow* window_ = nullptr;
  std::vector<InputEvent> pending_;
  bool resized_ = false;
};

}  // namespace globe
