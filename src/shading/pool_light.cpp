#include "shading/pool_light.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <optional>
#include <thread>

#include "shading/hammersley.hpp"
#include "shared/noise.h"
#include "shared/objects.h"
#include "shared/pool_light.h"

namespace tp::render {
namespace {

// The sky straight through the window is summed over the upper hemisphere
// cut in equal solid angles: this many bands of the cosine from the zenith,
// and of azimuth (SkyBins); each holds the sky's mean over kSkySubsamples^2
// points, so that a bright blob smaller than a bin still brings its light.
// A bin is hidden (by a wall, a box) or not as its centre is: at 16 x 64
// bins a box in the air over a texel took 2.1% too little of its light
// (PoolLight.ABoxInTheAirHidesTheSkyItStandsBefore), at 32 x 128 0.01%.
constexpr uint32_t kSkyBands = 32, kSkyAzimuths = 128, kSkySubsamples = 2;
// Cosine-weighted directions from each texel for the light that comes
// back: the same Hammersley set for every texel, so that the error varies
// smoothly from texel to texel rather than as noise.
constexpr uint32_t kDirections = 128;
// Diffuse bounces after the texel's own at most; each keeps at most the
// surfaces' albedo (0.6-0.7 in the scenes), so what is left past them is
// under 1% of the light.
constexpr uint32_t kBounces = 8;
// A path whose throughput falls under this has nothing left to bring.
constexpr float kNegligible = 1e-3f;
// How far a continued ray starts off the surface it leaves, in metres.
constexpr float kOffset = 1e-4f;
// How far above the floor's mesh a wall texel's point is taken where the
// floor rises over it: the texel is read by the floor's edge.
constexpr float kAboveFloor = 0.02f;

// What the bake's paths lose on their way through the water: its absorption
// alone. Light the water scatters out of a path is not lost but turned, and
// stays in the pool's light (what the one-scatter model of
// shared/water_scattering.h leaves out); with the whole extinction the
// frame under the surface of scenes/underwater.json was 19% and 25% darker
// than the path-traced truth's in green and blue (docs/pool-light.md).
glm::vec3 absorption(const shader::PoolParams& pool) { return glm::vec3(pool.extinction) - glm::vec3(pool.scattering); }

class PoolLightBake {
 public:
  PoolLightBake(const shader::PoolParams& pool, const std::vector<glm::vec4>& floorVertices, const SkyRadiance& sky,
                const PoolLightSun& sun, const std::vector<shader::BoxParams>& boxes)
      : pool_(pool),
        vertices_(floorVertices.data()),
        sky_(sky),
        skyBins_(sky, kSkyBands, kSkyAzimuths, kSkySubsamples),
        sun_(sun),
        boxes_(boxes) {
    frame_.sunDirection = glm::vec4(sun.direction, 0.0f);
    frame_.sunIrradiance = glm::vec4(sun.irradiance, 0.0f);
    ior_ = pool.water.y;
    level_ = pool.water.x;
    absorption_ = absorption(pool);
    for (const shader::BoxParams& b : boxes_)
      for (const glm::vec3& n : boxFaceNormals(b)) boxFaceLight_.push_back(openIrradiance(n));
  }

  // The irradiance at texel k (shared/pool_light.h's order).
  glm::vec3 texel(uint32_t k) const {
    glm::vec3 p, n;
    texelPoint(k, p, n);
    p += kOffset * n;
    glm::vec3 sum(0.0f);
    for (uint32_t i = 0; i < kDirections; ++i) {
      const glm::vec3 d = cosineAbout(n, hammersley(i, kDirections));
      sum += incoming(p, d, shader::hashUint(k * kDirections + i));
    }
    return window(p, n) + sum * (glm::pi<float>() / float(kDirections));
  }

