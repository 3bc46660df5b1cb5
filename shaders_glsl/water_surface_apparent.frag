#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface, apparent-depth refraction (the original course project's
// approximation): the refracted ray is followed down to the pool's mean floor
// depth only, that point is projected to the screen, and the frame's own image
// of the pool under the water (copied before the water is drawn) is read there.
#include "lib/water_shading.glsl"

layout(binding = 5) uniform sampler2D underwater;

void main() {
  const vec3 view = normalize(worldPosition - frame.cameraPosition.xyz);
  const vec3 n = normalize(worldNormal);
  const vec3 reflected = reflectedRadiance(worldPosition, reflect(view, n));
  vec3 transmitted = vec3(0.0);
  const vec3 t = refract(view, n, 1.0 / surface.absorption.w);
  if (dot(t, t) > 0.0 && t.y < 0.0) {
    const float meanFloor = pool.box.y - pool.box.z;
    const float distance = max(worldPosition.y - meanFloor, 0.0) / -t.y;
    const vec4 clip = frame.viewProjection * vec4(worldPosition + distance * t, 1.0);
    const vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * frame.viewport.xy;
    const ivec2 texel = clamp(ivec2(pixel), ivec2(0), ivec2(frame.viewport.xy) - 1);
    transmitted = texelFetch(underwater, texel, 0).rgb * exp(-surface.absorption.rgb * distance);
  }
  color = vec4(mix(transmitted, reflected, waterFresnel(view, n)), 1.0);
}
