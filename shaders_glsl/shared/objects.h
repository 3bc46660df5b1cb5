// The scene's objects (spheres and boxes, Lambertian or glass) as the shaders see them:
// a uniform buffer filled once per frame (render/objects_model.cpp) for the
// rays cast in shaders (the water's reflected and refracted rays), the push
// constants of their draws, and the ray's tests against a sphere and a box
// (the cast against all of them: shared/object_cast.h).
#ifndef TP_SHARED_OBJECTS_H
#define TP_SHARED_OBJECTS_H
#include "shared/interop.h"

#define TP_MAX_SPHERES 4
#define TP_MAX_BOXES 4

TP_BEGIN

struct SceneObjects {
  // x: spheres, y: boxes; z, w: how many of them (the first) reach down
  // into the pool, where the rays below the water surface can meet them
  uvec4 count;
  vec4 spheres[TP_MAX_SPHERES];         // xyz centre, w radius
  vec4 sphereAlbedo[TP_MAX_SPHERES];    // rgb
  vec4 sphereMaterial[TP_MAX_SPHERES];  // x: specular, y: roughness (shared/glossy.h); z: glass's index (0: not glass)
  vec4 boxCenter[TP_MAX_BOXES];         // xyz centre, w yaw (radians, about +y, from +x towards -z)
  vec4 boxHalfSize[TP_MAX_BOXES];       // xyz half the edge lengths in the box's own frame; w: glass's index (0: not glass)
  vec4 boxAlbedo[TP_MAX_BOXES];         // rgb
};

// Push constants of the sphere pass: one draw per sphere.
struct SphereParams {
  vec4 sphere;         // xyz centre, w radius
  vec4 albedo;         // rgb
  uvec4 tessellation;  // x: stacks, y: slices
  vec4 material;       // x: specular, y: roughness (shared/glossy.h)
};

// Push constants of the box pass: one draw per box.
struct BoxParams {
  vec4 center;    // xyz centre, w yaw (radians)
  vec4 halfSize;  // xyz
  vec4 albedo;    // rgb
};

// A box's frame: its local axes in world space (x and z turned by the yaw about y).
TP_INLINE vec3 boxAxisX(float yaw) { return vec3(cos(yaw), 0.0f, -sin(yaw)); }
TP_INLINE vec3 boxAxisZ(float yaw) { return vec3(sin(yaw), 0.0f, cos(yaw)); }
// A world vector in the frame of a box turned by `yaw`, and back.
TP_INLINE vec3 toBoxFrame(vec3 v, float yaw) { return vec3(dot(v, boxAxisX(yaw)), v.y, dot(v, boxAxisZ(yaw))); }
TP_INLINE vec3 fromBoxFrame(vec3 v, float yaw) {
  return v.x * boxAxisX(yaw) + vec3(0.0f, v.y, 0.0f) + v.z * boxAxisZ(yaw);
}

// Distance along origin + s dir (dir unit) to the sphere's front surface, or -1.
TP_INLINE float raySphere(vec3 origin, vec3 dir, vec4 sphere) {
  vec3 oc = origin - vec3(sphere);
  float b = dot(oc, dir);
  float c = dot(oc, oc) - sphere.w * sphere.w;
  float discriminant = b * b - c;
  if (discriminant < 0.0f) return -1.0f;
  float s = -b - sqrt(discriminant);
  return s > 0.0f ? s : -1.0f;
}

// The slab test in the box's frame: x the distance to its front face (or -1
// when missed or when the origin is inside), yzw the world normal there.
TP_INLINE vec4 rayBox(vec3 origin, vec3 dir, vec4 center, vec4 halfSize) {
  vec3 ax = boxAxisX(center.w), az = boxAxisZ(center.w);
  vec3 o = toBoxFrame(origin - vec3(center), center.w), d = toBoxFrame(dir, center.w);
  float sNear = -1e30f, sFar = 1e30f;
  int axis = -1;
  float side = 0.0f;
  for (int k = 0; k < 3; ++k) {
    if (abs(d[k]) < 1e-12f) {
      if (abs(o[k]) > halfSize[k]) return vec4(-1.0f);
      continue;
    }
    float a = (-halfSize[k] - o[k]) / d[k], b = (halfSize[k] - o[k]) / d[k];
    float enter = min(a, b), leave = max(a, b);
    if (enter > sNear) {
      sNear = enter;
      axis = k;
      side = d[k] > 0.0f ? -1.0f : 1.0f;
    }
    sFar = min(sFar, leave);
  }
  if (axis < 0 || sNear > sFar || sNear <= 0.0f) return vec4(-1.0f);
  vec3 n = axis == 0 ? side * ax : (axis == 1 ? vec3(0.0f, side, 0.0f) : side * az);
  return vec4(sNear, n);
}

// The nearest of the three faces that a ray from o along d, inside a box of
// half sizes h, heads for (all in the box's frame): how far, and its axis.
struct BoxFaceAhead {
  float distance;
  int axis;
};
TP_INLINE BoxFaceAhead boxFaceAhead(vec3 o, vec3 d, vec3 h) {
  BoxFaceAhead face;
  face.distance = 1e30f;
  face.axis = 0;
  for (int a = 0; a < 3; ++a) {
    float to = d[a] != 0.0f ? ((d[a] > 0.0f ? h[a] : -h[a]) - o[a]) / d[a] : 1e30f;
    if (to < face.distance) {
      face.distance = to;
      face.axis = a;
    }
  }
  return face;
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::SceneObjects) == 16 + 48 * TP_MAX_SPHERES + 48 * TP_MAX_BOXES);
static_assert(sizeof(tp::shader::SphereParams) == 64);
static_assert(sizeof(tp::shader::BoxParams) == 48);
#endif

#endif
