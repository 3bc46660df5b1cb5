#include "viewer/water_pick.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tp::app {
namespace {

glm::dmat4 worldToClip(const scene::Camera& camera, uint32_t width, uint32_t height) {
  return glm::dmat4(camera.projection(float(width) / float(height))) * glm::dmat4(camera.view());
}

// The t range in which lo <= origin + t * direction <= hi on one axis,
// intersected with [enter, exit]; false when it is empty.
bool clipSlab(double origin, double direction, double lo, double hi, double& enter, double& exit) {
  if (direction == 0.0) return origin >= lo && origin <= hi;
  double t0 = (lo - origin) / direction, t1 = (hi - origin) / direction;
  if (t0 > t1) std::swap(t0, t1);
  enter = std::max(enter, t0);
  exit = std::min(exit, t1);
  return enter <= exit;
}

// The rest plane as a one-cell state's stand-in: a flat surface at u = 0.
const sim::WaterState kRestPlane{1, {0.0f}, {0.0f}};

}  // namespace

Ray pixelRay(const scene::Camera& camera, uint32_t width, uint32_t height, glm::dvec2 pixel) {
  const glm::dmat4 clipToWorld = glm::inverse(worldToClip(camera, width, height));
  const glm::dvec2 ndc(2.0 * pixel.x / width - 1.0, 2.0 * pixel.y / height - 1.0);
  const glm::dvec4 nearPoint = clipToWorld * glm::dvec4(ndc, 0.0, 1.0);
  const glm::dvec4 farPoint = clipToWorld * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 direction = glm::dvec3(farPoint) / farPoint.w - glm::dvec3(nearPoint) / nearPoint.w;
  return Ray{glm::dvec3(camera.position), glm::normalize(direction)};
}

glm::dvec2 worldToPixel(const scene::Camera& camera, uint32_t width, uint32_t height, glm::dvec3 point) {
  const glm::dvec4 clip = worldToClip(camera, width, height) * glm::dvec4(point, 1.0);
  return {(clip.x / clip.w + 1.0) * 0.5 * width, (clip.y / clip.w + 1.0) * 0.5 * height};
}

double waterHeightAt(const scene::Water& water, const sim::WaterState& state, double x, double z) {
  const int64_t n = state.n;
  auto u = [&](int64_t i, int64_t j) { return double(state.u[size_t(j * n + i)]); };
  if (n == 1) return double(water.level) + u(0, 0);
  const double h = double(water.extent) / double(n), corner = -0.5 * double(water.extent);
  const double last = double(n - 1);
  const double gx = std::clamp((x - corner) / h - 0.5, 0.0, last), gz = std::clamp((z - corner) / h - 0.5, 0.0, last);
  const int64_t i = std::min(int64_t(gx), n - 2), j = std::min(int64_t(gz), n - 2);
  const double fx = gx - double(i), fz = gz - double(j);
  // The two triangles of the quad, split along the diagonal from (i+1, j) to (i, j+1).
  const double height = fx + fz <= 1.0 ? u(i, j) + fx * (u(i + 1, j) - u(i, j)) + fz * (u(i, j + 1) - u(i, j))
                                       : u(i + 1, j + 1) + (1.0 - fx) * (u(i, j + 1) - u(i + 1, j + 1)) +
                                             (1.0 - fz) * (u(i + 1, j) - u(i + 1, j + 1));
  return double(water.level) + height;
}

std::optional<glm::dvec3> pickWater(const Ray& ray, const scene::Water& water, const sim::WaterState* state) {
  const sim::WaterState& surface = state != nullptr && state->n > 0 ? *state : kRestPlane;
  const auto [lowest, highest] = std::minmax_element(surface.u.begin(), surface.u.end());
  // The box the surface lies in: the square, and its heights widened by a
  // millimetre so that flat water's crossing lies inside the range sampled.
  constexpr double kMargin = 1e-3;
  const double half = 0.5 * double(water.extent);
  double enter = 0.0, exit = std::numeric_limits<double>::infinity();
  if (!clipSlab(ray.origin.x, ray.direction.x, -half, half, enter, exit) ||
      !clipSlab(ray.origin.z, ray.direction.z, -half, half, enter, exit) ||
      !clipSlab(ray.origin.y, ray.direction.y, double(water.level) + *lowest - kMargin,
                double(water.level) + *highest + kMargin, enter, exit)) {
    return std::nullopt;
  }
  auto above = [&](double t) {
    const glm::dvec3 p = ray.at(t);
    return p.y - waterHeightAt(water, surface, p.x, p.z);
  };
  auto hit = [&](double t) {
    const glm::dvec3 p = ray.at(t);
    return glm::dvec3(p.x, waterHeightAt(water, surface, p.x, p.z), p.z);
  };
  // Samples a quarter cell apart along the ray's horizontal path.
  const double cell = double(water.extent) / double(state != nullptr && state->n > 0 ? state->n : water.grid);
  const double across = (exit - enter) * glm::length(glm::dvec2(ray.direction.x, ray.direction.z));
  const int64_t samples = std::max<int64_t>(1, int64_t(std::ceil(across / (0.25 * cell))));
  double previous = enter;
  const double first = above(enter);
  if (first == 0.0) return hit(enter);
  const bool startsAbove = first > 0.0;
  for (int64_t k = 1; k <= samples; ++k) {
    const double t = k == samples ? exit : enter + (exit - enter) * double(k) / double(samples);
    const double f = above(t);
    if (f == 0.0) return hit(t);
    if ((f > 0.0) != startsAbove) {
      double lo = previous, hi = t;  // the ray is on its first side at lo, across at hi
      for (int iteration = 0; iteration < 200; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        ((above(mid) > 0.0) == startsAbove ? lo : hi) = mid;
      }
      return hit(std::abs(above(lo)) <= std::abs(above(hi)) ? lo : hi);
    }
    previous = t;
  }
  return std::nullopt;
}

std::optional<double> raySphere(const Ray& ray, glm::dvec3 center, double radius) {
  const glm::dvec3 offset = ray.origin - center;
  const double b = glm::dot(offset, ray.direction);
  const double c = glm::dot(offset, offset) - radius * radius;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  const double t = -b - root >= 0.0 ? -b - root : -b + root;
  if (t < 0.0) return std::nullopt;
  return t;
}

std::optional<SpherePick> pickSphere(const Ray& ray, std::span<const scene::Sphere> spheres) {
  std::optional<SpherePick> nearest;
  for (size_t index = 0; index < spheres.size(); ++index) {
    const auto t = raySphere(ray, glm::dvec3(spheres[index].center), double(spheres[index].radius));
    if (t && (!nearest || *t < nearest->t)) nearest = SpherePick{index, *t, ray.at(*t)};
  }
  return nearest;
}

std::optional<glm::dvec3> rayPlaneY(const Ray& ray, double y, double maxDistance) {
  if (ray.direction.y == 0.0) return std::nullopt;
  const double t = (y - ray.origin.y) / ray.direction.y;
  if (!(t >= 0.0 && t <= maxDistance)) return std::nullopt;
  glm::dvec3 point = ray.at(t);
  point.y = y;
  return point;
}

}  // namespace tp::app
