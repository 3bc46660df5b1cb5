#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace tp::render {

// What a reference ray hit: one of the triangle meshes (index into the meshes
// the scene was built from, its triangle and barycentrics) or an exact sphere.
struct ReferenceHit {
  float distance = 0.0f;
  int mesh = -1;    // index of the mesh, or -1
  int sphere = -1;  // index of the sphere, or -1
  uint32_t triangle = 0;
  glm::vec2 barycentric{0.0f};      // weights of the triangle's second and third vertex
  glm::vec3 geometricNormal{0.0f};  // unit, not oriented
  bool hit() const { return mesh >= 0 || sphere >= 0; }
};

// How far a continued ray starts off the surface it leaves, in metres: far
// above float round-off at the scene's scale, far below any feature.
inline constexpr float kSurfaceOffset = 1e-4f;

// The frame's triangles in an Embree 3 BVH, and its spheres cast exactly.
class ReferenceScene {
 public:
  ReferenceScene(const std::vector<scene::Mesh>& meshes, const std::vector<scene::Sphere>& spheres);
  ~ReferenceScene();
  ReferenceScene(const ReferenceScene&) = delete;
  ReferenceScene& operator=(const ReferenceScene&) = delete;

  // The nearest hit along origin + s dir (dir unit) with s in (tNear, inf).
  ReferenceHit intersect(glm::vec3 origin, glm::vec3 dir, float tNear) const;

 private:
  struct Embree;
  std::unique_ptr<Embree> embree_;
  std::vector<glm::vec4> spheres_;  // xyz centre, w radius
};

// Whether p lies under the water's surface in the pool (`surface`: the
// surface alone, or none without water; `poolHalf`: half the pool's
// side): the line up from p meets it, cast a little in from the walls.
bool underTheWaterSurface(const ReferenceScene* surface, float poolHalf, glm::vec3 p);

}  // namespace tp::render