  // The irradiance at the dry band's texel k (counted from its first), but
  // the sun's own arrival: the sky over the rim and the sky and the sun the
  // flat water mirrors, summed over the sky's bins; the rest by the texel's
  // directions: the other walls above the water, lit by the sun and by the
  // dry band's light the buffer holds (the pass before's; none in the
  // first), and the pool's light through the surface.
  glm::vec3 dryTexel(uint32_t k) const {
    glm::vec3 p, n;
    dryTexelPoint(k, p, n);
    p += kOffset * n;
    glm::vec3 sum(0.0f);
    for (const SkyBins::Bin& bin : skyBins_.bins()) {
      if (glm::dot(n, bin.direction) > 0.0f && seesTheSky(p, bin.direction))
        sum += bin.light * glm::dot(n, bin.direction);
      sum += bin.light * mirrored(p, n, bin.direction);
    }
    if (sun_.direction.y > 0.0f) sum += sun_.irradiance * mirrored(p, n, sun_.direction);
    glm::vec3 rest(0.0f);
    for (uint32_t i = 0; i < kDirections; ++i) {
      const glm::vec3 d = cosineAbout(n, hammersley(i, kDirections));
      rest += fromTheAir(p, d, shader::hashUint((TP_POOL_LIGHT_DRY_START + k) * kDirections + i));
    }
    return sum + rest * (glm::pi<float>() / float(kDirections));
  }

  // How far along d from o the water's surface is, from below (1e30 going
  // down).
  float toSurface(glm::vec3 o, glm::vec3 d) const { return d.y > 0.0f ? (level_ - o.y) / d.y : 1e30f; }

  // What the water takes from the bake's paths per metre (::absorption).
  glm::vec3 waterAbsorption() const { return absorption_; }

  // A ray from o along d meeting the surface's underside `distance` on:
  // absorbed on the way, the sky through Snell's window added to `radiance`
  // (n^2 its radiance times Fresnel's transmission; the wall above the
  // water's where the line out meets it) when `withSky`, and turned down, the reflected share
  // (all of it outside the window) left in `throughput`.
  void underside(glm::vec3& o, glm::vec3& d, float distance, glm::vec3& throughput, glm::vec3& radiance,
                 bool withSky) const {
    throughput *= glm::exp(-absorption_ * distance);
    const glm::vec3 q = o + distance * d;
    const float reflected = shader::fresnelDielectric(d.y, ior_, 1.0f);
    if (withSky && reflected < 1.0f) {
      const glm::vec3 air = glm::refract(d, glm::vec3(0.0f, -1.0f, 0.0f), ior_);
      const std::optional<glm::vec3> met = metAbove(q, air);
      radiance += throughput * ((1.0f - reflected) * ior_ * ior_) * (met ? *met : sky_(air));
    }
    throughput *= reflected;
    d.y = -d.y;
    o = q - glm::vec3(0.0f, kOffset, 0.0f);
  }

  // The albedo of the floor or wall `hit` at p.
  glm::vec3 albedo(const shader::PoolHit& hit, glm::vec3 p) const {
    return hit.floor
               ? shader::groundAlbedo(pool_.tiles, glm::vec2(p.x, p.z), glm::vec2(0.0f))
               : shader::poolWallAlbedo(pool_, shader::poolWallCoordinates(pool_, p, hit.normal), glm::vec2(0.0f));
  }

  // Whether a ray leaving the water's surface at q along `air` (upwards)
  // clears the walls above the water: the sky, not the pool's own rim.
  bool clearsTheRim(glm::vec3 q, glm::vec3 air) const {
    const glm::vec2 walls = shader::poolWallDistances(pool_, q, air);
    return q.y + std::min(walls.x, walls.y) * air.y >= pool_.box.y;
  }

  // Whether a line in the air from q along `air` (upwards) reaches the sky:
  // it clears the rim and meets no box.
  bool seesTheSky(glm::vec3 q, glm::vec3 air) const {
    return clearsTheRim(q, air) && nearestBox(q, air, 1e30f).index < 0;
  }

  // Whether the sun reaches p under the water through the flat surface:
  // its refracted line up to the surface meets no wall, nor does its line
  // on in the air.
  bool sunReaches(glm::vec3 p) const {
    const glm::vec3 toSun = sun_.direction;
    if (toSun.y <= 0.0f) return false;
    return seesOut(p, refractedUp(toSun), toSun) >= 0.0f;
  }

