// The sun through the waves, read from the caustics texture (red: the ratio
// to flat water, green: the layers of the water's light that reach the
// texel; caustics.frag).
#ifndef TP_LIB_CAUSTICS_LOOKUP
#define TP_LIB_CAUSTICS_LOOKUP
#include "shared/shading.h"

// The ratio at world point p's light line (shared/shading.h's causticsUv),
// bilinear between the texels the water's light reaches. The others are
// lines no light through the water meets: where the water stands below its
// rest level at a wall, the wall between the two is in the air. Read with
// the rest, they drew a dark line across the wall there. Where none of the
// four reaches, the sun comes whole.
float causticsRatio(sampler2D caustics, PoolParams pool, vec3 toSun, vec3 p) {
  const vec2 uv = causticsUv(pool, toSun, p);
  const vec2 f = fract(uv * vec2(textureSize(caustics, 0)) - 0.5);
  // textureGather's order: (0, 1), (1, 1), (1, 0), (0, 0).
  const vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  const vec4 weight = bilinear * vec4(greaterThan(textureGather(caustics, uv, 1), vec4(0.0)));
  const float reached = dot(weight, vec4(1.0));
  return reached > 0.0 ? dot(weight, textureGather(caustics, uv, 0)) / reached : 1.0;
}

// The same where the caustics reach p (under the water's rest level, in the
// pool: shared/shading.h's causticsReach), 1 elsewhere. For surfaces that
// may lie above the water or below it: the walls, the objects.
float sunThroughWaves(sampler2D caustics, PoolParams pool, vec3 toSun, vec3 p) {
  return causticsReach(pool, p) ? causticsRatio(caustics, pool, toSun, p) : 1.0;
}

#endif
