#version 450
#extension GL_GOOGLE_include_directive : require
// A Lambertian sphere (shared/shading.h).
#include "shared/shading.h"
#include "shared/objects.h"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { SphereParams params; };

void main() { color = vec4(sphereRadiance(frame, params.albedo.rgb, normalize(worldNormal)), 1.0); }
