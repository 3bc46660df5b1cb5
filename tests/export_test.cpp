// `tidepool export`: the scene's triangles as OBJ and PLY, the water at a
// frame checked against the CPU reference.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "process.hpp"
#include "scene/scene_file.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "sim/reference_sim.hpp"
#include "sim/wake_measures.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

struct ObjContents {
  std::vector<glm::vec3> vertices;
  size_t faces = 0;
  std::vector<std::string> objects;
};

ObjContents readObj(const std::string& path) {
  ObjContents c;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      glm::vec3 v;
      s >> v.x >> v.y >> v.z;
      c.vertices.push_back(v);
    } else if (tag == "f") {
      ++c.faces;
    } else if (tag == "o") {
      std::string name;
      s >> name;
      c.objects.push_back(name);
    }
  }
  return c;
}

// The exported water has a ring of vertices on the walls around the cells:
// cell (i, j)'s vertex is (i + 1, j + 1) of the (n + 2)^2 grid.
size_t waterVertex(uint32_t n, uint32_t i, uint32_t j) { return size_t(j + 1) * (n + 2) + i + 1; }
size_t waterVertices(uint32_t n) { return size_t(n + 2) * (n + 2); }
size_t waterTriangles(uint32_t n) { return 2 * size_t(n + 1) * (n + 1); }

}  // namespace

TEST(ExportCli, ObjHoldsTheGroundAndTheWaterAtTheFrame) {
  ScratchDir dir;
  const std::string obj = dir.file("scene.obj");
  constexpr uint32_t kFrame = 4;
  ProcessResult r = runTidepool("export --validate --frame " + std::to_string(kFrame) + " --out " + obj, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const scene::Scene s = scene::defaultScene();
  const uint32_t n = s.water.grid;
  const ObjContents c = readObj(obj);
  EXPECT_EQ(c.objects, (std::vector<std::string>{"ground", "pool_walls", "pool_floor", "sphere0", "water"}));
  const size_t floorVertices = size_t(render::kPoolFloorGrid) * render::kPoolFloorGrid;
  const size_t sphereVertices = size_t(render::kSphereStacks + 1) * (render::kSphereSlices + 1);
  const size_t first = 16 + 16 + floorVertices + sphereVertices;  // the water's first vertex
  ASSERT_EQ(c.vertices.size(), first + waterVertices(n));
  EXPECT_EQ(c.faces, 8u + 8u + 2u * size_t(render::kPoolFloorGrid - 1) * (render::kPoolFloorGrid - 1) +
                         2u * render::kSphereStacks * render::kSphereSlices + waterTriangles(n));

  // The water's heights against the double-precision reference run for the
  // same frames (float32 round-off over a few steps).
  sim::ReferenceSim reference(sim::waterParams(s), sim::waterInitialState(s.water));
  reference.steps(uint64_t(kFrame) * sim::waterSubsteps(s.water), sim::waterStep(s.water));
  double worst = 0.0, moved = 0.0;
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      const double y = c.vertices[first + waterVertex(n, i, j)].y;
      worst = std::max(worst, std::abs(y - (s.water.level + reference.u()[size_t(j) * n + i])));
      moved = std::max(moved, std::abs(y - s.water.level));
    }
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(moved, 0.005);  // the drops are there (flat water: 0)
  // Cell (i, j) sits at world ((i + 1/2) h - L/2, (j + 1/2) h - L/2).
  const float h = s.water.extent / float(n);
  EXPECT_FLOAT_EQ(c.vertices[first + waterVertex(n, 2, 1)].x, 2.5f * h - 0.5f * s.water.extent);
  EXPECT_FLOAT_EQ(c.vertices[first + waterVertex(n, 2, 1)].z, 1.5f * h - 0.5f * s.water.extent);
  // The floor follows the terrain: heights spread over most of its amplitude around the mean depth.
  float low = 1e9f, high = -1e9f;
  for (size_t k = 32; k < 32 + floorVertices; ++k) {
    low = std::min(low, c.vertices[k].y);
    high = std::max(high, c.vertices[k].y);
  }
  EXPECT_GT(high - low, 0.3f * s.terrain.amplitude);
  EXPECT_GE(low, s.ground.height - s.pool.depth - 0.5f * s.terrain.amplitude);
  EXPECT_LE(high, s.ground.height - s.pool.depth + 0.5f * s.terrain.amplitude);
}

