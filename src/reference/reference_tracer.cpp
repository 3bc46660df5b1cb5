#include "reference/reference_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <optional>
#include <stdexcept>

#include "reference/camera_rays.hpp"
#include "reference/glossy_quadrature.hpp"
#include "reference/pixel_rotation.hpp"
#include "reference/reference_caustics.hpp"
#include "reference/reference_scene.hpp"
#include "reference/row_progress.hpp"
#include "render/sky_image.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/glass_caustic.hpp"
#include "shading/glossy_model.hpp"
#include "shading/hammersley.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_light.hpp"
#include "shading/pool_model.hpp"
#include "shading/sky_model.hpp"
#include "shading/water_model.hpp"
#include "shared/glass.h"
#include "shared/glossy.h"
#include "shared/haze.h"
#include "shared/objects.h"
#include "shared/pool_light.h"
#include "shared/shading.h"
#include "shared/sky.h"
#include "shared/sun_shadow.h"
#include "shared/water_scattering.h"

namespace tp::render {
namespace {

// Texels a side of the light-traced caustics over the pool (reference_caustics):
// 1.6 cm in the default 4 m pool, a million photons.
constexpr uint32_t kReferenceCausticsSize = 256;

// The point of the sun's disc sample s of pixel `pixel` aims its shadow rays
// at: the base-3 and base-5 radical inverses (independent of the pixel's own
// points), turned by the pixel's rotation so that neighbouring pixels do not
// share their penumbra's pattern.
glm::vec2 sunSample(uint32_t s, size_t pixel) {
  const glm::vec2 turn = pixelRotation(pixel);
  return {wrapUnit(radicalInverseBase(s, 3) + turn.x), wrapUnit(radicalInverseBase(s, 5) + turn.y)};
}

// Where along a stretch of water sample s of pixel `pixel` takes the light
// scattered there, in [0, 1): the base-7 radical inverse, turned by an offset
// of the pixel's own (after the two of pixelRotation).
float scatterSample(uint32_t s, size_t pixel) {
  const uint32_t offset = hashPixel(hashPixel(hashPixel(uint32_t(pixel))));
  return wrapUnit(radicalInverseBase(s, 7) + unitFloat(offset));
}

// The numbers one path of a pixel's sample makes its choices by: the point of
// the sun's disc (the unit square's) its shadow rays aim at, and where along
// each stretch of water it gathers the scattered light.
struct PathSample {
  glm::vec2 sun{0.0f};
  float scatter = 0.5f;
};

enum class Material { Ground, PoolWalls, PoolFloor, Water, Box, Sphere };

Material materialOf(const std::string& meshName) {
  if (meshName == "ground") return Material::Ground;
  if (meshName == "pool_walls") return Material::PoolWalls;
  if (meshName == "pool_floor") return Material::PoolFloor;
  if (meshName == "water") return Material::Water;
  if (meshName.rfind("box", 0) == 0) return Material::Box;
  if (meshName.rfind("sphere", 0) == 0) return Material::Sphere;
  throw std::logic_error("reference: no material for mesh " + meshName);
}

// Unpolarised Fresnel reflectance for a ray meeting a surface at cosI, going
// from index n1 into n2; 1 under total internal reflection (cosT < 0 then).
float fresnel(float cosI, float n1, float n2, float& cosT) {
  const float eta = n1 / n2;
  const float sin2T = eta * eta * (1.0f - cosI * cosI);
  if (sin2T >= 1.0f) {
    cosT = -1.0f;
    return 1.0f;
  }
  cosT = std::sqrt(1.0f - sin2T);
  const float rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  const float rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
  return 0.5f * (rs * rs + rp * rp);
}

struct SurfacePoint {
  glm::vec3 position{std::numeric_limits<float>::infinity()};
  glm::vec3 normal{0.0f};
};

class Tracer {
 public:
  Tracer(const scene::Scene& scene, const sim::WaterState* water, uint32_t frame, const shader::FrameUniforms& uniforms,
         std::optional<SkyImage> skyImage, uint32_t maxSpecular)
      : uniforms_(uniforms),
        hazeDistance_(scene.sky.hazeDistance),
        shadows_(scene.render.shadows),
        sunRadius_(glm::radians(scene.sky.sunAngularRadiusDegrees)),
        sky_(skyParams(scene.sky)),
        skyImage_(std::move(skyImage)),
        ground_(groundParams(scene)),
        maxSpecular_(maxSpecular),
        extinction_(scene.water.absorption + scene.water.scattering),
        scattering_(scene.water.scattering),
        anisotropy_(scene.water.scatteringAnisotropy),
        ior_(scene.water.ior) {
    if (hasPool(scene)) {
      PoolModel pool = poolModel(scene);
      pool_ = pool.params;
      // The raster's baked light under the water, baked alike.
      PoolLight light = bakePoolLight(
          pool_, std::move(pool.floorVertices),
          [&](glm::vec3 d) { return skyImage_ ? skyImageRadiance(*skyImage_, d) : shader::skyRadiance(sky_, d, 0.0f); },
          PoolLightSun{glm::vec3(uniforms.sunDirection), glm::vec3(uniforms.sunIrradiance)}, opaqueBoxes(scene));
      floorVertices_ = std::move(light.floorAndLight);
      poolHalf_ = 0.5f * scene.water.extent;
      level_ = scene.water.level;
    }
    // The texels the glossy lobes integrate: the sky texture the raster's prefilter reads.
    if (hasGlossySurface(scene))
      glossySky_ = skyImage_ ? *skyImage_ : proceduralSkyImage(scene.sky, scene.sky.textureWidth);
    const float time = float(frame) * scene.water.frameTime;
    const scene::Scene placed = scene::sceneAt(scene, time);
    std::vector<scene::Mesh> traced;
    size_t boxes = 0;
    for (auto& mesh : sceneMeshes(scene, water, time)) {
      const Material m = materialOf(mesh.name);
      if (m == Material::Sphere) continue;  // cast exactly instead of their tessellation
      const scene::Box* box = m == Material::Box ? &placed.boxes.at(boxes++) : nullptr;
      if (box && scene::isGlass(*box)) {  // cast exactly, and traced through
        glassBoxes_.push_back(glassBoxParams(*box));
        continue;
      }
      materials_.push_back(m);
      albedo_.push_back(box ? box->albedo : glm::vec3(0.0f));
      if (m == Material::Water) waterMesh_ = int(traced.size());
      traced.push_back(std::move(mesh));
    }
    for (const scene::Sphere& sphere : placed.spheres) (scene::isGlass(sphere) ? glass_ : spheres_).push_back(sphere);
    casters_ = shadowCasters(scene, time);
    GlassTableCache().fill(scene, time, *glassTables_);
    if (water) waterNormals_ = waterVertexNormals(*water, scene.water.extent);
    if (water && scene.render.caustics) {
      CausticReceivers receivers{{}, spheres_};
      for (size_t m = 0; m < traced.size(); ++m) {
        if (materials_[m] == Material::PoolFloor || materials_[m] == Material::PoolWalls ||
            materials_[m] == Material::Box)
          receivers.meshes.push_back(traced[m]);
      }
      const WaterToTheWalls toTheWalls = waterSurfaceToTheWalls(scene, *water);
      caustics_ = traceCaustics(scene, toTheWalls.mesh, toTheWalls.normals, receivers, kReferenceCausticsSize);
      surfaceToTheWalls_ =
          std::make_unique<ReferenceScene>(std::vector<scene::Mesh>{toTheWalls.mesh}, std::vector<scene::Sphere>{});
    }
    bvh_ = std::make_unique<ReferenceScene>(traced, spheres_);
    tracedMeshes_ = std::move(traced);
  }

