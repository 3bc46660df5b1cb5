// The albedo of the patterned planes (shared/ground.h): a checker, or tiles
// with grout (the pool's floor and walls, the terrace's pavers), and around
// the pool a coping and past the terrace a lawn. One text for C++ and GLSL,
// so the raster passes and the CPU reference draw the same. Every term is
// box-filtered over the pixel's footprint, so far tiles do not alias; a zero
// footprint point-samples (the reference filters by its samples).
#ifndef TP_SHARED_SURFACE_PATTERN_H
#define TP_SHARED_SURFACE_PATTERN_H
#include "shared/brick.h"
#include "shared/ground.h"
#include "shared/interop.h"
#include "shared/noise.h"
#include "shared/specialization.h"

TP_BEGIN

// Each tile draws its tone between albedoA and albedoB from this seed.
const uint kTileToneSeed = 211u;
// The coping is laid in stones about this many coping widths long.
const float kCopingStoneLength = 2.5f;
// The lawn's albedo varies by up to this fraction, by a fractal sum of
// gradient noise in world metres (this frequency, octaves, persistence, seed).
const float kLawnVariation = 0.35f;
const float kLawnFrequency = 0.35f;
const uint kLawnOctaves = 3u;
const float kLawnPersistence = 0.5f;
const uint kLawnSeed = 313u;

// Integral from 0 to x of the square wave that is +1 on [0,1) and -1 on [1,2), period 2.
TP_INLINE vec2 squareWaveIntegral(vec2 x) {
  vec2 f = fract(x * 0.5f);
  return 2.0f * (f - 2.0f * max(f - 0.5f, 0.0f));
}

// Fraction of the footprint [p - w/2, p + w/2]^2 on odd squares (0..1): the box
// filter is separable, so the mean of the product of the two square waves is
// the product of their means.
TP_INLINE float filteredChecker(vec2 p, vec2 w) {
  if (w.x <= 0.0f || w.y <= 0.0f) {
    vec2 f = fract(p * 0.5f);
    return (f.x < 0.5f) != (f.y < 0.5f) ? 1.0f : 0.0f;
  }
  w = max(w, vec2(1e-6f));
  vec2 wave = (squareWaveIntegral(p + 0.5f * w) - squareWaveIntegral(p - 0.5f * w)) / w;
  return 0.5f - 0.5f * wave.x * wave.y;
}

// Share of [x - w/2, x + w/2] inside [a, b); w 0 point-samples.
TP_INLINE float bandShare(float x, float w, float a, float b) {
  if (w <= 0.0f) return x >= a && x < b ? 1.0f : 0.0f;
  TP_PRECISE float inside = min(b, x + 0.5f * w) - max(a, x - 0.5f * w);
  return clamp(inside / w, 0.0f, 1.0f);
}

// A surface with joints, `share` of it on the stones (or tiles) and the
// rest on the joints: the albedo the pixel averages.
TP_INLINE vec3 jointedAlbedo(vec3 joint, vec3 stone, float share) {
  TP_PRECISE vec3 albedo = joint + (stone - joint) * share;
  return albedo;
}

// Tiles at p (metres in the plane) over a footprint (metres): the share on
// tile rather than grout is the product of the two joints' pulses (exact in
// a row; across rows the centre's row places the head joints, as for the
// bricks). A tile's tone is its own, drawn between albedoA and albedoB; once
// the footprint spans a tile the tones fade to their mean, so far tiles do
// not sparkle.
TP_INLINE vec3 tilesAlbedo(GroundParams g, vec2 p, vec2 footprint) {
  TP_PRECISE vec2 q = p * vec2(g.tiles);
  TP_PRECISE vec2 qFootprint = footprint * vec2(g.tiles);
  float row = floor(q.y);
  TP_PRECISE float along = q.x + 2.0f * g.albedoB.w * brickCourseShift(row);
  TP_PRECISE float onTile =
      brickPulse(along, qFootprint.x, g.tiles.z) * brickPulse(q.y, qFootprint.y, g.tiles.w);
  TP_PRECISE float spread = clamp(1.0f - max(qFootprint.x, qFootprint.y), 0.0f, 1.0f);
  TP_PRECISE float tone = 0.5f + spread * (latticeValue(int(floor(along)), int(row), kTileToneSeed) - 0.5f);
  TP_PRECISE vec3 tile = vec3(g.albedoA) + (vec3(g.albedoB) - vec3(g.albedoA)) * tone;
  return jointedAlbedo(vec3(g.jointAlbedo), tile, onTile);
}

