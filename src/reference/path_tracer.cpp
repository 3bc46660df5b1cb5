#include "reference/path_tracer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "reference/camera_rays.hpp"
#include "reference/environment_light.hpp"
#include "reference/path_bsdf.hpp"
#include "reference/path_sampler.hpp"
#include "reference/reference_caustics.hpp"
#include "reference/reference_scene.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/hammersley.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "shared/glass.h"
#include "shared/haze.h"
#include "shared/pool_trace.h"
#include "shared/shading.h"
#include "shared/water_scattering.h"

namespace tp::render {
namespace {

// Texels a side of the light-traced focusing of the sun under the waves:
// 1.6 cm in the default 4 m pool.
constexpr uint32_t kCausticsSize = 256;
// Russian roulette starts after this many bounces, and keeps a path with
// its throughput's largest channel as probability, at most this.
constexpr uint32_t kRouletteAfter = 3;
constexpr float kRouletteMaxKeep = 0.95f;
// The passes a render is cut into at most, for its progress and time budget.
constexpr uint32_t kMaxPasses = 32;

enum class Surface { Ground, PoolWalls, PoolFloor, Water, Box, GlassBox, Sphere, GlassSphere };
enum class Medium { Air, Water, Glass };

Surface surfaceOf(const std::string& meshName, bool glass) {
  if (meshName == "ground") return Surface::Ground;
  if (meshName == "pool_walls") return Surface::PoolWalls;
  if (meshName == "pool_floor") return Surface::PoolFloor;
  if (meshName == "water") return Surface::Water;
  if (meshName.rfind("box", 0) == 0) return glass ? Surface::GlassBox : Surface::Box;
  throw std::logic_error("path tracer: no material for mesh " + meshName);
}

// The power heuristic (exponent 2) weight of a strategy of density a
// against one of density b.
float powerHeuristic(float a, float b) {
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

float largest(glm::vec3 v) { return std::max({v.x, v.y, v.z}); }

// A direction drawn from Henyey-Greenstein's phase function about `forward`
// (cos = forward . result), for u uniform in the unit square.
glm::vec3 sampleHenyeyGreenstein(glm::vec3 forward, float g, glm::vec2 u) {
  float cosAngle;
  if (std::abs(g) < 1e-3f) {
    cosAngle = 1.0f - 2.0f * u.x;
  } else {
    const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u.x);
    cosAngle = std::clamp((1.0f + g * g - s * s) / (2.0f * g), -1.0f, 1.0f);
  }
  const float sinAngle = std::sqrt(std::max(0.0f, 1.0f - cosAngle * cosAngle));
  const float phi = glm::two_pi<float>() * u.y;
  glm::vec3 t, b;
  tangentFrame(forward, t, b);
  return glm::normalize(sinAngle * std::cos(phi) * t + sinAngle * std::sin(phi) * b + cosAngle * forward);
}

// What a path met: the surface, where, its normals (the geometric one
// facing the ray), its material.
struct PathHit {
  Surface surface = Surface::Ground;
  float distance = std::numeric_limits<float>::infinity();
  glm::vec3 position{0.0f};
  glm::vec3 geometric{0.0f};  // unit, facing the ray
  glm::vec3 shading{0.0f};    // unit, the water's and floor's interpolated normal; else the geometric
  int object = -1;            // the glass or opaque object's index
  bool hit() const { return std::isfinite(distance); }
};

// The state a path carries between its vertices for the combination of its
// light samples with its BSDF's directions.
struct PathState {
  bool diffuseSeen = false;                               // a vertex that sampled the lights has been met
  float lastPdf = 0.0f;                                   // the density its BSDF drew the path's direction with
  bool lastInWater = false;                               // it lay in the water (the sun then reached it by refraction)
  uint32_t specularSince = 0, waterRefractionsSince = 0;  // interfaces crossed or reflected off since
  uint32_t waterReflectionsSince = 0;                     // reflections off the water's surface from above since
};

class PathTracer {
 public:
  PathTracer(const scene::Scene& scene, const sim::WaterState* water, uint32_t frame, uint32_t maxBounces)
      : env_(scene),
        maxBounces_(maxBounces),
        hazeDistance_(scene.sky.hazeDistance),
        extinction_(scene.water.absorption + scene.water.scattering),
        scattering_(scene.water.scattering),
        anisotropy_(scene.water.scatteringAnisotropy),
        waterIor_(scene.water.ior),
        ground_(groundParams(scene)) {
    if (hasPool(scene)) {
      PoolModel pool = poolModel(scene);
      pool_ = pool.params;
      floorVertices_ = std::move(pool.floorVertices);
      poolHalf_ = 0.5f * scene.water.extent;
      level_ = scene.water.level;
    }
    const float time = float(frame) * scene.water.frameTime;
    const scene::Scene placed = scene::sceneAt(scene, time);
    std::optional<WaterToTheWalls> surface;
    if (water) surface = waterSurfaceToTheWalls(scene, *water);
    std::vector<scene::Mesh> traced;
    size_t boxes = 0;
    for (auto& mesh : sceneMeshes(scene, water, time)) {
      if (mesh.name.rfind("sphere", 0) == 0) continue;  // cast exactly instead of their tessellation
      const scene::Box* box = mesh.name.rfind("box", 0) == 0 ? &placed.boxes.at(boxes++) : nullptr;
      const Surface s = surfaceOf(mesh.name, box && scene::isGlass(*box));
      surfaces_.push_back(s);
      boxes_.push_back(box ? *box : scene::Box{});
      if (s == Surface::Water) {
        // The surface reaching the walls, as exported: no slot between it and them.
        waterMesh_ = int(traced.size());
        waterNormals_ = surface->normals;
        traced.push_back(surface->mesh);
        traced.back().name = mesh.name;
        continue;
      }
      traced.push_back(std::move(mesh));
    }
    spheres_ = placed.spheres;
    if (surface) {
      flatWater_ = std::all_of(surface->mesh.positions.begin(), surface->mesh.positions.end(),
                               [&](glm::vec3 v) { return std::abs(v.y - level_) <= kSurfaceOffset; });
      surfaceOnly_ =
          std::make_unique<ReferenceScene>(std::vector<scene::Mesh>{surface->mesh}, std::vector<scene::Sphere>{});
      if (env_.hasSun()) {
        CausticReceivers receivers;
        for (size_t m = 0; m < traced.size(); ++m) {
          const Surface s = surfaces_[m];
          if (s == Surface::PoolFloor || s == Surface::PoolWalls || s == Surface::Box)
            receivers.meshes.push_back(traced[m]);
        }
        for (const scene::Sphere& sphere : spheres_)
          if (!scene::isGlass(sphere)) receivers.spheres.push_back(sphere);
        caustics_ = traceCaustics(scene, surface->mesh, surface->normals, receivers, kCausticsSize);
        if (!flatWater_)
          reflections_ = traceReflectedCaustics(scene, surface->mesh, surface->normals, receivers, kCausticsSize);
      }
    }
    bvh_ = std::make_unique<ReferenceScene>(traced, spheres_);
    meshes_ = std::move(traced);
  }