  // Radiance arriving at `origin` from direction -dir; `first` receives the
  // first surface. Under the water: what the surface met sends, attenuated,
  // and what the water on the way scatters towards `origin`. `skip`: the
  // glass sphere the ray leaves, which it does not meet again.
  glm::vec3 radiance(glm::vec3 origin, glm::vec3 dir, bool inWater, uint32_t specular, PathSample path,
                     SurfacePoint* first, const scene::Sphere* skip = nullptr) const {
    const ReferenceHit hit = bvh_->intersect(origin, dir, 0.0f);
    float distance = hit.hit() ? hit.distance : std::numeric_limits<float>::infinity();
    const scene::Sphere* glass = nullptr;
    for (const scene::Sphere& sphere : glass_) {
      const float s = shader::raySphere(origin, dir, glm::vec4(sphere.center, sphere.radius));
      if (&sphere != skip && s > 0.0f && s < distance) {
        distance = s;
        glass = &sphere;
      }
    }
    // A glass box: the slab test meets none that the ray starts in or on.
    std::optional<size_t> glassBox;
    glm::vec3 boxNormal(0.0f);
    for (size_t b = 0; b < glassBoxes_.size(); ++b) {
      const glm::vec4 met = shader::rayBox(origin, dir, glassBoxes_[b].center, glassBoxes_[b].halfSize);
      if (met.x > 0.0f && met.x < distance) {
        distance = met.x;
        glassBox = b;
        boxNormal = glm::vec3(met.y, met.z, met.w);
        glass = nullptr;
      }
    }
    if (!glass && !glassBox && !hit.hit()) return inWater ? glm::vec3(0.0f) : sky(dir);
    const glm::vec3 p = origin + distance * dir;
    const float outside = inWater ? ior_ : 1.0f;  // the index of the medium the ray is in
    const glm::vec3 leaving = glassBox ? glassBoxRadiance(*glassBox, boxNormal, p, dir, outside, specular, path, first)
                              : glass  ? glassRadiance(*glass, p, dir, outside, specular, path, first)
                                       : surfaceRadiance(p, dir, hit, specular, path, first);
    if (!inWater) return leaving;
    return glm::exp(-extinction_ * distance) * leaving + inScatter(origin, dir, distance, path);
  }

