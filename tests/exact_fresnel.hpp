#pragma once
// Fresnel's reflectance worked out in double for the tests' closed forms,
// apart from the code under test.
#include <cmath>

namespace tp::test {

// Reflectance of unpolarised light going from air into a medium of index
// `ior` at incidence cosine cosI, from Fresnel's equations (Born and Wolf,
// 1.5.2).
inline double fresnelFromAir(double cosI, double ior) {
  const double sinT = std::sqrt(1.0 - cosI * cosI) / ior, cosT = std::sqrt(1.0 - sinT * sinT);
  const double rs = (cosI - ior * cosT) / (cosI + ior * cosT);
  const double rp = (cosT - ior * cosI) / (cosT + ior * cosI);
  return 0.5 * (rs * rs + rp * rp);
}

}  // namespace tp::test
