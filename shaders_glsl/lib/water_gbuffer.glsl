// The water's G-buffer: what shading the surface seen from above needs of a
// pixel, which water_surface_gbuffer.frag stores where the mesh is drawn and
// water_surface_deferred.comp reads, once per pixel. The ray differentials
// come from the fragment stage's derivatives, on the mesh's own triangles,
// so the deferred shading gives the forward shader's bits. Five RGBA32F
// targets (TP_WATER_GBUFFER_TARGETS):
//   0: position xyz; w: the frame's tag (0 where cleared: no surface)
//   1: normal xyz (as interpolated, not normalized); w: rd.originX.x
//   2: rd.originX.yz, rd.originY.xy
//   3: rd.originY.z, rd.directionX
//   4: rd.directionY; w: 0
#ifndef TP_LIB_WATER_GBUFFER
#define TP_LIB_WATER_GBUFFER
#include "lib/ray_differential.glsl"

struct WaterSample {
  vec3 position, normal;
  RayDifferential rd;
};

struct WaterGbufferTexels {
  vec4 t[TP_WATER_GBUFFER_TARGETS];
};

WaterGbufferTexels packWaterSample(WaterSample s, float tag) {
  const RayDifferential rd = s.rd;
  WaterGbufferTexels g;
  g.t[0] = vec4(s.position, tag);
  g.t[1] = vec4(s.normal, rd.originX.x);
  g.t[2] = vec4(rd.originX.yz, rd.originY.xy);
  g.t[3] = vec4(rd.originY.z, rd.directionX);
  g.t[4] = vec4(rd.directionY, 0.0);
  return g;
}

WaterSample unpackWaterSample(WaterGbufferTexels g) {
  const RayDifferential rd = RayDifferential(vec3(g.t[1].w, g.t[2].xy), vec3(g.t[2].zw, g.t[3].x), g.t[3].yzw,
                                             g.t[4].xyz);
  return WaterSample(g.t[0].xyz, g.t[1].xyz, rd);
}

#endif
