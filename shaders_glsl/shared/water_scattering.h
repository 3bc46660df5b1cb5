// Light scattered once in the water: what a path under the water gathers
// from the sun's beam and the pool's light that the water scatters towards
// it, in closed form. Compiled for the raster (the water's rays, and what the camera
// sees from under the surface) and for C++, where tests hold it against an
// independent quadrature and the semi-infinite slab's closed form. The
// reference does not use it: it samples the same integral along its own rays,
// with a shadow ray to the sun at each point (reference_tracer.cpp).
//
// The model. The water scatters with coefficient sigma_s (per colour) and
// the Henyey-Greenstein phase function of anisotropy g, and attenuates with
// extinction sigma_t = absorption + sigma_s. The light enters through the
// flat surface at the rest level, as the floor's sun light does (no Fresnel
// loss, as the floor and the caustics map take it):
//   - the sun as a beam along its refracted direction, with the horizontal
//     irradiance it has above the water (the beam narrows by cos(air) /
//     cos(water)), attenuated by exp(-sigma_t d / mu) at depth d, mu the
//     cosine of the refracted beam with the vertical; its phase is HG's;
//   - everything else, the sky through the surface and the light the floor,
//     the walls and the surface's underside send back, as the pool's light
//     around (the radiance arriving from every direction, in SH9: the
//     caller's, shared/pool_light.h's at the path's middle), the same all
//     along the path; scattered by HG's phase, whose band l carries g^l
//     (Funk and Hecke). The floor's light is as large as the sky's: a vertical beam
//     of the sky alone left the water far less hazy than in the path-traced
//     truth (docs/light-in-the-water.md).
// The sun's beam is shadowed by what casts the sun's shadows
// (shared/sun_shadow.h's sunRayOpen), taken at a few points of the path;
// the pool's light is not.
#ifndef TP_SHARED_WATER_SCATTERING_H
#define TP_SHARED_WATER_SCATTERING_H
#include "shared/constants.h"
#include "shared/frame.h"
#include "shared/interop.h"
#include "shared/sh9.h"
#include "shared/sun_shadow.h"
#include "shared/water_surface.h"

// In GLSL the functions read the includer's `frame` in place and ask its
// frameSunRayOpen (shared/sun_shadow.h), so include this after the Frame
// block and sun_shadow.h. In C++ the frame comes by reference. A shader's
// scattering code is compiled only into its TP_SCATTERING variants
// (cmake/shaders.cmake), for scenes whose water scatters: on lavapipe even
// code that never runs costs (docs/light-in-the-water.md).
#ifdef __cplusplus
#define TP_FRAME_PARAM const FrameUniforms &frame,
#define TP_FRAME_ARG frame,
#define TP_SCATTER_SUN_SHARE(p) sunRayOpen(frame.shadows, p, vec3(frame.sunDirection))
#define TP_SCATTER_TO_SUN vec3(frame.sunDirection)
#define TP_SCATTER_UNFOLDED(x) (x)
#else
#define TP_FRAME_PARAM
#define TP_FRAME_ARG
#define TP_SCATTER_SUN_SHARE(p) frameSunRayOpen(p)
// The sun's direction and the medium's values the code below tests, read so
// that lavapipe does not compile the shader again at every draw
// (TP_UNIFORM_INDEX_BASE in shared/frame.h).
#define TP_SCATTER_TO_SUN frameToSun()
#define TP_SCATTER_UNFOLDED(x) ((x) + TP_OPAQUE_ZERO)
#endif

TP_BEGIN

// Henyey-Greenstein's phase function, per steradian, of the angle between
// the light's travel and the scattered light's (cosTheta).
TP_INLINE float henyeyGreenstein(float cosTheta, float g) {
  float denominator = 1.0f + g * g - 2.0f * g * cosTheta;
  return (1.0f - g * g) / (4.0f * kPi * denominator * sqrt(denominator));
}

// Below this optical length the segment's integral takes its series: the
// closed form's 1 - exp(-kL) loses its digits to cancellation there.
const float kScatterSeriesBelow = 1e-3f;

// The integral of exp(-k s) over s in [0, length]; k may be negative or 0.
TP_INLINE float attenuatedLength(float k, float length) {
  float x = k * length;
  if (abs(x) < kScatterSeriesBelow) return length * (1.0f - x * (0.5f - x / 6.0f));
  return (1.0f - exp(-x)) / k;
}

