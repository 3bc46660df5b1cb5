#pragma once
#include <string>
#include <vector>

#include "scene/shaded_mesh.hpp"

namespace tp::io {

// The material library beside an OBJ: the same path ending in .mtl.
std::string mtlPathFor(const std::string& objPath);

// Writes a Wavefront OBJ (an `o` object per mesh, with `vn` normals, `vt`
// texture coordinates and `usemtl` its material) and its .mtl beside it (a
// `newmtl` per mesh, named as the mesh), each through a temporary file; the
// OBJ is renamed into place last, once both are whole.
void writeObj(const std::string& path, const std::vector<scene::ShadedMesh>& meshes);

}  // namespace tp::io
