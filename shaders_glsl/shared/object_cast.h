// The one cast against all of the scene's objects (the water's reflected and
// refracted rays), shared with C++ to measure it.
//
// In GLSL it reads the includer's uniform block instance `objects` in place:
// a struct passed by value is copied whole for every pixel on lavapipe, and
// its arrays, indexed in a loop, then live in scratch memory (20 of the
// water pass's 82 ms at 1280x720). In C++ it takes the struct by reference.
#ifndef TP_SHARED_OBJECT_CAST_H
#define TP_SHARED_OBJECT_CAST_H
#include "shared/objects.h"

#ifdef __cplusplus
#define TP_OBJECTS_PARAM const SceneObjects &objects,
#else
#define TP_OBJECTS_PARAM
#endif

TP_BEGIN

struct ObjectHit {
  float distance;  // -1: none nearer than the limit
  vec3 normal;     // unit, world
  vec3 albedo;
  vec2 material;  // x: specular, y: roughness; boxes have none
  float glass;    // a glass sphere's or box's index of refraction; 0: not glass
  uint sphere;    // the sphere's slot among the objects; kSkipNoSphere for a box
  uint box;       // the box's slot; kSkipNoSphere for a sphere
};

// castObjects' `skip` when no sphere is to be passed by; ObjectHit's
// `sphere` when the hit is a box or nothing, and its `box` when it is a
// sphere or nothing.
const uint kSkipNoSphere = 0xffffffffu;

// How far along its ray a sphere is met by a ray that starts inside it: at
// once. The water's surface passes through a sphere at its waterline, and the
// sphere's tessellation lies inside the sphere, so slivers of that surface
// are drawn; their rays must see the sphere, not what lies past it.
const float kInsideSphereHit = 1e-6f;

// The nearest sphere or box along origin + s dir (dir unit) with s < limit,
// among the first `counts` (x spheres, y boxes): count.xy for every object,
// count.zw for those below the rim, which alone rays under the water can meet.
// Sphere `skip` is passed by: the glass sphere a ray leaves (its origin lies
// on that sphere, where round-off could put it inside). A ray leaving a glass
// box needs no such skip: the slab test meets no box the ray starts in.
TP_INLINE ObjectHit castObjects(TP_OBJECTS_PARAM uvec2 counts, vec3 origin, vec3 dir, float limit, uint skip) {
  ObjectHit hit;
  hit.distance = -1.0f;
  hit.normal = vec3(0.0f);
  hit.albedo = vec3(0.0f);
  hit.material = vec2(0.0f);
  hit.glass = 0.0f;
  hit.sphere = kSkipNoSphere;
  hit.box = kSkipNoSphere;
  float nearest = limit;
  for (uint i = 0u; i < counts.x; ++i) {
    if (i == skip) continue;
    vec3 fromCentre = origin - vec3(objects.spheres[i]);
    float s = dot(fromCentre, fromCentre) < objects.spheres[i].w * objects.spheres[i].w
                  ? kInsideSphereHit
                  : raySphere(origin, dir, objects.spheres[i]);
    if (s > 0.0f && s < nearest) {
      nearest = s;
      hit.distance = s;
      hit.normal = normalize(origin + s * dir - vec3(objects.spheres[i]));
      hit.albedo = vec3(objects.sphereAlbedo[i]);
      hit.material = vec2(objects.sphereMaterial[i]);
      hit.glass = objects.sphereMaterial[i].z;
      hit.sphere = i;
      hit.box = kSkipNoSphere;
    }
  }
  for (uint i = 0u; i < counts.y; ++i) {
    vec4 b = rayBox(origin, dir, objects.boxCenter[i], objects.boxHalfSize[i]);
    if (b.x > 0.0f && b.x < nearest) {
      nearest = b.x;
      hit.distance = b.x;
      hit.normal = vec3(b.y, b.z, b.w);
      hit.albedo = vec3(objects.boxAlbedo[i]);
      hit.material = vec2(0.0f);
      hit.glass = objects.boxHalfSize[i].w;
      hit.sphere = kSkipNoSphere;
      hit.box = i;
    }
  }
  return hit;
}

TP_END

#endif
