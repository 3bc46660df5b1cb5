// ViewSession::setScene, the one path of the panel's edits (and --script
// set): each kind of change lands where it should (live on the renderer, in
// a renderer made from it that carries the water on, or in a new simulation
// from frame 0), and the frames then equal a renderer made for the changed
// scene from its start: an independent answer, since that one never saw the
// change happen.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "gpu_test.hpp"
#include "process.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"
#include "viewer/view_session.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;

class ViewSessionTest : public GpuTest {
 protected:
  app::ViewSession session(const scene::Scene& scene) {
    return app::ViewSession(std::make_unique<render::Renderer>(ctx(), scene, kWidth, kHeight), kWidth, kHeight, "",
                            TIDEPOOL_SHADERS_DIR);
  }
  // Renders the session's next frame as the viewer does. The viewer reads
  // the linear frame back only when a save asks for it (wantsHdr); the tests
  // compare that frame, so `hdr` reads it back always unless told otherwise.
  render::RenderedFrame next(app::ViewSession& s, bool hdr = true) {
    render::RenderedFrame frame = s.renderer().render({.frame = s.frame(), .hdr = hdr || s.wantsHdr()});
    s.rendered(frame);
    return frame;
  }
  std::vector<float> fresh(const scene::Scene& scene, uint32_t frame) {
    return render::Renderer(ctx(), scene, kWidth, kHeight).render({.frame = frame}).rgba;
  }
};

// Shading settings make a new renderer that goes on with the water: the frame
// after equals a renderer of the changed scene run from frame 0.
TEST_F(ViewSessionTest, ShadingChangesCarryTheWaterOn) {
  const scene::Scene start = scene::defaultScene();
  app::ViewSession s = session(start);
  for (int i = 0; i < 4; ++i) next(s);
  const render::Renderer* before = &s.renderer();
  scene::Scene changed = s.renderer().scene();
  changed.render.refraction = "apparent";
  changed.render.caustics = false;
  changed.ao = scene::aoPreset("fast");
  changed.water.ior = 1.4f;
  changed.sky.sunElevationDegrees = 20.0f;
  ASSERT_TRUE(s.setScene(changed)) << s.message();
  EXPECT_NE(&s.renderer(), before);
  EXPECT_EQ(s.renderer().scene(), changed);
  EXPECT_EQ(s.frame(), 4u);
  const render::RenderedFrame shown = next(s);
  EXPECT_TRUE(shown.rgba == fresh(changed, 4));
  // The change shows: the old scene's frame 4 differs.
  EXPECT_FALSE(shown.rgba == fresh(start, 4));
}

// The camera, the water's dynamics and a still sphere's centre go to the
// renderer live: the same renderer, the scene it holds changed.
TEST_F(ViewSessionTest, LiveChangesKeepTheRenderer) {
  app::ViewSession s = session(scene::defaultScene());
  next(s);
  const render::Renderer* before = &s.renderer();
  scene::Scene changed = s.renderer().scene();
  changed.camera.position.x += 0.5f;
  changed.water.waveSpeed = 0.9f;
  changed.water.damping = 0.1f;
  changed.water.boundary = "wrap";
  changed.spheres.at(0).center.x -= 0.3f;
  ASSERT_TRUE(s.setScene(changed)) << s.message();
  EXPECT_EQ(&s.renderer(), before);
  EXPECT_EQ(s.renderer().scene(), changed);
  EXPECT_EQ(s.frame(), 1u);
  // The camera as the panel set it, bit for bit: a frame with it equals a
  // renderer given that camera (the water is the live renderer's own).
  next(s);
  EXPECT_EQ(s.renderer().scene().camera, changed.camera);
}

// The water's own simulation (here its grid) starts again at frame 0 in a
// new renderer, which draws a fresh renderer's frame 0.
TEST_F(ViewSessionTest, NewSimulationStartsAgainAtFrameZero) {
  app::ViewSession s = session(scene::defaultScene());
  for (int i = 0; i < 3; ++i) next(s);
  scene::Scene changed = s.renderer().scene();
  changed.water.grid = 64;
  ASSERT_TRUE(s.setScene(changed)) << s.message();
  EXPECT_EQ(s.frame(), 0u);
  EXPECT_NE(s.message().find("starts again"), std::string::npos) << s.message();
  EXPECT_TRUE(next(s).rgba == fresh(changed, 0));
}

// An impossible scene changes nothing and says why.
TEST_F(ViewSessionTest, ImpossibleScenesChangeNothing) {
  app::ViewSession s = session(scene::defaultScene());
  next(s);
  const scene::Scene before = s.renderer().scene();
  scene::Scene bad = before;
  bad.spheres.at(0).radius = -1.0f;
  EXPECT_FALSE(s.setScene(bad));
  EXPECT_TRUE(s.messageIsError());
  EXPECT_NE(s.message().find("radius"), std::string::npos) << s.message();
  EXPECT_EQ(s.renderer().scene(), before);
  EXPECT_FALSE(s.apply(app::command::Set{"water.wave_speed", "-2"}));
  EXPECT_NE(s.message().find("water.wave_speed"), std::string::npos) << s.message();
  EXPECT_FALSE(s.apply(app::command::Set{"water.colour", "1"}));
  EXPECT_EQ(s.renderer().scene(), before);
}

// The save-scene command writes the scene as it stands, read back equal.
TEST_F(ViewSessionTest, SaveSceneWritesTheSceneAsItStands) {
  ScratchDir dir;
  app::ViewSession s(std::make_unique<render::Renderer>(ctx(), scene::defaultScene(), kWidth, kHeight), kWidth, kHeight,
                     dir.path().string(), TIDEPOOL_SHADERS_DIR);
  next(s);
  ASSERT_TRUE(s.apply(app::command::Set{"render.exposure", "0.5"})) << s.message();
  ASSERT_TRUE(s.apply(app::command::SaveScene{})) << s.message();
  const std::string path = (std::filesystem::path(dir.path()) / "scene-0000.json").string();
  EXPECT_NE(s.message().find(path), std::string::npos) << s.message();
  EXPECT_EQ(scene::loadSceneFile(path), s.renderer().scene());
  EXPECT_FALSE(s.apply(app::command::SaveScene{"/dev/null/x.json"}));
  EXPECT_TRUE(s.messageIsError());
}

// The save key's EXR holds render's attributes: the frame number and rate
// beside the camera, as `render --frame N` writes them.
TEST_F(ViewSessionTest, SavedFrameHoldsRendersAttributes) {
  ScratchDir dir;
  app::ViewSession s(std::make_unique<render::Renderer>(ctx(), scene::defaultScene(), kWidth, kHeight), kWidth, kHeight,
                     dir.path().string(), TIDEPOOL_SHADERS_DIR);
  for (int i = 0; i < 3; ++i) next(s);
  ASSERT_TRUE(s.apply(app::command::Save{}));
  next(s, false);
  auto in = OIIO::ImageInput::open(dir.file("view-0003.exr"));
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.get_int_attribute("frame", -1), 3);
  const OIIO::ParamValue* fps = spec.find_attribute("framesPerSecond", OIIO::TypeRational);
  ASSERT_TRUE(fps);
  const int* rate = static_cast<const int*>(fps->data());
  EXPECT_EQ(rate[0], 30);  // 1 / water.frame_time
  EXPECT_EQ(rate[1], 1);
  EXPECT_TRUE(spec.find_attribute("worldToCamera", OIIO::TypeMatrix44));
  EXPECT_NE(spec.get_string_attribute("software").find("tidepool"), std::string::npos);
}

}  // namespace
}  // namespace tp::test
