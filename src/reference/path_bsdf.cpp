#include "reference/path_bsdf.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "shading/hammersley.hpp"

namespace tp::render {
namespace {

// Cycles clamps GGX's alpha to this from below: a perfect mirror's lobe is a
// delta the evaluation cannot hold in float.
constexpr float kMinAlpha = 1e-4f;

float alphaOf(const SurfaceBsdf& m) { return std::max(m.roughness * m.roughness, kMinAlpha); }

float diffusePdf(glm::vec3 n, glm::vec3 wi) { return std::max(glm::dot(n, wi), 0.0f) / glm::pi<float>(); }

// D(h) n.h / (4 |wo.h|): the density of wi when h is drawn by D(h) n.h.
float lobePdf(float alpha, glm::vec3 n, glm::vec3 wo, glm::vec3 wi) {
  if (glm::dot(n, wi) <= 0.0f) return 0.0f;
  const glm::vec3 h = glm::normalize(wo + wi);
  const float cosH = glm::dot(n, h), woH = std::abs(glm::dot(wo, h));
  return woH > 0.0f ? ggxD(alpha, cosH) * cosH / (4.0f * woH) : 0.0f;
}

}  // namespace

float ggxD(float alpha, float cosH) {
  if (cosH <= 0.0f) return 0.0f;
  const float a2 = alpha * alpha, t = cosH * cosH * (a2 - 1.0f) + 1.0f;
  return a2 / (glm::pi<float>() * t * t);
}

float ggxG1(float alpha, float cosV) {
  if (cosV <= 0.0f) return 0.0f;
  const float a2 = alpha * alpha;
  return 2.0f * cosV / (cosV + std::sqrt(a2 + (1.0f - a2) * cosV * cosV));
}

glm::vec3 bsdfTimesCosine(const SurfaceBsdf& m, glm::vec3 n, glm::vec3 wo, glm::vec3 wi) {
  const float cosI = glm::dot(n, wi), cosO = glm::dot(n, wo);
  if (cosI <= 0.0f || cosO <= 0.0f) return glm::vec3(0.0f);
  glm::vec3 f = (1.0f - m.specular) * m.albedo * (cosI / glm::pi<float>());
  if (m.specular > 0.0f) {
    const float alpha = alphaOf(m);
    const glm::vec3 h = glm::normalize(wo + wi);
    const float lobe = ggxD(alpha, glm::dot(n, h)) * ggxG1(alpha, cosO) * ggxG1(alpha, cosI) / (4.0f * cosO);
    f += glm::vec3(m.specular * lobe);
  }
  return f;
}

float bsdfPdf(const SurfaceBsdf& m, glm::vec3 n, glm::vec3 wo, glm::vec3 wi) {
  float pdf = (1.0f - m.specular) * diffusePdf(n, wi);
  if (m.specular > 0.0f) pdf += m.specular * lobePdf(alphaOf(m), n, wo, wi);
  return pdf;
}

BsdfSample sampleBsdf(const SurfaceBsdf& m, glm::vec3 n, glm::vec3 wo, glm::vec3 u3) {
  glm::vec3 t, b;
  tangentFrame(n, t, b);
  BsdfSample s;
  if (u3.z < m.specular) {
    // h from D(h) n.h: tan^2 theta_h = alpha^2 u / (1 - u).
    const float alpha = alphaOf(m);
    const float tan2 = alpha * alpha * u3.x / std::max(1.0f - u3.x, 1e-7f);
    const float cosH = 1.0f / std::sqrt(1.0f + tan2), sinH = std::sqrt(std::max(0.0f, 1.0f - cosH * cosH));
    const float phi = glm::two_pi<float>() * u3.y;
    const glm::vec3 h = sinH * std::cos(phi) * t + sinH * std::sin(phi) * b + cosH * n;
    s.wi = glm::reflect(-wo, h);
  } else {
    const glm::vec3 local = cosineHemisphere(glm::vec2(u3.x, u3.y));
    s.wi = glm::normalize(local.x * t + local.y * b + local.z * n);
  }
  s.pdf = bsdfPdf(m, n, wo, s.wi);
  if (s.pdf <= 0.0f) return BsdfSample{};
  s.weight = bsdfTimesCosine(m, n, wo, s.wi) / s.pdf;
  return s;
}

}  // namespace tp::render
