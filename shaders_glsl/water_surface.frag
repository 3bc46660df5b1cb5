#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface, accurate refraction: the refracted ray is cast against
// the pool (walls exactly, the terrain floor by marching and bisection) and
// the spheres, and attenuated along its path through the water.
#include "lib/water_shading.glsl"

layout(binding = 6) uniform sampler2D caustics;

void main() {
  const vec3 view = normalize(worldPosition - frame.cameraPosition.xyz);
  const vec3 n = normalize(worldNormal);
  const vec3 reflected = reflectedRadiance(worldPosition, reflect(view, n));
  vec3 transmitted = vec3(0.0);
  const vec3 t = refract(view, n, 1.0 / surface.absorption.w);
  if (dot(t, t) > 0.0 && t.y < 0.0) {  // from above there is no total internal reflection
    const PoolHit hit = tracePool(pool, worldPosition, t);
    vec3 radiance = hit.floor ? poolFloorRadiance(pool, frame, hit.position, hit.normal, fwidth(hit.position.xz),
                                                  texture(caustics, causticsUv(pool, hit.position.xz)).r)
                              : poolWallRadiance(pool, frame, hit.normal);
    float distance = hit.distance;
    for (uint i = 0u; i < objects.count.x; ++i) {  // a sphere in front of the pool's surfaces
      const float s = raySphere(worldPosition, normalize(t), objects.spheres[i]);
      if (s > 0.0 && s < distance) {
        distance = s;
        const vec3 p = worldPosition + s * normalize(t);
        radiance = sphereRadiance(frame, objects.sphereAlbedo[i].rgb, normalize(p - objects.spheres[i].xyz));
      }
    }
    transmitted = radiance * exp(-surface.absorption.rgb * distance);
  }
  color = vec4(mix(transmitted, reflected, waterFresnel(view, n)), 1.0);
}
