#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface seen from above (its front faces; the back faces are
// water_surface_below.frag's draw), accurate refraction: the refracted ray is
// cast against the pool (walls exactly, the terrain floor by marching and
// bisection) and the objects, and attenuated along its path through the water.
// Frames normally shade it deferred (water_surface_deferred.comp); this
// forward shader is what that is compared with (docs/frame-skipping.md).
#include "lib/water_shading.glsl"

void main() {
  const ViewFromAbove v = viewFromAbove(surface, frame.cameraPosition.xyz, worldPosition, worldNormal);
  const RayDifferential rd = rayDifferential(worldPosition, normalize(v.refracted));
  color = vec4(seenFromAbove(worldPosition, v, rd), 1.0);
}