  // The line in the water that leaves the flat surface along `air`.
  glm::vec3 refractedUp(glm::vec3 air) const { return -glm::refract(-air, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / ior_); }

  // How far p is from the surface along `up` (in the water, rising) when
  // that line meets no wall and its way on along `air` clears the rim;
  // -1 when the pool hides the sky that way.
  float seesOut(glm::vec3 p, glm::vec3 up, glm::vec3 air) const {
    const float toSurface = reachesTheSurface(p, up);
    if (toSurface < 0.0f) return -1.0f;
    const glm::vec3 q = p + toSurface * up;
    if (!seesTheSky(q, air)) return -1.0f;
    return toSurface;
  }

  // How far p is from the surface along `up` (in the water, rising) when
  // that line meets no wall and no box on the way; -1 when it does.
  float reachesTheSurface(glm::vec3 p, glm::vec3 up) const {
    const float toSurface = (level_ - p.y) / up.y;
    const glm::vec2 walls = shader::poolWallDistances(pool_, p, up);
    if (std::min(walls.x, walls.y) < toSurface || nearestBox(p, up, toSurface).index >= 0) return -1.0f;
    return toSurface;
  }

  // The sun's irradiance at p with normal n through the flat surface, where
  // it reaches (sunReaches).
  glm::vec3 sunThroughFlatWater(glm::vec3 p, glm::vec3 n) const {
    return shader::sunThroughFlatWater(pool_, frame_, p, n);
  }

 private:
  // The sky straight through the flat surface onto p with normal n: over
  // the air's directions, Fresnel's transmission, the absorption along the
  // refracted line, and the solid angle the water compresses (cos in the
  // air over cos in the water; the radiance's n^2 and the solid angle's
  // 1 / n^2 cancel), where the line clears the walls under the water; the
  // walls above it where the line out meets them.
  glm::vec3 window(glm::vec3 p, glm::vec3 n) const {
    glm::vec3 sum(0.0f);
    for (const SkyBins::Bin& bin : skyBins_.bins()) {
      const glm::vec3 up = refractedUp(bin.direction);
      const float facing = glm::dot(n, up);
      if (facing <= 0.0f) continue;
      const float toSurface = reachesTheSurface(p, up);
      // A wall or a box under the water: its light is incoming()'s.
      if (toSurface < 0.0f) continue;
      const std::optional<glm::vec3> met = metAbove(p + toSurface * up, bin.direction);
      const glm::vec3 light = met ? binSolidAngle_ * *met : bin.light;
      const float transmitted = 1.0f - shader::fresnelDielectric(bin.direction.y, 1.0f, ior_);
      sum += light * (transmitted * bin.direction.y * facing / up.y) * glm::exp(-absorption_ * toSurface);
    }
    return sum;
  }

  // The share of light arriving along -`toLight` that the flat water
  // mirrors onto p (above it) with normal n, times the cosine there: Fresnel's
  // reflectance where the mirrored line meets the water before a wall and
  // leaves it clear of the rim.
  float mirrored(glm::vec3 p, glm::vec3 n, glm::vec3 toLight) const {
    const glm::vec3 down(toLight.x, -toLight.y, toLight.z);
    const float facing = glm::dot(n, down);
    if (facing <= 0.0f || toLight.y <= 0.0f) return 0.0f;
    const float s = (p.y - level_) / toLight.y;
    const glm::vec2 walls = shader::poolWallDistances(pool_, p, down);
    if (std::min(walls.x, walls.y) < s || nearestBox(p, down, s).index >= 0 || !seesTheSky(p + s * down, toLight))
      return 0.0f;
    return shader::fresnelDielectric(toLight.y, 1.0f, ior_) * facing;
  }

