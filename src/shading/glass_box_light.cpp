#include "shading/glass_box_light.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/sky_model.hpp"
#include "shared/glass.h"
#include "shared/sun_shadow.h"

namespace tp::render {
namespace {

// Rays per grid step along each side of the lattice.
constexpr int kRaysPerStep = 3;
// A branch of a ray (reflected inside, or let out) lighter than this is dropped.
constexpr float kLeastWeight = 0.01f;
// Faces met before a ray is dropped: a box's light pipe reflects a few times.
constexpr int kMostEvents = 32;
// The sun this low casts no grid (its rays run along the layers).
constexpr float kLowestSun = 0.02f;
// Past the straight shadow's square, the grid reaches this share of the
// square's side further each way, for the light the box bends and mirrors.
constexpr float kMargin = 0.2f;
// How far above the box's top (or the water) the rays start, in metres.
constexpr float kStartAbove = 0.01f;

enum class Medium { Air, Water, Glass };

// What the traced rays see of the scene: the sun, the water's flat surface
// over the pool's square (`water`; its poolHalf 0 where there is no pool),
// the box.
struct Setting {
  glm::vec3 toSun{0.0f, 1.0f, 0.0f}, inWater{0.0f, 1.0f, 0.0f};
  float sunRadius = 0.0f;
  shader::GlassSurround water{0.0f, 0.0f, 1.0f};
  shader::BoxParams box{};
  float ior = 1.5f;

