// Sun shadows: the share of the sun's disc a point sees past the opaque
// spheres, the boxes and the pool's walls, and the light the glass spheres
// in the air and the glass boxes shade and focus, for every diffuse surface's sun term
// (shading.h). Shared with C++ to test it against closed forms and
// against rays sampled over the disc; the raster's model traced takes only
// the glass spheres' tables from it and traces its own shadow rays
// (reference_tracer.cpp).
//
// Under the water the shadow ray is bent as through flat water: from the
// point up along the sun's refracted direction to the surface, then on
// towards the sun. The waves' focusing is the caustics map's.
//
// In GLSL it reads the includer's `frame` (shared/frame.h's FrameUniforms)
// in place, so include it after that uniform block: a struct passed by value
// is copied whole for every pixel on lavapipe, and arrays indexed in a loop
// then live in scratch memory (shared/object_cast.h found the same). In C++
// the casters come by reference.
#ifndef TP_SHARED_SUN_SHADOW_H
#define TP_SHARED_SUN_SHADOW_H
#include "shared/constants.h"
#include "shared/interop.h"
#include "shared/objects.h"
#include "shared/shadow_casters.h"
#include "shared/specialization.h"

#ifdef __cplusplus
#define TP_CASTERS_PARAM const ShadowCasters &casters,
#define TP_CASTERS_ARG casters,
#define TP_CASTERS casters
#define TP_CASTERS_SUN(i) casters.sun[i]
#define TP_CASTERS_POOL(i) casters.pool[i]
#define TP_CASTERS_GLASS(i) casters.glass[i]
#define TP_GLASS_PARAM const GlassTables &tables,
#define TP_GLASS_ARG tables,
#define TP_GLASS_TABLE(i) tables.values[i]
#else
#define TP_CASTERS_PARAM
#define TP_CASTERS_ARG
#define TP_CASTERS frame.shadows
// The casters' sun and pool vectors, read through TP_UNIFORM_INDEX_BASE
// (shared/frame.h). The tests here on the casters and the sun had lavapipe
// compile the pool's and the sphere's shaders again in every frame, about
// 160 ms a pass without Mesa's shader cache and 2-2.5 ms with it
// (docs/sun-shadows.md#cost).
#define TP_CASTERS_SUN(i) frame.shadows.sun[TP_UNIFORM_INDEX_BASE + (i)]
#define TP_CASTERS_POOL(i) frame.shadows.pool[TP_UNIFORM_INDEX_BASE + (i)]
#define TP_CASTERS_GLASS(i) frame.shadows.glass[TP_UNIFORM_INDEX_BASE + (i)]
// The glass spheres' tables: in a storage buffer of their own. In the
// frame's uniforms, 16 KB of them made lavapipe slow to create every
// pipeline: a render started 2.7 s later.
#define TP_GLASS_PARAM
#define TP_GLASS_ARG
#define TP_GLASS_TABLE(i) glassTables[i]
layout(binding = TP_GLASS_TABLES_BINDING) readonly buffer GlassTableValues { float glassTables[]; };
#endif

TP_BEGIN

// Which casters' code a shader holds is shared/specialization.h's
// kSphereShadows and kBoxShadows: a scene without boxes, say, draws with
// none of the boxes' code (docs/sun-shadows.md#cost).

// A point this much farther from a sphere's centre than its radius is off it:
// nearer, it is the sphere's own surface (its tessellation lies inside), which
// its own n.l shades.
const float kShadowOwnSurface = 1.002f;
// Sun directions sampled over the disc for the boxes' shadows (a Fermat
// spiral), and how far along each a ray starts off the surface, in metres.
const uint kBoxShadowRays = 8u;
const float kShadowRayStart = 1e-3f;

// The area where two discs of radii a and b, their centres d apart, overlap.
TP_INLINE float discOverlap(float a, float b, float d) {
  if (d >= a + b) return 0.0f;
  if (d <= abs(a - b)) return kPi * min(a, b) * min(a, b);
  float ca = clamp((d * d + a * a - b * b) / (2.0f * d * a), -1.0f, 1.0f);
  float cb = clamp((d * d + b * b - a * a) / (2.0f * d * b), -1.0f, 1.0f);
  float k = (-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b);
  return a * a * acos(ca) + b * b * acos(cb) - 0.5f * sqrt(max(k, 0.0f));
}