  // The light of the wall above the water that a ray in the air from o
  // along d meets `distance` on, inward normal `normal`: its albedo over pi
  // times the sun where it reaches and the dry band's light the buffer
  // holds (the pass before's; none before their first).
  glm::vec3 dryWall(glm::vec3 o, glm::vec3 d, float distance, glm::vec3 normal) const {
    const glm::vec3 w = o + distance * d + kOffset * normal;
    glm::vec3 e(0.0f);
    if (glm::dot(normal, sun_.direction) > 0.0f && seesTheSky(w, sun_.direction))
      e += sun_.irradiance * glm::dot(normal, sun_.direction);
    e += shader::poolLightDryAt(pool_, w, normal, vertices_);
    return albedo(shader::PoolHit{distance, w, normal, false}, w) / glm::pi<float>() * e;
  }

  // The light of what a ray leaving the water's surface at q along `air`
  // meets before the sky: a wall above the water short of the rim
  // (dryWall's), or a box (boxInTheAir); none where it sees the sky.
  std::optional<glm::vec3> metAbove(glm::vec3 q, glm::vec3 air) const {
    const glm::vec2 walls = shader::poolWallDistances(pool_, q, air);
    const float wall = std::min(walls.x, walls.y);
    const bool belowTheRim = q.y + wall * air.y < pool_.box.y;
    const BoxHit box = nearestBox(q, air, belowTheRim ? wall : 1e30f);
    if (box.index >= 0) return boxInTheAir(box);
    if (belowTheRim) return dryWall(q, air, wall, shader::poolWallNormal(walls, air));
    return std::nullopt;
  }

  // The nearest of the boxes along o + s d short of `limit`: index -1 where
  // none is met.
  struct BoxHit {
    int index = -1;
    float distance = 0.0f;
    glm::vec3 normal{0.0f};  // outward
  };
  BoxHit nearestBox(glm::vec3 o, glm::vec3 d, float limit) const {
    BoxHit nearest;
    for (size_t k = 0; k < boxes_.size(); ++k) {
      const glm::vec4 hit = shader::rayBox(o, d, boxes_[k].center, boxes_[k].halfSize);
      if (hit.x > 0.0f && hit.x < limit) {
        limit = hit.x;
        nearest = {int(k), hit.x, glm::vec3(hit.y, hit.z, hit.w)};
      }
    }
    return nearest;
  }

  // The radiance of a box in the air: its albedo over pi times the sun on
  // its face and the open sky's irradiance there (boxFaceLight_), its
  // shadows and the ground's light left out.
  glm::vec3 boxInTheAir(const BoxHit& hit) const {
    const shader::BoxParams& b = boxes_[size_t(hit.index)];
    const std::array<glm::vec3, 6> normals = boxFaceNormals(b);
    size_t face = 0;
    for (size_t f = 1; f < normals.size(); ++f)
      if (glm::dot(hit.normal, normals[f]) > glm::dot(hit.normal, normals[face])) face = f;
    glm::vec3 e = boxFaceLight_[size_t(hit.index) * 6 + face];
    if (sun_.direction.y > 0.0f) e += sun_.irradiance * std::max(glm::dot(hit.normal, sun_.direction), 0.0f);
    return glm::vec3(b.albedo) / glm::pi<float>() * e;
  }

  // The outward normals of a box's six faces.
  static std::array<glm::vec3, 6> boxFaceNormals(const shader::BoxParams& b) {
    const glm::vec3 x = shader::boxAxisX(b.center.w), z = shader::boxAxisZ(b.center.w), y(0.0f, 1.0f, 0.0f);
    return {x, -x, y, -y, z, -z};
  }

  // The sky's irradiance on a surface of normal n open to the whole sky (its
  // bins'), nothing from below the horizon.
  glm::vec3 openIrradiance(glm::vec3 n) const {
    glm::vec3 sum(0.0f);
    for (const SkyBins::Bin& bin : skyBins_.bins()) sum += bin.light * std::max(glm::dot(n, bin.direction), 0.0f);
    return sum;
  }

