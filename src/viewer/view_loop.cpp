#include "viewer/view_loop.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "base/atomic_file.hpp"
#include "base/median.hpp"
#include "cli/gpu_session.hpp"
#include "cli/profile_table.hpp"
#include "io/image_io.hpp"
#include "render/renderer.hpp"
#include "viewer/frame_presenter.hpp"
#include "viewer/resolution_governor.hpp"
#include "viewer/swapchain.hpp"
#include "viewer/view_input.hpp"
#include "viewer/view_panel.hpp"
#include "viewer/window.hpp"

namespace tp::app {
namespace {

using Clock = std::chrono::steady_clock;

// The weight of the newest frame interval in the panel's frames per second.
constexpr double kFpsSmoothing = 0.1;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct ViewStats {
  uint32_t framesShown = 0;
  double seconds = 0.0;  // from the first frame's start to the last one's present
  // From the first frame's present to the last one's: the steady rate, without
  // the first frame's one-off costs (lavapipe compiles each pipeline's shaders
  // on its first draw, the sky and the caches are filled).
  double secondsAfterFirst = 0.0;
  double renderSeconds = 0.0;  // in Renderer::render, readback included
  double showSeconds = 0.0;    // in FramePresenter::show and swapchain recreation, waits for FIFO included
  uint32_t recreations = 0;
  vk::Extent2D window;
  vk::Extent2D rendered;           // the size of the last frame rendered
  std::vector<double> intervals;   // seconds between frames shown, from the first
  uint32_t resolutionChanges = 0;  // made by --target-fps
  uint32_t lastFrame = 0;          // the frame number of the last frame rendered
  scene::Scene lastScene;          // the scene as it stood then (panel and script edits made)
};

// The framebuffer's size once the window is not minimised (until then it
// sleeps in the window system); 0 x 0 when it was closed meanwhile.
vk::Extent2D waitForArea(Window& window) {
  while (window.minimised()) {
    if (window.shouldClose()) return {0, 0};
    window.waitEvents();
  }
  return window.framebufferSize();
}

vk::Extent2D firstArea(Window& window) {
  const vk::Extent2D area = waitForArea(window);
  if (area.width == 0) throw std::runtime_error("the window was closed before its first frame");
  return area;
}

// The window, the swapchain on it, the panel's overlay, and the showing of one frame.
class Display {
 public:
  Display(const gpu::Context& ctx, Window& window, vk::Extent2D frameSize)
      : ctx_(ctx),
        window_(window),
        surface_(window.createSurface(ctx.instance())),
        swapchain_(ctx, surface_, firstArea(window)),
        overlay_(ctx, window.handle(), swapchain_),
        presenter_(ctx, frameSize) {}

  UiOverlay& overlay() { return overlay_; }

  // Shows the frame (with the panel's last widgets over it when `panel`),
  // recreating the swapchain (and showing it again) until it is presented.
  // Returns false when the window was closed while minimised: the frame was
  // not shown.
  bool show(const FramePresenter::Frame& frame, bool panel, ViewStats& stats) {
    for (;;) {
      const vk::Extent2D area = waitForArea(window_);
      if (area.width == 0) return false;
      // A resize the swapchain has already followed (after an out-of-date
      // present) needs nothing more.
      const bool resized = window_.takeResized() && area != swapchain_.extent();
      if (stale_ || resized) {
        // The one wait for idle: the old swapchain's images and semaphores
        // may still be in use by a present.
        ctx_.queue().waitIdle();
        if (!swapchain_.recreate(area)) {  // the surface has no area yet
          window_.waitEvents();
          continue;
        }
        stale_ = false;
        ++stats.recreations;
      }
      switch (presenter_.show(swapchain_, frame, panel ? &overlay_ : nullptr)) {
        case FramePresenter::Result::Presented:
          return true;
        case FramePresenter::Result::PresentedSuboptimal:
          stale_ = true;
          return true;
        case FramePresenter::Result::OutOfDate:
          stale_ = true;
          break;
      }
    }
  }
  vk::Extent2D extent() const { return swapchain_.extent(); }

