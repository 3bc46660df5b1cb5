// Where a box can show in a frame (shading/screen_rect.hpp), against the
// box's own points projected one by one.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/screen_rect.hpp"

namespace tp::test {
namespace {

constexpr glm::uvec2 kPixels{160, 90};

// Vulkan's clip space: depth 0 to 1, y down.
glm::mat4 viewProjection(glm::vec3 eye, glm::vec3 target) {
  glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(55.0f), 160.0f / 90.0f, 0.05f, 500.0f);
  projection[1][1] *= -1.0f;
  return projection * glm::lookAtRH(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
}

// The pixel whose centre is nearest the point's projection, if it is in front and in the frame.
bool pixelOf(const glm::mat4& vp, glm::vec3 p, glm::ivec2& pixel) {
  const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
  if (!(clip.w > 0.0f) || clip.z < 0.0f || clip.z > clip.w) return false;
  const glm::vec2 at = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(kPixels) - 0.5f;
  pixel = glm::ivec2(glm::round(at));
  return pixel.x >= 0 && pixel.y >= 0 && pixel.x < int(kPixels.x) && pixel.y < int(kPixels.y);
}

}  // namespace

TEST(ScreenRect, EveryPointOfTheBoxInViewFallsInItsRectangle) {
  int inside = 0;
  for (const glm::vec3 eye :
       {glm::vec3(3.4f, 1.45f, 4.3f), glm::vec3(0.0f, 0.25f, 4.0f), glm::vec3(-6.0f, 3.0f, 1.0f)}) {
    SCOPED_TRACE(eye.x);
    const glm::mat4 vp = viewProjection(eye, glm::vec3(0.0f, -0.25f, 0.0f));
    // From the default camera a box wholly in view; from the others the pool, past the frame's edges.
    const bool wholly = eye.x == 3.4f;
    const glm::vec3 lo = wholly ? glm::vec3(-1.0f, -0.5f, -1.0f) : glm::vec3(-2.0f, -1.4f, -2.0f);
    const glm::vec3 hi = wholly ? glm::vec3(1.0f, 0.0f, 1.0f) : glm::vec3(2.0f, 0.0f, 2.0f);
    const render::PixelRect r = render::pixelsCovering(vp, kPixels, lo, hi);
    ASSERT_FALSE(r.empty());
    // A point's pixel lies in the rectangle: every point of a 40^3 lattice through the box.
    bool beyond = false;
    glm::ivec2 least(kPixels), most(-1);
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j)
        for (int k = 0; k <= 40; ++k) {
          const glm::vec3 p = glm::mix(lo, hi, glm::vec3(i, j, k) / 40.0f);
          glm::ivec2 pixel;
          if (!pixelOf(vp, p, pixel)) continue;
          ++inside;
          least = glm::min(least, pixel);
          most = glm::max(most, pixel);
          const bool in =
              pixel.x >= int(r.lo.x) && pixel.y >= int(r.lo.y) && pixel.x < int(r.hi.x) && pixel.y < int(r.hi.y);
          beyond = beyond || !in;
        }
    EXPECT_FALSE(beyond);
    // Wholly in view, the rectangle is the points' own, with a pixel and its rounding each side.
    if (wholly) {
      for (int axis = 0; axis < 2; ++axis) {
        EXPECT_GE(int(r.lo[axis]), least[axis] - 2);
        EXPECT_LE(int(r.hi[axis]), most[axis] + 3);
        EXPECT_GT(least[axis], 0);
        EXPECT_LT(most[axis], int(kPixels[axis]) - 1);
      }
    }
  }
  EXPECT_GT(inside, 1000);
}

TEST(ScreenRect, ABoxBehindTheCameraIsNowhereAndOneAroundItEverywhere) {
  const glm::mat4 vp = viewProjection(glm::vec3(0.0f, 1.0f, 5.0f), glm::vec3(0.0f, 1.0f, 10.0f));
  EXPECT_TRUE(render::pixelsCovering(vp, kPixels, glm::vec3(-2.0f, -1.0f, -2.0f), glm::vec3(2.0f, 0.0f, 2.0f)).empty());
  const render::PixelRect around =
      render::pixelsCovering(vp, kPixels, glm::vec3(-1.0f, 0.0f, 4.0f), glm::vec3(1.0f, 2.0f, 6.0f));
  EXPECT_EQ(around.lo, glm::uvec2(0u));
  EXPECT_EQ(around.hi, kPixels);
  // Left of the frame, in front: nowhere.
  EXPECT_TRUE(render::pixelsCovering(vp, kPixels, glm::vec3(40.0f, 0.0f, 9.0f), glm::vec3(41.0f, 1.0f, 10.0f)).empty());
}

TEST(ScreenRect, UnitedRectanglesHoldBoth) {
  const render::PixelRect a{{2u, 3u}, {10u, 8u}}, b{{6u, 1u}, {12u, 5u}};
  const render::PixelRect u = render::united(a, b);
  EXPECT_EQ(u.lo, glm::uvec2(2u, 1u));
  EXPECT_EQ(u.hi, glm::uvec2(12u, 8u));
  EXPECT_EQ(render::united(render::PixelRect{}, a).lo, a.lo);
}

}  // namespace tp::test
