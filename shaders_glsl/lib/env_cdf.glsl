// Inverting the environment sampler's CDFs (env_rows.comp, env_marginal.comp)
// by binary search, for the passes that draw from them (env_sh.comp,
// glossy_prefilter.comp). The including shader declares the buffers
// `conditional` (per row: width + 1 entries) and `marginal` (height + 2).
#ifndef TP_LIB_ENV_CDF
#define TP_LIB_ENV_CDF

// The piece k (< n) of the CDF starting at `base` (n + 1 entries) that holds
// x: the last with cdf[k] <= x, so never a piece of zero probability; in
// .y, how far across it x lies.
vec2 invertConditional(uint base, uint n, float x) {
  uint lo = 0u, hi = n;
  while (hi - lo > 1u) {
    const uint mid = (lo + hi) / 2u;
    if (conditional[base + mid] <= x) lo = mid; else hi = mid;
  }
  const float width = conditional[base + lo + 1u] - conditional[base + lo];
  return vec2(float(lo), width > 0.0 ? clamp((x - conditional[base + lo]) / width, 0.0, 1.0) : 0.5);
}

vec2 invertMarginal(uint n, float x) {
  uint lo = 0u, hi = n;
  while (hi - lo > 1u) {
    const uint mid = (lo + hi) / 2u;
    if (marginal[mid] <= x) lo = mid; else hi = mid;
  }
  const float width = marginal[lo + 1u] - marginal[lo];
  return vec2(float(lo), width > 0.0 ? clamp((x - marginal[lo]) / width, 0.0, 1.0) : 0.5);
}

// The texel drawn for a point xi of the unit square (marginal by xi.x, then
// the row's conditional by xi.y) and, in zw, the fractions across it (u,
// cos theta) that envTexelDirection takes.
vec4 envDrawTexel(vec2 xi, uvec2 size) {
  const vec2 row = invertMarginal(size.y, xi.x);
  const uint j = uint(row.x);
  const vec2 column = invertConditional(j * (size.x + 1u), size.x, xi.y);
  return vec4(column.x, row.x, column.y, row.y);
}

#endif
