// `tidepool export` read back by an independent reader (Assimp): the OBJ with
// its .mtl and the binary glTF hold every object by name with its triangles,
// unit normals, texture coordinates and material, and the water reaches the
// pool's walls; a glTF sequence moves (export_test.cpp checks the heights).
#include <gtest/gtest.h>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <algorithm>
#include <assimp/Importer.hpp>
#include <glm/glm.hpp>
#include <map>

#include "assimp_meshes.hpp"
#include "process.hpp"
#include "scene/scene_file.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"

namespace tp::test {
namespace {

// What each object of the default scene holds once exported: vertices, triangles.
struct Counts {
  size_t vertices, triangles;
};

std::map<std::string, Counts> defaultSceneCounts() {
  const uint32_t n = scene::defaultScene().water.grid, f = render::kPoolFloorGrid;
  const uint32_t stacks = render::kSphereStacks, slices = render::kSphereSlices;
  return {{"ground", {16, 8}},
          {"pool_walls", {16, 8}},
          {"pool_floor", {size_t(f) * f, 2 * size_t(f - 1) * (f - 1)}},
          {"sphere0", {size_t(stacks + 1) * (slices + 1), 2 * size_t(stacks) * slices}},
          {"water", {size_t(n + 2) * (n + 2), 2 * size_t(n + 1) * (n + 1)}}};
}

glm::vec3 diffuse(const aiScene& scene, const aiMesh& mesh) {
  aiColor3D c;
  EXPECT_EQ(scene.mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, c), aiReturn_SUCCESS);
  return {c.r, c.g, c.b};
}

std::string materialName(const aiScene& scene, const aiMesh& mesh) {
  return scene.mMaterials[mesh.mMaterialIndex]->GetName().C_Str();
}

// The y of every vertex of the water, in the order read.
std::vector<float> waterHeights(const aiScene& scene) {
  const aiMesh* water = meshesByName(scene).at("water");
  std::vector<float> y;
  for (unsigned k = 0; k < water->mNumVertices; ++k) y.push_back(water->mVertices[k].y);
  return y;
}

// Checks what both formats must hold; `expectedVertices` gives each object's
// vertex count as read (Assimp's OBJ reader unshares vertices, joined again here).
void expectDefaultScene(const aiScene& scene, const std::map<std::string, size_t>& expectedVertices) {
  const scene::Scene s = scene::defaultScene();
  const auto meshes = meshesByName(scene);
  const auto counts = defaultSceneCounts();
  ASSERT_EQ(meshes.size(), counts.size());
  for (const auto& [name, count] : counts) {
    ASSERT_TRUE(meshes.contains(name)) << name;
    const aiMesh& m = *meshes.at(name);
    EXPECT_EQ(m.mNumFaces, count.triangles) << name;
    EXPECT_EQ(m.mNumVertices, expectedVertices.at(name)) << name;
    ASSERT_TRUE(m.HasNormals()) << name;
    ASSERT_TRUE(m.HasTextureCoords(0)) << name;
    float worstNormal = 0.0f;
    for (unsigned k = 0; k < m.mNumVertices; ++k) {
      worstNormal = std::max(worstNormal, std::abs(m.mNormals[k].Length() - 1.0f));
      ASSERT_GE(m.mTextureCoords[0][k].x, -1e-6f) << name;
      ASSERT_LE(m.mTextureCoords[0][k].x, 1.0f + 1e-6f) << name;
    }
    EXPECT_LT(worstNormal, 1e-5f) << name;
    EXPECT_EQ(materialName(scene, m), name);
  }
  const glm::vec3 sphere = diffuse(scene, *meshes.at("sphere0"));
  EXPECT_NEAR(glm::length(sphere - s.spheres[0].albedo), 0.0f, 1e-5f);
  const glm::vec3 water = diffuse(scene, *meshes.at("water"));
  EXPECT_NEAR(glm::length(water - glm::exp(-s.water.absorption)), 0.0f, 1e-5f);

  // No crack: the water spans the pool from wall to wall.
  const aiMesh& w = *meshes.at("water");
  glm::vec3 low(1e9f), high(-1e9f);
  for (unsigned k = 0; k < w.mNumVertices; ++k) {
    low = glm::min(low, glm::vec3(w.mVertices[k].x, w.mVertices[k].y, w.mVertices[k].z));
    high = glm::max(high, glm::vec3(w.mVertices[k].x, w.mVertices[k].y, w.mVertices[k].z));
  }
  const float half = 0.5f * s.water.extent;
  EXPECT_FLOAT_EQ(low.x, -half);
  EXPECT_FLOAT_EQ(high.x, half);
  EXPECT_FLOAT_EQ(low.z, -half);
  EXPECT_FLOAT_EQ(high.z, half);
  // The walls stand at the same place.
  const aiMesh& walls = *meshes.at("pool_walls");
  for (unsigned k = 0; k < walls.mNumVertices; ++k) {
    EXPECT_FLOAT_EQ(std::max(std::abs(walls.mVertices[k].x), std::abs(walls.mVertices[k].z)), half);
  }
}

std::map<std::string, size_t> exportedVertices() {
  std::map<std::string, size_t> v;
  for (const auto& [name, count] : defaultSceneCounts()) v[name] = count.vertices;
  return v;
}

}  // namespace