  // What the camera at `eye`, in the air, sees along dir through the haze
  // (shared/haze.h): `radiance` from the surface `first`, faded towards the
  // sky at the horizon; where no surface is, below the horizon, all haze.
  glm::vec3 throughHaze(glm::vec3 radiance, glm::vec3 eye, glm::vec3 dir, const SurfacePoint& first) const {
    const float distance =
        std::isfinite(first.position.x) ? glm::distance(first.position, eye) : std::numeric_limits<float>::infinity();
    return seenThroughHaze(radiance, dir, distance, hazeDistance_, [&](glm::vec3 across) { return sky(across); });
  }

 private:
  // Radiance leaving the surface `hit` at p towards -dir.
  glm::vec3 surfaceRadiance(glm::vec3 p, glm::vec3 dir, const ReferenceHit& hit, uint32_t specular, PathSample path,
                            SurfacePoint* first) const {
    if (hit.sphere >= 0) {
      const scene::Sphere& sphere = spheres_[size_t(hit.sphere)];
      const glm::vec3 n = glm::normalize(p - sphere.center);
      if (first) *first = {p, n};
      return glossy(
          sphere.albedo / glm::pi<float>() *
              shader::objectIrradiance(pool_, uniforms_, p, n, surfaceSun(p, path) * focus(p), floorVertices_.data()),
          dir, n, glm::vec2(sphere.specular, sphere.roughness));
    }
    const glm::vec2 xz(p.x, p.z);
    switch (materials_[size_t(hit.mesh)]) {
      case Material::Ground: {
        const glm::vec3 n(0.0f, 1.0f, 0.0f);
        if (first) *first = {p, n};
        return shader::groundRadiance(ground_, uniforms_, xz, glm::vec2(0.0f), n, surfaceSun(p, path));
      }
      case Material::PoolWalls: {
        const glm::vec3 n = glm::dot(hit.geometricNormal, dir) > 0.0f ? -hit.geometricNormal : hit.geometricNormal;
        if (first) *first = {p, n};
        return glossy(shader::poolWallRadiance(pool_, uniforms_, p, n, glm::vec2(0.0f), surfaceSun(p, path) * focus(p),
                                               floorVertices_.data()),
                      dir, n, glm::vec2(pool_.wallGloss));
      }
      case Material::PoolFloor: {
        const glm::vec3 n = shader::poolFloorMeshNormal(pool_, xz, floorVertices_.data());
        if (first) *first = {p, n};
        return shader::poolFloorRadiance(pool_, uniforms_, p, n, glm::vec2(0.0f), surfaceSun(p, path) * focus(p),
                                         floorVertices_.data());
      }
      case Material::Box: {
        const glm::vec3 n = glm::dot(hit.geometricNormal, dir) > 0.0f ? -hit.geometricNormal : hit.geometricNormal;
        if (first) *first = {p, n};
        return albedo_[size_t(hit.mesh)] / glm::pi<float>() *
               shader::objectIrradiance(pool_, uniforms_, p, n, surfaceSun(p, path) * focus(p), floorVertices_.data());
      }
      case Material::Water:
        return water(p, dir, hit, specular, path, first);
      case Material::Sphere:
        break;
    }
    return glm::vec3(0.0f);
  }

