// The CPU ambient-occlusion reference (render/reference_ao) against answers
// computed here independently of it: a quadrature of the cosine-weighted
// hemisphere in double precision for a wall, the closed form of a cone for a
// sphere, and the open plane's exact 1.
//
// Measured with the default 1024 rays, radius 0.5 m (64 pixels per case, each
// with its own Cranley-Patterson shift), worst over each test's cases:
//   corner, d/R in [0.002, 0.9]:     worst pixel 0.0055, RMS 0.0021, mean of 64 pixels 0.00046;
//   the corner seen from the wall:   worst pixel 0.0055, RMS 0.0022, mean 0.00033 (normal -x), 0.00028 (-z);
//   sphere above the ground:         worst pixel 0.0017, RMS 0.0008, mean 0.00075.
// The bounds are 0.047 per pixel and 0.0059 for a mean of 64 pixels. With 256
// rays the corner's worst pixel is 0.017 (RMS 0.0059), with 4096 0.0021 (RMS
// 0.0007): the error falls as about N^-0.77, faster than independent rays' N^-0.5.
// The sphere's mean error does not fall with N: it is the ray origins' 1e-4 m
// offset along the normal, which brings the sphere nearer by that much and
// widens its cone by 2 a^2 / h^3 * 1e-4 = 7.5e-4 for the case a = 0.2, h = 0.22.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <vector>

#include "reference/reference_ao.hpp"
#include "scene/scene.hpp"

namespace tp::test {
namespace {

constexpr float kRadius = 0.5f;
const uint32_t kRays = render::ReferenceAoOptions{}.rays;
constexpr uint32_t kPixelsPerCase = 64;

// A pixel's AO is an average of N rays whose hit is a 0/1 outcome: with
// independent rays its standard error is at most 0.5 / sqrt(N) (variance p(1-p)
// <= 1/4). Hammersley points converge faster than independent ones for these
// regions with smooth boundaries, so three such standard errors is a safe bound;
// it still catches a uniform instead of a cosine weighting, which moves the
// corner's AO by up to 0.058.
double pixelBound(uint32_t rays) { return 3.0 * 0.5 / std::sqrt(double(rays)); }
// Pixels at the same point differ only in their Cranley-Patterson shift, a
// pseudo-random offset: their estimates are unbiased and independent, so the
// mean of P of them has a standard error sqrt(P) times smaller. This is the
// sharper check for a bias (one that every pixel shares), such as a radius 10%
// off (which moves the corner's AO by up to 0.026).
double meanBound(uint32_t rays, uint32_t pixels) { return pixelBound(rays) / std::sqrt(double(pixels)); }

// The ground plane alone: with the water off there is no pool; no spheres, no boxes.
scene::Scene openGround() {
  scene::Scene s = scene::defaultScene();
  s.water.enabled = false;
  s.spheres.clear();
  s.boxes.clear();
  return s;
}

// The ground and a 20 m box on it whose face x = 0 (spanning z in [-10, 10],
// y in [0, 20]) is, within the radius, an infinite wall meeting the ground at
// a right angle. Its face z = -10 is another such wall.
scene::Scene groundAndWall() {
  scene::Scene s = openGround();
  s.boxes.push_back({.center = {10.0f, 10.0f, 0.0f}, .size = glm::vec3(20.0f)});
  return s;
}

// Surface AOVs made up by the test: one row per case, the same width for all.
struct SurfaceImage {
  std::vector<float> position, normal;
  uint32_t width = kPixelsPerCase, height = 0;

