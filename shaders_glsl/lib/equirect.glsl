// Equirectangular mapping: u = phi / 2pi + 1/2 with phi = atan(z, x), v = theta / pi
// with theta = acos(y), the original course project's convention.
#ifndef TP_LIB_EQUIRECT
#define TP_LIB_EQUIRECT

const float PI = 3.14159265358979323846;

vec2 directionToEquirect(vec3 d) {
  return vec2(atan(d.z, d.x) / (2.0 * PI) + 0.5, acos(clamp(d.y, -1.0, 1.0)) / PI);
}

vec3 equirectToDirection(vec2 uv) {
  float phi = (uv.x - 0.5) * 2.0 * PI;
  float theta = uv.y * PI;
  return vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
}

#endif
