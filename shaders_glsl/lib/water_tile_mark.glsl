// Marks the workgroup's tile as changed at a step index when any of its cells
// changed to the bit: the flags from which the next step's tile list is built
// (sim/water_tiles.hpp). The including shader declares `uint changedAt[]` and
// runs one workgroup per tile.
#ifndef TP_LIB_WATER_TILE_MARK
#define TP_LIB_WATER_TILE_MARK

shared bool tileChanged;

// Bitwise, so that -0 against +0 or a NaN payload counts as a change: a
// skipped tile must hold exactly what a step would have written.
bool cellChanged(vec4 before, vec4 after) { return any(notEqual(floatBitsToUint(before), floatBitsToUint(after))); }

// One write per tile rather than one per changed cell. Has barriers: call it
// from every invocation of the workgroup.
void markTileIfChanged(bool changed, uint tile, uint stepIndex) {
  if (gl_LocalInvocationIndex == 0u) tileChanged = false;
  memoryBarrierShared();
  barrier();
  if (changed) tileChanged = true;
  memoryBarrierShared();
  barrier();
  if (gl_LocalInvocationIndex == 0u && tileChanged) changedAt[tile] = stepIndex;
}

#endif