// The plane's own pattern at p: the checker or the tiles (no tiles' code
// without a tiled plane in the scene: shared/specialization.h).
TP_INLINE vec3 patternAlbedo(GroundParams g, vec2 p, vec2 footprint) {
  if (g.albedoA.w == 0.0f || !kTiledSurfaces) {
    float odd = filteredChecker(p / g.plane.z, footprint / g.plane.z);
    return mix(vec3(g.albedoA), vec3(g.albedoB), odd);
  }
  return tilesAlbedo(g, p, footprint);
}

// The pattern's mean albedo: what it averages to seen from afar (by rays
// that do not filter it, and in exported materials).
TP_INLINE vec3 patternMeanAlbedo(GroundParams g) {
  TP_PRECISE vec3 tones = 0.5f * (vec3(g.albedoA) + vec3(g.albedoB));
  if (g.albedoA.w == 0.0f) return tones;
  TP_PRECISE float onTile = (1.0f - 2.0f * g.tiles.z) * (1.0f - 2.0f * g.tiles.w);
  return jointedAlbedo(vec3(g.jointAlbedo), tones, onTile);
}

// The ground at world xz: its pattern; then, out from the pool's edge, the
// coping's band of stones; past the terrace's edge, the lawn. Both edges are
// squares, so the distance out is the larger of |x| and |z|, and the
// footprint across an edge is the one along that axis.
TP_INLINE vec3 groundAlbedo(GroundParams g, vec2 xz, vec2 footprint) {
  vec3 albedo = patternAlbedo(g, xz, footprint);
  const bool onXSide = abs(xz.x) > abs(xz.y);
  const float outward = max(abs(xz.x), abs(xz.y));
  const float across = onXSide ? footprint.x : footprint.y;
  const float hole = g.plane.w, coping = g.jointAlbedo.w, terrace = g.copingAlbedo.w;
  // Both belong to the terrace, a tiled plane: no code for them without one
  // (lavapipe runs an if's body for every pixel, masked, wherever it is compiled in).
  const float onCoping = kTiledSurfaces && hole > 0.0f && coping > 0.0f ? bandShare(outward, across, hole, hole + coping) : 0.0f;
  if (onCoping > 0.0f) {
    // Whole stones along each side, about kCopingStoneLength widths long,
    // with joints on the pool's corners: each corner is one square stone.
    TP_PRECISE float stones = max(1.0f, floor(2.0f * hole / (kCopingStoneLength * coping) + 0.5f));
    TP_PRECISE float stone = 2.0f * hole / stones;
    TP_PRECISE float along = (onXSide ? xz.y : xz.x) + hole;
    TP_PRECISE float onStone =
        brickPulse(along / stone, (onXSide ? footprint.y : footprint.x) / stone, g.lawnAlbedo.w / stone);
    vec3 copingAlbedo = jointedAlbedo(vec3(g.jointAlbedo), vec3(g.copingAlbedo), onStone);
    albedo = mix(albedo, copingAlbedo, onCoping);
  }
  const float onLawn = kTiledSurfaces && terrace > 0.0f ? bandShare(outward, across, terrace, 1e30f) : 0.0f;
  if (onLawn > 0.0f) {
    TP_PRECISE float spread = clamp(1.0f - 2.0f * kLawnFrequency * max(footprint.x, footprint.y), 0.0f, 1.0f);
    TP_PRECISE float grass =
        fractalNoise01(TP_NOISE_GRADIENT, xz * kLawnFrequency, kLawnSeed, kLawnOctaves, kLawnPersistence);
    TP_PRECISE vec3 lawn = vec3(g.lawnAlbedo) * (1.0f - kLawnVariation * (0.5f + spread * (grass - 0.5f)));
    albedo = mix(albedo, lawn, onLawn);
  }
  return albedo;
}

TP_END

#endif