  // The radiance reaching the camera along origin + s dir, starting in
  // `medium`; `first` receives the first surface met, if any.
  glm::vec3 cameraPath(glm::vec3 origin, glm::vec3 dir, Medium medium, PathSampler& sampler) const {
    glm::vec3 radiance(0.0f), throughput(1.0f);
    PathState state;
    std::optional<float> firstDistance;
    const bool inAirAtStart = medium == Medium::Air;
    const glm::vec3 eyeDir = dir;
    for (uint32_t bounce = 0; bounce <= maxBounces_; ++bounce) {
      const PathHit hit = intersect(origin, dir, medium);
      if (!firstDistance) firstDistance = hit.distance;
      if (medium == Medium::Water) {
        if (!hit.hit()) break;  // out of the pool's water through a crack: nothing to add
        if (scatters()) {
          const float mean = (extinction_.x + extinction_.y + extinction_.z) / 3.0f;
          const float s = -std::log1p(-sampler.uniform()) / mean;
          if (s < hit.distance) {
            throughput *= scattering_ * glm::exp(-extinction_ * s) / (mean * std::exp(-mean * s));
            origin += s * dir;
            const glm::vec3 wo = -dir;
            auto phase = [&](glm::vec3 toLight) {
              return shader::henyeyGreenstein(glm::dot(-toLight, -wo), anisotropy_);
            };
            auto response = [&](glm::vec3 toLight) { return glm::vec3(phase(toLight)); };
            radiance += throughput * (sunThroughWater(origin, sampler, response) +
                                      skyThroughWater(origin, sampler, response, phase));
            const glm::vec3 next = sampleHenyeyGreenstein(dir, anisotropy_, sampler.uniform2());
            state = PathState{true, shader::henyeyGreenstein(glm::dot(next, dir), anisotropy_), true, 0, 0, 0};
            dir = next;
            if (!roulette(bounce, throughput, sampler)) break;
            continue;
          }
          throughput *= glm::exp(-extinction_ * hit.distance) / std::exp(-mean * hit.distance);
        } else {
          throughput *= glm::exp(-extinction_ * hit.distance);
        }
      }
      if (!hit.hit()) {
        if (medium == Medium::Air) radiance += throughput * escaped(dir, state);
        break;
      }
      switch (hit.surface) {
        case Surface::Water:
          waterInterface(hit, origin, dir, medium, throughput, state, sampler);
          break;
        case Surface::GlassSphere:
        case Surface::GlassBox:
          glassInterface(hit, origin, dir, medium, throughput, state, sampler);
          break;
        default:
          if (!diffuseVertex(hit, origin, dir, medium, throughput, radiance, state, sampler)) bounce = maxBounces_;
          break;
      }
      if (!roulette(bounce, throughput, sampler)) break;
    }
    if (!inAirAtStart) return radiance;
    return seenThroughHaze(radiance, eyeDir, firstDistance.value_or(std::numeric_limits<float>::infinity()),
                           hazeDistance_, [&](glm::vec3 across) { return env_.sky(across) + env_.sun(across); });
  }