  // The radiance reaching o along -d from a ray in the air inside the pool
  // (d's first leg from the dry band): a wall above the water (dryWall) or
  // a box (boxInTheAir); the water, whose mirror is followed to a wall
  // above it or a box and whose
  // refraction brings the pool's light out (1 / n^2 of it past Fresnel's
  // transmission); the sky is the bins'.
  glm::vec3 fromTheAir(glm::vec3 o, glm::vec3 d, uint32_t seed) const {
    glm::vec3 weight(1.0f), radiance(0.0f);
    for (int leg = 0; leg < 2; ++leg) {
      const glm::vec2 walls = shader::poolWallDistances(pool_, o, d);
      const float sWall = std::min(walls.x, walls.y);
      const float sWater = d.y < 0.0f ? (o.y - level_) / -d.y : 1e30f;
      const bool wallFirst = sWall < sWater, overTheRim = wallFirst && o.y + sWall * d.y >= pool_.box.y;
      const BoxHit box = nearestBox(o, d, overTheRim ? 1e30f : std::min(sWall, sWater));
      if (box.index >= 0) {
        radiance += weight * boxInTheAir(box);
        break;
      }
      if (wallFirst) {
        if (!overTheRim) radiance += weight * dryWall(o, d, sWall, shader::poolWallNormal(walls, d));
        break;
      }
      if (leg == 1) break;  // mirrored twice: the floor's light is the first mirror's
      const glm::vec3 q = o + sWater * d;
      const float reflected = shader::fresnelDielectric(-d.y, 1.0f, ior_);
      const glm::vec3 below = glm::refract(d, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / ior_);
      radiance +=
          weight * ((1.0f - reflected) / (ior_ * ior_)) * incoming(q - glm::vec3(0.0f, kOffset, 0.0f), below, seed);
      weight *= reflected;
      o = q + glm::vec3(0.0f, kOffset, 0.0f);
      d.y = -d.y;
    }
    return radiance;
  }

  // The dry band's texel k: on its wall, from the rim down to the rest level.
  void dryTexelPoint(uint32_t k, glm::vec3& p, glm::vec3& n) const {
    const float half = pool_.box.x;
    const uint32_t w = k / (TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_UP);
    const uint32_t cell = k % (TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_UP);
    const float along = (2.0f * (float(cell % TP_POOL_LIGHT_ALONG) + 0.5f) / TP_POOL_LIGHT_ALONG - 1.0f) * half;
    const float down = (float(cell / TP_POOL_LIGHT_ALONG) + 0.5f) / TP_POOL_LIGHT_UP;
    const float y = pool_.box.y - down * (pool_.box.y - level_);
    wallPoint(w, along, y, p, n);
  }

  // The point `along` its wall w (poolLightWall's order) at height y, and
  // the wall's inward normal.
  void wallPoint(uint32_t w, float along, float y, glm::vec3& p, glm::vec3& n) const {
    const float side = w % 2 == 0 ? -pool_.box.x : pool_.box.x;
    n = w < 2 ? glm::vec3(w == 0 ? 1.0f : -1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, w == 2 ? 1.0f : -1.0f);
    p = w < 2 ? glm::vec3(side, y, along) : glm::vec3(along, y, side);
  }

  // The floor under xz: the mesh met by a ray down from the rest level.
  shader::PoolHit floorUnder(glm::vec2 xz) const {
    const float inside = pool_.box.x - kOffset;
    const glm::vec3 from(std::clamp(xz.x, -inside, inside), level_, std::clamp(xz.y, -inside, inside));
    return shader::tracePool(pool_, from, glm::vec3(0.0f, -1.0f, 0.0f), vertices_);
  }

