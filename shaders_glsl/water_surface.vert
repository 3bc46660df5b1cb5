#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface: one vertex per simulation cell, read straight from the
// simulation's storage buffer (no copy); the normal from central differences of u.
#include "shared/frame.h"
#include "shared/water.h"
#include "shared/water_surface.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 2) readonly buffer Cells { WaterCell cells[]; };
layout(push_constant) uniform Push { WaterSurfaceParams surface; };
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

float heightAt(int i, int j) {
  int n = int(surface.grid.x);
  return cells[clamp(j, 0, n - 1) * n + clamp(i, 0, n - 1)].u;
}

void main() {
  const int n = int(surface.grid.x);
  const int i = gl_VertexIndex % n, j = gl_VertexIndex / n;
  const WaterCell c = cells[gl_VertexIndex];
  const float h = surface.placement.w;
  // One-sided at the edges (the clamped neighbour is the cell itself): divide by the real spacing.
  const float dx = float(min(i + 1, n - 1) - max(i - 1, 0)) * h;
  const float dz = float(min(j + 1, n - 1) - max(j - 1, 0)) * h;
  const float dudx = (heightAt(i + 1, j) - heightAt(i - 1, j)) / dx;
  const float dudz = (heightAt(i, j + 1) - heightAt(i, j - 1)) / dz;
  worldNormal = normalize(vec3(-dudx, 1.0, -dudz));
  worldPosition = vec3(surface.placement.x + c.x, surface.placement.y + c.u, surface.placement.z + c.z);
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