TEST(ExportCli, PlyHasAConsistentHeader) {
  ScratchDir dir;
  const std::string ply = dir.file("scene.ply");
  ASSERT_EQ(runTidepool("export --validate --out " + ply, dir).exitCode, 0);
  std::ifstream in(ply);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const uint32_t n = scene::defaultScene().water.grid, f = render::kPoolFloorGrid;
  const uint32_t sphereVertices = (render::kSphereStacks + 1) * (render::kSphereSlices + 1);
  const uint32_t sphereFaces = 2 * render::kSphereStacks * render::kSphereSlices;
  const size_t vertices = 32 + f * f + sphereVertices + waterVertices(n);
  const size_t faces = 16 + 2 * (f - 1) * (f - 1) + sphereFaces + waterTriangles(n);
  EXPECT_NE(text.find("element vertex " + std::to_string(vertices) + "\n"), std::string::npos);
  EXPECT_NE(text.find("element face " + std::to_string(faces) + "\n"), std::string::npos);
  const size_t body = text.find("end_header\n") + 11;
  EXPECT_EQ(size_t(lineCount(text.substr(body))), size_t(vertices + faces));
}

TEST(ExportCli, BadOutputsFailCleanly) {
  ScratchDir dir;
  writeText(dir.file("broken.json"), "{\"water\": {\"grid\": \"many\"}}");
  const std::vector<std::string> files{"broken.json"};
  EXPECT_NE(expectUsageError("export --out " + dir.file("scene.stl"), dir, files)
                .find(".obj, .ply, .glb or .exr (a heightfield)"),
            std::string::npos);
  expectCleanFailure("export --out /dev/null/scene.obj", dir, files);
  expectCleanFailure("export", dir, files);
  EXPECT_NE(expectCleanFailure("export --scene " + dir.file("broken.json") + " --out " + dir.file("x.obj"), dir, files)
                .find("water.grid"),
            std::string::npos);
}

// A sphere moving down into calm water along its path raises the surface by
// exactly the volume it comes to occupy below the rest level (the cap's), and
// the export puts it where the path says at the frame's time.
TEST(ExportCli, MovingSphereDisplacesTheVolumeItOccupies) {
  ScratchDir dir;
  const std::string sceneFile = dir.file("moving.json"), obj = dir.file("moving.obj");
  writeText(sceneFile, R"({"water": {"drops": []},
    "spheres": [{"radius": 0.45, "path": [{"time": 0.0, "center": [0.9, 0.4, -0.7]},
                                           {"time": 0.5, "center": [0.9, -0.3, -0.7]}]}]})");
  constexpr uint32_t kFrame = 9;
  ProcessResult r = runTidepool(
      "export --validate --scene " + sceneFile + " --frame " + std::to_string(kFrame) + " --out " + obj, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const scene::Scene s = scene::loadSceneFile(sceneFile);
  const float t = kFrame * s.water.frameTime;
  const glm::vec3 center = scene::sphereCenterAt(s.spheres[0], t);
  EXPECT_NEAR(center.y, 0.4f - 0.7f * t / 0.5f, 1e-6f);

  const ObjContents c = readObj(obj);
  const uint32_t n = s.water.grid;
  const size_t floorVertices = size_t(render::kPoolFloorGrid) * render::kPoolFloorGrid;
  const size_t sphereVertices = size_t(render::kSphereStacks + 1) * (render::kSphereSlices + 1);
  const size_t sphereFirst = 32 + floorVertices, first = sphereFirst + sphereVertices;
  ASSERT_EQ(c.vertices.size(), first + waterVertices(n));
  for (size_t k = sphereFirst; k < first; ++k) {
    ASSERT_NEAR(glm::length(c.vertices[k] - center), s.spheres[0].radius, 1e-5f);
  }

  // Volume the sphere occupies below the rest level (it is inside the grid).
  const double h = s.water.extent / n;
  const double submerged = sim::sphereCapVolume(s.spheres[0].radius, center.y, s.water.level);
  double waterChange = 0.0;
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i)
      waterChange += (double(c.vertices[first + waterVertex(n, i, j)].y) - s.water.level) * h * h;
  }
  EXPECT_GT(submerged, 0.05);  // it is well in
  EXPECT_NEAR(waterChange, submerged, 1e-3 * submerged);
}