  // Whether anything but the water's surface meets origin + s dir for s in (0, limit).
  bool blocked(glm::vec3 origin, glm::vec3 dir, float limit) const {
    float from = kSurfaceOffset;
    for (;;) {
      const ReferenceHit hit = bvh_->intersect(origin, dir, from);
      if (!hit.hit() || hit.distance >= limit) return false;
      if (hit.mesh != waterMesh_ || hit.sphere >= 0) return true;
      from = hit.distance + kSurfaceOffset;  // through the surface: the flat water's bend is below
    }
  }

  // 1 where the shadow ray from p to the point `sample` of the sun's disc
  // (uniform over the disc) meets nothing, else 0: under the water in the
  // pool, bent as through flat water at its level (shared/sun_shadow.h's
  // model), traced against every mesh and sphere the camera sees.
  float sunShare(glm::vec3 p, glm::vec2 sample) const {
    if (!shadows_) return 1.0f;
    const glm::vec3 toSun(uniforms_.sunDirection);
    const glm::vec3 side = glm::normalize(
        glm::cross(toSun, std::abs(toSun.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f)));
    const glm::vec3 up = glm::cross(side, toSun);
    const float r = sunRadius_ * std::sqrt(sample.x), angle = glm::two_pi<float>() * sample.y;
    const glm::vec3 dir =
        glm::normalize(std::cos(r) * toSun + std::sin(r) * (std::cos(angle) * side + std::sin(angle) * up));
    if (dir.y <= 0.0f) return 0.0f;
    if (!inPoolWater(p)) return blocked(p, dir, std::numeric_limits<float>::infinity()) ? 0.0f : 1.0f;
    const glm::vec3 inWater = -glm::refract(-dir, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / ior_);
    const float toSurface = (level_ - p.y) / inWater.y;
    if (blocked(p, inWater, toSurface)) return 0.0f;
    return blocked(p + toSurface * inWater, dir, std::numeric_limits<float>::infinity()) ? 0.0f : 1.0f;
  }

  // The sun's share at a surface's point p: past the casters (sunShare),
  // times what the glass spheres in the air let through, from the raster's
  // tables (shared/sun_shadow.h's glassSunShare, shading/glass_caustic.hpp).
  float surfaceSun(glm::vec3 p, PathSample path) const {
    return sunShare(p, path.sun) * shader::glassSunShare(casters_, *glassTables_, p, glm::vec3(uniforms_.sunDirection));
  }