  // The surface at the end of the ray from `origin` (its position and
  // normal, for the AOVs), or nothing.
  std::optional<std::pair<glm::vec3, glm::vec3>> firstSurface(glm::vec3 origin, glm::vec3 dir, Medium medium) const {
    const PathHit hit = intersect(origin, dir, medium);
    if (!hit.hit()) return std::nullopt;
    glm::vec3 n = hit.shading;
    if (hit.surface == Surface::Water || hit.surface == Surface::GlassSphere || hit.surface == Surface::GlassBox) {
      n = hit.surface == Surface::Water ? (n.y < 0.0f ? -n : n) : outward(hit);
    }
    return std::make_pair(hit.position, n);
  }

 private:
  bool scatters() const { return shader::waterScatters(glm::vec4(scattering_, 0.0f)); }

  // The nearest surface along origin + s dir for a path in `medium`: inside
  // glass the water's surface through it is not there.
  PathHit intersect(glm::vec3 origin, glm::vec3 dir, Medium medium) const {
    float from = 0.0f;
    for (;;) {
      const ReferenceHit r = bvh_->intersect(origin, dir, from);
      if (!r.hit()) return PathHit{};
      if (medium == Medium::Glass && r.mesh == waterMesh_ && r.sphere < 0) {
        from = r.distance + kSurfaceOffset;
        continue;
      }
      return describe(r, origin, dir);
    }
  }

