// Aerial perspective: the air between the camera and what it sees scatters
// the sky's light into the view and takes the surface's out. With a haze
// distance D, a surface s metres away keeps exp(-s / D) of its light and
// the rest is the sky's at the horizon below the view (along the view's
// azimuth): far surfaces fade into the horizon, and the ground meets the sky
// without an edge. Shared by resolve.comp and the reference tracer.
#ifndef TP_SHARED_HAZE_H
#define TP_SHARED_HAZE_H
#include "shared/interop.h"

TP_BEGIN

// The share of a surface's light that crosses `distance` metres of air.
TP_INLINE float hazeTransmittance(float distance, float hazeDistance) { return exp(-distance / hazeDistance); }

// The direction at the horizon below (or above) unit direction d: the sky
// there is the light the haze brings. Straight up or down, any azimuth.
TP_INLINE vec3 hazeHorizonDirection(vec3 d) {
  float across = length(vec2(d.x, d.z));
  return across > 0.0f ? vec3(d.x / across, 0.0f, d.z / across) : vec3(1.0f, 0.0f, 0.0f);
}

// A surface's radiance seen `distance` metres away through the haze, with
// `horizon` the sky's radiance along hazeHorizonDirection.
TP_INLINE vec3 hazed(vec3 radiance, vec3 horizon, float distance, float hazeDistance) {
  return mix(horizon, radiance, hazeTransmittance(distance, hazeDistance));
}

TP_END

#endif
