#include "viewer/view_command.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "base/data_dir.hpp"
#include "cli/frame_size.hpp"
#include "cli/gpu_session.hpp"
#include "cli/number_checks.hpp"
#include "cli/usage_error.hpp"
#include "cli/whole_number.hpp"
#include "scene/scene_file.hpp"
#include "viewer/view_loop.hpp"

namespace tp::app {
namespace {

UsageError badValue(const char* option, const std::string& value, const char* expected) {
  return UsageError(std::string(option) + " " + value + ": expected " + expected);
}

ScriptedDrop scriptedDrop(const std::string& text) {
  constexpr const char* form = "FRAME:X,Z,RADIUS,AMP, e.g. 30:0.5,-0.3,0.25,0.04 (a positive radius)";
  const size_t colon = text.find(':');
  if (colon == std::string::npos) throw badValue("--script-drop", text, form);
  const auto frame = wholeNumber<uint32_t>(std::string_view(text).substr(0, colon));
  float values[4];
  std::string_view rest = std::string_view(text).substr(colon + 1);
  for (int i = 0; i < 4; ++i) {
    const size_t comma = i < 3 ? rest.find(',') : rest.size();
    if (comma == std::string_view::npos) throw badValue("--script-drop", text, form);
    const auto value = wholeNumber<float>(rest.substr(0, comma));
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
  const auto frame = wholeNumber<uint32_t>(std::string_view(text).substr(0, colon));
  const auto wh = parseFrameSize(std::string_view(text).substr(colon + 1), 1, kMaxFrameSide);
  if (!frame || !wh) throw badValue("--script-resize", text, form);
  return {*frame, wh->width, wh->height};
}

constexpr const char* kScriptForm =
    "FRAME:ACTION[:ARGS] with ACTION one of orbit:DX,DY (window pixels dragged), zoom:NOTCHES, "
    "fly:FORWARD,RIGHT,SECONDS (each of FORWARD, RIGHT in -1..1, SECONDS in (0, 10]), reset, drop:X,Y, grab:X,Y, "
    "drag:X,Y (frame pixels), release, pause, step, save, reload, save-scene[:PATH.json], set:KEY=VALUE (a scene "
    "file's key joined by dots, a JSON value or a bare word); e.g. 12:orbit:40,-10, 30:set:render.refraction=apparent";

// `count` finite numbers separated by commas, or nothing.
std::optional<std::vector<double>> numberList(std::string_view text, size_t count) {
  std::vector<double> values;
  for (size_t k = 0; k < count; ++k) {
    const size_t comma = k + 1 < count ? text.find(',') : text.size();
    if (comma == std::string_view::npos) return std::nullopt;
    const auto value = wholeNumber<double>(text.substr(0, comma));
    if (!value || !std::isfinite(*value)) return std::nullopt;
    values.push_back(*value);
    text = text.substr(std::min(comma + 1, text.size()));
  }
  return values;
}

ScriptedCommand scriptedCommand(const std::string& text, uint32_t width, uint32_t height) {
  const std::string_view all(text);
  const size_t colon = all.find(':');
  const auto frame = wholeNumber<uint32_t>(all.substr(0, colon));
  if (colon == std::string_view::npos || !frame) throw badValue("--script", text, kScriptForm);
  const std::string_view rest = all.substr(colon + 1);
  const size_t argsAt = rest.find(':');
  const std::string_view action = rest.substr(0, argsAt);
  const std::optional<std::string_view> args =
      argsAt == std::string_view::npos ? std::nullopt : std::optional(rest.substr(argsAt + 1));
  auto fail = [&](const std::string& why) { return UsageError("--script " + text + ": " + why); };
  // The action's arguments: exactly `count` numbers (none: no ":ARGS").
  auto values = [&](size_t count, const char* form) {
    if (count == 0) {
      if (args) throw fail(std::string("expected FRAME:") + form + " (no arguments)");
      return std::vector<double>{};
    }
    const auto list = args ? numberList(*args, count) : std::nullopt;
    if (!list) throw fail(std::string("expected FRAME:") + form);
    return *list;
  };
  auto pixel = [&](const char* form) {
    const std::vector<double> v = values(2, form);
    if (v[0] < 0.0 || v[1] < 0.0 || v[0] > width || v[1] > height) {
      throw fail("the pixel is outside the " + std::to_string(width) + "x" + std::to_string(height) + " frame");
    }
    return glm::dvec2(v[0], v[1]);
  };
  const auto make = [&]() -> ViewCommand {
    if (action == "orbit") {
      const auto v = values(2, "orbit:DX,DY (window pixels dragged)");
      return command::Orbit{v[0], v[1]};
    }
    if (action == "zoom") return command::Zoom{values(1, "zoom:NOTCHES (wheel notches, positive closer)")[0]};
    if (action == "fly") {
      const auto v = values(3, "fly:FORWARD,RIGHT,SECONDS");
      if (std::abs(v[0]) > 1.0 || std::abs(v[1]) > 1.0 || !(v[2] > 0.0 && v[2] <= 10.0)) {
        throw fail("FORWARD and RIGHT must lie in -1..1 and SECONDS in (0, 10]");
      }
      return command::Fly{v[0], v[1], v[2]};
    }
    if (action == "drop") return command::Drop{pixel("drop:X,Y (frame pixels)")};
    if (action == "grab") return command::Grab{pixel("grab:X,Y (frame pixels)")};
    if (action == "drag") return command::Drag{pixel("drag:X,Y (frame pixels)")};
    if (action == "save-scene") {
      const std::string path = args ? std::string(*args) : std::string();
      if (args && (path.empty() || !base::hasExtension(path, ".json")))
        throw fail("the scene's path must end in .json");
      if (!path.empty()) base::checkWritable(path);
      return command::SaveScene{path};
    }
    if (action == "set") {
      const size_t equals = args ? args->find('=') : std::string_view::npos;
      if (equals == std::string_view::npos || equals == 0) throw fail("expected FRAME:set:KEY=VALUE");
      return command::Set{std::string(args->substr(0, equals)), std::string(args->substr(equals + 1))};
    }
    const std::pair<const char*, ViewCommand> bare[] = {
        {"reset", command::ResetCamera{}}, {"release", command::Release{}}, {"pause", command::TogglePause{}},
        {"step", command::Step{}},         {"save", command::Save{}},       {"reload", command::ReloadShaders{}}};
    for (const auto& [name, c] : bare) {
      if (action != name) continue;
      values(0, name);
      return c;
    }
    throw fail("unknown action \"" + std::string(action) + "\"; expected " + kScriptForm);
  };
  return {*frame, make()};
}

void requireBeforeEnd(const char* option, uint32_t frame, uint32_t frames) {
  if (frames > 0 && frame >= frames) {
    throw UsageError(std::string(option) + " at frame " + std::to_string(frame) + " is past the last frame (" +
                     std::to_string(frames - 1) + " with --frames " + std::to_string(frames) + ")");
  }
}

}  // namespace

CLI::App* addViewCommand(CLI::App& app, ViewOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Show the scene live in a window (GLFW, Vulkan swapchain), rendered by the renderer `render` uses: frame N is "
      "the water after N frames. The mouse, wheel and keys move the camera, drop into the water, drag the sphere, "
      "pause, step, save and reload the shaders (below); the panel (Dear ImGui) shows and edits every parameter of "
      "the scene, the GPU passes and counters, and saves the scene as a file `render` reproduces. Escape or closing "
      "the window quits");
  cmd->footer(
      "Controls:\n"
      "  left drag on a sphere      move it in the horizontal plane at its centre's height (it displaces the water)\n"
      "  left click on the water    a drop where the pixel's ray meets the surface\n"
      "  left drag elsewhere,\n"
      "  right drag anywhere        orbit the camera about its target\n"
      "  wheel                      zoom (the distance to the target)\n"
      "  W A S D                    fly: forward, left, back, right, horizontally\n"
      "  R                          reset the camera to the scene's\n"
      "  Space                      pause / run the simulation (the frame number holds; the camera still moves)\n"
      "  N or .                     step one frame (pauses)\n"
      "  P or F12                   save the next frame rendered (paused: the frame shown) as view-NNNN.exr, float\n"
      "                             linear RGBA with the camera attributes, in --save-dir; NNNN: its frame number\n"
      "  F5                         compile the shaders in --shader-dir again and use those that changed (the water,\n"
      "                             camera and frame go on); a shader that fails prints its errors and keeps its code\n"
      "  F1                         hide / show the panel (the mouse and keys over it work the panel)\n"
      "  Escape                     quit");
  addSceneOptions(cmd, o.scene);
  cmd->add_option("--size", o.size,
                  "Frame size WxH, and the window's first size; the frame keeps this size and is scaled to the "
                  "window, its aspect kept")
      ->type_name("WxH")
      ->capture_default_str()
      ->check(frameSizeCheck(1, kMaxFrameSide));
  auto* frames =
      cmd->add_option("--frames", o.frames,
                      "Show N frames, then exit: frame numbers 0 to N-1 unless paused (the mouse and keys still work)")
          ->type_name("N")
          ->check(inRange(1u, 1000000u));
  cmd->add_option("--screenshot", o.screenshot,
                  "With --frames: save the last frame shown here, as `render` writes it (.exr: float linear RGBA; "
                  ".png: the 8-bit sRGB frame shown); written via a temporary file")
      ->type_name("PATH")
      ->needs(frames);
  cmd->add_option("--script-drop", o.scriptDrops,
                  "Testing aid: drop into the water just before the FRAME-th frame shown (counted from 0) "
                  "(FRAME:X,Z,RADIUS,AMP in metres, as a scene's water.drops; repeatable)")
      ->type_name("SPEC")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--script-resize", o.scriptResize,
                  "Testing aid: ask the window system for a WxH window just before the FRAME-th frame shown "
                  "(FRAME:WxH); the frame's size stays --size")
      ->type_name("SPEC");
  cmd->add_option("--save-dir", o.saveDir,
                  "Where the save key (P, F12) writes view-NNNN.exr (NNNN: the frame number; -2, -3, ... added "
                  "rather than overwrite); default: the working directory")
      ->type_name("DIR");
  cmd->add_option("--shader-dir", o.shaderDir,
                  "The GLSL sources the reload key (F5) compiles: a folder laid out as shaders_glsl/; default: "
                  "PREFIX/share/tidepool/shaders_glsl for an installed PREFIX/bin/tidepool, else the shaders_glsl/ "
                  "this tidepool was built from; here: " +
                      base::dataDir("shaders_glsl", TIDEPOOL_SHADERS_DIR).string())
      ->type_name("DIR");
  cmd->add_option("--script", o.script,
                  "Testing aid: apply a command just before the FRAME-th frame shown (counted from 0; with a pause "
                  "not the frame number), through the same handler as the mouse and keys: FRAME:ACTION[:ARGS] with "
                  "ACTION orbit:DX,DY (window pixels dragged), zoom:NOTCHES, fly:FORWARD,RIGHT,SECONDS, reset, "
                  "drop:X,Y, grab:X,Y, drag:X,Y (frame pixels from the top-left corner), release, pause (toggles), "
                  "step, save, reload, save-scene[:PATH.json] (default: scene-NNNN.json in --save-dir), set:KEY=VALUE "
                  "(a scene file's key joined by dots, e.g. water.wave_speed=0.8, spheres.0.radius=0.3, "
                  "render.refraction=apparent, ao.preset=fast); repeatable, applied by frame and in the order given")
      ->type_name("SPEC")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_flag("--no-panel", o.noPanel, "Start with the panel hidden (F1 shows it)");
  cmd->add_option("--target-fps", o.targetFps,
                  "Dynamic resolution: render below --size (down to an eighth of each side) when the frames come "
                  "slower than F per second, back up when they come fast enough; the frame shown is scaled to the "
                  "window, and the panel and the summary give the size rendered")
      ->type_name("F")
      ->check(inRange(1.0, 1000.0));
  cmd->add_flag("--profile", o.profile,
                "At the end, print the last frame rendered's passes as `render --profile` does (GPU ms, dispatches, "
                "draws, workgroups; no wall ms: the frames are submitted whole)");
  addGpuOptions(cmd, o.validate, o.device);
  return cmd;
}