  PathHit describe(const ReferenceHit& r, glm::vec3 origin, glm::vec3 dir) const {
    PathHit h;
    h.distance = r.distance;
    h.position = origin + r.distance * dir;
    h.geometric = glm::dot(r.geometricNormal, dir) > 0.0f ? -r.geometricNormal : r.geometricNormal;
    h.shading = h.geometric;
    if (r.sphere >= 0) {
      h.object = r.sphere;
      h.surface = scene::isGlass(spheres_[size_t(r.sphere)]) ? Surface::GlassSphere : Surface::Sphere;
      return h;
    }
    h.surface = surfaces_[size_t(r.mesh)];
    h.object = r.mesh;
    if (h.surface == Surface::Water) {
      const uint32_t* corner = &meshes_[size_t(r.mesh)].indices[size_t(r.triangle) * 3];
      const glm::vec2 b = r.barycentric;
      h.shading = glm::normalize((1.0f - b.x - b.y) * waterNormals_[corner[0]] + b.x * waterNormals_[corner[1]] +
                                 b.y * waterNormals_[corner[2]]);
    } else if (h.surface == Surface::PoolFloor) {
      h.shading = shader::poolFloorMeshNormal(pool_, glm::vec2(h.position.x, h.position.z), floorVertices_.data());
    }
    if (glm::dot(h.shading, h.geometric) < 0.0f) h.shading = -h.shading;
    return h;
  }

  // A glass object's outward normal at the hit.
  glm::vec3 outward(const PathHit& h) const {
    if (h.surface == Surface::GlassSphere) return glm::normalize(h.position - spheres_[size_t(h.object)].center);
    const glm::vec3 centre = boxes_[size_t(h.object)].center;
    return glm::dot(h.geometric, h.position - centre) >= 0.0f ? h.geometric : -h.geometric;
  }

  bool underTheSurface(glm::vec3 p) const { return underTheWaterSurface(surfaceOnly_.get(), poolHalf_, p); }

  bool roulette(uint32_t bounce, glm::vec3& throughput, PathSampler& sampler) const {
    if (largest(throughput) <= 0.0f) return false;
    if (bounce < kRouletteAfter) return true;
    const float keep = std::min(largest(throughput), kRouletteMaxKeep);
    if (sampler.uniform() >= keep) return false;
    throughput /= keep;
    return true;
  }

  // The sky and sun along a direction a path left the scene by, weighted
  // against the light samples that could have found it.
  glm::vec3 escaped(glm::vec3 dir, const PathState& state) const {
    const glm::vec3 sky = env_.sky(dir), sun = env_.sun(dir);
    if (!state.diffuseSeen) return sky + sun;
    if (state.specularSince == 0) {
      // Straight from a vertex in the air, which sampled both.
      return sky * powerHeuristic(state.lastPdf, env_.skyPdf(dir)) + sun * powerHeuristic(state.lastPdf, env_.sunPdf());
    }
    // Out of the water by one refraction: the sun is sunThroughWater's, and
    // under flat water the sky skyThroughWater's too, weighed against it.
    if (state.lastInWater && state.specularSince == 1 && state.waterRefractionsSince == 1)
      return flatWater_ ? sky * powerHeuristic(state.lastPdf, skyPdfInWater(dir)) : sky;
    // Off the water by one reflection from the air: the sun is
    // sunMirroredByWater's, under flat water weighed against it.
    if (!state.lastInWater && state.specularSince == 1 && state.waterReflectionsSince == 1 &&
        (flatWater_ || reflections_))
      return sky + (flatWater_ ? sun * powerHeuristic(state.lastPdf, env_.sunPdf()) : glm::vec3(0.0f));
    return sky + sun;
  }

  // The index of refraction of a medium outside glass at p.
  float indexAt(Medium m) const { return m == Medium::Water ? waterIor_ : 1.0f; }

  // The water's surface: reflected or refracted by exact Fresnel, chosen by it.
  void waterInterface(const PathHit& hit, glm::vec3& origin, glm::vec3& dir, Medium& medium, glm::vec3& throughput,
                      PathState& state, PathSampler& sampler) const {
    const glm::vec3 up = hit.geometric.y < 0.0f ? -hit.geometric : hit.geometric;
    const bool fromAbove = glm::dot(dir, up) < 0.0f;
    const Medium before = fromAbove ? Medium::Air : Medium::Water;
    glm::vec3 n = hit.shading;  // facing the ray
    float cosI = -glm::dot(dir, n);
    if (cosI <= 0.0f) {  // an interpolated normal facing away: the flat triangle's
      n = hit.geometric;
      cosI = -glm::dot(dir, n);
    }
    const float n1 = fromAbove ? 1.0f : waterIor_, n2 = fromAbove ? waterIor_ : 1.0f;
    const float reflectance = shader::fresnelDielectric(cosI, n1, n2);
    const bool refracted = sampler.uniform() >= reflectance;
    dir = refracted ? glm::normalize(glm::refract(dir, n, n1 / n2)) : glm::normalize(glm::reflect(dir, n));
    const bool below = glm::dot(dir, up) < 0.0f;
    medium = below ? Medium::Water : Medium::Air;
    if (medium != before) {
      const float ratio = indexAt(before) / indexAt(medium);
      throughput *= ratio * ratio;
      if (refracted) ++state.waterRefractionsSince;
    } else if (fromAbove) {
      ++state.waterReflectionsSince;
    }
    ++state.specularSince;
    origin = hit.position + (below ? -kSurfaceOffset : kSurfaceOffset) * up;
  }