// The share of a disc of angular radius `radius` about `toSun` that a sphere
// leaves visible from p: the two discs of directions (the sphere's of angular
// radius asin(r / d)) overlapping, as flat discs.
TP_INLINE float sphereSunVisibility(vec3 p, vec3 toSun, float radius, vec4 sphere) {
  vec3 v = vec3(sphere) - p;
  float d = length(v), along = dot(v, toSun);
  float visible = 1.0f;
  // Only near the shadow's cone: its centre towards the sun, and missed by
  // less than r + radius d (sin(a + b) <= sin a + b), off its own surface.
  bool near = along > 0.0f && d > sphere.w * kShadowOwnSurface &&
              dot(v, v) - along * along < (sphere.w + radius * d) * (sphere.w + radius * d);
  if (near) {
    float apart = atan(length(cross(v, toSun)), along);
    float angular = asin(sphere.w / d);
    visible = 1.0f - discOverlap(radius, angular, apart) / (kPi * radius * radius);
  }
  return visible;
}

// The share of a disc that lies on the inner side of a straight edge at
// signed distance u disc radii from its centre (positive: the centre inside).
TP_INLINE float discShareInside(float u) {
  u = clamp(u, -1.0f, 1.0f);
  return 0.5f + (u * sqrt(1.0f - u * u) + asin(u)) / kPi;
}

// The share of the disc about `toSun` seen from p through a square opening
// of half side h at height `top` (p below it): each edge of the opening with
// p spans a plane, and the directions on its inner side pass the edge.
TP_INLINE float openingSunVisibility(vec3 p, vec3 toSun, float radius, float h, float top) {
  float above = top - p.y;
  float share = 1.0f;
  // The inner normals of the planes through p and the edges x = h, x = -h,
  // z = h, z = -h: along the edge's axis a, out of it by the side s.
  TP_DONT_UNROLL for (int edge = 0; edge < 4 && above > 0.0f; ++edge) {
    float s = (edge % 2 == 0) ? 1.0f : -1.0f;
    vec3 n = edge < 2 ? vec3(-s * above, h - s * p.x, 0.0f) : vec3(0.0f, h - s * p.z, -s * above);
    share *= discShareInside(asin(dot(normalize(n), toSun)) / radius);
  }
  return share;
}

// Whether origin + s dir meets the box for some s > 0: the slab test without
// the face it enters by, vector-wide (a shadow ray needs no normal).
TP_INLINE bool rayMeetsBox(vec3 origin, vec3 dir, vec4 center, vec4 halfSize) {
  vec3 o = toBoxFrame(origin - vec3(center), center.w), d = toBoxFrame(dir, center.w);
  // Parallel axes: a tiny direction keeps the division finite and the sign right.
  vec3 inverse = 1.0f / max(abs(d), vec3(1e-12f)) * sign(d + vec3(1e-30f));
  vec3 a = (-vec3(halfSize) - o) * inverse, b = (vec3(halfSize) - o) * inverse;
  vec3 enter = min(a, b), leave = max(a, b);
  float sNear = max(max(enter.x, enter.y), enter.z), sFar = min(min(leave.x, leave.y), leave.z);
  return sFar >= max(sNear, 0.0f);
}

// The share of the disc about `toSun` no box hides from p (rays over the disc).
TP_INLINE float boxesSunVisibility(TP_CASTERS_PARAM vec3 p, vec3 toSun, float radius, float minY, float maxY) {
  if (!kBoxShadows) return 1.0f;
  uint boxes = uint(TP_CASTERS_SUN(2));
  vec3 side = normalize(cross(toSun, abs(toSun.y) < 0.9f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f)));
  vec3 up = cross(side, toSun);
  float seen = 0.0f;
  TP_DONT_UNROLL for (uint i = 0u; i < (boxes > 0u ? kBoxShadowRays : 0u); ++i) {
    float r = radius * sqrt((float(i) + 0.5f) / float(kBoxShadowRays));
    float angle = 2.39996323f * float(i);  // the golden angle
    vec3 dir = normalize(toSun + r * (cos(angle) * side + sin(angle) * up));
    bool hidden = false;
    for (uint b = 0u; b < boxes; ++b) {
      vec4 center = TP_CASTERS.boxCenter[b], halfSize = TP_CASTERS.boxHalfSize[b];
      if (center.y + halfSize.y < minY || center.y - halfSize.y > maxY) continue;  // not on this leg of the ray
      if (rayMeetsBox(p + kShadowRayStart * dir, dir, center, halfSize)) hidden = true;
    }
    seen += hidden ? 0.0f : 1.0f;
  }
  return boxes > 0u ? seen / float(kBoxShadowRays) : 1.0f;
}

