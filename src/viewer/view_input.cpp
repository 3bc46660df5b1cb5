#include "viewer/view_input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "viewer/frame_presenter.hpp"

namespace tp::app {

std::optional<glm::dvec2> framePixelAt(glm::dvec2 windowPixel, vk::Extent2D frame, vk::Extent2D window) {
  const auto [low, high] = letterbox(frame, window);
  const glm::dvec2 local(windowPixel.x - low.x, windowPixel.y - low.y);
  const glm::dvec2 size(high.x - low.x, high.y - low.y);
  if (local.x < 0.0 || local.y < 0.0 || local.x >= size.x || local.y >= size.y) return std::nullopt;
  return glm::dvec2(local.x * frame.width / size.x, local.y * frame.height / size.y);
}

void ViewInput::handle(const InputEvent& event, vk::Extent2D window, const Apply& apply) {
  using Kind = InputEvent::Kind;
  switch (event.kind) {
    case Kind::KeyDown:
      switch (event.code) {
        case GLFW_KEY_N:
        case GLFW_KEY_PERIOD:
          apply(command::Step{});
          break;
        case GLFW_KEY_SPACE:
          if (!event.repeat) apply(command::TogglePause{});
          break;
        case GLFW_KEY_R:
          if (!event.repeat) apply(command::ResetCamera{});
          break;
        case GLFW_KEY_P:
        case GLFW_KEY_F12:
          if (!event.repeat) apply(command::Save{});
          break;
        case GLFW_KEY_F5:
          if (!event.repeat) apply(command::ReloadShaders{});
          break;
        default:
          break;
      }
      break;
    case Kind::ButtonDown: {
      if (mouse_ != Mouse::Idle) break;  // a second button during a drag changes nothing
      cursor_ = event.position;
      button_ = event.code;
      const auto pixel = framePixelAt(event.position, frame_, window);
      if (event.code == GLFW_MOUSE_BUTTON_LEFT && pixel && apply(command::Grab{*pixel})) {
        mouse_ = Mouse::Dragging;
      } else if (event.code == GLFW_MOUSE_BUTTON_LEFT && pixel && apply(command::Drop{*pixel})) {
        button_ = -1;
      } else if (event.code == GLFW_MOUSE_BUTTON_LEFT || event.code == GLFW_MOUSE_BUTTON_RIGHT) {
        mouse_ = Mouse::Orbiting;
      }
      break;
    }
    case Kind::ButtonUp:
      if (event.code != button_) break;
      if (mouse_ == Mouse::Dragging) apply(command::Release{});
      mouse_ = Mouse::Idle;
      button_ = -1;
      break;
    case Kind::CursorMove: {
      const glm::dvec2 moved = event.position - cursor_;
      cursor_ = event.position;
      if (mouse_ == Mouse::Orbiting) {
        apply(command::Orbit{moved.x, moved.y});
      } else if (mouse_ == Mouse::Dragging) {
        // Off the frame (on a bar) the sphere waits for the cursor to come back.
        if (const auto pixel = framePixelAt(event.position, frame_, window)) apply(command::Drag{*pixel});
      }
      break;
    }
    case Kind::Scroll:
      if (event.position.y != 0.0) apply(command::Zoom{event.position.y});
      break;
  }
}

std::optional<command::Fly> ViewInput::flying(const Window& window, double seconds) const {
  const double forward = double(window.keyHeld(GLFW_KEY_W)) - double(window.keyHeld(GLFW_KEY_S));
  const double right = double(window.keyHeld(GLFW_KEY_D)) - double(window.keyHeld(GLFW_KEY_A));
  if (forward == 0.0 && right == 0.0) return std::nullopt;
  return command::Fly{forward, right, seconds};
}

}  // namespace tp::app
