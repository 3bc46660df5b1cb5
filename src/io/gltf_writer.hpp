#pragma once
#include <string>
#include <vector>

#include "scene/shaded_mesh.hpp"

namespace tp::io {

// Writes binary glTF 2.0 (.glb) through tinygltf: a node per mesh, named as
// the mesh, holding its positions, normals, texture coordinates and indices
// as accessors into one buffer, and a metallic-roughness material (the
// refracting ones with KHR_materials_transmission and KHR_materials_ior).
// Written through a temporary file.
void writeGlb(const std::string& path, const std::vector<scene::ShadedMesh>& meshes);

}  // namespace tp::io