  // What the water on origin + s dir, 0 < s < length, scatters towards
  // origin: shared/water_scattering.h's model (the sun's beam entering
  // through the flat surface at the rest level, the pool's light around at
  // the segment's middle), sampled at one point per path, not integrated in
  // closed form, the sun's beam there passing a shadow ray (sunShare). The
  // point is drawn with a density proportional to the mean extinction's
  // attenuation along the segment.
  glm::vec3 inScatter(glm::vec3 origin, glm::vec3 dir, float length, PathSample path) const {
    if (!shader::waterScatters(glm::vec4(scattering_, 0.0f)) || !std::isfinite(length)) return glm::vec3(0.0f);
    const float mean = (extinction_.x + extinction_.y + extinction_.z) / 3.0f;  // > 0: it scatters
    const float reach = -std::expm1(-mean * length);                            // the share of [0, length) drawn from
    const float s = -std::log1p(-path.scatter * reach) / mean;
    const float density = mean * std::exp(-mean * s) / reach;
    const glm::vec3 x = origin + s * dir;
    const float depth = level_ - x.y;
    // The light around at the segment's middle, as the raster takes it.
    const glm::vec3 middle = origin + (0.5f * length) * dir;
    glm::vec3 light =
        shader::poolLightScattered(shader::poolLightAround(pool_, middle, floorVertices_.data()), dir, anisotropy_);
    const glm::vec3 toSun(uniforms_.sunDirection);
    if (toSun.y > 0.0f) {
      const glm::vec3 travel = glm::refract(-toSun, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / ior_);
      const float mu = -travel.y;
      light += shader::henyeyGreenstein(-glm::dot(travel, dir), anisotropy_) * glm::vec3(uniforms_.sunIrradiance) *
               (toSun.y / mu) * glm::exp(-extinction_ * (depth / mu)) * sunShare(x, path.sun);
    }
    return scattering_ * light * glm::exp(-extinction_ * s) / density;
  }

  // The sun's irradiance at p through the waves relative to flat water: the
  // light-traced caustics on p's light line, under the water's surface; 1
  // elsewhere or without caustics.
  float focus(glm::vec3 p) const {
    if (!caustics_ || !underTheSurface(p)) return 1.0f;
    return caustics_->at(shader::causticsLine(pool_, glm::vec3(uniforms_.sunDirection), p));
  }

  // Whether p lies in the pool under the water's surface: the line up from
  // it meets the surface reaching the walls, cast a little in from them so as
  // not to run along the mesh's edge. Above the water drawn down by a wave, in
  // the air, whatever the rest level.
  bool underTheSurface(glm::vec3 p) const { return underTheWaterSurface(surfaceToTheWalls_.get(), poolHalf_, p); }

  glm::vec3 sky(glm::vec3 dir) const {
    return skyImage_ ? skyImageRadiance(*skyImage_, dir) : shader::skyRadiance(sky_, dir, 1.0f);
  }

  // The light along glass's two rays, each by its weight (shared/glass.h).
  static glm::vec3 glassMix(const shader::GlassExit& g, glm::vec3 leaving, glm::vec3 reflected) {
    return shader::glassLeavingWeight(g) * leaving + g.reflectance * reflected;
  }

  // The glass model of shared/glass.h with the exact exit point, met by a
  // ray in a medium of index `outside`: the reflected ray and the ray
  // leaving the chord's far end traced on, in the water where they start
  // under its rest level in the pool (where the exit refracts into water).
  // Past the specular depth they look up the sky, as the raster's deepest
  // rays do.
  glm::vec3 glassRadiance(const scene::Sphere& glass, glm::vec3 p, glm::vec3 dir, float outside, uint32_t specular,
                          PathSample path, SurfacePoint* first) const {
    const glm::vec3 n = glm::normalize(p - glass.center);
    if (first) *first = {p, n};
    const shader::GlassExit g = shader::glassSphereExactExit(p, dir, n, glass.radius, glass.ior, outside, surround());
    if (specular >= maxSpecular_) return glassMix(g, sky(g.leaving), sky(g.reflected));
    auto follow = [&](glm::vec3 from, glm::vec3 d) {
      return radiance(from, d, inPoolWater(from), specular + 1, path, nullptr, &glass);
    };
    return glassMix(g, follow(g.exitPoint, g.leaving), follow(p, g.reflected));
  }

  // The same for glass box `b`, met at p on the face of outward normal n:
  // the exact path through it (shared/glass.h).
  glm::vec3 glassBoxRadiance(size_t b, glm::vec3 n, glm::vec3 p, glm::vec3 dir, float outside, uint32_t specular,
                             PathSample path, SurfacePoint* first) const {
    if (first) *first = {p, n};
    const shader::GlassExit g = shader::glassBoxPaths(p, dir, n, glassBoxes_[b].center, glassBoxes_[b].halfSize,
                                                      glassBoxes_[b].glass.x, outside, surround());
    if (specular >= maxSpecular_) return glassMix(g, sky(g.leaving), sky(g.reflected));
    auto follow = [&](glm::vec3 from, glm::vec3 d) {
      return radiance(from, d, inPoolWater(from), specular + 1, path, nullptr);
    };
    return glassMix(g, follow(g.exitPoint, g.leaving), follow(p, g.reflected));
  }