// Glass exports as the renderer draws it: clear, smooth and of its own
// index, whatever albedo its scene entry holds; a Lambertian box keeps its
// albedo and no index.
TEST(ExportCli, GlassIsClearAndKeepsItsIndex) {
  ScratchDir dir;
  const std::string sceneFile = dir.file("glass.json"), obj = dir.file("glass.obj");
  writeText(sceneFile, R"({"spheres": [{"material": "glass", "ior": 1.6, "albedo": [0.8, 0.3, 0.2]}],
    "boxes": [{"center": [1, 0.5, 1], "material": "glass", "ior": 1.7}, {"center": [-1, 0.5, 1]}]})");
  ProcessResult r = runTidepool("export --validate --scene " + sceneFile + " --out " + obj, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(dir.file("glass.mtl"));
  std::map<std::string, std::string> materials;
  std::string line, name;
  while (std::getline(in, line)) {
    if (line.rfind("newmtl ", 0) == 0)
      name = line.substr(7);
    else if (!name.empty())
      materials[name] += line + "\n";
  }
  for (const auto& [mesh, ior] : {std::pair{"sphere0", "Ni 1.6"}, std::pair{"box0", "Ni 1.7"}}) {
    EXPECT_NE(materials[mesh].find(ior), std::string::npos) << materials[mesh];
    EXPECT_NE(materials[mesh].find("Tf 1 1 1"), std::string::npos) << materials[mesh];
  }
  EXPECT_NE(materials["box1"].find("Kd 0.3 0.5 0.7"), std::string::npos) << materials["box1"];
  EXPECT_EQ(materials["box1"].find("Ni "), std::string::npos) << materials["box1"];
}

// A sequence runs the water once through the range: each frame as a single
// export of it writes it, the water moving between frames.
TEST(ExportCli, FramesWriteAMeshSequence) {
  ScratchDir dir;
  ProcessResult r = runTidepool("export --validate --frames 0-2 --out " + dir.file("pool.####.obj"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const size_t water = waterVertices(scene::defaultScene().water.grid);
  std::vector<std::vector<glm::vec3>> heights;
  for (const char* frame : {"0000", "0001", "0002"}) {
    const std::string obj = dir.file(std::string("pool.") + frame + ".obj");
    ASSERT_TRUE(std::filesystem::is_regular_file(dir.file(std::string("pool.") + frame + ".mtl"))) << frame;
    const ObjContents c = readObj(obj);
    ASSERT_GE(c.vertices.size(), water) << frame;
    heights.emplace_back(c.vertices.end() - std::ptrdiff_t(water), c.vertices.end());  // the water is last
    EXPECT_NE(r.out.find(obj), std::string::npos) << "a line of progress per frame:\n" << r.out;
  }
  for (size_t f = 1; f < heights.size(); ++f) {
    float change = 0.0f;
    for (size_t k = 0; k < water; ++k) change = std::max(change, std::abs(heights[f][k].y - heights[f - 1][k].y));
    EXPECT_GT(change, 1e-4f) << "frame " << f;
  }
  std::filesystem::create_directory(dir.file("single"));
  const std::string single = dir.file("single/pool.0002.obj");
  ASSERT_EQ(runTidepool("export --frame 2 --out " + single, dir).exitCode, 0);
  // Compared whole but not printed: gtest's diff of two 6 MB texts would not end.
  EXPECT_TRUE(readText(single) == readText(dir.file("pool.0002.obj"))) << "frame 2 of the sequence differs";
}

TEST(ExportCli, BadSequencesAreRefused) {
  ScratchDir dir;
  const std::string pattern = dir.file("pool.####.obj");
  EXPECT_NE(expectUsageError("export --frames 2-1 --out " + pattern, dir).find("--frames 2-1"), std::string::npos);
  EXPECT_NE(expectUsageError("export --frames x --out " + pattern, dir).find("--frames"), std::string::npos);
  EXPECT_NE(expectUsageError("export --frames 0-2 --out " + dir.file("pool.obj"), dir).find("####"), std::string::npos);
  expectUsageError("export --frame 1 --frames 0-2 --out " + pattern, dir);
  EXPECT_NE(expectUsageError("export --frames 0-2 --out " + dir.file("pool.####.fbx"), dir).find(".ply"),
            std::string::npos);
  expectCleanFailure("export --frames 0-2 --out /dev/null/pool.####.obj", dir, {});
}

}  // namespace tp::test
