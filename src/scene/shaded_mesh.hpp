#pragma once
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "scene/mesh.hpp"

namespace tp::scene {

// What a mesh is made of, in the terms OBJ's .mtl and glTF's PBR material
// take (docs/simulation.md#export says how each field is written).
struct SurfaceMaterial {
  glm::vec3 albedo{0.8f};  // diffuse reflectance; the water's: what a metre of it lets through
  float specular = 0.0f;   // the glossy lobe's share (shared/glossy.h)
  float roughness = 1.0f;  // of the glossy lobe, 0 (sharpest) to 1
  float ior = 0.0f;        // of a refracting surface (water, glass); 0 for an opaque one
};

// A mesh as a DCC takes it: a unit normal and texture coordinates (u right,
// v up) for every position, and the material it is made of.
struct ShadedMesh {
  Mesh mesh;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  SurfaceMaterial material;
};

}  // namespace tp::scene