  void addRow(const std::vector<glm::vec3>& points, glm::vec3 n) {
    ASSERT_EQ(points.size(), width);
    for (const glm::vec3& p : points) {
      position.insert(position.end(), {p.x, p.y, p.z, 1.0f});
      normal.insert(normal.end(), {n.x, n.y, n.z, 0.0f});
    }
    ++height;
  }
  // The same point in every pixel of a row: the row's pixels differ only in their shifts.
  void addRow(glm::vec3 p, glm::vec3 n) { addRow(std::vector<glm::vec3>(width, p), n); }
};

std::vector<float> traceAo(const scene::Scene& s, const SurfaceImage& image, uint32_t rays = kRays) {
  return render::referenceAmbientOcclusion(
      s, nullptr, 0.0f, image.position, image.normal, image.width, image.height,
      {.radius = kRadius, .rays = rays, .exactSpheres = true, .originOffset = {}, .progress = nullptr});
}

// Occluded fraction of the cosine-weighted hemisphere at a point on one plane
// at distance d from a second plane perpendicular to it, counting hits within
// R: a direction at angle theta from the normal and phi about it (phi = 0
// towards the wall) meets the wall at distance d / (sin theta cos phi), so it
// counts iff sin theta cos phi >= d / R. The cosine-weighted measure is
// cos theta sin theta dtheta dphi / pi. 2000 x 2000 midpoint quadrature in double.
double wallOccludedFraction(double d, double R) {
  constexpr int n = 2000;
  const double pi = std::numbers::pi, dTheta = 0.5 * pi / n, dPhi = 2.0 * pi / n;
  std::vector<double> cosPhi(n);
  for (int j = 0; j < n; ++j) cosPhi[size_t(j)] = std::cos(-pi + (j + 0.5) * dPhi);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * dTheta, sinTheta = std::sin(theta), weight = std::cos(theta) * sinTheta;
    for (int j = 0; j < n; ++j)
      if (sinTheta * cosPhi[size_t(j)] >= d / R) sum += weight;
  }
  return sum * dTheta * dPhi / pi;
}

struct Errors {
  double worstPixel = 0.0, rmsPixel = 0.0, mean = 0.0;
  void keepWorst(const Errors& e) {
    worstPixel = std::max(worstPixel, e.worstPixel);
    rmsPixel = std::max(rmsPixel, e.rmsPixel);
    mean = std::max(mean, e.mean);
  }
};

// How far the row's pixels are from `exact`: the worst pixel, their RMS, and their mean.
Errors rowErrors(const std::vector<float>& ao, uint32_t row, uint32_t width, double exact) {
  Errors e;
  double sum = 0.0, squares = 0.0;
  for (uint32_t x = 0; x < width; ++x) {
    const double value = ao[size_t(row) * width + x];
    e.worstPixel = std::max(e.worstPixel, std::abs(value - exact));
    sum += value;
    squares += (value - exact) * (value - exact);
  }
  e.rmsPixel = std::sqrt(squares / width);
  e.mean = std::abs(sum / width - exact);
  return e;
}

void printErrors(const char* what, const Errors& worst) {
  std::printf("%s, %u rays: worst pixel error %.4f (bound %.4f), RMS %.4f, worst mean of %u pixels %.5f (bound %.4f)\n",
              what, kRays, worst.worstPixel, pixelBound(kRays), worst.rmsPixel, kPixelsPerCase, worst.mean,
              meanBound(kRays, kPixelsPerCase));
}

const std::vector<double> kWallDistances = {0.001, 0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.45};

// Every row of `ao` against AO = 1 - wallOccludedFraction(d) for the row's d.
void expectWallAo(const std::vector<float>& ao, const char* what) {
  Errors worst;
  for (uint32_t row = 0; row < kWallDistances.size(); ++row) {
    const double exact = 1.0 - wallOccludedFraction(kWallDistances[row], kRadius);
    const Errors e = rowErrors(ao, row, kPixelsPerCase, exact);
    EXPECT_LE(e.worstPixel, pixelBound(kRays)) << what << ", d = " << kWallDistances[row];
    EXPECT_LE(e.mean, meanBound(kRays, kPixelsPerCase)) << what << ", d = " << kWallDistances[row];
    worst.keepWorst(e);
  }
  printErrors(what, worst);
}

double rowMean(const std::vector<float>& ao, uint32_t row) {
  double sum = 0.0;
  for (uint32_t x = 0; x < kPixelsPerCase; ++x) sum += ao[size_t(row) * kPixelsPerCase + x];
  return sum / kPixelsPerCase;
}

}  // namespace

TEST(ReferenceAo, OpenPlaneIsUnoccluded) {
  SurfaceImage image;
  // Points far from the origin (where the ground's four triangles meet) and from its edge, 100 m away.
  for (const glm::vec3 p :
       {glm::vec3(30.0f, 0.0f, 20.0f), glm::vec3(-25.0f, 0.0f, 40.0f), glm::vec3(-50.0f, 0.0f, -50.0f)})
    image.addRow(p, {0.0f, 1.0f, 0.0f});
  // A row of sky: no surface, AO 1 by definition.
  image.addRow(glm::vec3(std::numeric_limits<float>::infinity()), glm::vec3(0.0f));
  for (const float value : traceAo(openGround(), image)) EXPECT_EQ(value, 1.0f);
}