  // A glass sphere's or box's surface, met from outside or inside.
  void glassInterface(const PathHit& hit, glm::vec3& origin, glm::vec3& dir, Medium& medium, glm::vec3& throughput,
                      PathState& state, PathSampler& sampler) const {
    const glm::vec3 out = outward(hit);
    const bool entering = glm::dot(dir, out) < 0.0f;
    const Medium around = underTheSurface(hit.position) ? Medium::Water : Medium::Air;
    const float glassIor =
        hit.surface == Surface::GlassSphere ? spheres_[size_t(hit.object)].ior : boxes_[size_t(hit.object)].ior;
    const float n1 = entering ? indexAt(around) : glassIor, n2 = entering ? glassIor : indexAt(around);
    const glm::vec3 n = entering ? out : -out;
    const float cosI = std::max(-glm::dot(dir, n), 0.0f);
    const float reflectance = shader::fresnelDielectric(cosI, n1, n2);
    const bool refracted = sampler.uniform() >= reflectance;
    dir = refracted ? glm::normalize(glm::refract(dir, n, n1 / n2)) : glm::normalize(glm::reflect(dir, n));
    const bool inside = glm::dot(dir, out) < 0.0f;
    if (inside != !entering) throughput *= (n1 / n2) * (n1 / n2);
    medium = inside ? Medium::Glass : around;
    ++state.specularSince;
    origin = hit.position + (inside ? -kSurfaceOffset : kSurfaceOffset) * out;
  }

  // The opaque surface's material at a hit.
  SurfaceBsdf material(const PathHit& hit) const {
    const glm::vec2 xz(hit.position.x, hit.position.z);
    switch (hit.surface) {
      case Surface::Ground:
        return {shader::groundAlbedo(ground_, xz, glm::vec2(0.0f)), 0.0f, 0.5f};
      case Surface::PoolFloor:
        return {shader::groundAlbedo(pool_.tiles, xz, glm::vec2(0.0f)), 0.0f, 0.5f};
      case Surface::PoolWalls:
        return {shader::poolWallAlbedo(pool_, shader::poolWallCoordinates(pool_, hit.position, hit.geometric),
                                       glm::vec2(0.0f)),
                pool_.wallGloss.x, pool_.wallGloss.y};
      case Surface::Box:
        return {boxes_[size_t(hit.object)].albedo, 0.0f, 0.5f};
      case Surface::Sphere: {
        const scene::Sphere& s = spheres_[size_t(hit.object)];
        return {s.albedo, s.specular, s.roughness};
      }
      default:
        return {};
    }
  }

  // Whether anything lies on origin + s dir for s in (0, limit); the
  // water's surface too unless `throughWater`.
  bool blocked(glm::vec3 origin, glm::vec3 dir, float limit, bool throughWater) const {
    float from = 0.0f;
    for (;;) {
      const ReferenceHit r = bvh_->intersect(origin, dir, from);
      if (!r.hit() || r.distance >= limit) return false;
      if (!throughWater || r.mesh != waterMesh_ || r.sphere >= 0) return true;
      from = r.distance + kSurfaceOffset;
    }
  }