// The share of the sun's disc seen from p along one straight leg towards
// `toSun` that ends `length` on, past the casters that reach between the
// heights minY and maxY; a sphere counts where the leg's central ray enters
// it (or, missing it, passes nearest) before the leg's end. `behind`: for the
// leg in the air above water, the leg under it times how much the water
// narrows the disc; a caster at distance D then sees the disc widened by
// (D + behind) / D, as a turn of the sun moves the leg's start too; and a
// start inside a sphere (the leg under the water passed through it) is dark,
// unless the receiver is on that sphere's own surface (at its waterline the
// leg is a hair long, and the tessellated surface lies inside the sphere).
TP_INLINE float legSunVisibility(TP_CASTERS_PARAM vec3 p, vec3 toSun, float radius, float minY, float maxY,
                                 float length, float behind, vec3 receiver) {
  float share = 1.0f;
  for (uint i = 0u; i < (kSphereShadows ? uint(TP_CASTERS_SUN(1)) : 0u); ++i) {
    vec4 s = TP_CASTERS.spheres[i];
    vec3 v = vec3(s) - p;
    if (behind > 0.0f && dot(v, v) < s.w * s.w && distance(receiver, vec3(s)) > s.w * kShadowOwnSurface) return 0.0f;
    float along = dot(v, toSun), miss2 = dot(v, v) - along * along;
    float enters = along - sqrt(max(s.w * s.w - miss2, 0.0f));
    if (s.y + s.w < minY || s.y - s.w > maxY || enters > length) continue;
    share = min(share, sphereSunVisibility(p, toSun, radius * (1.0f + behind / max(along, s.w)), s));
  }
  return min(share, boxesSunVisibility(TP_CASTERS_ARG p, toSun, radius, minY, maxY));
}

// The share of the sun's disc that lights p in the open air, outside the
// pool (the ground): past the spheres and boxes alone, on one straight leg.
// It is sunVisibility wherever p is out of the pool, without the code of
// the walls' openings and the bent leg under the water.
TP_INLINE float openAirSunVisibility(TP_CASTERS_PARAM vec3 p, vec3 toSun) {
  if (toSun.y <= 0.0f) return 0.0f;
  return legSunVisibility(TP_CASTERS_ARG p, toSun, TP_CASTERS_SUN(0), -1e30f, 1e30f, 1e30f, 0.0f, p);
}

