// What a ray leaving a surface sees, by analytic casts: the water's
// reflected and refracted rays and the glass's. Bindings 0, 1, 3, 4 and 6-8;
// the includer declares the rest. In the air: the spheres and boxes, the
// ground, the walls above the water, the water as flat, else the sky. Below
// the water: the pool (walls, and the floor lit through the caustics) and
// the objects, through the absorbing, scattering water.
//
// A shader cannot recurse, and lavapipe compiles every call inlined: each
// cast written out once more costs seconds of pipeline compilation. So the
// casts come in loops that follow one ray after another (glass.frag,
// backdrop below), each cast written once.
#ifndef TP_LIB_SCENE_RAYS
#define TP_LIB_SCENE_RAYS
#include "shared/glass.h"
#include "shared/objects.h"
#include "shared/shading.h"
#include "lib/caustics_lookup.glsl"
#include "lib/glossy_lookup.glsl"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
#include "lib/ray_differential.glsl"  // reads `frame` in place
#include "shared/water_scattering.h"  // reads `frame` in place
layout(binding = 1) uniform sampler2D skyTexture;
layout(binding = 3) uniform Pool { PoolParams pool; };
layout(binding = 4) uniform Objects { SceneObjects objects; };  // shared/object_cast.h's
layout(binding = 6) uniform sampler2D caustics;
layout(binding = 7) uniform sampler2D glossyMap;  // the glossy walls' and spheres' environment
layout(binding = 8) readonly buffer FloorVertices { vec4 floorVertices[]; };  // shared/pool_trace.h's
#include "shared/pool_light.h"
#include "shared/object_cast.h"

// The sky texture has one level: level 0 is what an implicit lookup reads,
// and compute shaders (water_surface_deferred.comp) have no implicit lookups.
// (The caustics are gathered, which reads level 0.)
vec3 sky(vec3 direction) { return textureLod(skyTexture, directionToEquirect(direction), 0.0).rgb; }

// The same averaged over a ray's footprint, rd its differential (of a unit
// direction: radians a pixel), its wider direction taken: what a lens
// spreads over many texels comes out as their mean. The mip level is the
// one whose lookup spreads as far as a pixel's box does: level L averages
// boxes of w = 2^L texels (sky_mips.comp) and the bilinear lookup adds a
// tent of half-width w, standard deviation w / 2 in all, against the box's
// p / sqrt(12) for a pixel p texels wide, so w = p / sqrt(3) (measured: the
// error of GlassTest.TheSkyThroughGlassIsFilteredAtOneSample is least
// there, 0.0310, against 0.0330 and 0.0327 with the footprint doubled and
// halved, and 0.0361 at level 0). Level 0 where a pixel spans less than
// sqrt(3) texels.
vec3 skyFiltered(vec3 direction, RayDifferential rd) {
  const float spread = max(length(rd.directionX), length(rd.directionY));
  const float texel = 2.0 * kPi / float(textureSize(skyTexture, 0).x);
  return textureLod(skyTexture, directionToEquirect(direction), log2(max(spread / (sqrt(3.0) * texel), 1.0))).rgb;
}

// What the water scatters into the ray from `start` along `dir` (unit, under
// the water) over `length`; nothing, and no code, in the variants for water
// that does not scatter.
#ifdef TP_SCATTERING
vec3 inScatter(vec3 start, vec3 dir, float length) {
  return waterInScatter(pool.extinction.rgb, pool.scattering, pool.water.x, pool.water.y, uint(pool.extinction.w),
                        poolLightAround(pool, start + (0.5 * length) * dir), start, dir, length);
}
#else
vec3 inScatter(vec3 start, vec3 dir, float length) { return vec3(0.0); }
#endif

// What lies round glass, and round the rays that leave it: the pool's water
// below its rest level, the air.
GlassSurround glassSurround() { return GlassSurround(pool.water.x, pool.box.x, pool.water.y); }