  // A light's sample `s` (its direction in the air) reaching p in the water
  // through the flat surface at the rest level: `response(toLight)` (the
  // BSDF times the cosine, or the phase function) times its radiance over
  // its density, Fresnel's transmission, its solid angle as the water
  // compresses it (cos in the air over cos in the water: the radiance's n^2
  // and the solid angle's 1 / n^2 cancel) and the absorption on the way
  // down; 0 where something is in the way. `toLight`: its direction in the water.
  template <typename Response>
  glm::vec3 refractedLight(glm::vec3 p, const LightSample& s, Response response, glm::vec3& toLight) const {
    if (s.pdf <= 0.0f || s.direction.y <= 0.0f) return glm::vec3(0.0f);
    toLight = -glm::refract(-s.direction, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / waterIor_);
    const glm::vec3 f = response(toLight);
    if (largest(f) <= 0.0f) return glm::vec3(0.0f);
    const float toSurface = std::max(level_ - p.y, 0.0f) / toLight.y;
    if (blocked(p, toLight, toSurface, true)) return glm::vec3(0.0f);
    if (blocked(p + toSurface * toLight, s.direction, std::numeric_limits<float>::infinity(), true))
      return glm::vec3(0.0f);
    const float transmitted = 1.0f - shader::fresnelDielectric(s.direction.y, 1.0f, waterIor_);
    return f * s.radiance / s.pdf * transmitted * (s.direction.y / toLight.y) * glm::exp(-extinction_ * toSurface);
  }

  // The sun at a point in the water: one point of its disc refracted down
  // to p, times the waves' focusing (caustics_).
  template <typename Response>
  glm::vec3 sunThroughWater(glm::vec3 p, PathSampler& sampler, Response response) const {
    if (!env_.hasSun()) return glm::vec3(0.0f);
    glm::vec3 toLight;
    const glm::vec3 light = refractedLight(p, env_.sampleSun(sampler.uniform2()), response, toLight);
    const float focus = caustics_ ? caustics_->at(shader::causticsLine(pool_, env_.sunDirection(), p)) : 1.0f;
    return light * focus;
  }

  // The sky at a point in the water under flat water: a direction drawn
  // from the sky's texels refracted down to p, weighed by the power
  // heuristic against the paths' own directions out by one refraction
  // (`pdf(toLight)`: their density). Nothing under waves, where those paths
  // alone find the sky.
  template <typename Response, typename Pdf>
  glm::vec3 skyThroughWater(glm::vec3 p, PathSampler& sampler, Response response, Pdf pdf) const {
    if (!flatWater_) return glm::vec3(0.0f);
    const LightSample s = env_.sampleSky(sampler.uniform2());
    glm::vec3 toLight;
    const glm::vec3 light = refractedLight(p, s, response, toLight);
    if (largest(light) <= 0.0f) return glm::vec3(0.0f);
    return light * powerHeuristic(skyPdfInWater(s.direction), pdf(toLight));
  }

  // The density per steradian of the water's directions with which
  // skyThroughWater draws the one that leaves the flat surface along `air`:
  // the sky's density times d omega_air / d omega_water = n^2 cos_water / cos_air.
  float skyPdfInWater(glm::vec3 air) const {
    if (air.y <= 0.0f) return 0.0f;
    const float sin2Water = (1.0f - air.y * air.y) / (waterIor_ * waterIor_);
    return env_.skyPdf(air) * waterIor_ * waterIor_ * std::sqrt(1.0f - sin2Water) / air.y;
  }

