#pragma once
#include <string>
#include <vector>

#include "scene/shaded_mesh.hpp"

namespace tp::io {

// Writes meshes in the format the extension names, each file through a
// temporary one: .obj, a Wavefront OBJ with its .mtl beside it (io/obj_writer.hpp);
// .ply, one ASCII PLY of all meshes merged, with normals (nx ny nz); .glb,
// binary glTF 2.0 (io/gltf_writer.hpp). Coordinates in text are printed with 9
// significant digits, so floats read back exactly.
void writeMeshes(const std::string& path, const std::vector<scene::ShadedMesh>& meshes);

// Whether `path` ends in .obj, .ply or .glb (case-insensitive).
bool isMeshOutput(const std::string& path);

// Throws unless `path` ends in .obj, .ply or .glb and a file can be created
// there (checked before long work starts).
void checkMeshOutput(const std::string& path);

}  // namespace tp::io