// Whether p lies in the pool's water, below its rest level.
bool inPoolWater(vec3 p) { return inSurroundingWater(glassSurround(), p); }

// The sun through the waves at `met` under the water, relative to flat
// water: the caustics texture at its light line.
float causticsAt(vec3 met) { return causticsRatio(caustics, pool, frame.sunDirection.xyz, met); }

// The sun at `met` under the water: its share in view, through the waves.
float sunUnderWater(vec3 met) { return frameSunShare(met) * causticsAt(met); }

// The pool's wall or floor `hit` met by a ray under the water along t, at
// `sunShare` of the sun (sunUnderWater); the floor's tiles and the wall's
// bricks filtered over `footprint` (hitFootprint).
vec3 poolSurfaceSeen(PoolHit hit, vec3 t, vec2 footprint, float sunShare) {
  if (hit.floor) return poolFloorRadiance(pool, frame, hit.position, hit.normal, footprint, sunShare);
  return glossyRadiance(glossyMap, poolWallRadiance(pool, frame, hit.position, hit.normal, footprint, sunShare), t,
                        hit.normal, pool.wallGloss.xy);
}

// What a ray in the air meets first of the ground, the walls above the
// water and the water (flat at its rest level), objects left out: how far,
// which, and the normal there (a wall's inward one).
const uint kMetNothing = 0u, kMetGround = 1u, kMetWall = 2u, kMetWater = 3u;
struct AirHit {
  float distance;  // 1e30 for nothing
  uint met;
  vec3 normal;
};

AirHit airSurface(vec3 p, vec3 r) {
  AirHit hit = AirHit(1e30, kMetNothing, vec3(0.0, 1.0, 0.0));
  const GroundParams ground = pool.ground;
  const float hole = ground.plane.w;  // 0: no pool
  const bool inHole = max(abs(p.x), abs(p.z)) < hole && p.y <= ground.plane.y;
  // Where the ray is in the hole (at p, or where it goes down through the
  // ground's plane), or meets the ground.
  float sEnter = inHole ? 0.0 : -1.0;
  if (!inHole && r.y < 0.0 && p.y > ground.plane.y) {
    const float s = (ground.plane.y - p.y) / r.y;
    const vec3 q = p + s * r;
    const float reach = max(abs(q.x), abs(q.z));
    if (reach < hole) {
      sEnter = s;
    } else if (reach <= ground.plane.x) {
      hit = AirHit(s, kMetGround, vec3(0.0, 1.0, 0.0));
    }
  }
  if (sEnter >= 0.0) {
    const vec3 q = p + sEnter * r;
    const vec2 walls = poolWallDistances(pool, q, r);
    const float sWall = min(walls.x, walls.y);
    const float toWater = r.y < 0.0 ? (pool.water.x - q.y) / r.y : 1e30;
    if (toWater < sWall) {
      hit = AirHit(sEnter + toWater, kMetWater, vec3(0.0, 1.0, 0.0));
    } else if (q.y + sWall * r.y <= pool.box.y) {  // below the rim; past it the ray leaves the hole
      hit = AirHit(sEnter + sWall, kMetWall, poolWallNormal(walls, r));
    }
  }
  return hit;
}

// The ground or a wall met in the air at q along r (AirHit), at `sunShare`
// of the sun; the ground's checker and the wall's bricks filtered over
// `footprint` (hitFootprint).
vec3 airSurfaceSeen(AirHit hit, vec3 q, vec3 r, vec2 footprint, float sunShare) {
  if (hit.met == kMetGround) return groundRadiance(pool.ground, frame, q.xz, footprint, hit.normal, sunShare);
  return glossyRadiance(glossyMap, poolWallRadiance(pool, frame, q, hit.normal, footprint, sunShare), r, hit.normal,
                        pool.wallGloss.xy);
}

// How far a ray under the water from p along r goes up to the flat surface
// at the rest level, or -1 when it meets a wall first or goes down.
float toSurfaceFromBelow(vec3 p, vec3 r) {
  if (r.y <= 0.0) return -1.0;
  const float s = (pool.water.x - p.y) / r.y;
  const vec2 walls = poolWallDistances(pool, p, r);
  return min(walls.x, walls.y) > s ? s : -1.0;
}

