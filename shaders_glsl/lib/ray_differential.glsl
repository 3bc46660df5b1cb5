// A ray's screen derivatives (Igehy 1999): of its origin and of its unit
// direction, one pixel right (x) and down (y). Taken from the fragment
// stage's derivatives; a compute shader (TP_NO_DERIVATIVES) has none, and
// reads them where a fragment shader stored them (lib/water_gbuffer.glsl).
// Reads the includer's `frame` in place.
#ifndef TP_LIB_RAY_DIFFERENTIAL
#define TP_LIB_RAY_DIFFERENTIAL
#include "shared/constants.h"
#include "shared/glass.h"

struct RayDifferential {
  vec3 originX, originY, directionX, directionY;
};

// The differential carried along its ray, origin + s dir, to where the ray
// meets a plane of normal n: the origins' derivatives taken in that plane
// (Igehy's transfer), the directions' unchanged.
RayDifferential transferredDifferential(RayDifferential rd, vec3 dir, float s, vec3 n) {
  const vec3 x = rd.originX + s * rd.directionX, y = rd.originY + s * rd.directionY;
  const float facing = dot(dir, n);
  return RayDifferential(x - dir * (dot(x, n) / facing), y - dir * (dot(y, n) / facing), rd.directionX,
                         rd.directionY);
}

// None: what a ray without a footprint carries, sampled at a point.
const RayDifferential kNoFootprint = RayDifferential(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));

// A transferred differential reflected off a surface of unit normal n,
// r = d - 2 (d.n) n, where n changes by dnX and dnY over it (a curved
// surface; zero on a plane): dr = dd - 2 ((d.n) dn + (n.dd + d.dn) n).
RayDifferential reflectedDifferential(RayDifferential rd, vec3 d, vec3 n, vec3 dnX, vec3 dnY) {
  const float c = dot(d, n);
  return RayDifferential(rd.originX, rd.originY,
                         rd.directionX - 2.0 * (c * dnX + (dot(n, rd.directionX) + dot(d, dnX)) * n),
                         rd.directionY - 2.0 * (c * dnY + (dot(n, rd.directionY) + dot(d, dnY)) * n));
}

// The same in a plane.
RayDifferential reflectedDifferential(RayDifferential rd, vec3 n) {
  return reflectedDifferential(rd, vec3(0.0), n, vec3(0.0), vec3(0.0));
}

// A transferred differential refracted through a surface of unit normal n
// facing the ray d (dot(n, d) < 0) into t, eta the ratio of the indices
// (GLSL's refract), where n changes by dnX and dnY over it (zero on a
// plane): t = eta d + mu n with mu = eta c1 - c2, c1 = -n.d and c2 = -n.t,
// so dt = eta dd + mu dn - k (n.dd + d.dn) n with k = eta - eta^2 c1 / c2.
RayDifferential refractedDifferential(RayDifferential rd, vec3 d, vec3 t, vec3 n, vec3 dnX, vec3 dnY, float eta) {
  const float k = eta - eta * eta * dot(n, d) / dot(n, t);
  const float mu = dot(n, t) - eta * dot(n, d);
  return RayDifferential(rd.originX, rd.originY,
                         eta * rd.directionX + mu * dnX - k * (dot(n, rd.directionX) + dot(d, dnX)) * n,
                         eta * rd.directionY + mu * dnY - k * (dot(n, rd.directionY) + dot(d, dnY)) * n);
}

// The same through a plane.
RayDifferential refractedDifferential(RayDifferential rd, vec3 d, vec3 t, vec3 n, float eta) {
  return refractedDifferential(rd, d, t, n, vec3(0.0), vec3(0.0), eta);
}

