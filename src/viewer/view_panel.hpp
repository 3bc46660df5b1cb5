#pragma once
#include <optional>
#include <string>
#include <vector>

#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "viewer/view_session.hpp"

namespace tp::app {

// What the panel shows besides the scene's parameters.
struct PanelStatus {
  uint32_t frame = 0;  // the frame number shown
  bool paused = false;
  double fps = 0.0;                                        // frames shown per second, lately
  const render::RenderedFrame* last = nullptr;             // the last frame rendered: its passes, counters, sleep
  const std::vector<std::string>* shaderErrors = nullptr;  // the last shader reload's, if it failed
  std::string message;  // the outcome of the last thing asked for: a saved path, a refused change
  bool messageIsError = false;
};

// Where the panel first stands in a window of `width` x `height` pixels:
// a third of the width at most (and kPanelMaxWidth), the window's height
// less a margin; in a window too narrow for kPanelMinWidth to be a third,
// started collapsed to its title bar, so the scene is seen first.
struct PanelPlacement {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
  bool collapsed = false;
};
constexpr float kPanelMaxWidth = 420.0f;
constexpr float kPanelMinWidth = 300.0f;  // the widgets with their labels legible
PanelPlacement panelPlacement(float width, float height);

// What was asked for in the panel this frame, to apply through ViewSession.
struct PanelRequests {
  std::optional<scene::Scene> scene;  // the parameters as edited (ViewSession::setScene)
  std::vector<ViewCommand> commands;  // pause, step, reset camera, save frame, reload shaders, save scene
};

// The viewer's Dear ImGui panel: every parameter a scene file has, drawn
// from the scene file's own key list (scene/scene_keys.hpp), the water's
// lambda and substeps, the profiler's passes and counters, frames per
// second, the last shader reload's errors, and buttons for what the keys do
// plus saving the scene. Call between UiOverlay::beginFrame and endFrame.
//
// Edits are made to a draft of the scene. Those the renderer takes live (the
// camera, the water's dynamics, a sphere's centre) are asked for as the
// widget moves; the others, which make a new renderer, when the widget is let
// go (a drag released, a field left, a box ticked, an item chosen).
class ViewPanel {
 public:
  PanelRequests draw(const scene::Scene& scene, const PanelStatus& status);

 private:
  scene::Scene draft_;
  std::string scenePath_;  // where "Save scene" writes; empty: scene-NNNN.json in the save folder
};

}  // namespace tp::app