  // What lies round glass: the pool's water below its rest level, the air.
  shader::GlassSurround surround() const { return {level_, waterMesh_ >= 0 ? poolHalf_ : 0.0f, ior_}; }

  // Whether p lies in the pool's water, below its rest level.
  bool inPoolWater(glm::vec3 p) const {
    return waterMesh_ >= 0 && p.y < level_ && std::max(std::abs(p.x), std::abs(p.z)) <= poolHalf_;
  }

  // A surface's radiance with its glossy lobe (material: specular, roughness)
  // about the mirror direction of `dir` in n: G exactly, by quadrature.
  glm::vec3 glossy(glm::vec3 diffuse, glm::vec3 dir, glm::vec3 n, glm::vec2 material) const {
    if (material.x <= 0.0f) return diffuse;
    const glm::dvec3 g =
        GlossyQuadrature(*glossySky_).radiance(glm::reflect(dir, n), shader::glossyExponent(material.y));
    return shader::glossyMix(diffuse, glm::vec3(g), material.x);
  }

  // Both branches at the surface, weighted by the exact Fresnel reflectance.
  glm::vec3 water(glm::vec3 p, glm::vec3 dir, const ReferenceHit& hit, uint32_t specular, PathSample path,
                  SurfacePoint* first) const {
    const scene::Mesh& mesh = tracedMeshes_[size_t(waterMesh_)];
    const uint32_t* corner = &mesh.indices[size_t(hit.triangle) * 3];
    const glm::vec2 b = hit.barycentric;
    const glm::vec3 shading = glm::normalize((1.0f - b.x - b.y) * waterNormals_[corner[0]] +
                                             b.x * waterNormals_[corner[1]] + b.y * waterNormals_[corner[2]]);
    if (first) *first = {p, shading};
    if (specular >= maxSpecular_) return glm::vec3(0.0f);
    const glm::vec3 up = hit.geometricNormal.y < 0.0f ? -hit.geometricNormal : hit.geometricNormal;
    const bool fromAbove = glm::dot(dir, up) < 0.0f;
    glm::vec3 n = fromAbove ? shading : -shading;  // facing the ray
    float cosI = -glm::dot(dir, n);
    if (cosI <= 0.0f) {  // an interpolated normal facing away: fall back to the flat triangle's
      n = fromAbove ? up : -up;
      cosI = -glm::dot(dir, n);
    }
    float cosT = 0.0f;
    const float n1 = fromAbove ? 1.0f : ior_, n2 = fromAbove ? ior_ : 1.0f;
    const float reflectance = fresnel(cosI, n1, n2, cosT);
    auto follow = [&](glm::vec3 d) {
      const bool below = glm::dot(d, up) < 0.0f;
      const glm::vec3 start = p + (below ? -kSurfaceOffset : kSurfaceOffset) * up;
      return radiance(start, d, below, specular + 1, path, nullptr);
    };
    glm::vec3 result = reflectance * follow(glm::normalize(dir + 2.0f * cosI * n));
    if (reflectance < 1.0f) {
      const float eta = n1 / n2;
      // Radiance crossing scales by (n1 / n2)^2, as the raster's surface scales it.
      result += (1.0f - reflectance) * eta * eta * follow(glm::normalize(eta * dir + (eta * cosI - cosT) * n));
    }
    return result;
  }