// The light one beam scatters into a path: travelling along `travel` (unit,
// downwards), of irradiance `beam` on a surface facing it at the level,
// attenuated along its way down by exp(-sigma_t depth / mu); the path starts
// `depth` under the level and goes along `dir` (unit) for `length`.
TP_INLINE vec3 beamInScatter(vec3 extinction, vec3 scattering, vec3 beam, float phase, float mu, float depth,
                             float dirY, float length) {
  vec3 k = extinction * (1.0f - dirY / mu);
  vec3 along = vec3(attenuatedLength(k.x, length), attenuatedLength(k.y, length), attenuatedLength(k.z, length));
  return scattering * phase * beam * exp(-extinction * (depth / mu)) * along;
}

// The radiance the water scatters towards -dir per unit of sigma_s from the
// pool's light around (`around`, SH9 of the radiance arriving from each
// direction): Henyey-Greenstein's phase of anisotropy g convolved with it,
// band l scaled by g^l; clamped at 0, where the truncated series rings.
TP_INLINE vec3 poolLightScattered(Sh9 around, vec3 dir, float g) {
  vec3 light = vec3(0.0f);
  for (uint i = 0u; i < 9u; ++i) {
    uint band = sh9Band(i);
    float factor = band == 0u ? 1.0f : (band == 1u ? g : g * g);
    light += factor * sh9Basis(i, dir) * vec3(around.c[i]);
  }
  return max(light, vec3(0.0f));
}

// Radiance arriving at `start`, under the water, along -dir from the water
// on the segment start + s dir, 0 < s < length: the sun's beam and the
// pool's light around (`around`) scattered once towards it (the model
// above). `scattering`: rgb sigma_s, w g; `level`: the rest level; `ior`:
// the water's index.
// `pieces` (water.scattering_shadow_pieces): the sun's beam is cut into this
// many equal pieces of the path, each lit or not as the sun's central ray
// from its middle is open: the shafts of light and shadow the spheres, the
// boxes and the walls make in it; within a piece the closed form holds. 0:
// the beam unshadowed, one closed form.
TP_INLINE vec3 waterInScatter(TP_FRAME_PARAM vec3 extinction, vec4 scattering, float level, float ior, uint pieces,
                              Sh9 around, vec3 start, vec3 dir, float length) {
  float depth = level - start.y;
  vec3 light = vec3(scattering) * poolLightScattered(around, dir, scattering.w) *
               vec3(attenuatedLength(extinction.x, length), attenuatedLength(extinction.y, length),
                    attenuatedLength(extinction.z, length));
  vec3 toSun = TP_SCATTER_TO_SUN;
  if (toSun.y <= 0.0f) return light;
  vec3 travel = refract(-toSun, vec3(0.0f, 1.0f, 0.0f), 1.0f / ior);
  float mu = -travel.y;
  vec3 beam = vec3(frame.sunIrradiance) * (toSun.y / mu);
  float phase = henyeyGreenstein(-dot(travel, dir), scattering.w);
  uint count = max(pieces, 1u);
  float piece = length / float(count);
  TP_DONT_UNROLL for (uint i = 0u; i < count; ++i) {
    float from = float(i) * piece;
    float share = pieces > 0u ? TP_SCATTER_SUN_SHARE(start + (from + 0.5f * piece) * dir) : 1.0f;
    light += share * exp(-extinction * from) *
             beamInScatter(extinction, vec3(scattering), beam, phase, mu, depth - from * dir.y, dir.y, piece);
  }
  return light;
}

// Whether the water scatters at all: with no scattering coefficient what it
// adds is exactly 0 (the camera in the air: its medium scatters nothing).
TP_INLINE bool waterScatters(vec4 scattering) { return scattering.x + scattering.y + scattering.z > 0.0f; }

// What the water between the camera and p scatters towards the camera, when
// the camera is under the surface (0 in air); added to what it sees of p,
// attenuated by viewTransmittance.
#if defined(__cplusplus) || defined(TP_SCATTERING)
TP_INLINE vec3 viewInScatter(TP_FRAME_PARAM CameraMedium medium, Sh9 around, vec3 p) {
  vec3 light = vec3(0.0f);
  vec3 camera = vec3(frame.cameraPosition);
  float length = distance(camera, p);
  if (waterScatters(TP_SCATTER_UNFOLDED(medium.scattering)) && length > 0.0f) {
    light = waterInScatter(TP_FRAME_ARG vec3(medium.extinction), medium.scattering, medium.water.x, medium.water.y,
                           uint(TP_SCATTER_UNFOLDED(medium.water.z)), around, camera, (p - camera) / length, length);
  }
  return light;
}
#else
vec3 viewInScatter(CameraMedium medium, Sh9 around, vec3 p) { return vec3(0.0); }
#endif

TP_END

#endif
