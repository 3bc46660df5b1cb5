#version 450
#extension GL_GOOGLE_include_directive : require
// The pool's walls, Lambertian (shared/shading.h).
#include "shared/shading.h"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform Pool { PoolParams pool; };

void main() { color = vec4(poolWallRadiance(pool, frame, normalize(worldNormal)), 1.0); }