 private:
  const gpu::Context& ctx_;
  Window& window_;
  vk::raii::SurfaceKHR surface_;
  Swapchain swapchain_;
  UiOverlay overlay_;  // before the presenter: destroyed after it waits for its last frame
  FramePresenter presenter_;
  bool stale_ = false;  // the swapchain no longer matches the window
};

// The window's input since the last frame, to the panel or to the view:
// F1 shows or hides the panel; over the panel, the mouse and keys work the
// panel alone. Then the fly keys, held for `elapsed` seconds (a stall, a slow
// frame or a minimised window, flies no farther than half a second's worth).
void routeInput(Window& window, UiOverlay& overlay, ViewInput& input, const ViewInput::Apply& apply, bool& panelShown,
                double elapsed) {
  for (const InputEvent& event : window.takeInput()) {
    if (event.kind == InputEvent::Kind::KeyDown && event.code == GLFW_KEY_F1) {
      if (!event.repeat) panelShown = !panelShown;
      continue;
    }
    const bool key = event.kind == InputEvent::Kind::KeyDown;
    if (panelShown && (key ? overlay.wantsKeyboard() : overlay.wantsMouse())) continue;
    input.handle(event, window.framebufferSize(), apply);
  }
  if (panelShown && overlay.wantsKeyboard()) return;
  if (const auto fly = input.flying(window, std::min(0.5, elapsed))) apply(*fly);
}

// The panel over the frame, and what it asks for.
void drawPanel(UiOverlay& overlay, ViewPanel& panel, ViewSession& session, const ViewInput::Apply& apply,
               uint32_t frame, double fps, const render::RenderedFrame& last) {
  overlay.beginFrame();
  const PanelStatus status{.frame = frame,
                           .paused = session.paused(),
                           .fps = fps,
                           .last = last.width == 0 ? nullptr : &last,
                           .shaderErrors = &session.shaderErrors(),
                           .message = session.message(),
                           .messageIsError = session.messageIsError()};
  PanelRequests requests = panel.draw(session.renderer().scene(), status);
  overlay.endFrame();
  for (const ViewCommand& c : requests.commands) apply(c);
  if (requests.scene) session.setScene(*requests.scene);
}

// What the script does before frame `shown`: a resize, drops, commands.
// Returns whether it dropped anything.
bool runScript(const ViewConfig& config, uint32_t shown, Window& window, ViewSession& session,
               const ViewInput::Apply& apply) {
  if (config.resize && config.resize->frame == shown) window.resize(config.resize->width, config.resize->height);
  bool dropped = false;
  for (const ScriptedDrop& d : config.drops) {
    if (d.frame != shown) continue;
    session.renderer().addDrop(d.drop);
    dropped = true;
  }
  for (const ScriptedCommand& c : config.script) {
    if (c.frame == shown) apply(c.command);
  }
  return dropped;
}

// The frames, until the window closes or config.frames were shown; the
// last one rendered is kept in `last` (with its linear RGBA when the
// screenshot is an EXR).
ViewStats showFrames(const gpu::Context& ctx, Window& window, const ViewConfig& config, render::RenderedFrame& last) {
  const vk::Extent2D frameSize{config.width, config.height};
  Display display(ctx, window, frameSize);
  ViewSession session(std::make_unique<render::Renderer>(ctx, config.scene, config.width, config.height), config.width,
                      config.height, config.saveDir, config.shaderDir);
  ViewInput input(frameSize);
  const ViewInput::Apply apply = [&](const ViewCommand& command) { return session.apply(command); };
  ViewStats stats;
  const Clock::time_point start = Clock::now();
  Clock::time_point titled = start, previous = start;
  std::string title;
  auto retitle = [&](bool now) {
    char text[128];
    if (session.paused()) {
      std::snprintf(text, sizeof text, "tidepool view - frame %u (paused)", stats.lastFrame);
    } else {
      std::snprintf(text, sizeof text, "tidepool view - frame %u - %.1f fps", stats.lastFrame,
                    stats.framesShown / secondsSince(start));
    }
    if (text != title && (now || secondsSince(titled) > 0.5)) {
      title = text;
      titled = Clock::now();
      window.setTitle(title);
    }
  };
  std::optional<ResolutionGovernor> governor;
  if (config.targetFps) governor.emplace(glm::uvec2(config.width, config.height), *config.targetFps);
  ViewPanel panel;
  bool panelShown = config.panel;
  // Frames per second over the last frames shown (an exponential average of their intervals).
  double frameInterval = 0.0;
  Clock::time_point lastShown = start, firstShown = start;
  uint32_t shown = 0;  // frames shown so far: the script's clock
  while (!config.frames || shown < *config.frames) {
    // Paused on a frame already shown, a viewer run by hand (no --frames, no
    // script counting frames shown) has nothing new to show: it sleeps until
    // input comes, or a moment passes (the fly keys are read, not sent).
    const bool byHand = !config.frames && config.script.empty() && config.drops.empty() && !config.resize;
    const bool waiting = byHand && session.paused() && !session.needsRender();
    if (waiting)
      window.waitEventsTimeout(0.1);
    else
      window.pollEvents();
    // Minimised: nothing is rendered, the loop sleeps in the window system.
    if (window.shouldClose() || waitForArea(window).width == 0) break;
    UiOverlay& overlay = display.overlay();
    const Clock::time_point now = Clock::now();
    routeInput(window, overlay, input, apply, panelShown, std::chrono::duration<double>(now - previous).count());
    previous = now;
    if (panelShown) {
      drawPanel(overlay, panel, session, apply, stats.lastFrame, frameInterval > 0.0 ? 1.0 / frameInterval : 0.0, last);
    }
    // With the panel up, a paused frame is shown again for the panel's sake.
    if (waiting && !session.needsRender() && !window.takeRefresh() && !panelShown) {
      retitle(true);
      continue;
    }
    const bool dropped = runScript(config, shown, window, session, apply);
    const bool final = config.frames && shown + 1 == *config.frames;
    const bool finalExr = final && base::hasExtension(config.screenshot, ".exr");
    const bool finalPng = final && base::hasExtension(config.screenshot, ".png");
    const Clock::time_point renderStart = Clock::now();
    // Paused on an unchanged frame, the last one rendered is shown again.
    if (session.needsRender() || dropped || finalExr || finalPng || last.width == 0) {
      last = session.renderer().render(
          {.frame = session.frame(), .hdr = session.wantsHdr() || finalExr, .ldr = finalPng, .present = true});
      stats.lastFrame = session.frame();
      session.rendered(last);
    }
    const Clock::time_point showStart = Clock::now();
    stats.renderSeconds += std::chrono::duration<double>(showStart - renderStart).count();
    const render::PresentableImage image = session.renderer().presentable();
    const bool presented = display.show({image.image->handle(), image.image->extent, image.layout}, panelShown, stats);
    stats.showSeconds += secondsSince(showStart);
    if (!presented) break;
    ++shown;
    ++stats.framesShown;
    const Clock::time_point shownAt = Clock::now();
    if (stats.framesShown == 1) firstShown = shownAt;
    const double interval = std::chrono::duration<double>(shownAt - lastShown).count();
    if (stats.framesShown > 1) stats.intervals.push_back(interval);
    frameInterval = frameInterval > 0.0 ? (1.0 - kFpsSmoothing) * frameInterval + kFpsSmoothing * interval : interval;
    lastShown = shownAt;
    if (governor && stats.framesShown > 1 && governor->frameShown(interval)) {
      session.renderAt(governor->size().x, governor->size().y);
    }
    retitle(false);
  }
  stats.seconds = secondsSince(start);
  if (stats.framesShown > 1) stats.secondsAfterFirst = std::chrono::duration<double>(lastShown - firstShown).count();
  stats.window = display.extent();
  stats.rendered = vk::Extent2D{last.width, last.height};
  stats.lastScene = session.renderer().scene();
  if (governor) stats.resolutionChanges = governor->changes();
  return stats;
}

}  // namespace

int runViewer(const ViewConfig& config) {
  Window window(config.width, config.height, "tidepool view");
  GpuSession session(gpu::ContextOptions{.validation = config.validate,
                                         .deviceName = config.device,
                                         .surfaceExtensions = window.requiredInstanceExtensions(),
                                         .swapchain = true});
  render::RenderedFrame last;
  const ViewStats stats = showFrames(session.context(), window, config, last);
  const double perFrame = stats.framesShown > 0 ? 1000.0 / stats.framesShown : 0.0;
  const double steadyFps = stats.secondsAfterFirst > 0.0 ? (stats.framesShown - 1) / stats.secondsAfterFirst : 0.0;
  const double medianFps = stats.intervals.empty() ? 0.0 : 1.0 / base::median(stats.intervals);
  std::printf(
      "view: %u frames at %ux%u in %.2f s, %.2f fps, %.2f after the first, %.2f median (render %.1f ms, show %.1f "
      "ms per frame) on %s; window %ux%u, swapchain recreations: %u; last frame number %u\n",
      stats.framesShown, config.width, config.height, stats.seconds,
      stats.seconds > 0.0 ? stats.framesShown / stats.seconds : 0.0, steadyFps, medianFps,
      stats.renderSeconds * perFrame, stats.showSeconds * perFrame, session.context().deviceName().c_str(),
      stats.window.width, stats.window.height, stats.recreations, stats.lastFrame);
  if (config.targetFps) {
    std::printf("dynamic resolution for %.1f fps: last frame rendered at %ux%u, %u changes of size\n",
                *config.targetFps, stats.rendered.width, stats.rendered.height, stats.resolutionChanges);
  }
  if (config.profile && !last.passes.empty()) {
    std::printf("last frame rendered (%u):\n", stats.lastFrame);
    printProfile(last);
  }
  if (config.frames && stats.framesShown < *config.frames) {
    throw std::runtime_error("the window was closed after " + std::to_string(stats.framesShown) + " of " +
                             std::to_string(*config.frames) + " frames" +
                             (config.screenshot.empty() ? "" : ": no screenshot written"));
  }
  if (!config.screenshot.empty()) {
    saveFrame(config.screenshot, last, stats.lastScene, stats.lastFrame);
    std::printf("wrote %s (frame %u, %ux%u)\n", config.screenshot.c_str(), stats.lastFrame, last.width, last.height);
  }
  return session.finish();
}

}  // namespace tp::app
