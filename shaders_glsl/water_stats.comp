#version 450
#extension GL_GOOGLE_include_directive : require
// Health statistics of the water state, one partial per 16x16 workgroup
// (a tree reduction in shared memory); the host adds the partials in double.
#include "shared/water.h"

layout(local_size_x = 16, local_size_y = 16) in;
const uint GROUP = 256;
layout(binding = 0) readonly buffer State { WaterCell cells[]; };
layout(binding = 1) writeonly buffer Partials { WaterStatsPartial partials[]; };
layout(binding = 4) readonly buffer Solid { uint solidDepths[]; };
layout(push_constant) uniform Push { WaterStatsParams params; };

#include "lib/water_solid.glsl"
#include "lib/water_update.glsl"

shared float sMaxU[GROUP];
shared float sMaxV[GROUP];
shared float sSumU[GROUP];
shared float sEnergy[GROUP];
shared uint sNonFinite[GROUP];

// The height open cell `self` sees at (i, j): its own where that is solid,
// as the step does, so that no edge of a solid cell holds energy.
float heightAt(int self, int i, int j) {
  int n = int(params.n);
  const int k = waterNeighbour(j, n, params.boundary) * n + waterNeighbour(i, n, params.boundary);
  return cells[kSolids ? waterOpenNeighbour(self, k) : k].u;
}

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  const int n = int(params.n);
  const uint t = gl_LocalInvocationIndex;
  float maxU = 0.0, maxV = 0.0, sumU = 0.0, energy = 0.0;
  uint nonFinite = 0u;
  if (p.x < n && p.y < n) {
    const int self = p.y * n + p.x;
    const WaterCell c = cells[self];
    // A solid cell holds no water: its height is a ghost of its neighbours' (lib/water_solid.glsl).
    const bool holdsWater = !kSolids || !waterSolid(self);
    if (holdsWater && (isnan(c.u) || isinf(c.u) || isnan(c.v) || isinf(c.v))) {
      nonFinite = 1u;
    } else if (holdsWater) {
      const float uW = heightAt(self, p.x - 1, p.y), uE = heightAt(self, p.x + 1, p.y);
      const float uS = heightAt(self, p.x, p.y - 1), uN = heightAt(self, p.x, p.y + 1);
      maxU = abs(c.u);
      maxV = abs(c.v);
      sumU = c.u;
      // The energy the symplectic scheme conserves exactly (without damping):
      // kinetic + potential over the east and north edges + the dt cross term.
      const float dE = c.u - uE, dN = c.u - uN;
      const float laplacian = (((uW - c.u) + (uE - c.u)) + ((uS - c.u) + (uN - c.u))) / (params.h * params.h);
      energy = 0.5 * c.v * c.v + 0.5 * params.c2 * (dE * dE + dN * dN) / (params.h * params.h) +
               0.5 * params.dt * params.c2 * c.v * laplacian;
    }
  }
  sMaxU[t] = maxU;
  sMaxV[t] = maxV;
  sSumU[t] = sumU;
  sEnergy[t] = energy;
  sNonFinite[t] = nonFinite;
  for (uint stride = GROUP / 2; stride > 0; stride /= 2) {
    barrier();
    if (t < stride) {
      sMaxU[t] = max(sMaxU[t], sMaxU[t + stride]);
      sMaxV[t] = max(sMaxV[t], sMaxV[t + stride]);
      sSumU[t] += sSumU[t + stride];
      sEnergy[t] += sEnergy[t + stride];
      sNonFinite[t] += sNonFinite[t + stride];
    }
  }
  if (t == 0) {
    const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    partials[group] = WaterStatsPartial(sMaxU[0], sMaxV[0], sSumU[0], sEnergy[0], sNonFinite[0], 0u, 0u, 0u);
  }
}
