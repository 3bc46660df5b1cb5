#include "app/window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace tp::app {
namespace {

// GLFW reports errors through a callback; the last one goes into the exception.
std::string lastGlfwError;

void recordGlfwError(int, const char* description) { lastGlfwError = description ? description : "unknown error"; }

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
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) {
    static_cast<Window*>(glfwGetWindowUserPointer(w))->resized_ = true;
  });
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
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
    throw std::runtime_error("cannot make a Vulkan surface for the window: " +
                             vk::to_string(vk::Result(result)) + (lastGlfwError.empty() ? "" : " (GLFW: " + lastGlfwError + ")"));
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

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

}  // namespace tp::app