  // The sun mirrored by the water at p in the air: one point of its disc,
  // reflected where the line from p meets the rest level, times Fresnel's
  // reflectance there (the mirror keeps the disc's solid angle). Under
  // flat water it is weighed by the power heuristic against the paths that
  // reach the sun by that one reflection; under waves it is multiplied by
  // the waves' focusing (reflections_, light-traced) and those paths are
  // not counted. Without it those paths alone found it: the sun's image on
  // the walls above the water, a disc's worth of light drawn by a wide
  // lobe, was the truth's fireflies.
  glm::vec3 sunMirroredByWater(glm::vec3 p, const PathHit& hit, const SurfaceBsdf& m, glm::vec3 wo,
                               PathSampler& sampler) const {
    if ((!flatWater_ && !reflections_) || waterMesh_ < 0 || !env_.hasSun() || p.y <= level_) return glm::vec3(0.0f);
    const LightSample s = env_.sampleSun(sampler.uniform2());
    if (s.pdf <= 0.0f || s.direction.y <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 mirrored(s.direction.x, -s.direction.y, s.direction.z);
    if (glm::dot(mirrored, hit.geometric) <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 f = bsdfTimesCosine(m, hit.shading, wo, mirrored);
    if (largest(f) <= 0.0f) return glm::vec3(0.0f);
    const float toWater = (p.y - level_) / s.direction.y;
    const glm::vec3 onWater = p + toWater * mirrored;
    if (std::abs(onWater.x) >= poolHalf_ || std::abs(onWater.z) >= poolHalf_) return glm::vec3(0.0f);
    if (blocked(p, mirrored, toWater, true) ||
        blocked(onWater, s.direction, std::numeric_limits<float>::infinity(), true))
      return glm::vec3(0.0f);
    const float reflectance = shader::fresnelDielectric(s.direction.y, 1.0f, waterIor_);
    const glm::vec3 light = f * s.radiance / s.pdf * reflectance;
    if (flatWater_) return light * powerHeuristic(s.pdf, bsdfPdf(m, hit.shading, wo, mirrored));
    return light * reflections_->at(mirrorPoint(p, env_.sunDirection(), level_));
  }

  // A Lambertian or glossy surface: its light samples (in the air the sun,
  // the sun mirrored by the flat water and the sky, in the water the sun
  // through the surface), then a direction
  // from its BSDF. False ends the path.
  bool diffuseVertex(const PathHit& hit, glm::vec3& origin, glm::vec3& dir, Medium medium, glm::vec3& throughput,
                     glm::vec3& radiance, PathState& state, PathSampler& sampler) const {
    const SurfaceBsdf m = material(hit);
    const glm::vec3 wo = -dir, n = hit.shading;
    const glm::vec3 p = hit.position + kSurfaceOffset * hit.geometric;
    if (medium == Medium::Air) {
      if (env_.hasSun()) {
        const LightSample s = env_.sampleSun(sampler.uniform2());
        const glm::vec3 f = bsdfTimesCosine(m, n, wo, s.direction);
        if (largest(f) > 0.0f && glm::dot(s.direction, hit.geometric) > 0.0f &&
            !blocked(p, s.direction, std::numeric_limits<float>::infinity(), false))
          radiance += throughput * f * s.radiance / s.pdf * powerHeuristic(s.pdf, bsdfPdf(m, n, wo, s.direction));
      }
      radiance += throughput * sunMirroredByWater(p, hit, m, wo, sampler);
      const LightSample s = env_.sampleSky(sampler.uniform2());
      if (s.pdf > 0.0f) {
        const glm::vec3 f = bsdfTimesCosine(m, n, wo, s.direction);
        if (largest(f) > 0.0f && glm::dot(s.direction, hit.geometric) > 0.0f &&
            !blocked(p, s.direction, std::numeric_limits<float>::infinity(), false))
          radiance += throughput * f * s.radiance / s.pdf * powerHeuristic(s.pdf, bsdfPdf(m, n, wo, s.direction));
      }
    } else if (medium == Medium::Water) {
      auto response = [&](glm::vec3 toLight) {
        return glm::dot(toLight, hit.geometric) > 0.0f ? bsdfTimesCosine(m, n, wo, toLight) : glm::vec3(0.0f);
      };
      radiance += throughput * (sunThroughWater(p, sampler, response) +
                                skyThroughWater(p, sampler, response,
                                                [&](glm::vec3 toLight) { return bsdfPdf(m, n, wo, toLight); }));
    }
    const glm::vec2 u = sampler.uniform2();
    const BsdfSample b = sampleBsdf(m, n, wo, glm::vec3(u, sampler.uniform()));
    if (b.pdf <= 0.0f || glm::dot(b.wi, hit.geometric) <= 0.0f) return false;
    throughput *= b.weight;
    state = PathState{true, b.pdf, medium == Medium::Water, 0, 0, 0};
    origin = p;
    dir = b.wi;
    return true;
  }

  EnvironmentLight env_;
  uint32_t maxBounces_;
  float hazeDistance_;
  glm::vec3 extinction_, scattering_;
  float anisotropy_, waterIor_;
  shader::GroundParams ground_;
  shader::PoolParams pool_{};
  std::vector<glm::vec4> floorVertices_;
  float poolHalf_ = 0.0f, level_ = 0.0f;
  bool flatWater_ = false;  // the surface lies at its rest level everywhere
  std::vector<scene::Mesh> meshes_;
  std::vector<Surface> surfaces_;  // per mesh
  std::vector<scene::Box> boxes_;  // per mesh: its box where it is one
  std::vector<scene::Sphere> spheres_;
  int waterMesh_ = -1;
  std::vector<glm::vec3> waterNormals_;
  std::optional<CausticsMap> caustics_, reflections_;
  std::unique_ptr<ReferenceScene> surfaceOnly_, bvh_;
};

}  // namespace

PathTracedFrame renderPathTraced(const scene::Scene& scene, const sim::WaterState* water, uint32_t frame,
                                 uint32_t width, uint32_t height, const PathTracerOptions& options) {
  if (options.samples == 0) throw std::invalid_argument("path tracer: samples must be at least 1");
  const auto start = std::chrono::steady_clock::now();
  // Its camera alone: the path tracer takes no SH9 of the sky.
  const shader::FrameUniforms uniforms = frameUniforms(scene, SkyLight{}, width, height);
  const PathTracer tracer(scene, water, frame, options.maxBounces);
  const Medium cameraMediumNow = cameraMedium(scene, water).extinction.w > 0.0f ? Medium::Water : Medium::Air;
  const CameraRays rays(uniforms, scene.camera.position, width, height);

  PathTracedFrame out{emptyTracedFrame(uniforms, width, height), 0};
  RenderedFrame& f = out.frame;
  const size_t pixels = size_t(width) * height;
  std::vector<glm::dvec3> sum(pixels, glm::dvec3(0.0));

  const uint32_t passes = std::min(options.samples, kMaxPasses);
  uint32_t done = 0;
  for (uint32_t pass = 0; pass < passes; ++pass) {
    const uint32_t end = uint32_t(uint64_t(options.samples) * (pass + 1) / passes);
#pragma omp parallel for schedule(dynamic, 1)
    for (uint32_t y = 0; y < height; ++y) {
      for (uint32_t x = 0; x < width; ++x) {
        const size_t k = size_t(y) * width + x;
        for (uint32_t s = done; s < end; ++s) {
          PathSampler sampler(k, s, options.seed);
          const glm::vec2 point = sampler.uniform2();
          const CameraRay ray = rays.at(float(x) + point.x, float(y) + point.y);
          const glm::vec3 l = tracer.cameraPath(ray.origin, ray.direction, cameraMediumNow, sampler);
          if (std::isfinite(l.x) && std::isfinite(l.y) && std::isfinite(l.z)) sum[k] += glm::dvec3(l);
        }
      }
    }
    done = end;
    if (options.progress) options.progress(done, options.samples);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.timeBudgetSeconds > 0.0 && elapsed >= options.timeBudgetSeconds) break;
  }
  out.samples = done;
#pragma omp parallel for schedule(dynamic, 1)
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t k = size_t(y) * width + x;
      for (int c = 0; c < 3; ++c) f.rgba[k * 4 + c] = float(sum[k][c] / double(done));
      f.rgba[k * 4 + 3] = 1.0f;
      const CameraRay ray = rays.at(float(x) + 0.5f, float(y) + 0.5f);
      if (const auto first = tracer.firstSurface(ray.origin, ray.direction, cameraMediumNow)) {
        for (int c = 0; c < 3; ++c) {
          f.normal[k * 4 + c] = first->second[c];
          f.position[k * 4 + c] = first->first[c];
        }
        f.position[k * 4 + 3] = -(uniforms.view * glm::vec4(first->first, 1.0f)).z;
      }
    }
  }
  return out;
}

}  // namespace tp::render
