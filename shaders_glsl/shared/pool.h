// The pool: a square hole in the ground, its inner walls (plain, tiled, or
// brick with noise dirt), and a tiled or checkered floor shaped by value-noise terrain. A uniform buffer filled once per scene
// (render/pool_model.cpp); the floor's height function is shared with C++.
#ifndef TP_SHARED_POOL_H
#define TP_SHARED_POOL_H
#include "shared/brick.h"
#include "shared/ground.h"
#include "shared/interop.h"
#include "shared/noise.h"
#include "shared/specialization.h"
#include "shared/surface_pattern.h"

TP_BEGIN

struct PoolParams {
  vec4 box;  // x: half size of the square pool, y: rim height, z: mean floor depth below the rim, w: terrain amplitude
  vec4 terrain;        // x: terrain frequency (1/m), y: persistence, z: lowest floor vertex, w: highest (metres)
  uvec4 noise;         // x: octaves, y: seed, z: the floor mesh's vertices per side; w unused
  vec4 wallAlbedo;     // rgb: of plain walls; w: 0 plain, 1 brick, 2 tiled as the floor
  GroundParams tiles;  // the floor's checker or tiles (shared/surface_pattern.h), and the tiled walls'
  vec4 brick;          // xy: 1 / (brick width, brick height) in metres; zw: half the joint in brick widths, heights
  vec4 brickAlbedo;    // rgb; w: the dirt (0: none, 1: black where the dirt noise is 1)
  vec4 mortarAlbedo;   // rgb; w unused
  vec4 wallGloss;      // x: the walls' specular, y: their roughness (shared/glossy.h)
  vec4 water;  // x: the water's rest level, y: its index of refraction (the caustics' light lines), z: their reach
               // (pool_model's causticsReach); w: the water's cells a side (0: no water simulated)
  // The water's medium for rays that carry no WaterSurfaceParams (the glass's):
  vec4 extinction;      // rgb: absorption plus scattering, 1/m; w: the scattered sun's shadow pieces
  vec4 scattering;      // rgb: 1/m; w: the phase's anisotropy (water_scattering.h)
  GroundParams ground;  // the ground around the pool, for rays cast in shaders (the glass's)
};

// Bricks' tones vary by up to this fraction, one tone per brick, so that
// the courses read as bricks rather than stripes.
const float kBrickToneVariation = 0.25f;
// The dirt: a fractal sum of gradient noise in world metres (this frequency,
// octaves, persistence and seed), normalised to [0, 1].
const float kBrickDirtFrequency = 3.0f;
const uint kBrickDirtOctaves = 4u;
const float kBrickDirtPersistence = 0.5f;
const uint kBrickDirtSeed = 101u;

// Height of the pool floor at world xz: the mean floor plus the terrain, a
// fractal sum of bilinear value noise normalised to [-amplitude/2, amplitude/2].
TP_INLINE float poolFloorHeight(PoolParams p, vec2 xz) {
  TP_PRECISE float total = 0.0f;
  TP_PRECISE float amplitude = 1.0f;
  for (uint i = 0u; i < p.noise.x; ++i) {
    total += amplitude;
    amplitude *= p.terrain.y;
  }
  TP_PRECISE float f = fractalNoise(TP_NOISE_VALUE_BILINEAR, xz * p.terrain.x, p.noise.y, p.noise.x, p.terrain.y);
  TP_PRECISE float h = p.box.y - p.box.z + p.box.w * (f / total - 0.5f);
  return h;
}

// A wall point's coordinates in metres: along the wall (x on the walls facing
// along z, z on those facing along x) and down from the rim.
TP_INLINE vec2 poolWallCoordinates(PoolParams p, vec3 position, vec3 normal) {
  return vec2(abs(normal.x) > 0.5f ? position.z : position.x, p.box.y - position.y);
}

const float kPoolWallPlain = 0.0f, kPoolWallBrick = 1.0f, kPoolWallTiles = 2.0f;

// The walls' albedo at wall coordinates `wall` (metres) over a footprint
// (metres; 0 point-samples): plain; tiled as the floor, the rows from the
// rim down; or brick and mortar by the fraction of the footprint on brick,
// each brick with its own tone, darkened by dirt.
TP_INLINE vec3 poolWallAlbedo(PoolParams p, vec2 wall, vec2 footprint) {
  if (p.wallAlbedo.w == kPoolWallPlain) return vec3(p.wallAlbedo);
  // Without brick walls in the scene, no brick code (shared/specialization.h).
  if (p.wallAlbedo.w == kPoolWallTiles || !kBrickWalls) return patternAlbedo(p.tiles, wall, footprint);
  TP_PRECISE vec2 q = wall * vec2(p.brick);
  TP_PRECISE vec2 qFootprint = footprint * vec2(p.brick);
  TP_PRECISE float onBrick = brickFraction(q, qFootprint, vec2(p.brick.z, p.brick.w));
  vec2 cell = brickCell(q);
  TP_PRECISE float tone = 1.0f - kBrickToneVariation * latticeValue(int(cell.x), int(cell.y), kBrickDirtSeed);
  TP_PRECISE vec3 mortar = vec3(p.mortarAlbedo);
  TP_PRECISE vec3 brick = vec3(p.brickAlbedo) * tone;
  TP_PRECISE float dirtNoise = fractalNoise01(TP_NOISE_GRADIENT, wall * kBrickDirtFrequency, kBrickDirtSeed,
                                              kBrickDirtOctaves, kBrickDirtPersistence);
  TP_PRECISE float clean = 1.0f - p.brickAlbedo.w * dirtNoise;
  TP_PRECISE vec3 albedo = jointedAlbedo(mortar, brick, onBrick) * clean;
  return albedo;
}

// The walls' albedo seen from afar (by rays that do not filter the pattern).
TP_INLINE vec3 poolWallMeanAlbedo(PoolParams p) {
  if (p.wallAlbedo.w == kPoolWallBrick) return vec3(p.brickAlbedo);
  if (p.wallAlbedo.w == kPoolWallTiles) return patternMeanAlbedo(p.tiles);
  return vec3(p.wallAlbedo);
}

// The lowest the floor can be: where the walls end.
TP_INLINE float poolBottom(PoolParams p) { return p.box.y - p.box.z - 0.5f * p.box.w; }

// The walls are drawn as bands, level strips from the rim to the bottom,
// each pair of neighbours sharing a whole edge. In a frame whose camera sees
// the walls below a height only through the water, which draws over them,
// and whose AO reads their depth and normal, the bands wholly below that
// height give their depth and normal alone (pool_floor_depth.frag) and the
// rest are lit (pool_walls.frag). Every frame draws the same triangles, so
// their depth is the same to the bit whichever way a band is drawn.
#define TP_POOL_WALL_BANDS 16

// Push constants of the walls' draws (pool_walls.vert): the bands drawn.
struct PoolWallsParams {
  uvec4 bands;  // x: the first, counted from the rim; y: how many
};

// The height of the edge above band `band` (TP_POOL_WALL_BANDS: the bottom).
TP_INLINE float poolWallBandTop(PoolParams p, uint band) {
  return p.box.y + (poolBottom(p) - p.box.y) * (float(band) / float(TP_POOL_WALL_BANDS));
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::PoolParams) == 400);
#endif

#endif
