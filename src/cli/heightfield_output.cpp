#include "cli/heightfield_output.hpp"

#include "base/atomic_file.hpp"
#include "cli/build_version.hpp"
#include "cli/frame_output.hpp"
#include "io/image_io.hpp"
#include "shading/water_model.hpp"

namespace tp::app {

bool isHeightfieldOutput(const std::string& path) { return base::hasExtension(path, ".exr"); }

void writeHeightfield(const std::string& path, const scene::Scene& scene, const sim::WaterState& water,
                      uint32_t frame) {
  const std::vector<glm::vec3> normals = render::waterVertexNormals(water, scene.water.extent);
  // Not N.X N.Y N.Z: OpenImageIO, and readers built on it, take a channel
  // named *.Z as the depth where there is no bare Z, as here; R G B is
  // OpenEXR's naming of a layer's three components.
  io::FloatImage image{water.n, water.n, {"Y", "N.R", "N.G", "N.B"}, std::vector<float>(water.u.size() * 4)};
  for (size_t k = 0; k < water.u.size(); ++k) {
    image.pixels[4 * k] = scene.water.level + water.u[k];
    for (int c = 0; c < 3; ++c) image.pixels[4 * k + 1 + c] = normals[k][c];
  }
  // Float: a height in metres and a direction are data, not colour.
  io::writeExr(path, image, std::vector<io::PixelType>(4, io::PixelType::Float),
               io::ExrAttributes{.software = versionText(), .frame = frame, .framesPerSecond = sceneFrameRate(scene)});
}

}  // namespace tp::app
