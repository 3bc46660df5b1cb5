#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tp::scene {

// A named triangle mesh in world space, counter-clockwise seen from outside.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;  // three per triangle
};

}  // namespace tp::scene
