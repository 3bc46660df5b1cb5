#include "io/mesh_io.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "base/atomic_file.hpp"

namespace tp::io {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

void writeObj(std::FILE* f, const std::vector<scene::Mesh>& meshes) {
  std::fprintf(f, "# tidepool scene export\n");
  size_t base = 1;  // OBJ indices are 1-based and global
  for (const auto& m : meshes) {
    std::fprintf(f, "o %s\n", m.name.c_str());
    for (const auto& p : m.positions) std::fprintf(f, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      std::fprintf(f, "f %zu %zu %zu\n", base + m.indices[t], base + m.indices[t + 1], base + m.indices[t + 2]);
    }
    base += m.positions.size();
  }
}

void writePly(std::FILE* f, const std::vector<scene::Mesh>& meshes) {
  size_t vertices = 0, faces = 0;
  for (const auto& m : meshes) {
    vertices += m.positions.size();
    faces += m.indices.size() / 3;
  }
  std::fprintf(f, "ply\nformat ascii 1.0\ncomment tidepool scene export\n");
  std::fprintf(f, "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n", vertices);
  std::fprintf(f, "element face %zu\nproperty list uchar uint vertex_indices\nend_header\n", faces);
  for (const auto& m : meshes) {
    for (const auto& p : m.positions) std::fprintf(f, "%.9g %.9g %.9g\n", p.x, p.y, p.z);
  }
  size_t base = 0;
  for (const auto& m : meshes) {
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      std::fprintf(f, "3 %zu %zu %zu\n", base + m.indices[t], base + m.indices[t + 1], base + m.indices[t + 2]);
    }
    base += m.positions.size();
  }
}

bool isObj(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".obj" || ext == ".OBJ") return true;
  if (ext == ".ply" || ext == ".PLY") return false;
  throw std::runtime_error("output " + path + " must end in .obj or .ply");
}

}  // namespace

void checkMeshOutput(const std::string& path) {
  isObj(path);
  base::checkWritable(path);
}

void writeMeshes(const std::string& path, const std::vector<scene::Mesh>& meshes) {
  const bool obj = isObj(path);
  base::AtomicFile file(path);
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(file.tempPath().c_str(), "w"));
  if (!f) throw std::runtime_error("cannot write " + path);
  obj ? writeObj(f.get(), meshes) : writePly(f.get(), meshes);
  if (std::fflush(f.get()) != 0 || std::ferror(f.get()))
    throw std::runtime_error("cannot write " + path + ": disk full?");
  f.reset();
  file.commit();
}

}  // namespace tp::io
