#version 450
// Test-only: y = a * x + y over n floats (the compute round-trip and the
// missing-barrier tests use it).
layout(local_size_x = 64) in;
layout(binding = 0) readonly buffer X { float x[]; };
layout(binding = 1) buffer Y { float y[]; };
layout(push_constant) uniform Push { float a; uint n; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= n) return;
  y[i] = a * x[i] + y[i];
}
