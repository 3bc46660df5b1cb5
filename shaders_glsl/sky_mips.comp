#version 450
// One level of the sky texture's mip chain from the level above it: each
// texel the mean of the four it covers (both sides halve, level by level).
// A lookup at level k then averages the sky over 2^k texels a side: the
// footprint of a ray whose direction spreads that far (skyFiltered,
// lib/scene_rays.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform readonly image2D finer;
layout(binding = 1, rgba16f) uniform writeonly image2D coarser;

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(coarser)))) return;
  const ivec2 q = 2 * p;
  const vec4 sum = imageLoad(finer, q) + imageLoad(finer, q + ivec2(1, 0)) + imageLoad(finer, q + ivec2(0, 1)) +
                   imageLoad(finer, q + ivec2(1, 1));
  imageStore(coarser, p, sum / 4.0);
}