// A point on the ground at distance d from the wall, for d/R from 0.002 to 0.9.
TEST(ReferenceAo, CornerMatchesQuadratureOfTheHemisphere) {
  SurfaceImage image;
  for (const double d : kWallDistances) {
    std::vector<glm::vec3> points;  // along the wall, |z| < 1: the wall's edges are 9 m beyond the radius
    for (uint32_t x = 0; x < kPixelsPerCase; ++x) points.push_back({float(-d), 0.0f, -0.8f + 0.025f * float(x)});
    image.addRow(points, {0.0f, 1.0f, 0.0f});
  }
  const std::vector<float> ao = traceAo(groundAndWall(), image);
  expectWallAo(ao, "corner, ground normal +y");

  // The occluded fraction is, by Malley's method, the area of the unit disc's
  // segment beyond c = d/R over pi: it confirms the quadrature, to within the
  // midpoint rule's first-order error on an indicator (about half a cell along
  // the boundary, ~1/(2n) = 2.5e-4; measured at most 1.1e-4).
  for (const double d : kWallDistances) {
    const double c = d / kRadius, segment = (std::acos(c) - c * std::sqrt(1.0 - c * c)) / std::numbers::pi;
    EXPECT_NEAR(wallOccludedFraction(d, kRadius), segment, 2.5e-4) << "d = " << d;
  }
  // Darker towards the wall: the mean AO grows with d (the steps between the
  // exact values, at least 0.015, are above the 0.006 bound on each mean)...
  for (uint32_t row = 1; row < kWallDistances.size(); ++row) EXPECT_GT(rowMean(ao, row), rowMean(ao, row - 1));
  // ...and tends to 1/2 at the wall, where the wall hides half the hemisphere.
  EXPECT_NEAR(1.0 - wallOccludedFraction(kWallDistances[0], kRadius), 0.5, 0.002);
  EXPECT_NEAR(rowMean(ao, 0), 0.5, 0.002 + meanBound(kRays, kPixelsPerCase));
}

// The same corner from points on the wall, the ground below at distance d:
// normals -x (the ground is the occluder) and -z (the box's side face z = -10),
// the orthonormal basis's two branches.
TEST(ReferenceAo, CornerSeenFromTheWallMatchesTheSameQuadrature) {
  SurfaceImage facingMinusX, facingMinusZ;
  for (const double d : kWallDistances) {
    std::vector<glm::vec3> onFaceX, onFaceZ;
    for (uint32_t x = 0; x < kPixelsPerCase; ++x) {
      onFaceX.push_back({0.0f, float(d), -0.8f + 0.025f * float(x)});
      onFaceZ.push_back({5.0f + 0.025f * float(x), float(d), -10.0f});
    }
    facingMinusX.addRow(onFaceX, {-1.0f, 0.0f, 0.0f});
    facingMinusZ.addRow(onFaceZ, {0.0f, 0.0f, -1.0f});
  }
  expectWallAo(traceAo(groundAndWall(), facingMinusX), "corner, wall normal -x");
  expectWallAo(traceAo(groundAndWall(), facingMinusZ), "corner, wall normal -z");
}

// A sphere of radius a centred at height h above a ground point: it hides the
// cone of half-angle alpha about the normal, sin alpha = a / h, whose
// cosine-weighted measure is sin^2 alpha. Every hit is nearer than
// sqrt(h^2 - a^2) < h < R, so all of the cone counts.
TEST(ReferenceAo, SphereAboveThePointHidesItsConeExactly) {
  struct Case {
    glm::vec3 groundPoint;
    float a, h;
  };
  const std::vector<Case> cases = {{{3.0f, 0.0f, 3.0f}, 0.1f, 0.25f},
                                   {{-3.0f, 0.0f, 3.0f}, 0.15f, 0.2f},
                                   {{3.0f, 0.0f, -3.0f}, 0.05f, 0.4f},
                                   {{-3.0f, 0.0f, -3.0f}, 0.2f, 0.22f}};
  scene::Scene s = openGround();
  SurfaceImage image;
  for (const Case& c : cases) {
    ASSERT_LT(c.h + c.a, kRadius);
    s.spheres.push_back({.center = c.groundPoint + glm::vec3(0.0f, c.h, 0.0f), .radius = c.a});
    image.addRow(c.groundPoint, {0.0f, 1.0f, 0.0f});
  }
  const std::vector<float> ao = traceAo(s, image);
  Errors worst;
  for (uint32_t row = 0; row < cases.size(); ++row) {
    const double sinAlpha = double(cases[row].a) / cases[row].h, exact = 1.0 - sinAlpha * sinAlpha;
    const Errors e = rowErrors(ao, row, kPixelsPerCase, exact);
    EXPECT_LE(e.worstPixel, pixelBound(kRays)) << "a = " << cases[row].a << ", h = " << cases[row].h;
    EXPECT_LE(e.mean, meanBound(kRays, kPixelsPerCase)) << "a = " << cases[row].a << ", h = " << cases[row].h;
    worst.keepWorst(e);
  }
  printErrors("sphere over the ground", worst);
}

