#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface seen from above (its front faces; the back faces are
// water_surface_below.frag's draw), accurate refraction: the refracted ray is
// cast against the pool (walls exactly, the terrain floor by marching and
// bisection) and the objects, and attenuated along its path through the water.
#include "lib/water_shading.glsl"

void main() {
  const vec3 view = normalize(worldPosition - frame.cameraPosition.xyz);
  const vec3 n = normalize(worldNormal);
  const vec3 reflected = radianceAbove(worldPosition, reflect(view, n));
  vec3 transmitted = vec3(0.0);
  const vec3 t = refract(view, n, 1.0 / surface.extinction.w);
  const vec3 down = normalize(t);
  const RayDifferential rd = rayDifferential(worldPosition, down);
  if (dot(t, t) > 0.0 && t.y < 0.0) transmitted = radianceBelow(worldPosition, down, rd);
  color = vec4(mix(transmitted, reflected, waterFresnel(-dot(view, n))), 1.0);
}