  bool pool() const { return water.poolHalf > 0.0f; }
  glm::vec2 sheared(glm::vec3 p, float top) const {
    return shader::sunSheared(p, toSun, inWater, shader::inSurroundingWater(water, p), water.level, top);
  }
};

Setting settingOf(const scene::Scene& scene, const scene::Box& box) {
  Setting s;
  s.toSun = sunDirection(scene.sky);
  s.sunRadius = glm::radians(scene.sky.sunAngularRadiusDegrees);
  if (hasPool(scene)) s.water = {scene.water.level, 0.5f * scene.water.extent, scene.water.ior};
  s.inWater = s.pool() ? -glm::refract(-s.toSun, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / s.water.waterIor) : s.toSun;
  s.box = boxParams(box);
  s.ior = box.ior;
  return s;
}

std::array<glm::vec3, 8> corners(const shader::BoxParams& b) {
  std::array<glm::vec3, 8> out{};
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 local((k & 1 ? 1.0f : -1.0f) * b.halfSize.x, (k & 2 ? 1.0f : -1.0f) * b.halfSize.y,
                          (k & 4 ? 1.0f : -1.0f) * b.halfSize.z);
    out[size_t(k)] = glm::vec3(b.center) + shader::fromBoxFrame(local, b.center.w);
  }
  return out;
}

GlassBoxGrid placement(const scene::Scene& scene, const Setting& s) {
  GlassBoxGrid g;
  const auto c = corners(s.box);
  float top = -std::numeric_limits<float>::infinity(), bottom = std::numeric_limits<float>::infinity();
  for (const glm::vec3& p : c) {
    top = std::max(top, p.y);
    bottom = std::min(bottom, p.y);
  }
  // The lowest surface the light may reach: the pool's floor at its deepest, or the ground.
  const float floor = s.pool() ? scene.ground.height - scene.pool.depth - scene.terrain.amplitude : scene.ground.height;
  bottom = std::min(bottom, floor) - kStartAbove;
  glm::vec2 low(std::numeric_limits<float>::infinity()), high(-std::numeric_limits<float>::infinity());
  for (const glm::vec3& p : c) {
    low = glm::min(low, s.sheared(p, top));
    high = glm::max(high, s.sheared(p, top));
  }
  // Square, so that one step serves both ways; wide enough for the light
  // the box turns aside and for the sun's disc spread over the depth.
  const float side = std::max(high.x - low.x, high.y - low.y);
  const float reach = 0.5f * side * (1.0f + 2.0f * kMargin) + s.sunRadius * (top - bottom) / s.toSun.y;
  const glm::vec2 middle = 0.5f * (low + high);
  g.square = glm::vec4(middle - reach, middle + reach);
  g.heights = glm::vec4(bottom, top, top, 0.0f);
  return g;
}

// One branch of a light ray.
struct Ray {
  glm::vec3 p, d;
  float weight;
  Medium medium;
};

// From inside the box: the distance to the face it leaves by, and that face's axis.
float leaveBox(const Setting& s, glm::vec3 p, glm::vec3 d, int& axis) {
  const glm::vec3 o = shader::toBoxFrame(p - glm::vec3(s.box.center), s.box.center.w);
  const shader::BoxFaceAhead face =
      shader::boxFaceAhead(o, shader::toBoxFrame(d, s.box.center.w), glm::vec3(s.box.halfSize));
  axis = face.axis;
  return std::max(face.distance, 0.0f);
}

// The light crossing each layer, tent by tent over the grid's points.
struct Layers {
  Layers(const GlassBoxGrid& g) : grid(g), sums(TP_GLASS_BOX_SIZE, 0.0) {
    step = (g.square.z - g.square.x) / float(TP_GLASS_BOX_SIDE - 1);
    layerStep = (g.heights.y - g.heights.x) / float(TP_GLASS_BOX_LAYERS - 1);
  }
  // The segment from p along d (down) to distance t, as it crosses the layers
  // above its end and up to its start.
  void cross(const Setting& s, glm::vec3 p, glm::vec3 d, float t, float weight) {
    if (d.y >= 0.0f) return;
    const float from = p.y, to = p.y + t * d.y;
    // Strictly below `from` and down to `to`: a layer at a face's height
    // counts on one side of it only.
    const int first = std::max(0, int(std::floor((to - grid.heights.x) / layerStep)) + 1);
    const int last = std::min(TP_GLASS_BOX_LAYERS - 1, int(std::floor((from - grid.heights.x) / layerStep)));
    for (int l = first; l <= last; ++l) {
      const float y = grid.heights.x + float(l) * layerStep;
      const glm::vec3 q = p + d * ((y - p.y) / d.y);
      const glm::vec2 a = s.sheared(q, grid.heights.z);
      const float u = (a.x - grid.square.x) / step, v = (a.y - grid.square.y) / step;
      const int i = int(std::floor(u)), j = int(std::floor(v));
      const float fu = u - float(i), fv = v - float(j);
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const int x = i + di, z = j + dj;
          if (x < 0 || z < 0 || x >= TP_GLASS_BOX_SIDE || z >= TP_GLASS_BOX_SIDE) continue;
          const float w = (di ? fu : 1.0f - fu) * (dj ? fv : 1.0f - fv);
          sums[(size_t(l) * TP_GLASS_BOX_SIDE + size_t(z)) * TP_GLASS_BOX_SIDE + size_t(x)] += double(weight * w);
        }
    }
  }
  const GlassBoxGrid& grid;
  std::vector<double> sums;
  float step = 0.0f, layerStep = 0.0f;
};

