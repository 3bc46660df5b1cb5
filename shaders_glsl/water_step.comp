#version 450
#extension GL_GOOGLE_include_directive : require
// One step of the heightfield water per dispatch: reads src, writes dst.
#include "lib/water_update.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) readonly buffer Src { WaterCell src[]; };
layout(binding = 1) writeonly buffer Dst { WaterCell dst[]; };
layout(push_constant) uniform Push { WaterStepParams params; };

float heightAt(int i, int j) {
  int n = int(params.n);
  return src[waterNeighbour(j, n, params.boundary) * n + waterNeighbour(i, n, params.boundary)].u;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  int n = int(params.n);
  if (p.x >= n || p.y >= n) return;
  WaterCell c = src[p.y * n + p.x];
  vec2 uv = waterUpdate(params, c.u, c.v, heightAt(p.x - 1, p.y), heightAt(p.x + 1, p.y), heightAt(p.x, p.y - 1),
                        heightAt(p.x, p.y + 1));
  c.u = uv.x;
  c.v = uv.y;
  dst[p.y * n + p.x] = c;
}
