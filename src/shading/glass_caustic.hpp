#pragma once
// The sun behind a glass sphere in the air: its shadow and its caustic, as a
// table of the irradiance on planes facing the sun, relative to the open
// sun (shared/shadow_casters.h's layout). The surfaces' shaders read it in
// their sun term (shared/sun_shadow.h's glassSunShare), and so does the
// raster's model traced (--reference-model); the truth traces the glass.
//
// A sphere is symmetric about its centre, so turning the sun turns the
// whole pattern about the centre: the table is traced for the disc's centre
// and spread over the disc, at a distance z past the centre, by a disc of
// radius z times the sun's angular radius. The ray's one pass through the
// glass is traced; the light its internal reflections let out is left out.
#include <map>
#include <utility>
#include <vector>

#include "scene/scene.hpp"
#include "shading/glass_box_light.hpp"
#include "shared/shadow_casters.h"

namespace tp::render {

// A ray along the axis (+along), at distance `across` from it (0 <= across <
// 1, in radii), through a sphere of index `ior` at the origin, in the plane
// through the axis.
struct GlassPassage {
  double entryAlong = 0.0;  // where it enters, along the axis: -sqrt(1 - across^2)
  double exitAcross = 0.0;  // where it leaves: across (signed) and along
  double exitAlong = 0.0;
  double directionAcross = 0.0;  // its direction out, unit
  double directionAlong = 1.0;
  double transmitted = 1.0;  // the share Fresnel's equations let through both faces
};
GlassPassage glassPassage(double across, double ior);

// The table of a sphere of index `ior` under a sun of angular radius
// `sunRadius` (radians): TP_GLASS_TABLE_SIZE values, row by row.
std::vector<float> glassCausticTable(double ior, double sunRadius);

// The glass spheres that cast the sun's shadow at `time`: with render.shadows
// on, those in the air (wholly above the water's rest level, or off the
// pool's square), the first TP_MAX_SPHERES, in the order their tables go.
std::vector<const scene::Sphere*> glassCasters(const scene::Scene& scene, float time);
// Whether the scene has glass that may cast (at some time): glass spheres,
// or glass boxes that cast (glassBoxCasters).
bool glassCastsShadows(const scene::Scene& scene);

// The tables of the glass casters at a time, each traced once per index
// and sun and kept; and the glass boxes' grids (glassBoxLightGrid), each
// traced again only when the box, the sun or the water changes.
class GlassTableCache {
 public:
  // Fills `tables` for the casters of `scene` at `time` (their order);
  // returns whether any value changed.
  bool fill(const scene::Scene& scene, float time, shader::GlassTables& tables);

 private:
  std::map<std::pair<float, float>, std::vector<float>> traced_;  // by (ior, sun radius)
  // What each glass box's grid was traced for, and the grid.
  struct BoxTraced {
    scene::Box box;
    scene::Sky sky;
    scene::Water water;
    scene::Ground ground;
    scene::Pool pool;
    scene::Terrain terrain;
    GlassBoxGrid grid;
  };
  std::vector<BoxTraced> boxes_;
};

}  // namespace tp::render
