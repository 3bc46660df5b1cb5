#pragma once
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "render/renderer.hpp"
#include "viewer/camera_controller.hpp"
#include "viewer/water_pick.hpp"

namespace tp::app {

// The viewer's commands: what the keyboard and mouse do (app/view_input),
// and what --script injects. Pixels are the frame's (its --size, from the
// top-left corner; pixel (i, j)'s centre is (i + 1/2, j + 1/2)), except
// Orbit's, which are the window's.
namespace command {
struct Orbit {
  double dx = 0.0, dy = 0.0;
};  // a mouse drag: right turns the view right, down raises the camera
struct Zoom {
  double notches = 0.0;
};  // wheel notches; forward (positive) closer
struct Fly {
  double forward = 0.0, right = 0.0, seconds = 0.0;
};  // keys held: W/S +-forward, D/A +-right
struct ResetCamera {};
struct Drop {
  glm::dvec2 pixel{0.0};
};  // a drop where the pixel's ray meets the water
struct Grab {
  glm::dvec2 pixel{0.0};
};  // mouse down: take the sphere the pixel shows
struct Drag {
  glm::dvec2 pixel{0.0};
};  // mouse moved: the grabbed sphere follows in its horizontal plane
struct Release {};
struct TogglePause {};
struct Step {};           // show the next frame and hold it (pausing if running)
struct Save {};           // save the frame as view-NNNN.exr
struct ReloadShaders {};  // compile the shaders again and make the renderer's pipelines from those that changed
// Save the scene as it now stands as a scene file (empty path: scene-NNNN.json in the save folder).
struct SaveScene {
  std::string path;
};
// Change one setting, named by its scene-file key with dots (scene::withSetting).
struct Set {
  std::string key, value;
};
}  // namespace command

using ViewCommand = std::variant<command::Orbit, command::Zoom, command::Fly, command::ResetCamera, command::Drop,
                                 command::Grab, command::Drag, command::Release, command::TogglePause, command::Step,
                                 command::Save, command::ReloadShaders, command::SaveScene, command::Set>;

// A drop made by a click: radius and amplitude in metres.
constexpr float kClickDropRadius = 0.15f;
constexpr float kClickDropAmplitude = 0.03f;

// Saves a rendered frame, frame number `frameNumber` of `scene`, as `render`
// writes it: `.exr` float linear RGBA with render's attributes
// (frameExrAttributes; the frame needs its HDR readback), `.png` the 8-bit
// sRGB frame; through a temporary file.
void saveFrame(const std::string& path, const render::RenderedFrame& frame, const scene::Scene& scene,
               uint32_t frameNumber);

// The viewer's state between frames and the one handler of its commands,
// whether they come from the window or from a script: the camera (a
// CameraController whose camera goes to Renderer::setCamera), the frame
// number the next render shows, pause, the sphere being dragged, a save
// asked for.
class ViewSession {
 public:
  // `saveDir`: where Save writes (empty: the working directory);
  // `shaderDir`: the GLSL sources ReloadShaders compiles.
  ViewSession(std::unique_ptr<render::Renderer> renderer, uint32_t width, uint32_t height, std::string saveDir,
              std::filesystem::path shaderDir);

  // The renderer, which ReloadShaders replaces by one made again from it.
  render::Renderer& renderer() { return *renderer_; }

  // Applies a command. Returns whether it took hold: false for a Drop whose
  // ray misses the water (or a scene without water), a Grab that meets no
  // sphere, a Drag with no sphere grabbed or whose ray misses the sphere's
  // plane (or meets it beyond the far plane), a shader reload with errors, a
  // scene save or setting that failed (message() says why); true otherwise.
  bool apply(const ViewCommand& command);

  // Makes the scene `wanted` the one shown, changing what differs in the
  // cheapest way that keeps the water going: the camera, the water's
  // dynamics and a sphere's centre live; anything else but the water's own
  // simulation (grid, extent, level, frame time, drops) by a renderer made
  // from the current one, which carries the water on; a change to those
  // restarts the water at frame 0 with a new renderer. An impossible scene
  // changes nothing: returns false, message() says why.
  bool setScene(const scene::Scene& wanted);

  // Renders from the next frame on at another size (dynamic resolution): a
  // renderer made from the current one, the water going on. Commands keep
  // taking pixels of the frame's full size.
  void renderAt(uint32_t width, uint32_t height);

  // The outcome of the last save, scene change or shader reload, for the panel.
  const std::string& message() const { return message_; }
  bool messageIsError() const { return messageIsError_; }
  // The errors of the last shader reload (empty when it compiled).
  const std::vector<std::string>& shaderErrors() const { return shaderErrors_; }

  // The frame number the next render shows: it advances by one per frame
  // rendered unless paused.
  uint32_t frame() const { return frame_; }
  bool paused() const { return paused_; }
  // Whether the next render must read back the HDR image (a save was asked for).
  bool wantsHdr() const { return saveAsked_; }
  // Whether the next frame must be rendered: always while running; paused,
  // when another frame number or a command since the last render changes the
  // picture (an unchanged paused frame need not be rendered again).
  bool needsRender() const { return !paused_ || changed_ || lastRendered_ != frame_; }

  // After the frame numbered frame() was rendered: writes the save asked for
  // (printing its path), then advances the frame number unless paused.
  void rendered(const render::RenderedFrame& frame);

 private:
  struct Grabbed {
    size_t index = 0;
    glm::vec3 center{0.0f};  // where the sphere was when grabbed
    glm::dvec3 anchor{0.0};  // the grab's ray on the horizontal plane through that centre
    glm::vec3 now{0.0f};     // where the drag has put it
  };
  void setCamera();
  // apply()'s commands that take more than a line: each returns what apply() does.
  Ray rayThrough(glm::dvec2 pixel) const;  // the camera's ray through a frame pixel
  bool dropAt(glm::dvec2 pixel);
  bool grab(glm::dvec2 pixel);
  bool drag(glm::dvec2 pixel);
  bool reloadShaders();
  bool saveScene(const std::string& path);  // empty: a name of its own in the save folder
  // `stem`-NNNN.`extension` in the save folder (NNNN: `frame`), never over an earlier one.
  std::string savePath(const char* stem, const char* extension, uint32_t frame) const;
  // Prints the message (on `stream`; by default stderr for an error, else
  // stdout) and keeps it for the panel.
  void tell(std::string message, bool error, std::FILE* stream = nullptr);

  std::unique_ptr<render::Renderer> renderer_;
  uint32_t width_, height_;
  std::string saveDir_;
  std::filesystem::path shaderDir_;
  CameraController camera_;
  uint32_t frame_ = 0;
  bool paused_ = false;
  bool saveAsked_ = false;
  bool changed_ = false;
  std::optional<uint32_t> lastRendered_;
  std::optional<Grabbed> grabbed_;
  std::string message_;
  bool messageIsError_ = false;
  std::vector<std::string> shaderErrors_;
};

}  // namespace tp::app
