#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface, apparent-depth refraction (the original course project's
// approximation): the refracted ray is followed down to the pool's mean floor
// depth only, that point is projected to the screen, and the frame's own image
// of the pool under the water (copied before the water is drawn) is read there.
// Only the front faces, the surface seen from above: the approximation is the
// original's view from above, and from below both modes draw the back faces
// with water_surface_below.frag.
#include "lib/water_shading.glsl"

layout(binding = 5) uniform sampler2D underwater;

void main() {
  const ViewFromAbove v = viewFromAbove(surface, frame.cameraPosition.xyz, worldPosition, worldNormal);
  const vec3 reflected = radianceAbove(worldPosition, reflect(v.view, v.normal));
  vec3 transmitted = vec3(0.0);
  const vec3 t = v.refracted;
  if (dot(t, t) > 0.0 && t.y < 0.0) {
    const ivec2 texel = ivec2(apparentDepthTexel(pool, frame, worldPosition, t));
    const float distance = apparentDepthDistance(pool, worldPosition, t);
    transmitted = (texelFetch(underwater, texel, 0).rgb * exp(-surface.extinction.rgb * distance) +
                   inScatter(worldPosition, t, distance)) /
                  waterRadianceGain();
  }
  color = vec4(mix(transmitted, reflected, waterFresnel(-dot(v.view, v.normal))), 1.0);
}