// The flat water met by a ray along r, from the side `fromWater` says: the
// exact Fresnel reflectance (1 past the critical angle), the reflected ray,
// and the refracted one (the zero vector past the critical angle).
struct FlatWaterSplit {
  float reflectance;
  vec3 reflected, refracted;
};

FlatWaterSplit flatWaterSplit(vec3 r, bool fromWater) {
  const vec3 facing = vec3(0.0, fromWater ? -1.0 : 1.0, 0.0);
  const float reflectance =
      fromWater ? fresnelDielectric(r.y, pool.water.y, 1.0) : fresnelDielectric(-r.y, 1.0, pool.water.y);
  return FlatWaterSplit(reflectance, reflect(r, facing),
                        refract(r, facing, fromWater ? pool.water.y : 1.0 / pool.water.y));
}

// The index of the medium a ray is in: the water's or the air's.
float mediumIndex(bool water) { return water ? pool.water.y : 1.0; }

// A glass sphere or box met at p along `dir` by a ray in the water or in the
// air: its exact paths (shared/glass.h). Lavapipe runs both branches for
// every pixel: the slots are held in range.
GlassExit glassObjectExit(ObjectHit object, vec3 p, vec3 dir, bool water) {
  if (object.box != kSkipNoSphere) {
    const uint box = min(object.box, uint(TP_MAX_BOXES - 1));
    return glassBoxPaths(p, dir, object.normal, objects.boxCenter[box], objects.boxHalfSize[box], object.glass,
                         mediumIndex(water), glassSurround());
  }
  const float radius = objects.spheres[min(object.sphere, uint(TP_MAX_SPHERES - 1))].w;
  return glassSphereExactExit(p, dir, object.normal, radius, object.glass, mediumIndex(water), glassSurround());
}

// The footprints of the two rays glass met along `dir` sends on
// (glassPathDifferentials), rd the ray's differential carried to the entry.
GlassDifferentials glassDifferentials(ObjectHit object, GlassExit g, vec3 dir, RayDifferential rd) {
  const bool box = object.box != kSkipNoSphere;
  const float yaw = box ? objects.boxCenter[min(object.box, uint(TP_MAX_BOXES - 1))].w : 0.0;
  const float curvature = box ? 0.0 : 1.0 / objects.spheres[min(object.sphere, uint(TP_MAX_SPHERES - 1))].w;
  return glassPathDifferentials(g, dir, object.normal, curvature, yaw, rd);
}

// The footprint of the pixel where its ray, origin + s dir, meets a surface
// with normal n, each differential carried along the ray to the surface's
// tangent plane: in xz on the floor and the ground, along the wall and down
// it on a wall (shared/pool.h's poolWallCoordinates).
vec2 hitFootprint(RayDifferential rd, vec3 dir, float s, vec3 n) {
  const RayDifferential at = transferredDifferential(rd, dir, s, n);
  const vec3 spread = abs(at.originX) + abs(at.originY);
  if (abs(n.y) > 0.5) return spread.xz;
  return vec2(abs(n.x) > 0.5 ? spread.z : spread.x, spread.y);
}

