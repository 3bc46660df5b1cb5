#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gpu/vulkan.hpp"

struct GLFWwindow;

namespace tp::app {

// One input event, as the window system gave it (app/view_input turns them
// into the viewer's commands).
struct InputEvent {
  enum class Kind { KeyDown, ButtonDown, ButtonUp, CursorMove, Scroll };
  Kind kind = Kind::KeyDown;
  int code = 0;              // KeyDown: the GLFW key; ButtonDown, ButtonUp: the GLFW mouse button
  bool repeat = false;       // KeyDown: the key held down, repeating
  glm::dvec2 position{0.0};  // the cursor in framebuffer pixels; Scroll: the wheel's offsets (y > 0: forward)
};

// A GLFW window with no client API, for a Vulkan surface. It initialises
// GLFW and terminates it when destroyed: one Window at a time. Escape closes
// it.
class Window {
 public:
  // Throws one line when no window can be opened: no display (DISPLAY unset
  // or unreachable), or GLFW without Vulkan.
  Window(uint32_t width, uint32_t height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // The instance extensions a surface on this window system needs.
  std::vector<std::string> requiredInstanceExtensions() const;
  // Destroy the surface before the instance and before this window.
  vk::raii::SurfaceKHR createSurface(const vk::raii::Instance& instance) const;

  // In pixels; 0 x 0 while minimised on some window systems.
  vk::Extent2D framebufferSize() const;
  // Iconified, or a framebuffer with no area: nothing to draw into.
  bool minimised() const;
  bool shouldClose() const;
  void pollEvents();
  // Blocks until an event arrives (while minimised nothing is drawn).
  void waitEvents();
  // Asks the window system for a new size; framebufferSize() follows when it
  // has done it.
  void resize(uint32_t width, uint32_t height);
  // Whether the framebuffer changed size since the last call.
  bool takeResized();
  // Whether the window system asked for the content to be drawn again (it
  // was exposed, or changed size) since the last call.
  bool takeRefresh();
  void setTitle(const std::string& title);
  // Like waitEvents, for at most `seconds`.
  void waitEventsTimeout(double seconds);

  // The input events since the last call, oldest first (Escape is not among
  // them: it closes the window).
  std::vector<InputEvent> takeInput();
  // Whether a key (GLFW_KEY_...) is held down now.
  bool keyHeld(int key) const;
  // For ImGui's GLFW backend, which chains its callbacks to this window's.
  GLFWwindow* handle() const { return window_; }

 private:
  void record(InputEvent event);
  glm::dvec2 toFramebuffer(double x, double y) const;

  GLFWwindow* window_ = nullptr;
  bool resized_ = false;
  bool refresh_ = false;
  std::vector<InputEvent> input_;
  glm::dvec2 cursor_{0.0};  // framebuffer pixels, as the last motion event put it
};

}  // namespace tp::app
