#include "shading/glass_caustic.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/gtc/constants.hpp>

#include "shading/pool_model.hpp"
#include "shared/glass.h"

namespace tp::render {
namespace {

// Impact distances traced across the beam, and points of the sun's disc
// each landing is spread over: with four times as many of each, no value
// moved by more than 0.5% of the open sun (or of itself, where larger).
constexpr int kRays = 8192;
constexpr int kDiscPoints = 32;

constexpr double kColumnStep = TP_GLASS_TABLE_REACH / (TP_GLASS_TABLE_COLUMNS - 1);
constexpr double kRowStep = TP_GLASS_TABLE_DEPTH / (TP_GLASS_TABLE_ROWS - 1);

// d refracted at a face of unit normal n facing it (dot(d, n) < 0), going
// from index n1 into n2; none past the critical angle (not met in a sphere).
glm::dvec2 refracted(glm::dvec2 d, glm::dvec2 n, double eta) {
  const double cosI = -glm::dot(d, n);
  const double cosT = std::sqrt(std::max(0.0, 1.0 - eta * eta * (1.0 - cosI * cosI)));
  return eta * d + (eta * cosI - cosT) * n;
}

// Points of the unit disc, evenly spread (a Fermat spiral).
struct DiscPoints {
  DiscPoints() {
    for (int k = 0; k < kDiscPoints; ++k) {
      const double r = std::sqrt((k + 0.5) / kDiscPoints), angle = 2.39996322972865332 * k;  // the golden angle
      points[size_t(k)] = {r * std::cos(angle), r * std::sin(angle)};
    }
  }
  std::array<glm::dvec2, kDiscPoints> points;
};

// A row's weights: a landing at distance `across` from the axis, spread
// over a disc of radius `spread` about it, shared between the columns by
// tents (each column's value is its tent's average).
void deposit(std::vector<double>& row, double across, double weight, glm::dvec2 spread, const DiscPoints& disc) {
  const double share = weight / kDiscPoints;
  for (const glm::dvec2& d : disc.points) {
    // The disc turned by the ray's own angle (spread: its radius times that
    // angle's cosine and sine), so that no ring of points shows.
    const double x = across + spread.x * d.x - spread.y * d.y, y = spread.y * d.x + spread.x * d.y;
    const double u = std::sqrt(x * x + y * y) * (1.0 / kColumnStep);
    const int column = int(u);
    const double f = u - column;
    if (column < TP_GLASS_TABLE_COLUMNS) row[size_t(column)] += (1.0 - f) * share;
    if (column + 1 < TP_GLASS_TABLE_COLUMNS) row[size_t(column) + 1] += f * share;
  }
}

// Where a ray of the beam crosses the plane `along` past the centre, and
// the share of its light there; none where it never does (it left the
// sphere sideways or backwards).
struct Crossing {
  bool crosses = false;
  double across = 0.0, share = 0.0;
};

Crossing crossing(const GlassPassage& g, double across, double along) {
  if (along <= g.exitAlong) {  // still inside: on the chord, through the first face only
    const double t = (along - g.entryAlong) / (g.exitAlong - g.entryAlong);
    return {true, across + t * (g.exitAcross - across), std::sqrt(g.transmitted)};
  }
  if (g.directionAlong <= 0.0) return {};
  const double t = (along - g.exitAlong) / g.directionAlong;
  return {true, g.exitAcross + t * g.directionAcross, g.transmitted};
}

}  // namespace

GlassPassage glassPassage(double across, double ior) {
  GlassPassage g;
  const glm::dvec2 entry(across, -std::sqrt(std::max(0.0, 1.0 - across * across)));
  g.entryAlong = entry.y;
  // In: the face's normal is the point itself (a unit sphere).
  const glm::dvec2 inside = refracted(glm::dvec2(0.0, 1.0), entry, 1.0 / ior);
  // The chord of a unit sphere along `inside` from `entry`.
  const glm::dvec2 exit = entry - 2.0 * glm::dot(entry, inside) * inside;
  const glm::dvec2 out = refracted(inside, -exit, ior);
  g.exitAcross = exit.x;
  g.exitAlong = exit.y;
  g.directionAcross = out.x;
  g.directionAlong = out.y;
  // Both faces meet the ray at the same pair of angles.
  const float reflected = shader::fresnelDielectric(float(-entry.y), 1.0f, float(ior));
  g.transmitted = double(1.0f - reflected) * double(1.0f - reflected);
  return g;
}

std::vector<float> glassCausticTable(double ior, double sunRadius) {
  // Straight rays out past the last column's tent at the widest disc, so
  // that the columns at the table's edge are filled from both sides.
  const double beam = TP_GLASS_TABLE_REACH + 2.0 * kColumnStep + sunRadius * TP_GLASS_TABLE_DEPTH;
  const double step = beam / kRays;
  std::vector<GlassPassage> passages;
  for (int k = 0; k < kRays && (k + 0.5) * step < 1.0; ++k) passages.push_back(glassPassage((k + 0.5) * step, ior));
  const DiscPoints disc;
  std::vector<glm::dvec2> turns(kRays);
  for (int k = 0; k < kRays; ++k) turns[size_t(k)] = {std::cos(0.7548776662 * k), std::sin(0.7548776662 * k)};
  std::vector<float> table(TP_GLASS_TABLE_SIZE);
  std::vector<double> lit(TP_GLASS_TABLE_COLUMNS), open(TP_GLASS_TABLE_COLUMNS);
  for (int r = 0; r < TP_GLASS_TABLE_ROWS; ++r) {
    std::fill(lit.begin(), lit.end(), 0.0);
    std::fill(open.begin(), open.end(), 0.0);
    const double along = r * kRowStep;
    for (int k = 0; k < kRays; ++k) {
      const double across = (k + 0.5) * step, weight = across;  // the annulus' light: 2 pi b db
      const glm::dvec2 spread = sunRadius * along * turns[size_t(k)];
      deposit(open, across, weight, spread, disc);
      if (size_t(k) >= passages.size()) {
        deposit(lit, across, weight, spread, disc);
        continue;
      }
      const Crossing c = crossing(passages[size_t(k)], across, along);
      if (c.crosses) deposit(lit, std::abs(c.across), weight * c.share, spread, disc);
    }
    // The same tents over the open sun: what each column's average of the
    // irradiance is relative to.
    for (int c = 0; c < TP_GLASS_TABLE_COLUMNS; ++c)
      table[size_t(r * TP_GLASS_TABLE_COLUMNS + c)] = float(lit[size_t(c)] / open[size_t(c)]);
  }
  return table;
}

std::vector<const scene::Sphere*> glassCasters(const scene::Scene& scene, float time) {
  std::vector<const scene::Sphere*> casters;
  if (!scene.render.shadows) return casters;
  const float half = 0.5f * scene.water.extent;
  for (const scene::Sphere& s : scene.spheres) {
    if (!scene::isGlass(s) || casters.size() == TP_MAX_SPHERES) continue;
    const glm::vec3 c = scene::sphereCenterAt(s, time);
    const bool offPool = std::max(std::abs(c.x), std::abs(c.z)) - s.radius >= half;
    // In the water the light would change medium in the glass: not modelled.
    if (!hasPool(scene) || offPool || c.y - s.radius >= scene.water.level) casters.push_back(&s);
  }
  return casters;
}

bool glassCastsShadows(const scene::Scene& scene) {
  return (scene.render.shadows && std::any_of(scene.spheres.begin(), scene.spheres.end(),
                                              [](const scene::Sphere& s) { return scene::isGlass(s); })) ||
         !glassBoxCasters(scene).empty();
}

bool GlassTableCache::fill(const scene::Scene& scene, float time, shader::GlassTables& tables) {
  const float sunRadius = glm::radians(scene.sky.sunAngularRadiusDegrees);
  bool changed = false;
  size_t slot = 0;
  for (const scene::Sphere* s : glassCasters(scene, time)) {
    auto [it, fresh] = traced_.try_emplace({s->ior, sunRadius});
    if (fresh) it->second = glassCausticTable(s->ior, sunRadius);
    float* to = tables.values + slot++ * TP_GLASS_TABLE_SIZE;
    if (std::memcmp(to, it->second.data(), sizeof(float) * TP_GLASS_TABLE_SIZE) != 0) {
      std::memcpy(to, it->second.data(), sizeof(float) * TP_GLASS_TABLE_SIZE);
      changed = true;
    }
  }
  const std::vector<const scene::Box*> boxes = glassBoxCasters(scene);
  boxes_.resize(boxes.size());
  for (size_t k = 0; k < boxes.size(); ++k) {
    BoxTraced& t = boxes_[k];
    const bool same = t.grid.values.size() == TP_GLASS_BOX_SIZE && t.box == *boxes[k] && t.sky == scene.sky &&
                      t.water == scene.water && t.ground == scene.ground && t.pool == scene.pool &&
                      t.terrain == scene.terrain;
    if (!same)
      t = {*boxes[k],
           scene.sky,
           scene.water,
           scene.ground,
           scene.pool,
           scene.terrain,
           glassBoxLightGrid(scene, *boxes[k])};
    float* to = tables.values + TP_GLASS_BOX_GRIDS_START + k * TP_GLASS_BOX_SIZE;
    if (std::memcmp(to, t.grid.values.data(), sizeof(float) * TP_GLASS_BOX_SIZE) != 0) {
      std::memcpy(to, t.grid.values.data(), sizeof(float) * TP_GLASS_BOX_SIZE);
      changed = true;
    }
  }
  return changed;
}

}  // namespace tp::render
