#pragma once
#include <functional>
#include <optional>

#include "viewer/view_session.hpp"
#include "viewer/window.hpp"

namespace tp::app {

// Where a framebuffer pixel of the window falls in the frame the presenter
// letterboxes into it (FramePresenter's letterbox): in the frame's pixels,
// or none on the bars.
std::optional<glm::dvec2> framePixelAt(glm::dvec2 windowPixel, vk::Extent2D frame, vk::Extent2D window);

// Turns the window's input into the viewer's commands, handed one by one to
// `apply` (ViewSession::apply, the handler --script reaches too):
//
//   left button on a sphere     grab it; moving drags it (Grab, Drag; Release on button up)
//   left button on the water    a drop there (Drop)
//   left button elsewhere,
//   or right button anywhere    moving orbits the camera (Orbit)
//   wheel                       zoom (Zoom)
//   W A S D held                fly (Fly, per frame: flying())
//   R                           reset the camera (ResetCamera)
//   Space                       pause / run (TogglePause)
//   N or .                      step one frame, pausing (Step; repeats while held)
//   P or F12                    save the frame as EXR (Save)
//
// (Escape closes the window: app/window.)
class ViewInput {
 public:
  using Apply = std::function<bool(const ViewCommand&)>;
  explicit ViewInput(vk::Extent2D frame) : frame_(frame) {}

  // `window`: the framebuffer's size now.
  void handle(const InputEvent& event, vk::Extent2D window, const Apply& apply);
  // The fly keys held now, as a Fly command for `seconds`; none when none is held.
  std::optional<command::Fly> flying(const Window& window, double seconds) const;

 private:
  enum class Mouse { Idle, Dragging, Orbiting };
  vk::Extent2D frame_;
  Mouse mouse_ = Mouse::Idle;
  int button_ = -1;         // the button that started the drag or orbit
  glm::dvec2 cursor_{0.0};  // the last cursor position, framebuffer pixels
};

}  // namespace tp::app