  void texelPoint(uint32_t k, glm::vec3& p, glm::vec3& n) const {
    const float half = pool_.box.x;
    constexpr uint32_t floorTexels = TP_POOL_LIGHT_FLOOR * TP_POOL_LIGHT_FLOOR;
    if (k < floorTexels) {
      const glm::vec2 uv((float(k % TP_POOL_LIGHT_FLOOR) + 0.5f) / TP_POOL_LIGHT_FLOOR,
                         (float(k / TP_POOL_LIGHT_FLOOR) + 0.5f) / TP_POOL_LIGHT_FLOOR);
      const shader::PoolHit floor = floorUnder((2.0f * uv - 1.0f) * half);
      p = floor.position;
      n = floor.normal;
      return;
    }
    const uint32_t w = (k - floorTexels) / (TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_DOWN);
    const uint32_t cell = (k - floorTexels) % (TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_DOWN);
    const float along = (2.0f * (float(cell % TP_POOL_LIGHT_ALONG) + 0.5f) / TP_POOL_LIGHT_ALONG - 1.0f) * half;
    const float down = (float(cell / TP_POOL_LIGHT_ALONG) + 0.5f) / TP_POOL_LIGHT_DOWN;
    const float y = level_ - down * (level_ - pool_.terrain.z);
    wallPoint(w, along, y, p, n);
    p.y = std::max(p.y, floorUnder(glm::vec2(p.x, p.z)).position.y + kAboveFloor);
  }

  // The radiance reaching o along -d (d: the way the path goes) from
  // everything but the sun and the sky straight through the surface
  // (window's).
  glm::vec3 incoming(glm::vec3 o, glm::vec3 d, uint32_t seed) const {
    glm::vec3 radiance(0.0f), throughput(1.0f);
    uint32_t state = seed;
    auto uniform = [&] {
      state = shader::hashUint(state);
      return float(state >> 8) * (1.0f / 16777216.0f);
    };
    for (uint32_t bounce = 0; bounce <= kBounces;) {
      shader::PoolHit hit = shader::tracePool(pool_, o, d, vertices_);
      const BoxHit box = nearestBox(o, d, hit.distance);
      if (box.index >= 0) hit = {box.distance, o + box.distance * d, box.normal, false};
      const float up = toSurface(o, d);
      if (up < hit.distance) {
        underside(o, d, up, throughput, radiance, bounce > 0);
      } else {
        throughput *= glm::exp(-absorption_ * hit.distance);
        const glm::vec3 p = hit.position + kOffset * hit.normal;
        throughput *= box.index >= 0 ? glm::vec3(boxes_[size_t(box.index)].albedo) : albedo(hit, p);
        if (sunReaches(p)) radiance += throughput / glm::pi<float>() * sunThroughFlatWater(p, hit.normal);
        d = cosineAbout(hit.normal, glm::vec2(uniform(), uniform()));
        o = p;
        ++bounce;
      }
      if (std::max({throughput.x, throughput.y, throughput.z}) < kNegligible) break;
    }
    return radiance;
  }

