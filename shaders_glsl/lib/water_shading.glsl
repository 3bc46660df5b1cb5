// The water surface's fragment shaders' common part: inputs and output, what
// its rays see (lib/water_light.glsl, bindings 0-4 and 6-8) and the surface
// seen from below.
#ifndef TP_LIB_WATER_SHADING
#define TP_LIB_WATER_SHADING
#include "lib/water_light.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;

// The surface seen from under the water (the back of the mesh, whose front
// faces the sky): reflected light from below, the refracted ray to the air
// (none past the critical angle: total internal reflection), and the water
// between the surface and the camera.
vec4 shadeFromBelow(vec3 view, vec3 n) {
  n = -n;  // towards the camera, into the water
  const vec3 r = reflect(view, n);
  const vec3 reflected = radianceBelow(worldPosition, r, rayDifferential(worldPosition, r));
  const vec3 t = refract(view, n, surface.extinction.w);
  const bool total = dot(t, t) == 0.0;
  const vec3 transmitted = total ? vec3(0.0) : radianceAbove(worldPosition, t) * waterRadianceGain();
  const float fresnel = total ? 1.0 : waterFresnel(-dot(t, n));
  const float toCamera = distance(frame.cameraPosition.xyz, worldPosition);
  const vec3 camera = frame.cameraPosition.xyz;
  return vec4(mix(transmitted, reflected, fresnel) * exp(-surface.extinction.rgb * toCamera) +
                  inScatter(camera, (worldPosition - camera) / toCamera, toCamera),
              1.0);
}

#endif
