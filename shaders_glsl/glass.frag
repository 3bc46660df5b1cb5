#version 450
#extension GL_GOOGLE_include_directive : require
// A glass sphere's or, with TP_GLASS_BOX, a glass box's front faces. A
// sphere: two-interface refraction in image space (Wyman 2005). The view ray
// is refracted into the glass at the front surface; the exit point is found
// by a binary search along the refracted ray against the back faces' view
// depth (glass_back.frag), the exit normal read there; the ray is refracted
// out (or, under total internal reflection, reflected back in and taken as
// if it left). A box: the exact path through it, its faces' reflections
// inside included (shared/glass.h). The exact Fresnel reflectance of the
// front surface mixes in the reflected ray. Both rays look up what they meet
// by the analytic casts the water's rays use (lib/scene_rays.glsl): the
// ground, the pool, its water as flat at its rest level, the objects, the
// sky (shared/glass.h has the model, which the CPU reference shares).
#include "lib/scene_rays.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
// xyz: outward normal of the nearest back face, w: its view depth (0: none).
layout(binding = 2) uniform sampler2D backFaces;
layout(binding = 5) uniform Medium { CameraMedium medium; };
#ifdef TP_GLASS_BOX
layout(push_constant) uniform Push { GlassBoxParams params; };
#else
layout(push_constant) uniform Push { GlassSphereParams params; };
#endif

#ifndef TP_GLASS_BOX
// Whether world point p lies in front of the back face under it (inside the
// glass, the exit not yet passed), with that back face's normal.
bool beforeBackFace(vec3 p, out vec3 backNormal) {
  backNormal = vec3(0.0);
  vec2 pixel = screenPixel(frame, p);
  if (any(lessThan(pixel, vec2(0.0))) || any(greaterThanEqual(pixel, frame.viewport.xy))) return false;
  vec4 back = texelFetch(backFaces, ivec2(pixel), 0);
  backNormal = back.xyz;
  return back.w > 0.0 && -(frame.view * vec4(p, 1.0)).z < back.w;
}

// The sphere's exact paths with the exit searched for in image space: the
// front surface's reflection and refraction are the exact ones, the exit
// point, its normal and the ray that leaves are the search's.
GlassExit searchedExit(GlassExit exact) {
  const vec3 inside = exact.inside;
  // The exit lies within the longest chord of the sphere, its diameter. The
  // entry point itself is before the back face behind it.
  float before = 0.0, after = 2.0 * params.sphere.w;
  vec3 exitNormal;
  beforeBackFace(worldPosition, exitNormal);
  for (uint i = 0u; i < params.search.x; ++i) {
    const float mid = 0.5 * (before + after);
    vec3 backNormal;
    if (beforeBackFace(worldPosition + mid * inside, backNormal)) {
      before = mid;
      exitNormal = backNormal;
    } else {
      after = mid;
    }
  }
  GlassExit g = exact;
  g.insideLength = 0.5 * (before + after);
  g.exitPoint = worldPosition + g.insideLength * inside;
  g.exitNormal = exitNormal;
  g.exitIor = params.glass.x / surroundIndexAt(glassSurround(), g.exitPoint);
  // No back face found at all (a sliver at the silhouette): straight through.
  g.leaving = dot(exitNormal, exitNormal) > 0.0 ? glassExitDirection(inside, normalize(exitNormal), g.exitIor) : inside;
  return g;
}
#endif

// The rays followed from one glass pixel, one after another: its two, and
// two more at each split (the flat water, other glass) while
// there is room; past that, the part going into the air is looked up in
// the sky and the rest left out.
const int kGlassRays = 6;
struct GlassRay {
  vec3 origin, dir;
  vec3 weight;           // its share of the pixel
  bool water;            // it starts in the pool's water
  uint skip;             // the glass sphere it leaves (castObjects)
  RayDifferential diff;  // its pixel's footprint, carried from the glass through the flat water and other glass
};