#if defined(TP_GLASS) || defined(TP_BACKDROP)
// What a glass sphere or box met by the water's rays shows along one of its exact
// paths, and what a glossy sphere's probe sees from its centre
// (glossy_probe.comp, with TP_BACKDROP): the backdrop, the scene without its objects, in straight-line code
// (a shader cannot recurse into the casts that met the glass). Lavapipe runs
// every branch of the water's shader for every pixel (masked) and every loop
// at least once, so what is written here costs the whole water surface. It
// shades what it meets as the water's own rays do, the floor's relief, the
// walls' pattern and gloss, the shadows and the caustics included, but
// leaves out the light the water scatters: with the floor flat at its mean
// depth, plain walls and no shadows, a weak lens (glass under the water)
// and glass in the surface's mirror from below showed the difference
// (docs/glass.md), and the water pass of scenes/glass.json now takes 1.1
// times for the floor's walk and 1.1 times more for the rest. At the flat
// water the ray into the air looks up the sky; from below, the reflection
// is left out unless the surface reflects it all. rd, the ray's
// differential at p, is carried through the flat water to the floor or the
// ground, whose pattern it filters. The sky it looks up at level 0:
// filtered, it came no nearer the reference
// (GlassTest.GlassShowsInTheWatersReflectionsAndRefractions against 256
// rays a pixel: 0.0365 either way) and cost every water pixel.
// The sky where a backdrop's ray ends: at level 0 or, for a probe
// (TP_BACKDROP), whose texels each cover several of the sky's, their mean
// over the ray's footprint: a point would miss the sun's disc, far smaller
// than a probe's texel.
vec3 backdropSky(vec3 r, RayDifferential rd) {
#if defined(TP_BACKDROP)
  return skyFiltered(r, rd);
#else
  return sky(r);
#endif
}

vec3 backdrop(vec3 p, vec3 r, RayDifferential rd) {
  vec3 sum = vec3(0.0), weight = vec3(1.0);
  // What the ray ends on, shaded once below: the ground, a wall, the floor, or the sky.
  AirHit end = AirHit(1e30, kMetNothing, vec3(0.0, 1.0, 0.0));
  bool water = inPoolWater(p);
  if (!water) {
    end = airSurface(p, r);
    if (end.met == kMetWater) {
      const FlatWaterSplit split = flatWaterSplit(r, false);
      const vec3 up = vec3(0.0, 1.0, 0.0);
      sum = split.reflectance * backdropSky(split.reflected, rd);
      weight = vec3(1.0 - split.reflectance) / (pool.water.y * pool.water.y);  // into the water: 1 / n^2
      rd = refractedDifferential(transferredDifferential(rd, r, end.distance, up), r, split.refracted, up,
                                 1.0 / pool.water.y);
      p += end.distance * r;
      r = split.refracted;
      water = true;
    }
  } else {
    const float up = toSurfaceFromBelow(p, r);
    const FlatWaterSplit split = flatWaterSplit(r, true);
    if (up > 0.0 && dot(split.refracted, split.refracted) > 0.0) {  // out into the sky
      weight = (1.0 - split.reflectance) * exp(-pool.extinction.rgb * up) * (pool.water.y * pool.water.y);  // out: n^2
      r = split.refracted;
      water = false;
    } else if (up > 0.0) {  // reflected whole
      weight = exp(-pool.extinction.rgb * up);
      const vec3 down = vec3(0.0, -1.0, 0.0);
      rd = reflectedDifferential(transferredDifferential(rd, r, up, down), down);
      p += up * r;
      r = split.reflected;
    }
  }
  float travel = 0.0;  // through the water
  PoolHit poolMet = poolHit(1e30, vec3(0.0), vec3(0.0, 1.0, 0.0), false);
  if (water) {
    // A wall, or the floor with its relief, as the water's own rays meet it.
    poolMet = tracePool(pool, p, r);
    end = AirHit(poolMet.distance, poolMet.floor ? kMetGround : kMetWall, poolMet.normal);
    travel = end.distance;
  }
  const vec3 q = p + end.distance * r;
  const vec2 footprint = hitFootprint(rd, r, end.distance, end.normal);
  // As the water's and the glass's own rays shade what they meet, shadows
  // and caustics included.
  const float sunShare = water ? sunUnderWater(q) : frameSunShare(q);
  const vec3 seen = end.met == kMetNothing ? backdropSky(r, rd)
                    : water                ? poolSurfaceSeen(poolMet, r, footprint, sunShare)
                                           : airSurfaceSeen(end, q, r, footprint, sunShare);
  return sum + weight * seen * exp(-pool.extinction.rgb * travel);
}
#endif