// The share of the sun's disc (direction toSun, above the horizon) that
// lights the point p: 1 in the open, 0 in the umbra.
TP_INLINE float sunVisibility(TP_CASTERS_PARAM vec3 p, vec3 toSun) {
  float radius = TP_CASTERS_SUN(0);
  if (toSun.y <= 0.0f) return 0.0f;
  float h = TP_CASTERS_POOL(0), rim = TP_CASTERS_POOL(1), level = TP_CASTERS_POOL(2);
  // The walls (|x| or |z| = h) count as in: the opposite wall shades them.
  bool inPool = TP_CASTERS_SUN(3) > 0.0f && max(abs(p.x), abs(p.z)) <= h + kShadowRayStart && p.y < rim;
  bool underWater = inPool && p.y < level;
  // Under the water: up the refracted ray to the surface, then on in the air.
  // The disc narrows by 1/ior across the plane of incidence and by
  // cos(air) / (ior cos(water)) in it: their geometric mean.
  float ior = TP_CASTERS_POOL(3);
  vec3 inWater = underWater ? -refract(-toSun, vec3(0.0f, 1.0f, 0.0f), 1.0f / ior) : toSun;
  float narrowing = underWater ? sqrt(toSun.y / inWater.y) / ior : 1.0f;
  vec3 q = underWater ? p + inWater * ((level - p.y) / inWater.y) : p;
  float behind = narrowing * distance(p, q);
  // One leg in the open, two under the water: each through its own opening
  // (the water's at the level, then the rim), its casters on its side of the
  // level. A loop, so that the shader holds the leg's code once, and none
  // with nothing to cast a shadow: lavapipe skips a loop no pixel is in, where
  // it runs every branch of an if.
  bool anyCaster = TP_CASTERS_SUN(1) > 0.0f || TP_CASTERS_SUN(2) > 0.0f || inPool;
  float legs = 1.0f, opening = 1.0f;
  TP_DONT_UNROLL for (int leg = !anyCaster ? 2 : underWater ? 0 : 1; leg < 2; ++leg) {
    bool water = leg == 0;
    vec3 from = water ? p : q, dir = water ? inWater : toSun;
    float legRadius = water ? radius * narrowing : radius;
    float top = water ? level : rim;
    legs = min(legs, legSunVisibility(TP_CASTERS_ARG from, dir, legRadius, water ? -1e30f : (underWater ? level : -1e30f),
                                      water ? level : 1e30f, water ? distance(p, q) : 1e30f,
                                      water ? 0.0f : behind, p));
    // The air leg's rim is (top - level) / toSun.y on: the disc widens there as for the casters.
    float widened = water || !underWater
                        ? legRadius
                        : legRadius * (1.0f + behind / max((top - level) / dir.y, kShadowRayStart));
    opening *= openingSunVisibility(from, dir, inPool ? widened : 1.0f, h, inPool ? top : -1e30f);
  }
  return legs * opening;
}

// Whether the sun's central ray from p reaches the sky (1) or not (0): bent
// at the level under the water, past the spheres and boxes each leg can meet
// (as sunVisibility counts them), out through the pool's walls and rim. The
// point test of the light the water scatters (water_scattering.h), which
// averages it along a path: far cheaper than the disc's share, whose
// penumbra the average softens anyway.
TP_INLINE float sunRayOpen(TP_CASTERS_PARAM vec3 p, vec3 toSun) {
  if (toSun.y <= 0.0f) return 0.0f;
  float h = TP_CASTERS_POOL(0), rim = TP_CASTERS_POOL(1), level = TP_CASTERS_POOL(2);
  bool inPool = TP_CASTERS_SUN(3) > 0.0f && max(abs(p.x), abs(p.z)) <= h && p.y < rim;
  bool underWater = inPool && p.y < level;
  vec3 inWater = underWater ? -refract(-toSun, vec3(0.0f, 1.0f, 0.0f), 1.0f / TP_CASTERS_POOL(3)) : toSun;
  vec3 q = underWater ? p + inWater * ((level - p.y) / inWater.y) : p;
  // Where the ray reaches the rim's height: out of the opening, or into a wall.
  vec3 top = q + toSun * (max(rim - q.y, 0.0f) / toSun.y);
  if (inPool && max(max(abs(q.x), abs(q.z)), max(abs(top.x), abs(top.z))) > h) return 0.0f;
  float open = 1.0f;
  TP_DONT_UNROLL for (int leg = underWater ? 0 : 1; leg < 2; ++leg) {
    bool water = leg == 0;
    vec3 from = water ? p : q, dir = water ? inWater : toSun;
    float length = water ? distance(p, q) : 1e30f;
    float minY = water || !underWater ? -1e30f : level, maxY = water ? level : 1e30f;
    for (uint i = 0u; i < (kSphereShadows ? uint(TP_CASTERS_SUN(1)) : 0u); ++i) {
      vec4 s = TP_CASTERS.spheres[i];
      float hit = raySphere(from, dir, s);
      if (s.y + s.w >= minY && s.y - s.w <= maxY && hit > 0.0f && hit < length) open = 0.0f;
    }
    for (uint b = 0u; b < (kBoxShadows ? uint(TP_CASTERS_SUN(2)) : 0u); ++b) {
      vec4 center = TP_CASTERS.boxCenter[b], halfSize = TP_CASTERS.boxHalfSize[b];
      if (center.y + halfSize.y < minY || center.y - halfSize.y > maxY) continue;
      if (rayMeetsBox(from + kShadowRayStart * dir, dir, center, halfSize)) open = 0.0f;
    }
  }
  return open;
}

