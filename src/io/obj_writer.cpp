#include "io/obj_writer.hpp"

#include <filesystem>

#include "base/atomic_file.hpp"
#include "io/text_file.hpp"

namespace tp::io {
namespace {

// One material in the terms of the .mtl format and its common PBR extension
// (Pr, Pm), as docs/simulation.md#export lists them.
void writeMaterial(std::FILE* f, const std::string& name, const scene::SurfaceMaterial& m) {
  std::fprintf(f, "newmtl %s\n", name.c_str());
  std::fprintf(f, "Kd %.6g %.6g %.6g\n", m.albedo.r, m.albedo.g, m.albedo.b);
  std::fprintf(f, "Ks %.6g %.6g %.6g\n", m.specular, m.specular, m.specular);
  // Blender reads Ns back as roughness 1 - sqrt(Ns / 1000).
  const double smooth = 1.0 - m.roughness;
  std::fprintf(f, "Ns %.6g\nPr %.6g\nPm 0\n", 1000.0 * smooth * smooth, m.roughness);
  if (m.ior > 0.0f) {
    // Refracting (illum 7: refraction with Fresnel): light through it is
    // filtered by the albedo (Tf).
    std::fprintf(f, "Ni %.6g\nTf %.6g %.6g %.6g\nd 1\nillum 7\n\n", m.ior, m.albedo.r, m.albedo.g, m.albedo.b);
  } else {
    std::fprintf(f, "d 1\nillum 2\n\n");
  }
}

void writeMeshes(std::FILE* f, const std::string& mtlName, const std::vector<scene::ShadedMesh>& meshes) {
  std::fprintf(f, "# tidepool scene export\nmtllib %s\n", mtlName.c_str());
  size_t base = 1;  // OBJ indices are 1-based and global, the same for v, vt and vn here
  for (const auto& s : meshes) {
    const scene::Mesh& m = s.mesh;
    std::fprintf(f, "o %s\nusemtl %s\n", m.name.c_str(), m.name.c_str());
    for (const auto& p : m.positions) std::fprintf(f, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    for (const auto& t : s.uvs) std::fprintf(f, "vt %.9g %.9g\n", t.x, t.y);
    for (const auto& n : s.normals) std::fprintf(f, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      const size_t a = base + m.indices[t], b = base + m.indices[t + 1], c = base + m.indices[t + 2];
      std::fprintf(f, "f %zu/%zu/%zu %zu/%zu/%zu %zu/%zu/%zu\n", a, a, a, b, b, b, c, c, c);
    }
    base += m.positions.size();
  }
}

}  // namespace

std::string mtlPathFor(const std::string& objPath) {
  return std::filesystem::path(objPath).replace_extension(".mtl").string();
}

void writeObj(const std::string& path, const std::vector<scene::ShadedMesh>& meshes) {
  const std::string mtlPath = mtlPathFor(path);
  base::AtomicFile mtl(mtlPath), obj(path);
  writeTemporary(mtl, [&](std::FILE* f) {
    std::fprintf(f, "# tidepool scene export: one material per object\n");
    for (const auto& s : meshes) writeMaterial(f, s.mesh.name, s.material);
  });
  writeTemporary(obj,
                 [&](std::FILE* f) { writeMeshes(f, std::filesystem::path(mtlPath).filename().string(), meshes); });
  mtl.commit();
  obj.commit();
}

}  // namespace tp::io
