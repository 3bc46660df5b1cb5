// Glass spheres and boxes: the push constants of their passes and the optics
// both the raster (glass.frag: for a sphere Wyman's two-interface refraction
// in image space, for a box the exact path) and the CPU reference
// (render/reference_tracer.cpp, the exact exit point) use, so that the
// difference between the two measures only how the raster finds the exit
// point and its normal, and what its casts leave out.
//
// The model, on both sides: at the front surface the exact unpolarised
// Fresnel reflectance (not Schlick's fit) splits the view ray into its
// reflection and its refraction into the glass; the refracted ray leaves at
// the exit point, refracted out by the exit normal, with no Fresnel loss
// there; where it cannot leave (total internal reflection) it takes the
// internally reflected direction instead, once, as if it left that way (a
// box: it reflects on inside, up to TP_GLASS_BOX_REFLECTIONS times). Each
// surface bends the ray by the glass's index over the index of what lies
// beyond it: the medium the ray came in at the front, and at the exit the
// pool's water or the air, by where the exit point lies (GlassSurround). Both
// rays that leave, the reflection and the exit ray, look up the scene: the
// raster by the analytic casts the water's rays use (lib/scene_rays.glsl),
// the reference by tracing them. Where the raster cannot go on (glass seen
// in the water's rays or through other glass) they look up the sky.
#ifndef TP_SHARED_GLASS_H
#define TP_SHARED_GLASS_H
#include "shared/interop.h"
#include "shared/objects.h"

TP_BEGIN

// Push constants of both glass passes, one draw per glass sphere. The first
// 48 bytes are laid out as SphereParams' (the sphere, albedo and tessellation
// sphere.vert reads), so sphere.vert tessellates it unchanged; the glass
// fields take the place of the Lambertian sphere's material.
struct GlassSphereParams {
  vec4 sphere;         // xyz centre, w radius
  vec4 albedo;         // unused (SphereParams' place)
  uvec4 tessellation;  // x: stacks, y: slices
  vec4 glass;          // x: index of refraction
  uvec4 search;        // x: binary-search steps for the exit point (render.glass_search_steps);
                       // y: its slot among SceneObjects' spheres, which its own rays pass by
};

// Push constants of the glass pass's draw of a glass box. The first 48 bytes
// are BoxParams', so box.vert draws it unchanged.
struct GlassBoxParams {
  vec4 center;    // xyz centre, w yaw (radians)
  vec4 halfSize;  // xyz
  vec4 albedo;    // unused (BoxParams' place)
  vec4 glass;     // x: index of refraction
};

// Unpolarised Fresnel reflectance of a dielectric interface for a ray meeting
// it at incidence cosine cosI (> 0), going from index n1 into n2; 1 past the
// critical angle.
TP_INLINE float fresnelDielectric(float cosI, float n1, float n2) {
  float eta = n1 / n2;
  float sin2T = eta * eta * (1.0f - cosI * cosI);
  if (sin2T >= 1.0f) return 1.0f;
  float cosT = sqrt(1.0f - sin2T);
  float rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  float rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
  return 0.5f * (rs * rs + rp * rp);
}

// Where glass stands: in the pool's water below its rest level inside the
// pool's square, in the air elsewhere. The surface is taken as flat there,
// as it is for the rays that leave the glass (lib/scene_rays.glsl's
// inPoolWater, the reference's).
struct GlassSurround {
  float level;     // the water's rest level
  float poolHalf;  // half the pool's side; 0: no water
  float waterIor;  // the water's index of refraction
};

// Whether p lies in the pool's water, below its rest level.
TP_INLINE bool inSurroundingWater(GlassSurround s, vec3 p) {
  return s.poolHalf > 0.0f && max(abs(p.x), abs(p.z)) < s.poolHalf && p.y < s.level;
}

// The index of refraction of what lies round the glass at p.
TP_INLINE float surroundIndexAt(GlassSurround s, vec3 p) { return inSurroundingWater(s, p) ? s.waterIor : 1.0f; }

// The ray inside the glass, direction t (unit), leaving through a surface of
// outward normal nOut, ior the glass's index over the index beyond: refracted
// out, or, under total internal reflection, reflected back in (the direction
// then looked up as if it left).
TP_INLINE vec3 glassExitDirection(vec3 t, vec3 nOut, float ior) {
  vec3 leaving = refract(t, -nOut, ior);
  if (dot(leaving, leaving) == 0.0f) return reflect(t, -nOut);
  return normalize(leaving);
}

// Whether the ray leaving through nOut is totally internally reflected.
TP_INLINE bool glassTotalInternalReflection(vec3 t, vec3 nOut, float ior) {
  float cosI = dot(t, nOut);
  return ior * ior * (1.0f - cosI * cosI) >= 1.0f;
}

// What a view ray does at a piece of glass: the front surface's reflection,
// and the ray that leaves from where it leaves.
struct GlassExit {
  float reflectance;  // exact Fresnel at the front surface
  vec3 reflected;     // from the entry point
  vec3 exitPoint;
  vec3 leaving;
  // The path inside, which the raster's ray differentials follow
  // (glassPathDifferentials, lib/ray_differential.glsl):
  vec3 inside;         // the refracted direction at the entry point
  float insideLength;  // the path's length, its legs between reflections summed
  vec3 lastInside;     // the direction of its last leg
  vec3 exitNormal;     // the outward normal where that leg ends
  // The glass's index over the index beyond it, at the entry and at the exit.
  float entryIor;
  float exitIor;
};