// Glass is no occluder: it is drawn after the SSAO, which does not see it, and
// it lets the sky's light through. A glass sphere and a glass box over ground
// points leave them open (AO exactly 1); the same shapes opaque hide at least
// the sphere's cone (sin^2 alpha = 0.25) and the box's (more).
TEST(ReferenceAo, GlassOccludesNothing) {
  const glm::vec3 underSphere(2.0f, 0.0f, 2.0f), underBox(-2.0f, 0.0f, -2.0f);
  SurfaceImage image;
  image.addRow(underSphere, {0.0f, 1.0f, 0.0f});
  image.addRow(underBox, {0.0f, 1.0f, 0.0f});
  scene::Scene s = openGround();
  s.spheres.push_back({.center = underSphere + glm::vec3(0.0f, 0.3f, 0.0f), .radius = 0.15f});
  s.boxes.push_back({.center = underBox + glm::vec3(0.0f, 0.2f, 0.0f), .size = glm::vec3(0.3f)});
  const std::vector<float> opaque = traceAo(s, image);
  EXPECT_LT(rowMean(opaque, 0), 1.0 - 0.25 + meanBound(kRays, kPixelsPerCase));
  EXPECT_LT(rowMean(opaque, 1), 1.0 - 0.25);
  s.spheres[0].material = "glass";
  s.boxes[0].material = "glass";
  for (const float value : traceAo(s, image)) EXPECT_EQ(value, 1.0f);
}

TEST(ReferenceAo, BadInputsThrow) {
  const scene::Scene s = openGround();
  SurfaceImage image;
  image.addRow(glm::vec3(1.0f, 0.0f, 1.0f), {0.0f, 1.0f, 0.0f});
  const std::vector<float> shorter(image.position.begin(), image.position.end() - 4);
  auto ao = [&](std::span<const float> position, std::span<const float> normal, render::ReferenceAoOptions options) {
    return render::referenceAmbientOcclusion(s, nullptr, 0.0f, position, normal, image.width, image.height, options);
  };
  EXPECT_THROW(ao(shorter, image.normal, {}), std::invalid_argument);
  EXPECT_THROW(ao(image.position, shorter, {}), std::invalid_argument);
  auto withRadius = [](float radius) {
    render::ReferenceAoOptions o;
    o.radius = radius;
    return o;
  };
  EXPECT_THROW(ao(image.position, image.normal, withRadius(0.0f)), std::invalid_argument);
  EXPECT_THROW(ao(image.position, image.normal, withRadius(-1.0f)), std::invalid_argument);
  EXPECT_THROW(ao(image.position, image.normal, withRadius(std::numeric_limits<float>::infinity())),
               std::invalid_argument);
  EXPECT_THROW(ao(image.position, image.normal, withRadius(std::numeric_limits<float>::quiet_NaN())),
               std::invalid_argument);
  render::ReferenceAoOptions noRays;
  noRays.rays = 0;
  EXPECT_THROW(ao(image.position, image.normal, noRays), std::invalid_argument);
  render::ReferenceAoOptions shortOffsets;
  const std::vector<float> oneOffset{0.01f};
  shortOffsets.originOffset = oneOffset;
  if (size_t(image.width) * image.height != 1) {
    EXPECT_THROW(ao(image.position, image.normal, shortOffsets), std::invalid_argument);
  }
  EXPECT_NO_THROW(ao(image.position, image.normal, {}));
}

TEST(ReferenceAo, SameInputsGiveIdenticalResults) {
  SurfaceImage image;
  for (const double d : kWallDistances) image.addRow(glm::vec3(float(-d), 0.0f, 0.0f), {0.0f, 1.0f, 0.0f});
  const std::vector<float> first = traceAo(groundAndWall(), image, 256), second = traceAo(groundAndWall(), image, 256);
  EXPECT_EQ(first, second);
  // Pixels at one point differ only in their shifts, and the shifts differ:
  // not every pixel of a row has the same value.
  for (uint32_t row = 0; row < image.height; ++row) {
    bool allEqual = true;
    for (uint32_t x = 1; x < image.width; ++x)
      allEqual = allEqual && first[row * image.width + x] == first[row * image.width];
    EXPECT_FALSE(allEqual) << "row " << row;
  }
}

}  // namespace tp::test
