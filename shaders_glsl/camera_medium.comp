#version 450
#extension GL_GOOGLE_include_directive : require
// Whether the camera is under the water, from the simulated surface at its
// xz: one invocation, after the simulation, before anything is drawn.
#include "shared/frame.h"
#include "lib/water_grid.glsl"

layout(local_size_x = 1) in;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) writeonly buffer Medium { CameraMedium medium; };

void main() {
  const vec3 camera = frame.cameraPosition.xyz;
  const vec4 quad = gridQuadAt(surface, camera.xz);
  const ivec2 i = ivec2(quad.xy);
  const vec4 corners = vec4(heightAt(i.x, i.y), heightAt(i.x + 1, i.y), heightAt(i.x, i.y + 1), heightAt(i.x + 1, i.y + 1));
  const bool under = underWaterSurface(surface, camera, corners, quad.zw);
  medium.extinction = under ? vec4(surface.extinction.rgb, 1.0) : vec4(0.0);
  medium.scattering = under ? surface.scattering : vec4(0.0);
  medium.water = under ? vec4(surface.placement.y, surface.extinction.w, float(surface.grid.y), 0.0) : vec4(0.0);
}