#ifdef TP_GLASS

// A glass sphere or box met at p along `dir`: the backdrop along its two
// exact paths, one after the other, each with its footprint (rd: the ray's
// differential carried to p), the ray in the water or in the air.
vec3 glassSeen(ObjectHit object, vec3 p, vec3 dir, RayDifferential rd, bool water) {
  const GlassExit g = glassObjectExit(object, p, dir, water);
  const GlassDifferentials footprints = glassDifferentials(object, g, dir, rd);
  vec3 sum = vec3(0.0);
  TP_DONT_UNROLL for (int k = 0; k < 2; ++k) {
    const vec3 from = k == 0 ? g.exitPoint : p, along = k == 0 ? g.leaving : g.reflected;
    sum += (k == 0 ? glassLeavingWeight(g) : g.reflectance) *
           backdrop(from, along, k == 0 ? footprints.leaving : footprints.reflected);
  }
  return sum;
}
#endif

// An object met at p along `dir` by a ray in the water or the air, at
// `sunShare` of the sun; rd, the ray's differential carried to p, filters
// what glass shows. The variants for scenes without glass (TP_GLASS
// undefined) meet none.
vec3 objectSeen(ObjectHit object, vec3 p, vec3 dir, float sunShare, RayDifferential rd, bool water) {
#ifdef TP_GLASS
  if (object.glass > 0.0) return glassSeen(object, p, dir, rd, water);
#endif
  return glossyRadiance(glossyMap, object.albedo / kPi * objectIrradiance(pool, frame, p, object.normal, sunShare), dir,
                        object.normal, object.material);
}

// What a ray leaving p (inside the pool, below the rim, in the air) along r
// upwards sees: an object, the part of a wall above the water, or the sky
// over the rim.
vec3 radianceAbove(vec3 p, vec3 r) {
  const vec2 walls = poolWallDistances(pool, p, r);
  const float sWall = min(walls.x, walls.y);
  const bool wall = sWall > 0.0 && p.y + sWall * r.y <= pool.box.y;  // below the rim
  const ObjectHit object = castObjects(objects.count.xy, p, r, wall ? sWall : 1e30, kSkipNoSphere);
  if (object.distance <= 0.0 && !wall) return sky(r);
  // One sun share for what is met (the shader holds its code once).
  const float distance = object.distance > 0.0 ? object.distance : sWall;
  const float sunShare = frameSunShare(p + distance * r);
  if (object.distance > 0.0) return objectSeen(object, p + distance * r, r, sunShare, kNoFootprint, false);
  // The wall's bricks point-sampled, as the reference tracer does: derivatives
  // are not to be had in this divergent branch.
  const vec3 wallNormal = poolWallNormal(walls, r);
  return glossyRadiance(glossyMap, poolWallRadiance(pool, frame, p + sWall * r, wallNormal, vec2(0.0), sunShare), r,
                        wallNormal, pool.wallGloss.xy);
}

// What a ray leaving p under the water along t sees: the pool (walls, and the
// floor lit through the caustics) or an object in front of it, attenuated
// along its path through the water.
vec3 radianceBelow(vec3 p, vec3 t, RayDifferential rd) {
  const PoolHit hit = tracePool(pool, p, t);
  const ObjectHit object = castObjects(objects.count.zw, p, t, hit.distance, kSkipNoSphere);
  const float distance = object.distance > 0.0 ? object.distance : hit.distance;
  // One sun share for what is met (the shader holds its code once).
  const vec3 met = p + distance * t;
  const float sunShare = sunUnderWater(met);
  const vec3 radiance = object.distance > 0.0
                            ? objectSeen(object, met, t, sunShare,
                                         transferredDifferential(rd, t, distance, object.normal), true)
                            : poolSurfaceSeen(hit, t, hitFootprint(rd, t, hit.distance, hit.normal), sunShare);
  return radiance * exp(-pool.extinction.rgb * distance) + inScatter(p, t, distance);
}

#endif
