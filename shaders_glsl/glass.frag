#version 450
#extension GL_GOOGLE_include_directive : require
// A glass sphere's front faces: two-interface refraction in image space
// (Wyman 2005). The view ray is refracted into the glass at the front surface;
// the exit point is found by a binary search along the refracted ray against
// the back faces' view depth (glass_back.frag), the exit normal read there;
// the ray is refracted out (or, under total internal reflection, reflected
// back in and looked up as if it left) and looks up the sky. The exact
// Fresnel reflectance of the front surface mixes in the reflected sky
// (shared/glass.h has the model, which the CPU reference shares).
#include "shared/equirect.h"
#include "shared/frame.h"
#include "shared/glass.h"
#include "shared/shading.h"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
#include "shared/water_scattering.h"  // reads `frame` in place
layout(binding = 1) uniform sampler2D skyTexture;
// xyz: outward normal of the nearest back face, w: its view depth (0: none).
layout(binding = 2) uniform sampler2D backFaces;
layout(binding = 3) uniform Medium { CameraMedium medium; };
layout(push_constant) uniform Push { GlassSphereParams params; };

vec3 sky(vec3 dir) { return texture(skyTexture, directionToEquirect(dir)).rgb; }

// Whether world point p lies in front of the back face under it (inside the
// glass, the exit not yet passed), with that back face's normal.
bool beforeBackFace(vec3 p, out vec3 backNormal) {
  backNormal = vec3(0.0);
  vec2 pixel = screenPixel(frame, p);
  if (any(lessThan(pixel, vec2(0.0))) || any(greaterThanEqual(pixel, frame.viewport.xy))) return false;
  vec4 back = texelFetch(backFaces, ivec2(pixel), 0);
  backNormal = back.xyz;
  return back.w > 0.0 && -(frame.view * vec4(p, 1.0)).z < back.w;
}

void main() {
  const vec3 n = normalize(worldNormal);
  const vec3 view = normalize(worldPosition - frame.cameraPosition.xyz);
  const float ior = params.glass.x;
  const float reflectance = fresnelDielectric(max(-dot(view, n), 0.0), 1.0, ior);
  const vec3 inside = refract(view, n, 1.0 / ior);  // from air into glass: always refracts
  // The exit lies within the longest chord of the sphere, its diameter. The
  // entry point itself is before the back face behind it.
  float before = 0.0, after = 2.0 * params.sphere.w;
  vec3 exitNormal;
  beforeBackFace(worldPosition, exitNormal);
  for (uint i = 0u; i < params.search.x; ++i) {
    const float mid = 0.5 * (before + after);
    vec3 backNormal;
    if (beforeBackFace(worldPosition + mid * inside, backNormal)) {
      before = mid;
      exitNormal = backNormal;
    } else {
      after = mid;
    }
  }
  // No back face found at all (a sliver at the silhouette): straight through.
  const vec3 leaving = dot(exitNormal, exitNormal) > 0.0 ? glassExitDirection(inside, normalize(exitNormal), ior) : inside;
  const vec3 radiance = mix(sky(leaving), sky(reflect(view, n)), reflectance);
  color = vec4(radiance * viewTransmittance(medium, frame.cameraPosition.xyz, worldPosition) +
                   viewInScatter(medium, worldPosition),
               1.0);
}