// The footprints of the two rays glass sends on, the one that leaves it and
// the front face's reflection: rd, the differential of the ray along `dir`
// carried to the entry point (outward normal n), followed along the paths g
// (Igehy 1999). A sphere's normal turns by the point's move times its
// curvature (1 / radius); a box's faces are flat (curvature 0), and its
// reflections inside are unfolded: the path runs straight through the
// box's mirror images, which flip the components of the direction that its
// reflections flip (in the frame of its yaw), and is mirrored back where it
// leaves.
struct GlassDifferentials {
  RayDifferential leaving, reflected;
};

// v mirrored by `flips` of its components in the frame of a box of yaw `yaw`.
vec3 mirroredInBox(vec3 v, vec3 flips, float yaw) { return fromBoxFrame(flips * toBoxFrame(v, yaw), yaw); }

// v shortened to `most` where it is longer.
vec3 atMost(vec3 v, float most) { return v * min(1.0, most / max(length(v), 1e-30)); }

// The most a surface of index ratio m bends a ray that passes it: from
// grazing to the critical angle, pi/2 - asin(1/m), going into the denser
// medium, and back the other way.
float refractionTurnBound(float m) { return 0.5 * kPi - asin(min(m, 1.0 / m)); }

GlassDifferentials glassPathDifferentials(GlassExit g, vec3 dir, vec3 n, float curvature, float yaw,
                                          RayDifferential rd) {
  GlassDifferentials result;
  result.reflected = reflectedDifferential(rd, dir, n, curvature * rd.originX, curvature * rd.originY);
  const RayDifferential entered =
      refractedDifferential(rd, dir, g.inside, n, curvature * rd.originX, curvature * rd.originY, 1.0 / g.entryIor);
  // Where the last leg runs against the first, a reflection flipped it.
  const vec3 flips =
      mix(vec3(1.0), vec3(-1.0), lessThan(toBoxFrame(g.inside, yaw) * toBoxFrame(g.lastInside, yaw), vec3(0.0)));
  // The exit face's mirror image is parallel to it: a face's normal is one of the box's axes.
  const RayDifferential far = transferredDifferential(entered, g.inside, g.insideLength, g.exitNormal);
  const RayDifferential atExit =
      RayDifferential(mirroredInBox(far.originX, flips, yaw), mirroredInBox(far.originY, flips, yaw),
                      mirroredInBox(far.directionX, flips, yaw), mirroredInBox(far.directionY, flips, yaw));
  // The inward normal there, which faces the ray, and how it turns.
  const vec3 m = -g.exitNormal, dmX = -curvature * atExit.originX, dmY = -curvature * atExit.originY;
  const vec3 refracted = refract(g.lastInside, m, g.exitIor);
  result.leaving = dot(refracted, refracted) > 0.0
                       ? refractedDifferential(atExit, g.lastInside, g.leaving, m, dmX, dmY, g.exitIor)
                       : reflectedDifferential(atExit, g.lastInside, m, dmX, dmY);
  if (curvature > 0.0) {
    // A sphere turns a ray by at most what its two surfaces bend it at the
    // rim, 2 (pi/2 - asin(1 / ior)) in one medium: a pixel's rays leave it
    // at most that much wider than they came. Near the silhouette the linear
    // model overshoots it by far (the turn's slope grows without bound where
    // the turn itself stays small).
    const float turn = refractionTurnBound(g.entryIor) + refractionTurnBound(g.exitIor);
    result.leaving.directionX = atMost(result.leaving.directionX, length(rd.directionX) + turn);
    result.leaving.directionY = atMost(result.leaving.directionY, length(rd.directionY) + turn);
  }
  return result;
}

#ifndef TP_NO_DERIVATIVES
// Taken where every lane of the pixel quad runs the same code: derivatives
// of values computed in divergent code (a cast's hit) are undefined. Scaled
// to the filter's width (FrameUniforms::sampling).
RayDifferential rayDifferential(vec3 origin, vec3 direction) {
  const float w = frame.sampling.x;
  return RayDifferential(w * dFdx(origin), w * dFdy(origin), w * dFdx(direction), w * dFdy(direction));
}
#endif

#endif
