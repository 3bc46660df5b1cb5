// A ray's screen derivatives (Igehy 1999): of its origin and of its unit
// direction, one pixel right (x) and down (y). Taken from the fragment
// stage's derivatives; a compute shader (TP_NO_DERIVATIVES) has none, and
// reads them where a fragment shader stored them (lib/water_gbuffer.glsl).
// Reads the includer's `frame` in place.
#ifndef TP_LIB_RAY_DIFFERENTIAL
#define TP_LIB_RAY_DIFFERENTIAL

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

// A transferred differential reflected in a plane of normal n.
RayDifferential reflectedDifferential(RayDifferential rd, vec3 n) {
  return RayDifferential(rd.originX, rd.originY, reflect(rd.directionX, n), reflect(rd.directionY, n));
}

// A transferred differential refracted through a plane of unit normal n
// facing the ray d (dot(n, d) < 0) into t, eta the ratio of the indices
// (GLSL's refract): t = eta d + (eta c1 - c2) n with c1 = -n.d and c2 =
// -n.t, so dt = eta dd - (eta - eta^2 c1 / c2) (n.dd) n (a plane's n does
// not vary).
RayDifferential refractedDifferential(RayDifferential rd, vec3 d, vec3 t, vec3 n, float eta) {
  const float k = eta - eta * eta * dot(n, d) / dot(n, t);
  return RayDifferential(rd.originX, rd.originY, eta * rd.directionX - k * dot(n, rd.directionX) * n,
                         eta * rd.directionY - k * dot(n, rd.directionY) * n);
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