// Follows one light ray and its branches down to the lowest layer.
void trace(const Setting& s, Ray start, bool withBox, Layers& layers) {
  std::array<Ray, 16> stack{};
  size_t count = 0;
  stack[count++] = start;
  while (count > 0) {
    Ray r = stack[--count];
    for (int event = 0; event < kMostEvents && r.weight >= kLeastWeight; ++event) {
      const float bottom = layers.grid.heights.x;
      if (r.medium != Medium::Glass && r.d.y >= 0.0f) break;  // going up: away from every layer
      // Half a layer past the lowest, so that round-off loses none of its crossings.
      float t =
          r.d.y < 0.0f ? (bottom - 0.5f * layers.layerStep - r.p.y) / r.d.y : std::numeric_limits<float>::infinity();
      enum class Next { End, Box, Level, Wall, Face } next = Next::End;
      glm::vec3 entryNormal(0.0f);
      int axis = 0;
      if (r.medium == Medium::Glass) {
        t = leaveBox(s, r.p, r.d, axis);
        next = Next::Face;
      } else {
        if (withBox) {
          const glm::vec4 hit = shader::rayBox(r.p, r.d, s.box.center, s.box.halfSize);
          if (hit.x > 0.0f && hit.x < t) t = hit.x, next = Next::Box, entryNormal = glm::vec3(hit.y, hit.z, hit.w);
        }
        if (r.medium == Medium::Air && s.pool() && r.p.y > s.water.level) {
          const float tl = (s.water.level - r.p.y) / r.d.y;
          const glm::vec3 q = r.p + tl * r.d;
          if (tl < t && std::max(std::abs(q.x), std::abs(q.z)) <= s.water.poolHalf) t = tl, next = Next::Level;
        }
        if (r.medium == Medium::Water) {
          // The pool's walls end it (their shadow is the sun term's own).
          for (int a : {0, 2}) {
            if (r.d[a] == 0.0f) continue;
            const float tw = ((r.d[a] > 0.0f ? s.water.poolHalf : -s.water.poolHalf) - r.p[a]) / r.d[a];
            if (tw < t) t = tw, next = Next::Wall;
          }
        }
      }
      layers.cross(s, r.p, r.d, t, r.weight);
      const glm::vec3 at = r.p + t * r.d;
      if (next == Next::End || next == Next::Wall) break;
      if (next == Next::Level) {
        const float cosI = -r.d.y;
        r.weight *= 1.0f - shader::fresnelDielectric(cosI, 1.0f, s.water.waterIor);
        r.d = glm::normalize(glm::refract(r.d, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / s.water.waterIor));
        r.p = at;
        r.medium = Medium::Water;
        continue;
      }
      if (next == Next::Box) {
        const glm::vec3 n = entryNormal;
        const float outside = r.medium == Medium::Water ? s.water.waterIor : 1.0f;
        const float cosI = std::max(-glm::dot(r.d, n), 0.0f);
        const float reflectance = shader::fresnelDielectric(cosI, outside, s.ior);
        // What the face reflects goes on outside: off a side, down to the ground.
        if (r.weight * reflectance >= kLeastWeight && count < stack.size())
          stack[count++] = Ray{at, glm::normalize(glm::reflect(r.d, n)), r.weight * reflectance, r.medium};
        r.weight *= 1.0f - reflectance;
        r.d = glm::normalize(glm::refract(r.d, n, outside / s.ior));
        r.p = at;
        r.medium = Medium::Glass;
        continue;
      }
      // A face from inside: let out by Fresnel's share, the rest reflected on inside.
      glm::vec3 local(0.0f);
      local[axis] = shader::toBoxFrame(r.d, s.box.center.w)[axis] > 0.0f ? 1.0f : -1.0f;
      const glm::vec3 n = shader::fromBoxFrame(local, s.box.center.w);  // outward
      const float beyond = shader::surroundIndexAt(s.water, at);
      const float cosI = std::max(glm::dot(r.d, n), 0.0f);
      const float reflectance = shader::fresnelDielectric(cosI, s.ior, beyond);
      const glm::vec3 mirrored = glm::normalize(glm::reflect(r.d, n));
      if (reflectance < 1.0f) {
        const float out = r.weight * reflectance;
        if (out >= kLeastWeight && count < stack.size()) stack[count++] = Ray{at, mirrored, out, Medium::Glass};
        r.weight *= 1.0f - reflectance;
        r.d = glm::normalize(glm::refract(r.d, -n, s.ior / beyond));
        r.medium = beyond > 1.0f ? Medium::Water : Medium::Air;
      } else {
        r.d = mirrored;
      }
      r.p = at;
    }
  }
}

