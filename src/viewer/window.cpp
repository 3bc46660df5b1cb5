#include "viewer/window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace tp::app {
namespace {

// GLFW reports errors through a callback; the last one goes into the exception.
std::string lastGlfwError;

void recordGlfwError(int, const char* description) { lastGlfwError = description ? description : "unknown error"; }

Window& self(GLFWwindow* window) { return *static_cast<Window*>(glfwGetWindowUserPointer(window)); }

[[noreturn]] void failToOpen(const std::string& what) {
  std::string message = "cannot open a window: " + what;
  if (!lastGlfwError.empty()) message += " (GLFW: " + lastGlfwError + ")";
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    message += "; DISPLAY is not set: run it under an X server, e.g. xvfb-run";
  }
  throw std::runtime_error(message);
}

}  // namespace

Window::Window(uint32_t width, uint32_t height, const std::string& title) {
  lastGlfwError.clear();
  glfwSetErrorCallback(recordGlfwError);
  if (glfwInit() != GLFW_TRUE) failToOpen("no display");
  if (glfwVulkanSupported() != GLFW_TRUE) {
    glfwTerminate();
    failToOpen("GLFW finds no Vulkan loader");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    glfwTerminate();
    failToOpen("GLFW could not create a " + std::to_string(width) + "x" + std::to_string(height) + " window");
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { self(w).resized_ = self(w).refresh_ = true; });
  glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { self(w).refresh_ = true; });
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (key == GLFW_KEY_ESCAPE) {
      if (action == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
    } else if (action == GLFW_PRESS || action == GLFW_REPEAT) {
      self(w).record({.kind = InputEvent::Kind::KeyDown, .code = key, .repeat = action == GLFW_REPEAT});
    }
  });
  // A button event is where the last motion event left the cursor:
  // glfwGetCursorPos asks the X server where it is now, past the events
  // still queued.
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  cursor_ = toFramebuffer(x, y);
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    Window& window = self(w);
    window.record({.kind = action == GLFW_PRESS ? InputEvent::Kind::ButtonDown : InputEvent::Kind::ButtonUp,
                   .code = button,
                   .position = window.cursor_});
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    Window& window = self(w);
    window.cursor_ = window.toFramebuffer(x, y);
    window.record({.kind = InputEvent::Kind::CursorMove, .position = window.cursor_});
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double x, double y) {
    self(w).record({.kind = InputEvent::Kind::Scroll, .position = {x, y}});
  });
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() const {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (names == nullptr) failToOpen("GLFW names no Vulkan surface extension for this window system");
  return std::vector<std::string>(names, names + count);
}

vk::raii::SurfaceKHR Window::createSurface(const vk::raii::Instance& instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  const VkResult result = glfwCreateWindowSurface(*instance, window_, nullptr, &surface);
  if (result != VK_SUCCESS) {
    throw std::runtime_error("cannot make a Vulkan surface for the window: " + vk::to_string(vk::Result(result)) +
                             (lastGlfwError.empty() ? "" : " (GLFW: " + lastGlfwError + ")"));
  }
  return vk::raii::SurfaceKHR(instance, surface);
}

vk::Extent2D Window::framebufferSize() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return {uint32_t(std::max(width, 0)), uint32_t(std::max(height, 0))};
}

bool Window::minimised() const {
  const vk::Extent2D size = framebufferSize();
  return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE || size.width == 0 || size.height == 0;
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void Window::pollEvents() { glfwPollEvents(); }

void Window::waitEvents() { glfwWaitEvents(); }

void Window::resize(uint32_t width, uint32_t height) { glfwSetWindowSize(window_, int(width), int(height)); }

bool Window::takeResized() {
  const bool resized = resized_;
  resized_ = false;
  return resized;
}

bool Window::takeRefresh() { return std::exchange(refresh_, false); }

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void Window::waitEventsTimeout(double seconds) { glfwWaitEventsTimeout(seconds); }

void Window::record(InputEvent event) { input_.push_back(event); }

std::vector<InputEvent> Window::takeInput() { return std::exchange(input_, {}); }

bool Window::keyHeld(int key) const { return glfwGetKey(window_, key) == GLFW_PRESS; }

// GLFW gives the cursor in screen coordinates, which differ from the
// framebuffer's pixels on a scaled display.
glm::dvec2 Window::toFramebuffer(double x, double y) const {
  int width = 0, height = 0;
  glfwGetWindowSize(window_, &width, &height);
  const vk::Extent2D framebuffer = framebufferSize();
  if (width <= 0 || height <= 0) return {x, y};
  return {x * framebuffer.width / width, y * framebuffer.height / height};
}

}  // namespace tp::app
