#include "io/mesh_io.hpp"

#include <stdexcept>

#include "base/atomic_file.hpp"
#include "io/gltf_writer.hpp"
#include "io/obj_writer.hpp"
#include "io/text_file.hpp"

namespace tp::io {
namespace {

void writePly(std::FILE* f, const std::vector<scene::ShadedMesh>& meshes) {
  size_t vertices = 0, faces = 0;
  for (const auto& s : meshes) {
    vertices += s.mesh.positions.size();
    faces += s.mesh.indices.size() / 3;
  }
  std::fprintf(f, "ply\nformat ascii 1.0\ncomment tidepool scene export\n");
  std::fprintf(f, "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n", vertices);
  std::fprintf(f, "property float nx\nproperty float ny\nproperty float nz\n");
  std::fprintf(f, "element face %zu\nproperty list uchar uint vertex_indices\nend_header\n", faces);
  for (const auto& s : meshes) {
    for (size_t k = 0; k < s.mesh.positions.size(); ++k) {
      const glm::vec3 p = s.mesh.positions[k], n = s.normals[k];
      std::fprintf(f, "%.9g %.9g %.9g %.9g %.9g %.9g\n", p.x, p.y, p.z, n.x, n.y, n.z);
    }
  }
  size_t base = 0;
  for (const auto& s : meshes) {
    const auto& i = s.mesh.indices;
    for (size_t t = 0; t + 2 < i.size(); t += 3)
      std::fprintf(f, "3 %zu %zu %zu\n", base + i[t], base + i[t + 1], base + i[t + 2]);
    base += s.mesh.positions.size();
  }
}

enum class MeshFormat { Obj, Ply, Glb };

MeshFormat meshFormat(const std::string& path) {
  if (base::hasExtension(path, ".obj")) return MeshFormat::Obj;
  if (base::hasExtension(path, ".ply")) return MeshFormat::Ply;
  if (base::hasExtension(path, ".glb")) return MeshFormat::Glb;
  throw std::runtime_error("output " + path + " must end in .obj, .ply or .glb");
}

}  // namespace

bool isMeshOutput(const std::string& path) {
  return base::hasExtension(path, ".obj") || base::hasExtension(path, ".ply") || base::hasExtension(path, ".glb");
}

void checkMeshOutput(const std::string& path) {
  if (meshFormat(path) == MeshFormat::Obj) base::checkWritable(mtlPathFor(path));
  base::checkWritable(path);
}

void writeMeshes(const std::string& path, const std::vector<scene::ShadedMesh>& meshes) {
  switch (meshFormat(path)) {
    case MeshFormat::Obj:
      writeObj(path, meshes);
      return;
    case MeshFormat::Glb:
      writeGlb(path, meshes);
      return;
    case MeshFormat::Ply: {
      base::AtomicFile file(path);
      writeTemporary(file, [&](std::FILE* f) { writePly(f, meshes); });
      file.commit();
    }
  }
}

}  // namespace tp::io