// Glass sphere `slot`'s table at `across` radii from its axis (less than
// TP_GLASS_TABLE_REACH) and `along` radii past its centre (>= 0): between
// its four nearest values; past the last row, the last row's.
TP_INLINE float glassTableAt(TP_GLASS_PARAM uint slot, float across, float along) {
  float u = across * float(TP_GLASS_TABLE_COLUMNS - 1) / float(TP_GLASS_TABLE_REACH);
  float v = min(along / float(TP_GLASS_TABLE_DEPTH), 1.0f) * float(TP_GLASS_TABLE_ROWS - 1);
  uint column = min(uint(u), uint(TP_GLASS_TABLE_COLUMNS - 2)), row = min(uint(v), uint(TP_GLASS_TABLE_ROWS - 2));
  float fu = u - float(column), fv = v - float(row);
  uint at = slot * uint(TP_GLASS_TABLE_SIZE) + row * uint(TP_GLASS_TABLE_COLUMNS) + column;
  float near = mix(TP_GLASS_TABLE(at), TP_GLASS_TABLE(at + 1u), fu);
  float far = mix(TP_GLASS_TABLE(at + uint(TP_GLASS_TABLE_COLUMNS)), TP_GLASS_TABLE(at + uint(TP_GLASS_TABLE_COLUMNS) + 1u), fu);
  return mix(near, far, fv);
}

// The sun at p relative to the open sun past the glass spheres in the air,
// for a point in the air: their shadows and caustics, from their tables
// (shading/glass_caustic.hpp).
TP_INLINE float glassSunShareInAir(TP_CASTERS_PARAM TP_GLASS_PARAM vec3 p, vec3 toSun) {
  float share = 1.0f;
  for (uint i = 0u; i < (kGlassShadows && toSun.y > 0.0f ? uint(TP_CASTERS_GLASS(0)) : 0u); ++i) {
    vec4 s = TP_CASTERS.glassSpheres[i];
    vec3 v = (p - vec3(s)) / s.w;
    float along = -dot(v, toSun), across2 = max(dot(v, v) - along * along, 0.0f);
    // The table read in a loop only the pixels in its reach enter: lavapipe
    // runs both sides of an if for every pixel, and skips a loop none is in.
    bool reached = along >= 0.0f && across2 < float(TP_GLASS_TABLE_REACH * TP_GLASS_TABLE_REACH);
    for (int k = 0; k < (reached ? 1 : 0); ++k) share *= glassTableAt(TP_GLASS_ARG i, sqrt(across2), along);
  }
  return share;
}

// Where the sun's central ray through p meets the height `top`, in x and z:
// the glass boxes' grids' coordinates across their layers. Under the water
// (`inWater`, the ray's direction there, from `q` at the level) the ray is
// followed up to the level first. Light the box lets straight through keeps
// these coordinates all the way down.
TP_INLINE vec2 sunSheared(vec3 p, vec3 toSun, vec3 inWater, bool underWater, float level, float top) {
  vec3 q = underWater ? p + inWater * ((level - p.y) / inWater.y) : p;
  return vec2(q.x, q.z) + vec2(toSun.x, toSun.z) * ((top - q.y) / toSun.y);
}