TEST(ExportFormats, ObjWithItsMtlReadsBackInAssimp) {
  ScratchDir dir;
  const std::string obj = dir.file("pool.obj");
  ProcessResult r = runTidepool("export --validate --frame 3 --out " + obj, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(std::filesystem::is_regular_file(dir.file("pool.mtl")));
  Assimp::Importer importer;
  // The OBJ reader gives each face its own corners; joined, the shared ones are
  // shared again: all but the ground's, whose four pieces meet at equal corners.
  const aiScene* scene = importer.ReadFile(obj, aiProcess_JoinIdenticalVertices);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  auto vertices = exportedVertices();
  vertices["ground"] = 8;
  expectDefaultScene(*scene, vertices);
  float ior = 0.0f;
  const aiMesh& water = *meshesByName(*scene).at("water");
  EXPECT_EQ(scene->mMaterials[water.mMaterialIndex]->Get(AI_MATKEY_REFRACTI, ior), aiReturn_SUCCESS);
  EXPECT_FLOAT_EQ(ior, scene::defaultScene().water.ior);
}

TEST(ExportFormats, GlbReadsBackInAssimp) {
  ScratchDir dir;
  const std::string glb = dir.file("pool.glb");
  ProcessResult r = runTidepool("export --validate --frame 3 --out " + glb, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(glb, 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  expectDefaultScene(*scene, exportedVertices());
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"pool.glb"});  // no temporary left
}

// A turned box: 12 triangles of their own corners, three normals apiece the
// face's (as box.vert shades it), each face's texture spanning [0, 1]^2.
TEST(ExportFormats, BoxesHaveFlatFaces) {
  ScratchDir dir;
  const std::string sceneFile = dir.file("box.json"), glb = dir.file("box.glb");
  writeText(sceneFile, R"({"water": {"enabled": false},
    "boxes": [{"center": [1, 0.2, 0], "size": [0.2, 0.4, 0.6], "yaw": 30, "albedo": [0.1, 0.2, 0.3]}]})");
  ProcessResult r = runTidepool("export --scene " + sceneFile + " --out " + glb, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(glb, 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  const aiMesh& box = *meshesByName(*scene).at("box0");
  ASSERT_EQ(box.mNumFaces, 12u);
  ASSERT_EQ(box.mNumVertices, 36u);
  std::vector<glm::vec3> normals;
  for (unsigned f = 0; f < box.mNumFaces; ++f) {
    const unsigned* i = box.mFaces[f].mIndices;
    const auto at = [&](unsigned k) { return glm::vec3(box.mVertices[k].x, box.mVertices[k].y, box.mVertices[k].z); };
    const glm::vec3 face = glm::normalize(glm::cross(at(i[1]) - at(i[0]), at(i[2]) - at(i[0])));
    for (int c = 0; c < 3; ++c) {
      const aiVector3D n = box.mNormals[i[c]];
      EXPECT_NEAR(glm::length(glm::vec3(n.x, n.y, n.z) - face), 0.0f, 1e-5f) << "face " << f;
    }
    if (std::none_of(normals.begin(), normals.end(), [&](glm::vec3 n) { return glm::length(n - face) < 1e-4f; }))
      normals.push_back(face);
  }
  EXPECT_EQ(normals.size(), 6u);
  glm::vec2 low(1e9f), high(-1e9f);
  for (unsigned k = 0; k < box.mNumVertices; ++k) {
    low = glm::min(low, glm::vec2(box.mTextureCoords[0][k].x, box.mTextureCoords[0][k].y));
    high = glm::max(high, glm::vec2(box.mTextureCoords[0][k].x, box.mTextureCoords[0][k].y));
  }
  EXPECT_NEAR(low.x, 0.0f, 1e-5f);
  EXPECT_NEAR(low.y, 0.0f, 1e-5f);
  EXPECT_NEAR(high.x, 1.0f, 1e-5f);
  EXPECT_NEAR(high.y, 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(diffuse(*scene, box) - glm::vec3(0.1f, 0.2f, 0.3f)), 0.0f, 1e-6f);
}

// A glTF sequence: a file per frame, the water moving between them.
TEST(ExportFormats, GlbSequenceReadsBackInAssimp) {
  ScratchDir dir;
  ProcessResult r = runTidepool("export --frames 0-2 --out " + dir.file("pool.####.glb"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::vector<float>> heights;
  for (const char* frame : {"0000", "0001", "0002"}) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(dir.file(std::string("pool.") + frame + ".glb"), 0);
    ASSERT_NE(scene, nullptr) << frame << ": " << importer.GetErrorString();
    heights.push_back(waterHeights(*scene));
  }
  for (size_t f = 1; f < heights.size(); ++f) {
    ASSERT_EQ(heights[f].size(), heights[0].size());
    float change = 0.0f;
    for (size_t k = 0; k < heights[f].size(); ++k)
      change = std::max(change, std::abs(heights[f][k] - heights[f - 1][k]));
    EXPECT_GT(change, 1e-4f) << "frame " << f;
  }
}

}  // namespace tp::test
