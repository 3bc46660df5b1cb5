#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "process.hpp"
#include "scene/scene_file.hpp"

namespace tp::test {
namespace {

std::string errorOf(const std::string& text) {
  try {
    scene::parseScene(text, "shot.json");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SceneFile, AbsentFieldsKeepTheDefaults) {
  auto s = scene::parseScene(R"({"camera": {"fov": 35, "position": [1, 2, 3]}, "ground": {"checker_size": 2}})", "x");
  auto d = scene::defaultScene();
  EXPECT_EQ(s.camera.fovYDegrees, 35.0f);
  EXPECT_EQ(s.camera.position, glm::vec3(1, 2, 3));
  EXPECT_EQ(s.camera.target, d.camera.target);
  EXPECT_EQ(s.ground.checkerSize, 2.0f);
  EXPECT_EQ(s.sky.sunElevationDegrees, d.sky.sunElevationDegrees);
  EXPECT_EQ(scene::parseScene("{}", "x").camera.fovYDegrees, d.camera.fovYDegrees);
}

TEST(SceneFile, ErrorsNameTheFileAndTheKey) {
  // A misspelt key names the nearest, as --set does.
  EXPECT_EQ(errorOf(R"({"camera": {"fvo": 35}})"),
            "shot.json: camera.fvo: is not a known key; did you mean camera.fov?");
  EXPECT_EQ(errorOf(R"({"water": {"grdi": 64}})"),
            "shot.json: water.grdi: is not a known key; did you mean water.grid?");
  EXPECT_EQ(errorOf(R"({"lights": []})"), "shot.json: lights: is not a known key");
  EXPECT_EQ(errorOf(R"({"camera": {"fov": "wide"}})"), "shot.json: camera.fov: expected a number, got string");
  EXPECT_EQ(errorOf(R"({"camera": {"position": [1, 2]}})"),
            "shot.json: camera.position: expected an array of 3 numbers");
  EXPECT_EQ(errorOf(R"({"sky": 3})"), "shot.json: sky: expected an object");
  EXPECT_EQ(errorOf(R"([1, 2])"), "shot.json: the top level: expected an object");
  EXPECT_EQ(errorOf(R"({"sky": {"texture_width": -5}})"),
            "shot.json: sky.texture_width: expected a non-negative integer, got -5");
}

// JSON allows a key twice in one object and the parser would keep the last:
// refused, with the key's path.
TEST(SceneFile, DuplicateKeysAreRefusedWithTheirPath) {
  EXPECT_EQ(errorOf(R"({"water": {"grid": 64, "grid": 32}})"),
            "shot.json: water.grid: the key appears twice in one object");
  EXPECT_EQ(errorOf(R"({"sky": {}, "water": {}, "sky": {}})"), "shot.json: sky: the key appears twice in one object");
  EXPECT_EQ(errorOf(R"({"spheres": [{"radius": 0.3}, {"radius": 0.2, "center": [0, 0, 0], "radius": 0.1}]})"),
            "shot.json: spheres[1].radius: the key appears twice in one object");
  // The same key in two objects is no duplicate.
  EXPECT_EQ(errorOf(R"({"spheres": [{"radius": 0.3}, {"radius": 0.2}]})"), "");
}

TEST(SceneFile, MalformedAndTruncatedJson) {
  EXPECT_NE(errorOf(R"({"camera": {"fov": 35)").find("shot.json: not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf("").find("shot.json: not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf("{\"camera\": nan}").find("not valid JSON"), std::string::npos);
}

// Parsed in full and refused for what they hold, not by crashing: 20 MB of
// numbers under an unknown key, and arrays nested a million deep.
TEST(SceneFile, HugeAndDeeplyNestedJson) {
  std::string huge = "{\"water\": {\"wave_speed\": 0.5}, \"junk\": [";
  for (int i = 0; i < 2'000'000; ++i) huge += "1234567.8,";
  huge += "0]}";
  EXPECT_NE(errorOf(huge).find("shot.json: junk: is not a known key"), std::string::npos);
  const std::string deep = std::string(1'000'000, '[') + std::string(1'000'000, ']');
  EXPECT_NE(errorOf(deep).find("shot.json: the top level: expected an object"), std::string::npos) << errorOf(deep);
  const std::string deepInside = "{\"camera\": " + std::string(100'000, '[') + std::string(100'000, ']') + "}";
  EXPECT_NE(errorOf(deepInside).find("camera: expected an object"), std::string::npos);
  const std::string cut = "{\"camera\": " + std::string(100'000, '[');
  EXPECT_NE(errorOf(cut).find("not valid JSON"), std::string::npos);
}

TEST(SceneFile, ImpossibleValuesAreRefused) {
  EXPECT_NE(errorOf(R"({"camera": {"fov": 180}})").find("camera fov"), std::string::npos);
  EXPECT_NE(errorOf(R"({"camera": {"fov": 1e999}})").find("shot.json: not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf(R"({"camera": {"near": 0}})").find("near"), std::string::npos);
  EXPECT_NE(errorOf(R"({"camera": {"position": [1, 2, 3], "target": [1, 2, 3]}})").find("target equals its position"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"camera": {"position": [0, 5, 0], "target": [0, 0, 0]}})").find("parallel"), std::string::npos);
  EXPECT_NE(errorOf(R"({"sky": {"sun_radiance": [1, -1, 1]}})").find("sky.sun_radiance must not be negative"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"render": {"exposure": 0}})").find("render.exposure"), std::string::npos);
  EXPECT_NE(errorOf(R"({"sky": {"clouds": {"coverage": 1.5}}})").find("sky.clouds.coverage"), std::string::npos);
  EXPECT_NE(errorOf(R"({"sky": {"haze_distance": -1}})").find("sky.haze_distance"), std::string::npos);
  EXPECT_NE(errorOf(R"({"sky": {"clouds": {"noise": "worley"}}})").find("sky.clouds.noise must be one of"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"sky": {"clouds": {"shape": 1}}})").find("sky.clouds.shape: is not a known key"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"pool": {"wall_pattern": "stone"}})").find("pool.wall_pattern must be one of"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"pool": {"mortar_fraction": 0.6}})").find("pool.mortar_fraction"), std::string::npos);
  EXPECT_NE(errorOf(R"({"pool": {"floor_pattern": "marble"}})").find("pool.floor_pattern must be one of"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"pool": {"tile_size": 0.1, "grout_width": 0.1}})")
                .find("pool.grout_width must be less than pool.tile_size"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"ground": {"pattern": "grass"}})").find("ground.pattern must be one of"), std::string::npos);
  EXPECT_NE(errorOf(R"({"ground": {"paver_depth": 0.05, "joint_width": 0.05}})")
                .find("ground.joint_width must be less than ground.paver_width and ground.paver_depth"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"ground": {"coping_width": -0.1}})").find("ground.coping_width"), std::string::npos);
  EXPECT_NE(errorOf(R"({"ground": {"lawn_albedo": [0, -1, 0]}})").find("ground.lawn_albedo must not be negative"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"pool": {"brick_width": 0.01, "brick_height": 0.1, "mortar_fraction": 0.2}})")
                .find("must be less than pool.brick_width"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"pool": {"wall_specular": 1.5}})").find("pool.wall_specular = 1.5 is outside [0"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"pool": {"wall_roughness": -0.1}})").find("pool.wall_roughness"), std::string::npos);
  EXPECT_NE(errorOf(R"({"spheres": [{"specular": -1}]})").find("spheres[].specular"), std::string::npos);
  EXPECT_NE(errorOf(R"({"spheres": [{"roughness": 2}]})").find("spheres[].roughness"), std::string::npos);
  EXPECT_NE(errorOf(R"({"spheres": [{"roughness": "rough"}]})").find("spheres[0].roughness: expected a number"),
            std::string::npos);
}

// Glass spheres: a material of the list, an index of refraction over 1 and
// at most 3, and 1 to 64 search steps; each refusal one line naming the key.
TEST(SceneFile, GlassKeys) {
  const auto s = scene::parseScene(R"({"spheres": [{"material": "glass", "ior": 1.33}, {}],
                                       "render": {"glass_search_steps": 16}})",
                                   "x");
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_TRUE(scene::isGlass(s.spheres[0]));
  EXPECT_EQ(s.spheres[0].ior, 1.33f);
  EXPECT_FALSE(scene::isGlass(s.spheres[1]));  // lambert by default
  EXPECT_EQ(s.spheres[1].ior, 1.5f);
  EXPECT_EQ(s.render.glassSearchSteps, 16u);
  EXPECT_EQ(errorOf(R"({"spheres": [{"material": "metal"}]})"),
            "shot.json: spheres[].material must be one of lambert, glass, got 'metal'");
  EXPECT_EQ(errorOf(R"({"spheres": [{"material": "glass", "ior": 1}]})"),
            "shot.json: spheres[].ior = 1 is outside (1, 3]");
  EXPECT_EQ(errorOf(R"({"spheres": [{"ior": 3.5}]})"), "shot.json: spheres[].ior = 3.5 is outside (1, 3]");
  EXPECT_EQ(errorOf(R"({"spheres": [{"ior": "glass"}]})"), "shot.json: spheres[0].ior: expected a number, got string");
  EXPECT_NE(errorOf(R"({"render": {"glass_search_steps": 0}})").find("render.glass_search_steps = 0 is outside [1"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"render": {"glass_search_steps": 65}})").find("render.glass_search_steps"), std::string::npos);
}

// Glass boxes: the spheres' two keys, checked the same way.
TEST(SceneFile, GlassBoxKeys) {
  const auto s = scene::parseScene(R"({"boxes": [{"material": "glass", "ior": 1.7}, {}]})", "x");
  ASSERT_EQ(s.boxes.size(), 2u);
  EXPECT_TRUE(scene::isGlass(s.boxes[0]));
  EXPECT_EQ(s.boxes[0].ior, 1.7f);
  EXPECT_FALSE(scene::isGlass(s.boxes[1]));  // lambert by default
  EXPECT_TRUE(scene::hasGlass(s));
  EXPECT_FALSE(scene::hasGlass(scene::parseScene(R"({"boxes": [{}]})", "x")));
  EXPECT_EQ(errorOf(R"({"boxes": [{"material": "metal"}]})"),
            "shot.json: boxes[].material must be one of lambert, glass, got 'metal'");
  EXPECT_EQ(errorOf(R"({"boxes": [{"material": "glass", "ior": 1}]})"), "shot.json: boxes[].ior = 1 is outside (1, 3]");
  EXPECT_EQ(errorOf(R"({"boxes": [{"ior": "glass"}]})"), "shot.json: boxes[0].ior: expected a number, got string");
}

TEST(SceneFile, UnreadableFiles) {
  EXPECT_THROW(scene::loadSceneFile("/nonexistent/scene.json"), std::runtime_error);
  EXPECT_THROW(scene::loadSceneFile("/tmp"), std::runtime_error);
}

TEST(SceneFile, DefaultJsonSpellsOutTheBuiltInScene) {
  EXPECT_TRUE(scene::loadSceneFile(std::string(TIDEPOOL_SOURCE_DIR) + "/scenes/default.json") == scene::defaultScene());
}

TEST(SceneFile, ExampleScenesLoad) {
  size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(TIDEPOOL_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_NO_THROW(scene::loadSceneFile(entry.path().string())) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 4u);
}

// A drop's frame: absent, the starting state's (0); else a whole frame number.
TEST(SceneFile, DropFrames) {
  const auto s = scene::parseScene(R"({"water": {"drops": [{"x": 0.5}, {"x": -0.5, "frame": 40}]}})", "x");
  ASSERT_EQ(s.water.drops.size(), 2u);
  EXPECT_EQ(s.water.drops[0].frame, 0u);
  EXPECT_EQ(s.water.drops[1].frame, 40u);
  EXPECT_EQ(s.water.drops[1].x, -0.5f);
  EXPECT_EQ(errorOf(R"({"water": {"drops": [{"frame": -1}]}})"),
            "shot.json: water.drops[0].frame: expected a non-negative integer, got -1");
  EXPECT_EQ(errorOf(R"({"water": {"drops": [{}, {"frame": 2.5}]}})"),
            "shot.json: water.drops[1].frame: expected a non-negative integer, got 2.5");
  EXPECT_EQ(errorOf(R"({"water": {"drops": [{"frame": "3"}]}})"),
            "shot.json: water.drops[0].frame: expected a non-negative integer, got \"3\"");
}

TEST(SceneFile, Boxes) {
  const auto s = scene::parseScene(
      R"({"boxes": [{"center": [1, -0.5, 0], "size": [0.2, 0.4, 0.6], "yaw": 30, "albedo": [0.1, 0.2, 0.3]}, {}]})",
      "x");
  ASSERT_EQ(s.boxes.size(), 2u);
  EXPECT_EQ(s.boxes[0].center, glm::vec3(1.0f, -0.5f, 0.0f));
  EXPECT_EQ(s.boxes[0].size, glm::vec3(0.2f, 0.4f, 0.6f));
  EXPECT_EQ(s.boxes[0].yawDegrees, 30.0f);
  EXPECT_EQ(s.boxes[0].albedo, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(s.boxes[1], scene::Box{});
  EXPECT_EQ(errorOf(R"({"boxes": [{"sise": [1, 1, 1]}]})"),
            "shot.json: boxes[0].sise: is not a known key; did you mean boxes[0].size?");
  EXPECT_EQ(errorOf(R"({"boxes": {"size": [1, 1, 1]}})"), "shot.json: boxes: expected an array of objects");
  EXPECT_NE(errorOf(R"({"boxes": [{"size": [1, 0, 1]}]})").find("shot.json: boxes[].size.y"), std::string::npos);
  EXPECT_NE(errorOf(R"({"boxes": [{}, {}, {}, {}, {}]})").find("shot.json: boxes: at most 4, got 5"),
            std::string::npos);
}

}  // namespace tp::test

namespace tp::test {

// A saved scene reads back to the same scene, to the bit: every example
// scene, and one whose values need all of a float's digits.
TEST(SceneFile, SavedScenesReadBackToTheSameScene) {
  std::vector<scene::Scene> scenes{scene::defaultScene()};
  for (const auto& entry : std::filesystem::directory_iterator(std::string(TIDEPOOL_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() == ".json") scenes.push_back(scene::loadSceneFile(entry.path().string()));
  }
  scene::Scene awkward = scene::defaultScene();
  awkward.camera.position = {std::nextafter(3.2f, 4.0f), 1.0f / 3.0f, -4.6e-7f};
  awkward.water.frameTime = 1.0f / 60.0f;
  awkward.water.level = std::nextafter(-0.15f, 0.0f);
  awkward.water.drops = {
      {0.1f, -0.7f, 0.123456789f, 1e-6f}, {0.5f, 0.2f, 0.3f, -0.02f, 12}, {0.0f, 0.0f, 0.1f, 0.01f, 1u << 30}};
  awkward.spheres[0].path = {{0.0f, {0.0f, -0.2f, 0.0f}}, {2.5f, {1.0f / 7.0f, -0.2f, 0.5f}}};
  awkward.spheres.push_back({.center = {0.3f, 0.5f, 0.1f}, .radius = 0.3f, .material = "glass", .ior = 1.0f / 0.7f});
  awkward.render.glassSearchSteps = 13;
  awkward.boxes = {{.center = {-0.8f, 0.2f, 0.6f}, .size = {0.3f, 0.6f, 0.3f}, .yawDegrees = 33.3f},
                   {.center = {0.8f, 0.1f, -0.6f}, .size = {0.2f, 0.4f, 0.5f}, .material = "glass", .ior = 1.9f}};
  awkward.ao = scene::aoPreset("baseline");
  awkward.ao.radius = 0.7f;
  awkward.render.refraction = "apparent";
  awkward.sky.sunRadiance = {12345.678f, 1e-3f, 3.4028235e38f};
  scenes.push_back(awkward);
  for (const auto& s : scenes) {
    const std::string text = scene::sceneToJson(s);
    EXPECT_TRUE(scene::parseScene(text, "saved.json") == s) << text;
  }
  // Short where a short decimal is exact: what the scene file says, it says back.
  EXPECT_NE(scene::sceneToJson(scene::defaultScene()).find("\"level\": -0.15,"), std::string::npos);
}

// The writer spells out every key the reader knows: the default scene's file
// has the keys of scenes/default.json, which spells out the built-in scene.
TEST(SceneFile, SavedSceneSpellsOutEveryKey) {
  const auto keys = [](const nlohmann::json& j) {
    std::vector<std::string> out;
    const nlohmann::json flat = j.flatten();  // items() of a temporary would dangle
    for (const auto& [path, value] : flat.items()) out.push_back(path);
    std::sort(out.begin(), out.end());
    return out;
  };
  std::ifstream in(std::string(TIDEPOOL_SOURCE_DIR) + "/scenes/default.json");
  const auto file = nlohmann::json::parse(in);
  const auto written = keys(nlohmann::json::parse(scene::sceneToJson(scene::defaultScene()))), spelled = keys(file);
  std::vector<std::string> missing, extra;
  std::set_difference(spelled.begin(), spelled.end(), written.begin(), written.end(), std::back_inserter(missing));
  std::set_difference(written.begin(), written.end(), spelled.begin(), spelled.end(), std::back_inserter(extra));
  EXPECT_TRUE(missing.empty()) << "not written: " << ::testing::PrintToString(missing);
  EXPECT_TRUE(extra.empty()) << "not in default.json: " << ::testing::PrintToString(extra);
}

TEST(SceneFile, SavingWritesAWholeFileOrNone) {
  ScratchDir dir;
  scene::Scene s = scene::defaultScene();
  s.water.damping = 0.45f;
  const std::string path = dir.file("saved.json");
  scene::saveSceneFile(path, s);
  EXPECT_TRUE(scene::loadSceneFile(path) == s);
  EXPECT_THROW(scene::saveSceneFile("/dev/null/x.json", s), std::runtime_error);
  EXPECT_THROW(scene::saveSceneFile(dir.file("x.txt"), s), std::runtime_error);
  EXPECT_THROW(scene::saveSceneFile(dir.path().string(), s), std::runtime_error);
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1u);  // saved.json alone: no temporary, nothing half-written
}

}  // namespace tp::test

namespace tp::test {

// A setting one past a list's end adds an element, its absent keys at their
// defaults; further out, or a key of an element not there, is refused with
// the way to add one.
TEST(SceneFile, SettingOnePastAListsEndAddsAnElement) {
  const scene::Scene one = scene::defaultScene();
  ASSERT_EQ(one.spheres.size(), 1u);
  const scene::Scene two = scene::withSetting(one, "spheres.1", R"({"center": [0.5, 0.2, 0], "radius": 0.2})");
  ASSERT_EQ(two.spheres.size(), 2u);
  EXPECT_EQ(two.spheres[0], one.spheres[0]);
  EXPECT_EQ(two.spheres[1].center, glm::vec3(0.5f, 0.2f, 0.0f));
  EXPECT_EQ(two.spheres[1].radius, 0.2f);
  EXPECT_EQ(two.spheres[1].material, scene::Sphere{}.material);
  EXPECT_EQ(scene::withSetting(one, "boxes.0", "{}").boxes, std::vector<scene::Box>{scene::Box{}});

  const std::string add = "; to add one, set it whole: --set ";
  const std::tuple<const scene::Scene*, std::string, std::string> cases[] = {
      {&one, "spheres.2", "spheres has 1 element (0)" + add + "'spheres.1={...}'"},
      {&one, "spheres.1.radius", "spheres has 1 element (0)" + add + "'spheres.1={...}'"},
      {&two, "spheres.5.radius", "spheres has 2 elements (0 to 1)" + add + "'spheres.2={...}'"},
      {&one, "boxes.0.yaw", "boxes has no elements" + add + "'boxes.0={...}'"},
      // A vector of numbers is not a list to add to.
      {&one, "camera.position.3", "(keys are a scene file's, joined by dots: water.wave_speed, spheres.0.radius)"},
  };
  for (const auto& [s, key, says] : cases) {
    try {
      (void)scene::withSetting(*s, key, "{}");
      ADD_FAILURE() << key << " was taken";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), key + ": not a key of the scene" + (says[0] == '(' ? " " : "; ") + says);
    }
  }
}

}  // namespace tp::test
