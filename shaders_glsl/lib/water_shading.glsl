// The water surface's shading shared by its two refraction modes: inputs,
// bindings 0-4, the reflection (the reflected ray cast against the spheres
// and the walls above the water, else the sky's equirectangular lookup) and
// Schlick's Fresnel.
#ifndef TP_LIB_WATER_SHADING
#define TP_LIB_WATER_SHADING
#include "shared/shading.h"
#include "shared/objects.h"
#include "shared/water_surface.h"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform sampler2D skyTexture;
layout(binding = 3) uniform Pool { PoolParams pool; };
layout(binding = 4) uniform Objects { SceneObjects objects; };
layout(push_constant) uniform Push { WaterSurfaceParams surface; };

vec3 sky(vec3 direction) { return texture(skyTexture, directionToEquirect(direction)).rgb; }

// What a ray reflected off the surface at p (inside the pool, below the rim)
// sees: a sphere, the part of a wall above the water, or the sky over the rim.
vec3 reflectedRadiance(vec3 p, vec3 r) {
  float nearest = 1e30;
  vec3 radiance = sky(r);
  const float halfSize = pool.box.x, rim = pool.box.y;
  const float sx = r.x > 0.0 ? (halfSize - p.x) / r.x : (r.x < 0.0 ? (-halfSize - p.x) / r.x : 1e30);
  const float sz = r.z > 0.0 ? (halfSize - p.z) / r.z : (r.z < 0.0 ? (-halfSize - p.z) / r.z : 1e30);
  const float sWall = min(sx, sz);
  if (sWall > 0.0 && p.y + sWall * r.y <= rim) {
    nearest = sWall;
    radiance = poolWallRadiance(pool, frame, sx < sz ? vec3(-sign(r.x), 0.0, 0.0) : vec3(0.0, 0.0, -sign(r.z)));
  }
  for (uint i = 0u; i < objects.count.x; ++i) {
    const float s = raySphere(p, r, objects.spheres[i]);
    if (s > 0.0 && s < nearest) {
      nearest = s;
      radiance = sphereRadiance(frame, objects.sphereAlbedo[i].rgb, normalize(p + s * r - objects.spheres[i].xyz));
    }
  }
  return radiance;
}

// Schlick's Fresnel reflectance for the view ray meeting normal n.
float waterFresnel(vec3 view, vec3 n) {
  const float ior = surface.absorption.w;
  const float f0 = ((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0));
  const float cosIn = clamp(-dot(view, n), 0.0, 1.0);
  return f0 + (1.0 - f0) * pow(1.0 - cosIn, 5.0);
}

#endif
