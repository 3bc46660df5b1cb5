// `export --out PATH.exr`: the water as a heightfield, against the water the
// simulation gives for that frame in this process and the normals the
// renderer shades it with, and against the exported mesh's water looked up
// in it by the mesh's own texture coordinates.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <assimp/postprocess.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>

#include "assimp_meshes.hpp"
#include "gpu_test.hpp"
#include "io/image_io.hpp"
#include "process.hpp"
#include "scene/scene.hpp"
#include "shading/water_model.hpp"
#include "sim/water_scene.hpp"

namespace tp::test {

class HeightfieldExport : public GpuTest {};

TEST_F(HeightfieldExport, HoldsTheFramesWaterAndItsNormals) {
  ScratchDir dir;
  ProcessResult r = runTidepool("export --set water.grid=32 --frame 7 --validate --out " + dir.file("h.exr"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runTidepool("export --set water.grid=32 --frames 6-7 --validate --out " + dir.file("s.#.exr"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;

  scene::Scene scene = scene::defaultScene();
  scene.water.grid = 32;
  const sim::WaterState water = sim::simulateWater(ctx(), scene, 7);
  const std::vector<glm::vec3> normals = render::waterVertexNormals(water, scene.water.extent);
  for (const char* name : {"h.exr", "s.7.exr"}) {
    SCOPED_TRACE(name);
    const io::FloatImage image = io::readImage(dir.file(name));
    ASSERT_EQ(image.channels, (std::vector<std::string>{"Y", "N.R", "N.G", "N.B"}));
    ASSERT_EQ(image.width, 32u);
    ASSERT_EQ(image.height, 32u);
    for (size_t k = 0; k < water.u.size(); ++k) {
      ASSERT_EQ(image.pixels[4 * k], scene.water.level + water.u[k]) << "cell " << k;
      for (int c = 0; c < 3; ++c) ASSERT_EQ(image.pixels[4 * k + 1 + c], normals[k][c]) << "cell " << k;
    }
  }
  // The frame and the rate are on each frame of the sequence.
  auto in = OIIO::ImageInput::open(dir.file("s.6.exr"));
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().get_int_attribute("frame", -1), 6);
  EXPECT_TRUE(in->spec().find_attribute("framesPerSecond", OIIO::TypeRational, true));
  // No channel is taken for a depth (OpenImageIO makes one of a *.Z) or an alpha.
  EXPECT_EQ(in->spec().z_channel, -1);
  EXPECT_EQ(in->spec().alpha_channel, -1);
  // Frame 6's water is not frame 7's: the sequence is stepped between its files.
  const io::FloatImage six = io::readImage(dir.file("s.6.exr")), seven = io::readImage(dir.file("s.7.exr"));
  double change = 0.0;
  for (size_t k = 0; k < six.pixels.size(); k += 4) change += std::abs(six.pixels[k] - seven.pixels[k]);
  EXPECT_GT(change, 0.0);
}

TEST(HeightfieldExportCli, RefusesAPoolWithoutWater) {
  ScratchDir dir;
  EXPECT_NE(expectUsageError("export --set water.enabled=false --out " + dir.file("h.exr"), dir)
                .find("a heightfield is the water's"),
            std::string::npos);
  EXPECT_NE(expectUsageError("export --out " + dir.file("h.tif"), dir).find(".exr (a heightfield)"), std::string::npos);
}

// A DCC displaces a mesh by an image at the mesh's UVs: u right, v up, and
// row 0 the top of the image. Every water vertex of the OBJ and the glTF,
// looked up so in the EXR of the same frame (the nearest pixel), finds its
// own height: the image is not mirrored against the mesh.
TEST(HeightfieldExportCli, MeshUvsFindEachVertexsHeightInTheExr) {
  ScratchDir dir;
  const std::string frame = "export --set water.grid=32 --frame 30 --out ";
  for (const char* name : {"h.exr", "m.obj", "m.glb"}) {
    const ProcessResult r = runTidepool(frame + dir.file(name), dir);
    ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
  }
  const io::FloatImage image = io::readImage(dir.file("h.exr"));
  const uint32_t n = image.width;
  const auto pixel = [&](float t) { return std::clamp(uint32_t(std::max(t, 0.0f) * float(n)), 0u, n - 1); };
  for (const char* name : {"m.obj", "m.glb"}) {
    SCOPED_TRACE(name);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(dir.file(name), aiProcess_JoinIdenticalVertices);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    const aiMesh* water = meshesByName(*scene).at("water");
    ASSERT_TRUE(water->HasTextureCoords(0));
    float low = 1e9f, high = -1e9f, worst = 0.0f;
    for (unsigned k = 0; k < water->mNumVertices; ++k) {
      const aiVector3D uv = water->mTextureCoords[0][k];
      const uint32_t column = pixel(uv.x), row = pixel(1.0f - uv.y);
      const float y = water->mVertices[k].y;
      worst = std::max(worst, std::abs(image.pixels[4 * (size_t(row) * n + column)] - y));
      low = std::min(low, y);
      high = std::max(high, y);
    }
    EXPECT_GT(high - low, 1e-3f) << "flat water would not see a mirrored image";
    EXPECT_LT(worst, 1e-6f) << "of waves " << high - low << " m high";
  }
}

}  // namespace tp::test
