#include "app/view_command.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "app/gpu_session.hpp"
#include "app/view_loop.hpp"
#include "io/atomic_file.hpp"

namespace tp::app {
namespace {

// The whole of `text` as a number, or nothing.
template <typename T>
std::optional<T> number(std::string_view text) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// "WxH", each side 1..kMaxFrameSide, or nothing.
std::optional<std::pair<uint32_t, uint32_t>> parseSize(std::string_view text) {
  const size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const auto w = number<uint32_t>(text.substr(0, x)), h = number<uint32_t>(text.substr(x + 1));
  if (!w || !h || *w == 0 || *h == 0 || *w > kMaxFrameSide || *h > kMaxFrameSide) return std::nullopt;
  return std::pair{*w, *h};
}

std::runtime_error badValue(const char* option, const std::string& value, const char* expected) {
  return std::runtime_error(std::string(option) + " " + value + ": expected " + expected);
}

constexpr const char* kSizeForm = "WIDTHxHEIGHT with each side 1 to 16384, e.g. 1280x720";

ScriptedDrop scriptedDrop(const std::string& text) {
  constexpr const char* form = "FRAME:X,Z,RADIUS,AMP, e.g. 30:0.5,-0.3,0.25,0.04 (a positive radius)";
  const size_t colon = text.find(':');
  if (colon == std::string::npos) throw badValue("--script-drop", text, form);
  const auto frame = number<uint32_t>(std::string_view(text).substr(0, colon));
  float values[4];
  std::string_view rest = std::string_view(text).substr(colon + 1);
  for (int i = 0; i < 4; ++i) {
    const size_t comma = i < 3 ? rest.find(',') : rest.size();
    if (comma == std::string_view::npos) throw badValue("--script-drop", text, form);
    const auto value = number<float>(rest.substr(0, comma));
    if (!value || !std::isfinite(*value)) throw badValue("--script-drop", text, form);
    values[i] = *value;
    rest = rest.substr(std::min(comma + 1, rest.size()));
  }
  if (!frame || values[2] <= 0.0f) throw badValue("--script-drop", text, form);
  return {*frame, scene::Drop{values[0], values[1], values[2], values[3]}};
}

ScriptedResize scriptedResize(const std::string& text) {
  constexpr const char* form = "FRAME:WxH with each side 1 to 16384, e.g. 30:640x360";
  const size_t colon = text.find(':');
  if (colon == std::string::npos) throw badValue("--script-resize", text, form);
  const auto frame = number<uint32_t>(std::string_view(text).substr(0, colon));
  const auto wh = parseSize(std::string_view(text).substr(colon + 1));
  if (!frame || !wh) throw badValue("--script-resize", text, form);
  return {*frame, wh->first, wh->second};
}

void requireBeforeEnd(const char* option, uint32_t frame, uint32_t frames) {
  if (frames > 0 && frame >= frames) {
    throw std::runtime_error(std::string(option) + " at frame " + std::to_string(frame) + " is past the last frame (" +
                             std::to_string(frames - 1) + " with --frames " + std::to_string(frames) + ")");
  }
}

}  // namespace

CLI::App* addViewCommand(CLI::App& app, ViewOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Show the scene live in a window (GLFW, Vulkan swapchain), rendered by the renderer `render` uses: frame N is "
      "the water after N frames. Escape or closing the window quits. Not yet: camera control, interaction, a "
      "panel, shader reload (README, \"Viewer\")");
  addSceneOptions(cmd, o.scene);
  cmd->add_option("--size", o.size,
                  "Frame size WxH, and the window's first size; the frame keeps this size and is scaled to the "
                  "window, its aspect kept")
      ->type_name("WxH")
      ->capture_default_str();
  auto* frames = cmd->add_option("--frames", o.frames, "Show N frames (0 to N-1) with no input, then exit")
                     ->type_name("N")
                     ->check(CLI::Range(1u, 1000000u));
  cmd->add_option("--screenshot", o.screenshot,
                  "With --frames: save the last frame shown here, as `render` writes it (.exr: float linear RGBA; "
                  ".png: the 8-bit sRGB frame shown); written via a temporary file")
      ->type_name("PATH")
      ->needs(frames);
  cmd->add_option("--script-drop", o.scriptDrops,
                  "Testing aid: drop into the water just before frame FRAME is rendered (FRAME:X,Z,RADIUS,AMP in "
                  "metres, as a scene's water.drops; repeatable)")
      ->type_name("SPEC")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--script-resize", o.scriptResize,
                  "Testing aid: ask the window system for a WxH window just before frame FRAME is rendered "
                  "(FRAME:WxH); the frame's size stays --size")
      ->type_name("SPEC");
  addGpuOptions(cmd, o.validate, o.device);
  return cmd;
}

int runView(const ViewOptions& o) {
  // Every input is checked before the window opens: a mistake costs nothing and leaves nothing.
  const auto frameSize = parseSize(o.size);
  if (!frameSize) throw badValue("--size", o.size, kSizeForm);
  ViewConfig config;
  config.width = frameSize->first;
  config.height = frameSize->second;
  checkFramePixels(config.width, config.height);
  if (o.frames > 0) config.frames = o.frames;
  if (!o.screenshot.empty()) {
    if (!io::hasExtension(o.screenshot, ".exr") && !io::hasExtension(o.screenshot, ".png")) {
      throw std::runtime_error("screenshot " + o.screenshot + " must end in .exr or .png");
    }
    io::checkWritable(o.screenshot);
    config.screenshot = o.screenshot;
  }
  for (const std::string& text : o.scriptDrops) {
    config.drops.push_back(scriptedDrop(text));
    requireBeforeEnd("--script-drop", config.drops.back().frame, o.frames);
  }
  if (!o.scriptResize.empty()) {
    config.resize = scriptedResize(o.scriptResize);
    requireBeforeEnd("--script-resize", config.resize->frame, o.frames);
  }
  config.scene = loadScene(o.scene);
  if (!config.drops.empty() && !config.scene.water.enabled) {
    throw std::runtime_error("--script-drop needs a scene with water (this one has water.enabled false)");
  }
  config.validate = o.validate;
  config.device = o.device;
  return runViewer(config);
}

}  // namespace tp::app
