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