// Layer l of `sums` averaged over a disc of `radius` grid steps about each
// point (none under half a step: the tents already spread that far).
void spreadOverDisc(std::vector<double>& sums, int l, float radius) {
  if (radius < 0.5f) return;
  const int reach = int(std::ceil(radius));
  std::vector<glm::ivec2> disc;
  for (int dv = -reach; dv <= reach; ++dv)
    for (int du = -reach; du <= reach; ++du)
      if (float(du * du + dv * dv) <= radius * radius) disc.push_back({du, dv});
  const size_t side = TP_GLASS_BOX_SIDE, base = size_t(l) * side * side;
  const std::vector<double> layer(sums.begin() + std::ptrdiff_t(base),
                                  sums.begin() + std::ptrdiff_t(base + side * side));
  for (int v = 0; v < int(side); ++v)
    for (int u = 0; u < int(side); ++u) {
      double sum = 0.0;
      int count = 0;
      for (const glm::ivec2& o : disc) {
        const int x = u + o.x, z = v + o.y;
        if (x < 0 || z < 0 || x >= int(side) || z >= int(side)) continue;
        sum += layer[size_t(z) * side + size_t(x)];
        ++count;
      }
      sums[base + size_t(v) * side + size_t(u)] = sum / count;
    }
}

}  // namespace

std::vector<const scene::Box*> glassBoxCasters(const scene::Scene& scene) {
  std::vector<const scene::Box*> casters;
  if (!scene.render.shadows || sunDirection(scene.sky).y <= kLowestSun) return casters;
  for (const scene::Box& b : scene.boxes)
    if (scene::isGlass(b) && casters.size() < TP_MAX_BOXES) casters.push_back(&b);
  return casters;
}

GlassBoxGrid glassBoxGridPlacement(const scene::Scene& scene, const scene::Box& box) {
  return placement(scene, settingOf(scene, box));
}

GlassBoxGrid glassBoxLightGrid(const scene::Scene& scene, const scene::Box& box) {
  const Setting s = settingOf(scene, box);
  GlassBoxGrid g = placement(scene, s);
  Layers lit(g), open(g);
  // A lattice over the square and one step past it each way, so that the
  // open light is even up to the grid's edge; all along the sun's central
  // ray, so that it stays even below the box (the disc follows).
  const float step = (g.square.z - g.square.x) / float(TP_GLASS_BOX_SIDE - 1);
  const int rays = (TP_GLASS_BOX_SIDE + 1) * kRaysPerStep;
  const float top = g.heights.z;
  const float start = std::max(top, s.pool() ? s.water.level : top) + kStartAbove;
  for (int j = 0; j < rays; ++j) {
    for (int i = 0; i < rays; ++i) {
      const glm::vec2 a(g.square.x - step + (float(i) + 0.5f) * step / kRaysPerStep,
                        g.square.y - step + (float(j) + 0.5f) * step / kRaysPerStep);
      // The point at the start's height whose sheared coordinates are a (in the air).
      const glm::vec2 xz = a + glm::vec2(s.toSun.x, s.toSun.z) * ((start - top) / s.toSun.y);
      const Ray ray{glm::vec3(xz.x, start, xz.y), -s.toSun, 1.0f, Medium::Air};
      trace(s, ray, true, lit);
      trace(s, ray, false, open);
    }
  }
  // The sun's disc: each layer's light spread over the disc seen from the
  // box's middle height, as the sun's angular radius times the distance.
  const float middle = s.box.center.y;
  for (int l = 0; l < TP_GLASS_BOX_LAYERS; ++l) {
    const float y = g.heights.x + float(l) * lit.layerStep;
    const float radius = s.sunRadius * std::max(middle - y, 0.0f) / s.toSun.y / step;
    spreadOverDisc(lit.sums, l, radius);
    spreadOverDisc(open.sums, l, radius);
  }
  g.values.resize(TP_GLASS_BOX_SIZE);
  for (size_t k = 0; k < g.values.size(); ++k)
    g.values[k] = open.sums[k] > 0.0 ? float(lit.sums[k] / open.sums[k]) : 1.0f;
  return g;
}

}  // namespace tp::render
