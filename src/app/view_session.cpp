#include "app/view_session.hpp"

#include <cstdio>
#include <filesystem>

#include "app/water_pick.hpp"
#include "gpu/spirv_library.hpp"
#include "io/atomic_file.hpp"
#include "io/image_io.hpp"

namespace tp::app {

void saveFrame(const std::string& path, const render::RenderedFrame& frame) {
  if (io::hasExtension(path, ".exr")) {
    io::FloatImage image{frame.width, frame.height, {"R", "G", "B", "A"}, frame.rgba};
    io::writeExr(path, image, std::vector<io::PixelType>(4, io::PixelType::Float),
                 io::ExrAttributes{.hasCamera = true, .worldToCamera = frame.worldToCamera, .worldToNDC = frame.worldToNDC});
  } else {
    io::writePng(path, frame.width, frame.height, frame.srgb);
  }
}

ViewSession::ViewSession(std::unique_ptr<render::Renderer> renderer, uint32_t width, uint32_t height,
                         std::string saveDir, std::filesystem::path shaderDir)
    : renderer_(std::move(renderer)), width_(width), height_(height), saveDir_(std::move(saveDir)),
      shaderDir_(std::move(shaderDir)), camera_(renderer_->scene().camera) {}

void ViewSession::setCamera() {
  renderer_->setCamera(camera_.camera());
  changed_ = true;
}

bool ViewSession::apply(const ViewCommand& command) {
  const scene::Scene& scene = renderer_->scene();
  const auto rayThrough = [&](glm::dvec2 pixel) { return pixelRay(scene.camera, width_, height_, pixel); };
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
          if (!scene.water.enabled) return false;
          const sim::WaterState water = renderer_->waterState();
          const auto hit = pickWater(rayThrough(c.pixel), scene.water, &water);
          if (!hit) return false;
          renderer_->addDrop(scene::Drop{float(hit->x), float(hit->z), kClickDropRadius, kClickDropAmplitude});
          std::printf("drop at x %.3f, z %.3f\n", hit->x, hit->z);
          changed_ = true;
        } else if constexpr (std::is_same_v<C, command::Grab>) {
          // The spheres where the frame on screen shows them (a path moves them in time).
          const float time = float(lastRendered_.value_or(frame_)) * scene.water.frameTime;
          const scene::Scene placed = scene::sceneAt(scene, time);
          const Ray ray = rayThrough(c.pixel);
          const auto picked = pickSphere(ray, placed.spheres);
          grabbed_.reset();
          if (!picked) return false;
          const glm::vec3 center = placed.spheres[picked->index].center;
          const auto anchor = rayPlaneY(ray, center.y, scene.camera.farPlane);
          if (!anchor) return false;
          grabbed_ = Grabbed{picked->index, center, *anchor, center};
        } else if constexpr (std::is_same_v<C, command::Drag>) {
          if (!grabbed_) return false;
          const auto to = rayPlaneY(rayThrough(c.pixel), grabbed_->center.y, scene.camera.farPlane);
          if (!to) return false;
          const glm::dvec3 moved = glm::dvec3(grabbed_->center) + (*to - grabbed_->anchor);
          grabbed_->now = glm::vec3(float(moved.x), grabbed_->center.y, float(moved.z));
          renderer_->moveSphere(grabbed_->index, grabbed_->now);
          changed_ = true;
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
          // A shader that fails keeps the code it had: its errors are shown
          // and the frame goes on with the last good pipelines.
          const gpu::ShaderReload reload = gpu::reloadShaders(shaderDir_);
          for (const std::string& error : reload.errors) std::fprintf(stderr, "shader reload: %s\n", error.c_str());
          std::printf("shader reload: %zu changed, %zu failed\n", reload.changed.size(), reload.errors.size());
          for (const std::string& name : reload.changed) std::printf("  %s\n", name.c_str());
          std::fflush(stdout);
          if (!reload.changed.empty()) {
            renderer_ = std::make_unique<render::Renderer>(*renderer_);
            changed_ = true;
          }
          return reload.errors.empty();
        }
        return true;
      },
      command);
}

std::string ViewSession::savePath() const {
  const std::filesystem::path dir = saveDir_.empty() ? std::filesystem::path() : std::filesystem::path(saveDir_);
  char name[64];
  std::snprintf(name, sizeof name, "view-%04u.exr", frame_);
  std::filesystem::path path = dir / name;
  // Never over an earlier save: a paused frame may be saved from several views.
  for (unsigned k = 2; std::filesystem::exists(path); ++k) {
    std::snprintf(name, sizeof name, "view-%04u-%u.exr", frame_, k);
    path = dir / name;
  }
  return path.string();
}

void ViewSession::rendered(const render::RenderedFrame& frame) {
  if (saveAsked_) {
    const std::string path = savePath();
    saveFrame(path, frame);
    std::printf("saved %s (frame %u)\n", path.c_str(), frame_);
    std::fflush(stdout);
    saveAsked_ = false;
  }
  changed_ = false;
  lastRendered_ = frame_;
  if (!paused_) ++frame_;
}

}  // namespace tp::app
