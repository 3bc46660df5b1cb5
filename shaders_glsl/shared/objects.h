// The scene's objects seen by rays cast in shaders (the water's refracted
// rays): spheres, a uniform buffer filled once per scene (render/objects_model.cpp).
#ifndef TP_SHARED_OBJECTS_H
#define TP_SHARED_OBJECTS_H
#include "shared/interop.h"

#define TP_MAX_SPHERES 4

TP_BEGIN

struct SceneObjects {
  uvec4 count;                          // x: spheres
  vec4 spheres[TP_MAX_SPHERES];         // xyz centre, w radius
  vec4 sphereAlbedo[TP_MAX_SPHERES];    // rgb
};

// Push constants of the sphere pass: one draw per sphere.
struct SphereParams {
  vec4 sphere;   // xyz centre, w radius
  vec4 albedo;   // rgb
  uvec4 tessellation;  // x: stacks, y: slices
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::SceneObjects) == 16 + 32 * TP_MAX_SPHERES);
static_assert(sizeof(tp::shader::SphereParams) == 48);
#endif

#endif