int runView(const ViewOptions& o) {
  // Every input is checked before the window opens: a mistake costs nothing and leaves nothing.
  const auto frameSize = parseFrameSize(o.size, 1, kMaxFrameSide);  // checked by the parser (frameSizeCheck)
  ViewConfig config;
  config.width = frameSize->width;
  config.height = frameSize->height;
  checkFramePixels(config.width, config.height);
  if (o.frames > 0) config.frames = o.frames;
  if (!o.screenshot.empty()) {
    if (!base::hasExtension(o.screenshot, ".exr") && !base::hasExtension(o.screenshot, ".png")) {
      throw UsageError("screenshot " + o.screenshot + " must end in .exr or .png");
    }
    base::checkWritable(o.screenshot);
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
  // The script in the order it applies: by frame, in the order given within one.
  std::vector<std::pair<ScriptedCommand, const std::string*>> script;
  for (const std::string& text : o.script) {
    script.emplace_back(scriptedCommand(text, config.width, config.height), &text);
    requireBeforeEnd("--script", script.back().first.frame, o.frames);
  }
  std::stable_sort(script.begin(), script.end(),
                   [](const auto& a, const auto& b) { return a.first.frame < b.first.frame; });
  bool grabbed = false, drops = false, saves = false;
  config.scene = loadScene(o.scene);
  // A moving camera starts where its path or turntable starts; the mouse moves it from there.
  config.scene.camera = scene::cameraAt(config.scene.camera, 0.0f);
  for (const auto& [scripted, text] : script) {
    const ViewCommand& c = scripted.command;
    if ((std::holds_alternative<command::Drag>(c) || std::holds_alternative<command::Release>(c)) && !grabbed) {
      throw UsageError("--script " + *text + ": no grab comes before it");
    }
    grabbed = (grabbed || std::holds_alternative<command::Grab>(c)) && !std::holds_alternative<command::Release>(c);
    drops |= std::holds_alternative<command::Drop>(c);
    saves |= std::holds_alternative<command::Save>(c);
    if (const auto* scenePath = std::get_if<command::SaveScene>(&c)) saves |= scenePath->path.empty();
    if (const auto* set = std::get_if<command::Set>(&c)) {
      // Each setting must make a possible scene of the one the viewer starts with.
      try {
        (void)scene::withSetting(config.scene, set->key, set->value);
      } catch (const std::exception& e) {
        throw UsageError("--script " + *text + ": " + e.what());
      }
    }
    config.script.push_back(scripted);
  }
  if (!o.saveDir.empty() || saves) {
    // What a save would write first: the directory must be there and writable.
    base::checkWritable((std::filesystem::path(o.saveDir) / "view-0000.exr").string());
    config.saveDir = o.saveDir;
  }
  // The default may be gone (a moved build): then only the reload key says so.
  if (!o.shaderDir.empty() && !std::filesystem::is_directory(o.shaderDir)) {
    throw UsageError("--shader-dir " + o.shaderDir + ": not a folder");
  }
  config.shaderDir = o.shaderDir.empty() ? base::dataDir("shaders_glsl", TIDEPOOL_SHADERS_DIR).string() : o.shaderDir;
  config.panel = !o.noPanel;
  if (o.targetFps > 0.0) config.targetFps = o.targetFps;
  config.profile = o.profile;
  if (!config.scene.water.enabled && (!config.drops.empty() || drops)) {
    throw UsageError(std::string(config.drops.empty() ? "--script drop" : "--script-drop") +
                     " needs a scene with water (this one has water.enabled false)");
  }
  config.validate = o.validate;
  config.device = o.device;
  return runViewer(config);
}

}  // namespace tp::app
