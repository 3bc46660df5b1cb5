#version 450
#extension GL_GOOGLE_include_directive : require
// Test-only: the footprints of the rays a glass sphere or box sends on
// (glassPathDifferentials, lib/ray_differential.glsl), for the tests to hold
// against finite differences of the exact paths on the CPU.
#define TP_NO_DERIVATIVES
#include "lib/ray_differential.glsl"

layout(local_size_x = 64) in;
struct GlassCase {
  vec4 origin, direction;      // the ray (xyz; direction unit); origin.w: the index of its medium,
                               // direction.w: the water's level round the glass
  vec4 originX, directionX;    // its differential (xyz); originX.w: the water's index, directionX.w:
                               // half the water's square (0: none)
  vec4 center;                 // xyz; w: a sphere's radius, a box's yaw
  vec4 box;                    // xyz: a box's half size (0 for a sphere); w: the index
};
layout(binding = 0) readonly buffer Cases { GlassCase cases[]; };
// Per case: the leaving ray's origin and direction derivatives, then the reflected ray's.
layout(binding = 1) writeonly buffer Values { vec4 values[]; };
layout(push_constant) uniform Push { uint count; };

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  const GlassCase c = cases[i];
  const vec3 o = c.origin.xyz, d = c.direction.xyz;
  const bool box = c.box.x > 0.0;
  const float ior = c.box.w;
  const vec4 boxHit = rayBox(o, d, c.center, vec4(c.box.xyz, 0.0));
  const float s = box ? boxHit.x : raySphere(o, d, c.center);
  const vec3 p = o + s * d;
  const vec3 n = box ? boxHit.yzw : (p - c.center.xyz) / c.center.w;
  const GlassSurround surround = GlassSurround(c.direction.w, c.directionX.w, c.originX.w);
  const GlassExit g = box ? glassBoxPaths(p, d, n, c.center, vec4(c.box.xyz, 0.0), ior, c.origin.w, surround)
                          : glassSphereExactExit(p, d, n, c.center.w, ior, c.origin.w, surround);
  const RayDifferential rd = RayDifferential(c.originX.xyz, vec3(0.0), c.directionX.xyz, vec3(0.0));
  const GlassDifferentials f = glassPathDifferentials(g, d, n, box ? 0.0 : 1.0 / c.center.w,
                                                      box ? c.center.w : 0.0, transferredDifferential(rd, d, s, n));
  values[4 * i] = vec4(f.leaving.originX, 0.0);
  values[4 * i + 1] = vec4(f.leaving.directionX, 0.0);
  values[4 * i + 2] = vec4(f.reflected.originX, 0.0);
  values[4 * i + 3] = vec4(f.reflected.directionX, 0.0);
}
