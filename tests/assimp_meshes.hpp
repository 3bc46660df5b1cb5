#pragma once
// What the tests read back through Assimp, the independent reader of what
// `tidepool export` writes.
#include <assimp/scene.h>

#include <map>
#include <string>

namespace tp::test {

// The meshes of a scene as Assimp reads them, by the name of the node holding each.
inline std::map<std::string, const aiMesh*> meshesByName(const aiScene& scene) {
  std::map<std::string, const aiMesh*> meshes;
  const auto visit = [&](const aiNode& node, const auto& self) -> void {
    for (unsigned k = 0; k < node.mNumMeshes; ++k) meshes[node.mName.C_Str()] = scene.mMeshes[node.mMeshes[k]];
    for (unsigned c = 0; c < node.mNumChildren; ++c) self(*node.mChildren[c], self);
  };
  visit(*scene.mRootNode, visit);
  return meshes;
}

}  // namespace tp::test