// The glass boxes' light at p, relative to the open sun's: between the
// eight nearest points of each grid that holds p (shading/glass_box_light.hpp).
TP_INLINE float glassBoxesSunShare(TP_CASTERS_PARAM TP_GLASS_PARAM vec3 p, vec3 toSun, vec3 inWater,
                                   bool underWater) {
  float share = 1.0f;
  float level = TP_CASTERS_POOL(2);
  for (uint i = 0u; i < (kGlassShadows ? uint(TP_CASTERS_GLASS(1)) : 0u); ++i) {
    vec4 square = TP_CASTERS.glassBoxGrids[2u * i], heights = TP_CASTERS.glassBoxGrids[2u * i + 1u];
    vec2 a = sunSheared(p, toSun, inWater, underWater, level, heights.z);
    float side = float(TP_GLASS_BOX_SIDE - 1);
    vec2 uv = (a - vec2(square.x, square.y)) / vec2(square.z - square.x, square.w - square.y) * side;
    float w = (p.y - heights.x) / (heights.y - heights.x) * float(TP_GLASS_BOX_LAYERS - 1);
    bool inside = min(uv.x, uv.y) >= 0.0f && max(uv.x, uv.y) < side && w >= 0.0f && w < float(TP_GLASS_BOX_LAYERS - 1);
    // The grid read in a loop only the pixels inside enter (as glassSunShareInAir's).
    for (int k = 0; k < (inside ? 1 : 0); ++k) {
      uint u = uint(uv.x), v = uint(uv.y), l = uint(w);
      vec2 f = uv - vec2(float(u), float(v));
      float fl = w - float(l);
      uint at = uint(TP_GLASS_BOX_GRIDS_START) + i * uint(TP_GLASS_BOX_SIZE) +
                (l * uint(TP_GLASS_BOX_SIDE) + v) * uint(TP_GLASS_BOX_SIDE) + u;
      float layers[2];
      for (int j = 0; j < 2; ++j) {
        uint base = at + uint(j) * uint(TP_GLASS_BOX_SIDE * TP_GLASS_BOX_SIDE);
        float near = mix(TP_GLASS_TABLE(base), TP_GLASS_TABLE(base + 1u), f.x);
        float far = mix(TP_GLASS_TABLE(base + uint(TP_GLASS_BOX_SIDE)), TP_GLASS_TABLE(base + uint(TP_GLASS_BOX_SIDE) + 1u), f.x);
        layers[j] = mix(near, far, f.y);
      }
      share *= mix(layers[0], layers[1], fl);
    }
  }
  return share;
}

// The same for any point: under the water it is read on the sun's ray up
// from p, past where that ray leaves the water by its leg under the water
// times how much the water narrows the disc (as sunVisibility widens the
// disc for the casters); and the glass boxes' grids.
TP_INLINE float glassSunShare(TP_CASTERS_PARAM TP_GLASS_PARAM vec3 p, vec3 toSun) {
  if (!kGlassShadows || toSun.y <= 0.0f) return 1.0f;
  float h = TP_CASTERS_POOL(0), level = TP_CASTERS_POOL(2);
  bool underWater = TP_CASTERS_SUN(3) > 0.0f && max(abs(p.x), abs(p.z)) <= h && p.y < level;
  vec3 inWater = underWater ? -refract(-toSun, vec3(0.0f, 1.0f, 0.0f), 1.0f / TP_CASTERS_POOL(3)) : toSun;
  vec3 q = underWater ? p + inWater * ((level - p.y) / inWater.y) : p;
  float narrowing = underWater ? sqrt(toSun.y / inWater.y) / TP_CASTERS_POOL(3) : 1.0f;
  return glassSunShareInAir(TP_CASTERS_ARG TP_GLASS_ARG q - toSun * (narrowing * distance(p, q)), toSun) *
         glassBoxesSunShare(TP_CASTERS_ARG TP_GLASS_ARG p, toSun, inWater, underWater);
}

#ifndef __cplusplus
// The share of the sun's disc the frame's casters leave in view at p, times
// what the glass spheres let through (glassSunShare); all of it in the
// variants for scenes where nothing casts a shadow (TP_NO_SHADOWS,
// cmake/shaders.cmake), which hold none of the code above.
// And whether the sun's central ray from p is open (sunRayOpen).
// And the share for a point out of the pool (openAirSunVisibility).
// The direction to the sun, read as the casters are (TP_CASTERS_SUN).
vec3 frameToSun() {
  const int i = TP_UNIFORM_INDEX_BASE;
  return vec3(frame.sunDirection[i], frame.sunDirection[i + 1], frame.sunDirection[i + 2]);
}
#ifdef TP_NO_SHADOWS
float frameSunShare(vec3 p) { return 1.0; }
float frameSunRayOpen(vec3 p) { return 1.0; }
float frameOpenAirSunShare(vec3 p) { return 1.0; }
#else
float frameSunShare(vec3 p) { return sunVisibility(p, frameToSun()) * glassSunShare(p, frameToSun()); }
float frameSunRayOpen(vec3 p) { return sunRayOpen(p, frameToSun()); }
float frameOpenAirSunShare(vec3 p) {
  return openAirSunVisibility(p, frameToSun()) * glassSunShareInAir(p, frameToSun()) *
         glassBoxesSunShare(p, frameToSun(), frameToSun(), false);
}
#endif
#endif

TP_END

#endif