  shader::FrameUniforms uniforms_;
  float hazeDistance_;     // sky.haze_distance: 0, clear air
  bool shadows_;           // render.shadows
  float sunRadius_;        // radians
  float poolHalf_ = 0.0f;  // half the pool's side
  float level_ = 0.0f;     // the water's rest level
  shader::SkyParams sky_;
  std::optional<SkyImage> skyImage_;
  std::optional<SkyImage> glossySky_;  // with glossy surfaces: the sky's texels
  shader::GroundParams ground_;
  shader::PoolParams pool_{};
  std::vector<glm::vec4> floorVertices_;  // the floor mesh's normals and heights, then the baked light
  uint32_t maxSpecular_;
  glm::vec3 extinction_;  // absorption plus scattering, 1/m
  glm::vec3 scattering_;  // 1/m
  float anisotropy_;      // Henyey-Greenstein g
  float ior_;
  std::vector<scene::Mesh> tracedMeshes_;
  std::vector<Material> materials_;
  std::vector<glm::vec3> albedo_;  // per traced mesh: the boxes'; unused for the others
  int waterMesh_ = -1;
  std::vector<glm::vec3> waterNormals_;
  std::optional<CausticsMap> caustics_;                // render.caustics: the floor's sun through the waves
  std::unique_ptr<ReferenceScene> surfaceToTheWalls_;  // with caustics: the water reaching the walls
  std::vector<scene::Sphere> spheres_;                 // the Lambertian ones, where they are at the frame's time
  std::vector<scene::Sphere> glass_;                   // the glass ones
  std::vector<shader::GlassBoxParams> glassBoxes_;     // the glass boxes, cast exactly
  shader::ShadowCasters casters_{};                    // the raster's, for its glass spheres' tables
  std::unique_ptr<shader::GlassTables> glassTables_ = std::make_unique<shader::GlassTables>();
  std::unique_ptr<ReferenceScene> bvh_;
};

}  // namespace

RenderedFrame renderReference(const scene::Scene& scene, const sim::WaterState* water, uint32_t frame, uint32_t width,
                              uint32_t height, const ReferenceOptions& options) {
  if (options.samples == 0) throw std::invalid_argument("reference samples must be at least 1");
  std::optional<SkyImage> skyImage;
  if (!scene.sky.image.empty()) skyImage = loadSkyImage(scene.sky);
  const shader::SkyParams sky = skyParams(scene.sky);
  const SkyLight light =
      sceneLight(scene, [&](glm::vec3 d) { return skyRadianceWithout(sky, skyImage ? &*skyImage : nullptr, d); });
  const shader::FrameUniforms uniforms = frameUniforms(scene, light, width, height);
  const Tracer tracer(scene, water, frame, uniforms, std::move(skyImage), options.maxSpecular);
  // Camera rays start in the water when the camera is under the surface.
  const bool cameraInWater = cameraMedium(scene, water).extinction.w > 0.0f;

  RenderedFrame out = emptyTracedFrame(uniforms, width, height);

  const glm::vec3 eye = scene.camera.position;
  const CameraRays rays(uniforms, eye, width, height);
  auto cameraRay = [&](float px, float py, glm::vec3& origin, glm::vec3& dir) {
    const CameraRay ray = rays.at(px, py);
    origin = ray.origin;
    dir = ray.direction;
  };
  RowProgress progress(height, options.progress);
#pragma omp parallel for schedule(dynamic, 1)
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t k = size_t(y) * width + x;
      glm::vec3 origin, dir, sum(0.0f);
      for (uint32_t s = 0; s < options.samples; ++s) {
        const glm::vec2 point = pixelSamplePoint(s, options.samples);
        cameraRay(float(x) + point.x, float(y) + point.y, origin, dir);
        SurfacePoint met;
        const glm::vec3 seen =
            tracer.radiance(origin, dir, cameraInWater, 0, {sunSample(s, k), scatterSample(s, k)}, &met);
        sum += cameraInWater ? seen : tracer.throughHaze(seen, eye, dir, met);
      }
      const glm::vec3 color = sum / float(options.samples);
      SurfacePoint first;
      cameraRay(float(x) + 0.5f, float(y) + 0.5f, origin, dir);
      tracer.radiance(origin, dir, cameraInWater, options.maxSpecular, PathSample{},
                      &first);  // no branches: the surface alone
      for (int c = 0; c < 3; ++c) {
        out.rgba[k * 4 + c] = color[c];
        out.normal[k * 4 + c] = first.normal[c];
        out.position[k * 4 + c] = first.position[c];
      }
      out.rgba[k * 4 + 3] = 1.0f;
      if (std::isfinite(first.position.x))
        out.position[k * 4 + 3] = -(uniforms.view * glm::vec4(first.position, 1.0f)).z;
    }
    progress.rowDone();
  }
  return out;
}

}  // namespace tp::render
