#include "shading/shadow_reach.hpp"

#include <algorithm>
#include <cmath>

namespace tp::render {
namespace {

// Float round-off in the shader's own tests, and in these: the bound is
// widened by this share and this many metres.
constexpr float kReachSlack = 0.01f;
constexpr float kReachSlackMetres = 0.01f;

}  // namespace

bool groundOutOfObjectShadows(const shader::ShadowCasters& casters, glm::vec3 toSun, float groundHeight, float hole) {
  if (toSun.y <= 0.0f) return true;  // the ground has no sun to lose (openAirSunVisibility)
  // A point p of the plane is in a caster's shadow or penumbra only where
  // its ray to the sun's centre passes the caster's bounding sphere (centre
  // c, radius r) within r + a d, a the sun's angular radius and d = |c - p|
  // (sun_shadow.h's sphereSunVisibility; a box's rays over the disc pass no
  // farther). With t the distance along that ray and m the miss, d <= t + m,
  // so m < (r + a t) / (1 - a); and p lies on the plane, which the miss
  // vector (normal to the ray) can reach by at most m cos(elevation). So
  // t < (k r + c.y - h) / (sin(elevation) - k a), k = cos(elevation) / (1 - a):
  // p's xz lies within m of the segment from c's xz back along the sun's by t.
  const float a = casters.sun.x;
  const float k = std::sqrt(std::max(0.0f, 1.0f - toSun.y * toSun.y)) / (1.0f - a);
  const float rise = toSun.y - k * a;
  if (rise <= 0.0f) return false;  // a sun at the horizon: the shadows reach any distance
  auto outOfReach = [&](glm::vec3 c, float r) {
    const float along = (k * r + c.y - groundHeight) / rise;
    if (along <= 0.0f) return true;  // too far under the plane for any of its rays to graze
    const float miss = (r + a * along) / (1.0f - a) * (1.0f + kReachSlack) + kReachSlackMetres;
    const glm::vec2 from(c.x, c.z), to = from - along * (1.0f + kReachSlack) * glm::vec2(toSun.x, toSun.z);
    const glm::vec2 low = glm::min(from, to) - miss, high = glm::max(from, to) + miss;
    return low.x > -hole && low.y > -hole && high.x < hole && high.y < hole;
  };
  for (uint32_t i = 0; i < uint32_t(casters.sun.y); ++i) {
    if (!outOfReach(glm::vec3(casters.spheres[i]), casters.spheres[i].w)) return false;
  }
  // A glass sphere's table reaches TP_GLASS_TABLE_REACH radii from its axis
  // at any distance (sun_shadow.h's glassSunShare): as a sphere that large.
  for (uint32_t i = 0; i < uint32_t(casters.glass.x); ++i) {
    const glm::vec4 s = casters.glassSpheres[i];
    if (!outOfReach(glm::vec3(s), float(TP_GLASS_TABLE_REACH) * s.w)) return false;
  }
  // A glass box's grid reaches its square, sheared back from the height it
  // is taken at down the sun's ray to the ground (sun_shadow.h's sunSheared).
  for (uint32_t i = 0; i < uint32_t(casters.glass.y); ++i) {
    const glm::vec4 square = casters.glassBoxGrids[2 * i], heights = casters.glassBoxGrids[2 * i + 1];
    if (groundHeight < heights.x || groundHeight > heights.y) continue;
    const glm::vec2 shift = glm::vec2(toSun.x, toSun.z) * ((heights.z - groundHeight) / toSun.y);
    const glm::vec2 low = glm::vec2(square.x, square.y) - shift, high = glm::vec2(square.z, square.w) - shift;
    if (!(low.x > -hole && low.y > -hole && high.x < hole && high.y < hole)) return false;
  }
  for (uint32_t i = 0; i < uint32_t(casters.sun.z); ++i) {
    if (!outOfReach(glm::vec3(casters.boxCenter[i]), glm::length(glm::vec3(casters.boxHalfSize[i])))) return false;
  }
  return true;
}

}  // namespace tp::render
