#pragma once
#include <string>
#include <vector>

#include "scene/mesh.hpp"

namespace tp::io {

// Writes meshes as one Wavefront OBJ (an `o` object per mesh) or one ASCII PLY
// (all meshes merged), chosen by the extension, through a temporary file.
// Coordinates are printed with 9 significant digits, so floats read back exactly.
void writeMeshes(const std::string& path, const std::vector<scene::Mesh>& meshes);

// Throws unless `path` ends in .obj or .ply and a file can be created there
// (checked before long work starts).
void checkMeshOutput(const std::string& path);

}  // namespace tp::io
