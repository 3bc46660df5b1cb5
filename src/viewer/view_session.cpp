#include "viewer/view_session.hpp"

#include <cstdio>
#include <filesystem>

#include "base/atomic_file.hpp"
#include "cli/frame_output.hpp"
#include "gpu/spirv_library.hpp"
#include "io/image_io.hpp"
#include "scene/scene_file.hpp"
#include "shading/water_model.hpp"
#include "viewer/water_pick.hpp"

namespace tp::app {

void saveFrame(const std::string& path, const render::RenderedFrame& frame, const scene::Scene& scene,
               uint32_t frameNumber) {
  if (base::hasExtension(path, ".exr")) {
    io::FloatImage image{frame.width, frame.height, {"R", "G", "B", "A"}, frame.rgba};
    io::writeExr(path, image, std::vector<io::PixelType>(4, io::PixelType::Float),
                 frameExrAttributes(scene, frame, frameNumber));
  } else {
    io::writePng(path, frame.width, frame.height, frame.srgb);
  }
}

ViewSession::ViewSession(std::unique_ptr<render::Renderer> renderer, uint32_t width, uint32_t height,
                         std::string saveDir, std::filesystem::path shaderDir)
    : renderer_(std::move(renderer)),
      width_(width),
      height_(height),
      saveDir_(std::move(saveDir)),
      shaderDir_(std::move(shaderDir)),
      camera_(renderer_->scene().camera) {}

void ViewSession::setCamera() {
  renderer_->setCamera(camera_.camera());
  changed_ = true;
}

bool ViewSession::apply(const ViewCommand& command) {
  const scene::Scene& scene = renderer_->scene();
  return std::visit(
      [&]<typename C>(const C& c) -> bool {
        if constexpr (std::is_same_v<C, command::Orbit>) {
          camera_.orbit(-c.dx * CameraControls::kOrbitRadiansPerPixel, c.dy * CameraControls::kOrbitRadiansPerPixel);
          setCamera();
        } else if constexpr (std::is_same_v<C, command::Zoom>) {
          camera_.zoom(c.notches);
          setCamera();
        } else if constexpr (std::is_same_v<C, command::Fly>) {
          camera_.fly(c.forward, c.right, c.seconds);
          setCamera();
        } else if constexpr (std::is_same_v<C, command::ResetCamera>) {
          camera_.reset();
          setCamera();
        } else if constexpr (std::is_same_v<C, command::Drop>) {
          return dropAt(c.pixel);
        } else if constexpr (std::is_same_v<C, command::Grab>) {
          return grab(c.pixel);
        } else if constexpr (std::is_same_v<C, command::Drag>) {
          return drag(c.pixel);
        } else if constexpr (std::is_same_v<C, command::Release>) {
          if (grabbed_ && grabbed_->now != grabbed_->center) {
            std::printf("moved sphere %zu to (%.3f, %.3f, %.3f)\n", grabbed_->index, grabbed_->now.x, grabbed_->now.y,
                        grabbed_->now.z);
          }
          grabbed_.reset();
        } else if constexpr (std::is_same_v<C, command::TogglePause>) {
          paused_ = !paused_;
        } else if constexpr (std::is_same_v<C, command::Step>) {
          // Running, frame_ is already the next frame.
          if (paused_) ++frame_;
          paused_ = true;
        } else if constexpr (std::is_same_v<C, command::Save>) {
          saveAsked_ = true;
          changed_ = true;
        } else if constexpr (std::is_same_v<C, command::ReloadShaders>) {
          return reloadShaders();
        } else if constexpr (std::is_same_v<C, command::SaveScene>) {
          return saveScene(c.path);
        } else if constexpr (std::is_same_v<C, command::Set>) {
          try {
            return setScene(scene::withSetting(scene, c.key, c.value));
          } catch (const std::exception& e) {
            tell(e.what(), true);
            return false;
          }
        }
        return true;
      },
      command);
}

Ray ViewSession::rayThrough(glm::dvec2 pixel) const {
  return pixelRay(renderer_->scene().camera, width_, height_, pixel);
}

bool ViewSession::dropAt(glm::dvec2 pixel) {
  const scene::Scene& scene = renderer_->scene();
  if (!scene.water.enabled) return false;
  const sim::WaterState water = renderer_->waterState();
  const auto hit = pickWater(rayThrough(pixel), scene.water, &water);
  if (!hit) return false;
  renderer_->addDrop(scene::Drop{float(hit->x), float(hit->z), kClickDropRadius, kClickDropAmplitude});
  std::printf("drop at x %.3f, z %.3f\n", hit->x, hit->z);
  changed_ = true;
  return true;
}

bool ViewSession::grab(glm::dvec2 pixel) {
  const scene::Scene& scene = renderer_->scene();
  // The spheres where the frame on screen shows them (a path moves them in time).
  const float time = float(lastRendered_.value_or(frame_)) * scene.water.frameTime;
  const scene::Scene placed = scene::sceneAt(scene, time);
  const Ray ray = rayThrough(pixel);
  const auto picked = pickSphere(ray, placed.spheres);
  grabbed_.reset();
  if (!picked) return false;
  const glm::vec3 center = placed.spheres[picked->index].center;
  const auto anchor = rayPlaneY(ray, center.y, scene.camera.farPlane);
  if (!anchor) return false;
  grabbed_ = Grabbed{picked->index, center, *anchor, center};
  return true;
}

bool ViewSession::drag(glm::dvec2 pixel) {
  const scene::Scene& scene = renderer_->scene();
  if (!grabbed_) return false;
  const auto to = rayPlaneY(rayThrough(pixel), grabbed_->center.y, scene.camera.farPlane);
  if (!to) return false;
  const glm::dvec3 moved = glm::dvec3(grabbed_->center) + (*to - grabbed_->anchor);
  grabbed_->now = glm::vec3(float(moved.x), grabbed_->center.y, float(moved.z));
  renderer_->moveSphere(grabbed_->index, grabbed_->now);
  changed_ = true;
  return true;
}

bool ViewSession::reloadShaders() {
  // A shader that fails keeps the code it had: its errors are shown
  // and the frame goes on with the last good pipelines.
  const gpu::ShaderReload reload = gpu::reloadShaders(shaderDir_);
  for (const std::string& error : reload.errors) std::fprintf(stderr, "shader reload: %s\n", error.c_str());
  // The summary on stdout either way: the errors themselves went to stderr.
  tell("shader reload: " + std::to_string(reload.changed.size()) + " changed, " + std::to_string(reload.errors.size()) +
           " failed",
       !reload.errors.empty(), stdout);
  for (const std::string& name : reload.changed) std::printf("  %s\n", name.c_str());
  std::fflush(stdout);
  shaderErrors_ = reload.errors;
  if (!reload.changed.empty()) {
    renderer_ = std::make_unique<render::Renderer>(render::GoOnFrom{*renderer_});
    changed_ = true;
  }
  return reload.errors.empty();
}

bool ViewSession::saveScene(const std::string& wanted) {
  const scene::Scene& scene = renderer_->scene();
  const std::string path = wanted.empty() ? savePath("scene", ".json", lastRendered_.value_or(frame_)) : wanted;
  try {
    scene::Scene saved = scene;
    // Read back from wherever the file goes.
    if (!saved.sky.image.empty()) saved.sky.image = std::filesystem::absolute(saved.sky.image).string();
    scene::saveSceneFile(path, saved);
  } catch (const std::exception& e) {
    tell(std::string("scene not saved: ") + e.what(), true);
    return false;
  }
  tell("saved scene " + path + " (at frame " + std::to_string(lastRendered_.value_or(frame_)) + ")", false);
  return true;
}

std::string ViewSession::savePath(const char* stem, const char* extension, uint32_t frame) const {
  const std::filesystem::path dir = saveDir_.empty() ? std::filesystem::path() : std::filesystem::path(saveDir_);
  char name[64];
  std::snprintf(name, sizeof name, "%s-%04u%s", stem, frame, extension);
  std::filesystem::path path = dir / name;
  // Never over an earlier save: a paused frame may be saved from several views.
  for (unsigned k = 2; std::filesystem::exists(path); ++k) {
    std::snprintf(name, sizeof name, "%s-%04u-%u%s", stem, frame, k, extension);
    path = dir / name;
  }
  return path.string();
}

void ViewSession::tell(std::string message, bool error, std::FILE* stream) {
  if (!stream) stream = error ? stderr : stdout;
  std::fprintf(stream, "%s\n", message.c_str());
  std::fflush(stream);
  message_ = std::move(message);
  messageIsError_ = error;
}

bool ViewSession::setScene(const scene::Scene& wanted) {
  try {
    scene::validateScene(wanted);
    const scene::Scene& now = renderer_->scene();
    if (wanted == now) return true;
    if (wanted.camera != now.camera) {
      camera_.moveTo(wanted.camera);
      setCamera();
    }
    // A still sphere's new centre displaces the water as a drag does.
    if (wanted.spheres.size() == now.spheres.size()) {
      for (size_t i = 0; i < wanted.spheres.size(); ++i) {
        const scene::Sphere& a = now.spheres[i];
        const scene::Sphere& b = wanted.spheres[i];
        if (a.path.empty() && b.path.empty() && a.center != b.center) renderer_->moveSphere(i, b.center);
      }
    }
    if (now.water.enabled && wanted.water.enabled) {
      const scene::Water dynamics = sim::withDynamicsOf(now.water, wanted.water);
      if (dynamics != now.water) renderer_->setWaterDynamics(dynamics);
    }
    changed_ = true;
    if (renderer_->scene() == wanted) return true;
    const uint32_t width = renderer_->width(), height = renderer_->height();
    if (sim::sameWaterMotion(renderer_->scene().water, wanted.water)) {
      renderer_ = std::make_unique<render::Renderer>(render::GoOnFrom{*renderer_}, wanted);
    } else {
      // A new simulation: it starts again at frame 0.
      renderer_ = std::make_unique<render::Renderer>(renderer_->context(), wanted, width, height);
      frame_ = 0;
      lastRendered_.reset();
      grabbed_.reset();
      tell("the water starts again: its grid, extent, level, frame time or drops changed", false);
    }
    return true;
  } catch (const std::exception& e) {
    tell(std::string("not applied: ") + e.what(), true);
    return false;
  }
}

void ViewSession::renderAt(uint32_t width, uint32_t height) {
  renderer_ = std::make_unique<render::Renderer>(render::GoOnFrom{*renderer_}, width, height);
  changed_ = true;
}

void ViewSession::rendered(const render::RenderedFrame& frame) {
  if (saveAsked_) {
    const std::string path = savePath("view", ".exr", frame_);
    saveFrame(path, frame, renderer_->scene(), frame_);
    std::printf("saved %s (frame %u)\n", path.c_str(), frame_);
    std::fflush(stdout);
    saveAsked_ = false;
  }
  changed_ = false;
  lastRendered_ = frame_;
  if (!paused_) ++frame_;
}

}  // namespace tp::app
