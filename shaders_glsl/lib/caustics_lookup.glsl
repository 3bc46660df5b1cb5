// The sun through the waves at world point p: the caustics texture at its
// light line where the caustics reach (under the water's rest level, in the
// pool), 1 elsewhere (shared/shading.h's causticsUv and causticsReach). For
// surfaces that may lie above the water or below it: the walls, the objects.
#ifndef TP_LIB_CAUSTICS_LOOKUP
#define TP_LIB_CAUSTICS_LOOKUP
#include "shared/shading.h"

float sunThroughWaves(sampler2D caustics, PoolParams pool, vec3 toSun, vec3 p) {
  return causticsReach(pool, p) ? texture(caustics, causticsUv(pool, toSun, p)).r : 1.0;
}

#endif
