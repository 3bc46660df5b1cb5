// The heightfield water: the per-cell state (also the water mesh's vertex
// data) and the push constants of the simulation shaders, declared once for
// C++ and GLSL. Numerics: ../shared/DESIGN.md, "Numerics of the water".
#ifndef TP_SHARED_WATER_H
#define TP_SHARED_WATER_H
#include "shared/interop.h"

TP_BEGIN

// One cell, one std430 vec4: x and z are the cell centre ((i+1/2)h, (j+1/2)h),
// u the height, v the vertical velocity. Cell (i, j) is element j*n + i.
struct WaterCell {
  float x;
  float u;
  float z;
  float v;
};

#define TP_WATER_BOUNDARY_CLAMP 0u
#define TP_WATER_BOUNDARY_WRAP 1u
#define TP_WATER_SCHEME_SYMPLECTIC 0u
#define TP_WATER_SCHEME_EXPLICIT 1u

// The specialization constant (a bool) of the step and statistics shaders
// that says some cells are solid (lib/water_solid.glsl): a pipeline without
// it has no code for them, which a branch on a push constant would leave
// in, at about a fifth of the step's time on lavapipe.
#define TP_SPEC_WATER_SOLIDS 1

// Side of a tile in cells: the unit of active-tile stepping (sim/water_tiles.hpp)
// and the workgroup of every water shader that marks the tiles it changes.
#define TP_WATER_TILE 16

// Push constants of water_step.comp and water_step_tiled.comp.
struct WaterStepParams {
  uint n;              // grid side (n x n cells)
  uint boundary;       // TP_WATER_BOUNDARY_*
  uint scheme;         // TP_WATER_SCHEME_*
  uint steps;          // steps this dispatch takes (tiled shader: at most its halo)
  float dt;            // seconds per step
  float waveFactor;    // dt * c^2 / h^2
  float damping;       // exp(-gamma * dt), the per-step velocity factor
  float maxDifference; // maxSlope * h: neighbours further apart pass water across their edge; <= 0: off
  float gridDamping;   // kappa * dt: v gains this times the sum of its differences to its 4 neighbours
  float spillHeight;   // clamp boundary: a cell along a wall higher than this spills down to it
  float slopeShare;    // the share of an edge's difference over maxDifference that crosses it in a step
  uint pad;
};

// The slope limiter's excess of a height difference: how far it lies beyond
// +-limit (0 within it). Odd in the difference, so the two cells of an edge
// see the same excess, negated. lib/water_update.glsl and the C++ stepper
// (sim/cpu_stepper.cpp) share it.
TP_INLINE float waterSlopeExcess(float difference, float limit) {
  return difference - clamp(difference, -limit, limit);
}

// Push constants of water_drop.comp: adds amplitude * (1 + cos(pi r / radius)) / 2
// to u within radius of the centre.
struct WaterDropParams {
  uint n;
  float h;
  float radius;
  float amplitude;
  vec2 center;  // world x, z
  uint markStep; // the state's step index: tiles whose cells change are marked changed at it
  uint pad;
};

// Push constants of water_sphere.comp: a sphere moving from one centre to
// another raises and lowers the surface column by column: u changes by the
// sphere's volume below the rest level within the column's square where it
// goes minus where it was (shared/sphere_column.h), over the square's area;
// or, with the spread forcing, that volume spread as shared/sphere_spread.h
// says.
struct WaterSphereParams {
  vec4 oldCenter;  // xyz, w: radius
  vec4 newCenter;  // xyz, w: rest level of the water surface
  uint n;
  float h;
  uint markStep;     // as in WaterDropParams
  uint wrap;         // 1: the grid wraps round (the spread forcing's images)
  float spreadDepth;  // the spread forcing's widening per metre of depth (shared/sphere_spread.h)
  float fast;         // the spread forcing above the wave speed: fastSpreadVariance's `fast`
  float topShare;     // and its `topShare`
  float widening;     // the spread bump's variance factor near the wave speed (sim::wakeWidening)
};

// Push constants of water_step_active.comp: one step over whole tiles. Tile t
// covers cells [tx*T, tx*T + T) x [ty*T, ty*T + T) with tx = t % tilesPerSide,
// ty = t / tilesPerSide, T = TP_WATER_TILE.
struct WaterTileStepParams {
  WaterStepParams step;  // steps == 1
  uint stepIndex;        // index of the state this step writes: tiles whose cells change are marked with it
  uint tilesPerSide;
  uint fromList;         // 1: workgroup k steps tile tileList[k]; 0: workgroup (x, y) steps tile (x, y)
  uint pad;
};

// Push constants of water_tile_list.comp.
struct WaterTileListParams {
  uint tilesPerSide;
  uint boundary;     // TP_WATER_BOUNDARY_*: whether tile neighbourhoods wrap
  uint changedStep;  // lists the tiles with a tile changed at this step index in their 3x3 neighbourhood
  uint accumulate;   // 1: add the listed count to the running total; 0: only count (for the dispatch rule)
};

// The tile list's counters, host-visible: the indirect dispatch of the next
// step and the running total of listed tiles (a 64-bit count in two halves).
struct WaterTileCounters {
  uint groupsX;  // VkDispatchIndirectCommand: tiles listed by the last water_tile_list.comp
  uint groupsY;
  uint groupsZ;
  uint totalLow;
  uint totalHigh;
  uint pad0;
  uint pad1;
  uint pad2;
};

// Push constants of water_stats.comp.
struct WaterStatsParams {
  uint n;
  uint boundary;
  float c2;          // c^2
  float h;
  float dt;
  float pad0;
  vec2 pad1;
};

// One workgroup's partial statistics, summed on the host in double.
struct WaterStatsPartial {
  float maxAbsU;
  float maxAbsV;
  float sumU;        // volume / h^2
  float energy;      // the symplectic scheme's conserved energy, per unit area
  uint nonFinite;    // count of NaN or infinite u or v
  uint pad0;
  uint pad1;
  uint pad2;
};

TP_END

#ifdef __cplusplus
#include <cstddef>
static_assert(sizeof(tp::shader::WaterCell) == 16);
static_assert(offsetof(tp::shader::WaterCell, x) == 0);
static_assert(offsetof(tp::shader::WaterCell, u) == 4);
static_assert(offsetof(tp::shader::WaterCell, z) == 8);
static_assert(offsetof(tp::shader::WaterCell, v) == 12);
static_assert(sizeof(tp::shader::WaterStepParams) == 48);
static_assert(sizeof(tp::shader::WaterDropParams) == 32);
static_assert(sizeof(tp::shader::WaterSphereParams) == 64);
static_assert(sizeof(tp::shader::WaterStatsParams) == 32);
static_assert(sizeof(tp::shader::WaterTileStepParams) == 64);
static_assert(offsetof(tp::shader::WaterTileStepParams, stepIndex) == 48);
static_assert(sizeof(tp::shader::WaterTileListParams) == 16);
static_assert(sizeof(tp::shader::WaterTileCounters) == 32);
static_assert(offsetof(tp::shader::WaterTileCounters, totalLow) == 12);
static_assert(offsetof(tp::shader::WaterDropParams, markStep) == 24);
static_assert(offsetof(tp::shader::WaterSphereParams, markStep) == 40);
static_assert(sizeof(tp::shader::WaterStatsPartial) == 32);
#endif

#endif
