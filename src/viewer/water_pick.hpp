#pragma once
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <span>

#include "scene/camera.hpp"
#include "scene/scene.hpp"
#include "sim/water_state.hpp"

namespace tp::app {

// A ray in world space, in double precision: origin + t * direction, t >= 0,
// direction of unit length.
struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
  glm::dvec3 at(double t) const { return origin + t * direction; }
};

// The ray from the camera's position through a point of a width x height
// frame, in pixels from the frame's top-left corner (pixel (i, j) covers
// [i, i+1] x [j, j+1]: its centre is (i + 1/2, j + 1/2)), through
// Camera::view() and projection(width / height) inverted: Vulkan's clip y
// points down the image, as the frame's rows do.
Ray pixelRay(const scene::Camera& camera, uint32_t width, uint32_t height, glm::dvec2 pixel);

// Where a world point lands in the frame, in the pixels pixelRay takes (no
// check that it is in front of the camera or inside the frame).
glm::dvec2 worldToPixel(const scene::Camera& camera, uint32_t width, uint32_t height, glm::dvec3 point);

// The ray's first crossing of the water's surface, inside the water's square
// (|x|, |z| < extent / 2, centred on the origin), from whichever side the
// ray starts on. The surface is the one the renderer draws: y = level + u,
// u interpolated linearly on the two triangles of each quad of cell centres
// ((i + 1/2) h - extent/2, (j + 1/2) h - extent/2) (render/water_model's
// waterGridIndices: the diagonal from (i+1, j) to (i, j+1)), and held at the
// edge cells' heights in the half cell between the outer centres and the
// walls (as the shaders' gridQuadAt clamps). Without a state (null, or
// n == 0) the surface is the rest plane y = level. None when the ray misses
// the square or never crosses the surface inside it.
//
// It samples the height along the ray every quarter cell and bisects the
// first interval where the ray changes side, to double round-off; the point
// returned has the surface's height at the hit's x and z. A ray that grazes
// a crest thinner than a quarter cell between two samples passes it.
std::optional<glm::dvec3> pickWater(const Ray& ray, const scene::Water& water, const sim::WaterState* state);

// The water's height y = level + u at world (x, z), as pickWater sees it.
double waterHeightAt(const scene::Water& water, const sim::WaterState& state, double x, double z);

// The nearest t >= 0 at which the ray meets the sphere (its far side when
// the origin is inside), or none.
std::optional<double> raySphere(const Ray& ray, glm::dvec3 center, double radius);

// The sphere the ray meets first, and where.
struct SpherePick {
  size_t index = 0;
  double t = 0.0;
  glm::dvec3 point{0.0};
};
std::optional<SpherePick> pickSphere(const Ray& ray, std::span<const scene::Sphere> spheres);

// Where the ray meets the horizontal plane at height y, no farther than
// maxDistance along it; none for a ray parallel to the plane or pointing away.
std::optional<glm::dvec3> rayPlaneY(const Ray& ray, double y, double maxDistance);

}  // namespace tp::app