  shader::PoolParams pool_;
  const glm::vec4* vertices_;
  const SkyRadiance& sky_;
  SkyBins skyBins_;
  // The solid angle of each of skyBins_'s bins (equal by construction).
  float binSolidAngle_ = 2.0f * glm::pi<float>() / float(kSkyBands * kSkyAzimuths);
  PoolLightSun sun_;
  std::vector<shader::BoxParams> boxes_;
  std::vector<glm::vec3> boxFaceLight_;  // openIrradiance of each box's faces (boxFaceNormals' order)
  shader::FrameUniforms frame_{};
  float ior_ = 1.0f, level_ = 0.0f;
  glm::vec3 absorption_{0.0f};
};

// Directions over the sphere for the light around: a Fibonacci lattice.
constexpr uint32_t kAroundDirections = 4096;

// The light around at `centre` (shared/pool_light.h's grid), from the bake
// whose texels `floorAndLight` holds after the floor's vertices.
shader::Sh9 lightAroundAt(const PoolLightBake& bake, const shader::PoolParams& pool,
                          const std::vector<glm::vec4>& floorAndLight, glm::vec3 centre) {
  const glm::vec4* data = floorAndLight.data();
  glm::dvec3 sum[9] = {};
  for (uint32_t i = 0; i < kAroundDirections; ++i) {
    const float y = 1.0f - 2.0f * (float(i) + 0.5f) / kAroundDirections;
    const float r = std::sqrt(std::max(0.0f, 1.0f - y * y)), a = 2.39996323f * float(i);  // the golden angle
    const glm::vec3 d(r * std::cos(a), y, r * std::sin(a));
    glm::vec3 o = centre, dir = d, radiance(0.0f), throughput(1.0f);
    // The first surface met, and once more past the underside's reflection.
    for (int leg = 0; leg < 2; ++leg) {
      const shader::PoolHit hit = shader::tracePool(pool, o, dir, data);
      const float up = bake.toSurface(o, dir);
      if (up < hit.distance) {
        bake.underside(o, dir, up, throughput, radiance, true);
        continue;
      }
      throughput *= glm::exp(-bake.waterAbsorption() * hit.distance);
      const glm::vec3 p = hit.position + kOffset * hit.normal;
      glm::vec3 irradiance = shader::poolLightAt(pool, p, hit.normal, data);
      if (bake.sunReaches(p)) irradiance += bake.sunThroughFlatWater(p, hit.normal);
      radiance += throughput * bake.albedo(hit, p) / glm::pi<float>() * irradiance;
      break;
    }
    for (uint32_t k = 0; k < 9; ++k) sum[k] += glm::dvec3(radiance) * double(shader::sh9Basis(k, d));
  }
  shader::Sh9 sh{};
  for (uint32_t k = 0; k < 9; ++k)
    sh.c[k] = glm::vec4(glm::vec3(sum[k] * (4.0 * glm::pi<double>() / kAroundDirections)), 0.0f);
  return sh;
}

// work(k) for k in [0, count), on every core.
template <typename Work>
void inParallel(uint32_t count, const Work& work) {
  std::atomic<uint32_t> next{0};
  auto run = [&] {
    for (uint32_t k = next++; k < count; k = next++) work(k);
  };
  std::vector<std::thread> threads(std::max(1u, std::thread::hardware_concurrency()) - 1);
  for (std::thread& t : threads) t = std::thread(run);
  run();
  for (std::thread& t : threads) t.join();
}

}  // namespace

PoolLight bakePoolLight(const shader::PoolParams& pool, std::vector<glm::vec4> floorVertices, const SkyRadiance& sky,
                        const PoolLightSun& sun, const std::vector<shader::BoxParams>& boxes) {
  PoolLight light;
  light.floorAndLight = std::move(floorVertices);
  const size_t first = light.floorAndLight.size();
  // The light's room made first: the bake reads the floor from this buffer.
  light.floorAndLight.resize(first + TP_POOL_LIGHT_SIZE);
  glm::vec4* texels = light.floorAndLight.data() + first;
  const PoolLightBake bake(pool, light.floorAndLight, sky, sun, boxes);
  // The walls above the water first: the texels under it see them through
  // the surface. The dry band sees the pool's light (its own paths), and its
  // walls one another: a pass without their light, then one with the
  // first's (what a third would add is the walls' albedo squared times
  // their share of the view, under 1%).
  constexpr uint32_t kDry = TP_POOL_LIGHT_TEXELS - TP_POOL_LIGHT_DRY_START;
  if (pool.water.w > 0.0f && pool.box.y > pool.water.x) {
    std::vector<glm::vec4> dry(kDry);
    for (int pass = 0; pass < 2; ++pass) {
      inParallel(kDry, [&](uint32_t k) { dry[k] = glm::vec4(bake.dryTexel(k), 0.0f); });
      std::copy(dry.begin(), dry.end(), texels + TP_POOL_LIGHT_DRY_START);
    }
  }
  inParallel(TP_POOL_LIGHT_DRY_START, [&](uint32_t k) { texels[k] = glm::vec4(bake.texel(k), 0.0f); });
  // The light around reads the texels: after them.
  glm::vec4* around = texels + TP_POOL_LIGHT_TEXELS;
  inParallel(TP_POOL_AROUND_POINTS, [&](uint32_t k) {
    const shader::Sh9 sh = lightAroundAt(bake, pool, light.floorAndLight, shader::poolAroundPoint(pool, int(k)));
    for (uint32_t m = 0; m < 9; ++m) around[9 * k + m] = sh.c[m];
  });
  return light;
}

}  // namespace tp::render