// The weight of the ray that leaves: what the front surface lets in, times
// the squared ratio of the indices of the medium the view ray came in by and
// the one the ray leaves into. Radiance over n^2 is kept along a ray, so
// the water's light seen from the air through glass that stands through the
// surface is 1 / n^2 of it, as through the water's own surface.
TP_INLINE float glassLeavingWeight(GlassExit g) {
  float ratio = g.exitIor / g.entryIor;
  return (1.0f - g.reflectance) * ratio * ratio;
}

// The front surface, met at a point of outward normal n along dir (unit):
// its reflection and the refraction into the glass. outside: the index of
// the medium the ray comes in. Where the glass's index is the lower of the
// two, the ray may be reflected whole; the way in is then the ray's own
// (its weight is zero), so that what follows it stays finite.
TP_INLINE GlassExit glassFrontSurface(vec3 dir, vec3 n, float ior, float outside) {
  GlassExit g;
  g.entryIor = ior / outside;
  g.reflectance = fresnelDielectric(max(-dot(dir, n), 0.0f), 1.0f, g.entryIor);
  g.reflected = reflect(dir, n);
  g.inside = refract(dir, n, 1.0f / g.entryIor);
  if (dot(g.inside, g.inside) == 0.0f) g.inside = dir;
  return g;
}

// The exact paths of a ray, direction dir (unit), meeting a glass sphere of
// `radius` and index `ior` at p, outward normal n, from a medium of index
// `outside`: its reflection, its refraction into the glass, the chord it
// crosses and the ray that leaves at the chord's far end. With the sphere's
// centre c, p - c = radius n: the far end lies at distance -2 radius (n . t)
// along t, where the normal is n mirrored in the plane normal to t. The
// raster's glass pass finds that end in image space instead.
TP_INLINE GlassExit glassSphereExactExit(vec3 p, vec3 dir, vec3 n, float radius, float ior, float outside,
                                         GlassSurround s) {
  GlassExit g = glassFrontSurface(dir, n, ior, outside);
  float chord = -2.0f * dot(n, g.inside);  // in radii
  g.insideLength = chord * radius;
  g.exitPoint = p + g.insideLength * g.inside;
  g.lastInside = g.inside;
  g.exitNormal = n + chord * g.inside;
  g.exitIor = ior / surroundIndexAt(s, g.exitPoint);
  g.leaving = glassExitDirection(g.inside, g.exitNormal, g.exitIor);
  return g;
}

// The most reflections inside a glass box before the ray is taken as leaving
// (by the internally reflected direction, as a sphere's does). A box's faces
// meet at right angles, so each reflection flips one component of the ray's
// direction in the box's frame: a ray that entered through a face leaves
// through the face opposite (where it meets the entry's refracted angle,
// below the critical one) after reflecting off the faces across its way,
// which it meets past the critical angle when the index exceeds sqrt 2.
// Eight is more than a box four times as long as it is wide needs.
#define TP_GLASS_BOX_REFLECTIONS 8

// The exact paths of a ray, direction dir (unit), meeting a glass box of
// index `ior` at p on a face of outward normal n, from a medium of index
// `outside`: its reflection there, and its refraction in, followed through
// the box's reflections to the face it leaves by. Each face it meets
// reflects it whole or lets it out by what lies beyond that point.
TP_INLINE GlassExit glassBoxPaths(vec3 p, vec3 dir, vec3 n, vec4 center, vec4 halfSize, float ior, float outside,
                                  GlassSurround surround) {
  GlassExit g = glassFrontSurface(dir, n, ior, outside);
  // In the box's frame, from p held inside it (round-off may put it out).
  vec3 h = vec3(halfSize);
  vec3 o = clamp(toBoxFrame(p - vec3(center), center.w), -h, h);
  vec3 d = toBoxFrame(g.inside, center.w);
  vec3 nOut = vec3(0.0f);
  g.insideLength = 0.0f;
  TP_DONT_UNROLL for (int k = 0; k <= TP_GLASS_BOX_REFLECTIONS; ++k) {
    BoxFaceAhead face = boxFaceAhead(o, d, h);
    int axis = face.axis;
    o = clamp(o + face.distance * d, -h, h);
    g.insideLength += face.distance;
    nOut = vec3(0.0f);
    nOut[axis] = d[axis] > 0.0f ? 1.0f : -1.0f;
    g.exitPoint = vec3(center) + fromBoxFrame(o, center.w);
    g.exitIor = ior / surroundIndexAt(surround, g.exitPoint);
    if (k == TP_GLASS_BOX_REFLECTIONS || !glassTotalInternalReflection(d, nOut, g.exitIor)) break;
    d[axis] = -d[axis];
  }
  g.leaving = fromBoxFrame(glassExitDirection(d, nOut, g.exitIor), center.w);
  g.lastInside = fromBoxFrame(d, center.w);
  g.exitNormal = fromBoxFrame(nOut, center.w);
  return g;
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::GlassSphereParams) == 80);
static_assert(offsetof(tp::shader::GlassSphereParams, glass) == 48);
static_assert(sizeof(tp::shader::GlassBoxParams) == 64);
#endif

#endif