void main() {
  const vec3 n = normalize(worldNormal);
  const vec3 view = normalize(worldPosition - frame.cameraPosition.xyz);
  // The view ray is in the camera's medium: the water pass draws over the
  // glass the camera sees across the water's surface.
  const bool cameraInWater = medium.extinction.w > 0.0;
  // The view ray's footprint, taken here where every lane of the quad runs
  // (the view ray and the point on the face are smooth across the quad).
  const RayDifferential viewFootprint = rayDifferential(worldPosition, view);
#ifdef TP_GLASS_BOX
  const GlassExit entry = glassBoxPaths(worldPosition, view, n, params.center, params.halfSize, params.glass.x,
                                        mediumIndex(cameraInWater), glassSurround());
  const uint self = kSkipNoSphere;
  const GlassDifferentials footprints =
      glassPathDifferentials(entry, view, n, 0.0, params.center.w, viewFootprint);
#else
  const GlassExit exact = glassSphereExactExit(worldPosition, view, n, params.sphere.w, params.glass.x,
                                               mediumIndex(cameraInWater), glassSurround());
  const GlassExit entry = searchedExit(exact);
  const uint self = params.search.y;
  // The footprints along the exact paths: the search's exit point and normal
  // jump from texel to texel, and across the silhouette's quads.
  const GlassDifferentials footprints =
      glassPathDifferentials(exact, view, n, 1.0 / params.sphere.w, 0.0, viewFootprint);
#endif
  const float reflectance = entry.reflectance;
  const vec3 leaving = entry.leaving, exitPoint = entry.exitPoint, reflected = entry.reflected;
  GlassRay rays[kGlassRays];
  rays[0] =
      GlassRay(exitPoint, leaving, vec3(glassLeavingWeight(entry)), inPoolWater(exitPoint), self, footprints.leaving);
  rays[1] =
      GlassRay(worldPosition, reflected, vec3(reflectance), inPoolWater(worldPosition), self, footprints.reflected);
  int count = 2;
  vec3 radiance = vec3(0.0);
  TP_DONT_UNROLL for (int k = 0; k < kGlassRays; ++k) {
    if (k >= count) break;
    const GlassRay ray = rays[k];
    // What the ray meets of the pool, the water's surface and the ground,
    // then whether an object is nearer.
    float up = -1.0, limit;
    PoolHit poolMet = poolHit(1e30, vec3(0.0), vec3(0.0, 1.0, 0.0), false);
    AirHit airMet = AirHit(1e30, kMetNothing, vec3(0.0, 1.0, 0.0));
    if (ray.water) {
      up = toSurfaceFromBelow(ray.origin, ray.dir);
      if (up <= 0.0) poolMet = tracePool(pool, ray.origin, ray.dir);
      limit = up > 0.0 ? up : poolMet.distance;
    } else {
      airMet = airSurface(ray.origin, ray.dir);
      limit = airMet.distance;
    }
    const ObjectHit object =
        castObjects(ray.water ? objects.count.zw : objects.count.xy, ray.origin, ray.dir, limit, ray.skip);
    const bool onObject = object.distance > 0.0;
    const float distance = onObject ? object.distance : limit;
    const vec3 met = ray.origin + distance * ray.dir;
    vec3 weight = ray.weight;
    if (ray.water) {
      radiance += weight * inScatter(ray.origin, ray.dir, distance);
      weight *= exp(-pool.extinction.rgb * distance);
    }
    const bool room = count + 2 <= kGlassRays;
    if (onObject && object.glass > 0.0) {
      // Other glass: its two exact paths.
      const GlassExit g = glassObjectExit(object, met, ray.dir, ray.water);
      if (!room) {
        radiance += weight * (glassLeavingWeight(g) * sky(g.leaving) + g.reflectance * sky(g.reflected));
        continue;
      }
      const vec3 exit = g.exitPoint;
      const GlassDifferentials footprints =
          glassDifferentials(object, g, ray.dir, transferredDifferential(ray.diff, ray.dir, distance, object.normal));
      rays[count++] = GlassRay(exit, g.leaving, weight * glassLeavingWeight(g), inPoolWater(exit), object.sphere,
                               footprints.leaving);
      rays[count++] =
          GlassRay(met, g.reflected, weight * g.reflectance, ray.water, object.sphere, footprints.reflected);
      continue;
    }
    if (!onObject && (up > 0.0 || airMet.met == kMetWater)) {
      // The flat water: its reflection and its refraction.
      const FlatWaterSplit split = flatWaterSplit(ray.dir, ray.water);
      const float reflectance = split.reflectance;
      // Radiance crossing scales by the squared ratio of the indices: the
      // air's light seen from the water n^2, the water's from the air 1 / n^2.
      const float gain = ray.water ? pool.water.y * pool.water.y : 1.0 / (pool.water.y * pool.water.y);
      if (!room) {  // the part going into the air (none past the critical angle)
        const bool intoAir = !ray.water || reflectance < 1.0;
        if (intoAir)
          radiance += weight * (ray.water ? (1.0 - reflectance) * gain * sky(split.refracted)
                                          : reflectance * sky(split.reflected));
        continue;
      }
      // The footprint carried on through the plane (Igehy 1999).
      const vec3 facing = vec3(0.0, ray.water ? -1.0 : 1.0, 0.0);
      const RayDifferential atWater = transferredDifferential(ray.diff, ray.dir, distance, facing);
      const float eta = ray.water ? pool.water.y : 1.0 / pool.water.y;
      if (reflectance < 1.0)
        rays[count++] = GlassRay(met, split.refracted, weight * (1.0 - reflectance) * gain, !ray.water, kSkipNoSphere,
                                 refractedDifferential(atWater, ray.dir, split.refracted, facing, eta));
      rays[count++] = GlassRay(met, split.reflected, weight * reflectance, ray.water, kSkipNoSphere,
                               reflectedDifferential(atWater, facing));
      continue;
    }
    if (!onObject && !ray.water && airMet.met == kMetNothing) {
      radiance += weight * skyFiltered(ray.dir, ray.diff);
      continue;
    }
    // An opaque surface: one sun share and one footprint for whichever.
    const float sunShare = frameSunShare(met) * (ray.water ? causticsAt(met) : 1.0);
    const vec3 surfaceNormal = ray.water ? poolMet.normal : airMet.normal;
    const vec2 footprint = hitFootprint(ray.diff, ray.dir, distance, surfaceNormal);
    vec3 seen;
    if (onObject) {
      seen = objectSeen(object, met, ray.dir, sunShare, kNoFootprint, ray.water);  // opaque: glass is followed above
    } else if (ray.water) {
      seen = poolSurfaceSeen(poolMet, ray.dir, footprint, sunShare);
    } else {
      seen = airSurfaceSeen(airMet, met, ray.dir, footprint, sunShare);
    }
    radiance += weight * seen;
  }
  // The water between the camera and the glass, when the camera is in it
  // (the camera medium's water is the pool's). Not viewInScatter: its
  // run-time guard, a loop, crashed lavapipe's rasterizer in this shader.
  const vec3 camera = frame.cameraPosition.xyz;
  const float toGlass = distance(camera, worldPosition);
  const vec3 between = medium.extinction.w > 0.0 ? inScatter(camera, (worldPosition - camera) / toGlass, toGlass) : vec3(0.0);
  color = vec4(radiance * viewTransmittance(medium, camera, worldPosition) + between, 1.0);
}
