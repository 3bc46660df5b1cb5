// The sun through the waves, read from the caustics texture (red: the ratio
// to flat water, green: the layers of the water's light that reach the
// texel; caustics.frag).
#ifndef TP_LIB_CAUSTICS_LOOKUP
#define TP_LIB_CAUSTICS_LOOKUP
#include "shared/shading.h"

// The ratio at world point p's light line (shared/shading.h's causticsUv),
// for p under the water: bilinear between the texels the water's light
// reaches. The others hold no light line of the water: past the line the
// water's edge at a wall sends its light to, where the wall stands in the
// air above a wave drawn down. Read with the rest, they darkened the wall
// just under the water there. Where none of the four is reached, the sun
// comes whole.
float causticsRatio(sampler2D caustics, PoolParams pool, vec3 toSun, vec3 p) {
  const vec2 uv = causticsUv(pool, toSun, p);
  const vec2 f = fract(uv * vec2(textureSize(caustics, 0)) - 0.5);
  // textureGather's order: (0, 1), (1, 1), (1, 0), (0, 0).
  const vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  const vec4 weight = bilinear * vec4(greaterThan(textureGather(caustics, uv, 1), vec4(0.0)));
  const float reached = dot(weight, vec4(1.0));
  return reached > 0.0 ? dot(weight, textureGather(caustics, uv, 0)) / reached : 1.0;
}

#endif
