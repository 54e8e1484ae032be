#include "engine/viewer/window.h"

#include "engine/vk/vk_check.h"

#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace globe {

namespace {

std::string glfwErrorText() {
  const char* description = nullptr;
  int code = glfwGetError(&description);
  if (code == GLFW_NO_ERROR) return "unknown GLFW error";
  return description ? description : "GLFW error " + std::to_string(code);
}

Window* self(GLFWwindow* w) { return static_cast<Window*>(glfwGetWindowUserPointer(w)); }

}  // namespace

bool Window::displayAvailable() {
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

Window::Window(uint32_t width_px, uint32_t height_px, const std::string& title) {
  if (!displayAvailable())
    throw std::runtime_error("no display: $DISPLAY is not set (run on a desktop, or under xvfb-run)");
  if (!glfwInit()) throw std::runtime_error("cannot initialise GLFW: " + glfwErrorText());
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw std::runtime_error("GLFW finds no Vulkan loader (is libvulkan1 installed?)");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan, not OpenGL
  window_ = glfwCreateWindow(int(width_px), int(height_px), title.c_str(), nullptr, nullptr);
  if (!window_) {
    std::string why = glfwErrorText();
    glfwTerminate();
    throw std::runtime_error("cannot open a window: " + why);
  }
  glfwSetWindowUserPointer(window_, this);
  // Installed before ImGui's backend, which chains to these.
  glfwSetKeyCallback(window_, &Window::onKey);
  glfwSetMouseButtonCallback(window_, &Window::onMouseButton);
  glfwSetCursorPosCallback(window_, &Window::onCursor);
  glfwSetCharCallback(window_, &Window::onChar);
  glfwSetFramebufferSizeCallback(window_, &Window::onFramebufferSize);
}

Window::~Window() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() const {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw std::runtime_error("GLFW cannot present with Vulkan here: " + glfwErrorText());
  return {names, names + count};
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  GLOBE_VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
  return surface;
}

std::vector<InputEvent> Window::pollEvents() {
  glfwPollEvents();
  std::vector<InputEvent> events;
  events.swap(pending_);
  return events;
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::setSize(uint32_t width_px, uint32_t height_px) {
  glfwSetWindowSize(window_, int(width_px), int(height_px));
}
void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

VkExtent2D Window::framebufferExtent() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

bool Window::takeResized() { return std::exchange(resized_, false); }

void Window::onKey(GLFWwindow* w, int key, int, int action, int) {
  if (action == GLFW_REPEAT || key == GLFW_KEY_UNKNOWN) return;
  self(w)->pending_.push_back({InputEvent::Type::kKey, key, action == GLFW_PRESS, 0, 0});
}

void Window::onMouseButton(GLFWwindow* w, int button, int action, int) {
  self(w)->pending_.push_back({InputEvent::Type::kMouseButton, button, action == GLFW_PRESS, 0, 0});
}

void Window::onCursor(GLFWwindow* w, double x, double y) {
  self(w)->pending_.push_back({InputEvent::Type::kMouseMove, 0, false, x, y});
}

void Window::onChar(GLFWwindow* w, unsigned int codepoint) {
  self(w)->pending_.push_back({InputEvent::Type::kChar, int(codepoint), true, 0, 0});
}

void Window::onFramebufferSize(GLFWwindow* w, int, int) { self(w)->resized_ = true; }

}  // namespace globe
