#pragma once
// The scene's opaque materials as the path tracer scatters light off them:
// a Lambertian base of `albedo` and, with share `specular`, a GGX
// microfacet lobe without Fresnel (white, single scattering, Smith's
// separable shadowing, alpha = roughness^2), the two mixed:
//
//   f(wo, wi) = (1 - s) albedo / pi + s D(h) G1(wo) G1(wi) / (4 |n.wo| |n.wi|)
//
// This is what Blender's Mix Shader of a Diffuse BSDF and a GGX Glossy BSDF
// computes, and so the material the Cycles comparison renders; the raster's
// prefiltered Phong lobe (shared/glossy.h) is an approximation of it,
// measured against it. (The dielectric interfaces, water and glass, take
// shared/glass.h's exact Fresnel.)
#include <glm/glm.hpp>

namespace tp::render {

struct SurfaceBsdf {
  glm::vec3 albedo{0.0f};
  float specular = 0.0f;  // the glossy lobe's share, 0 to 1
  float roughness = 0.5f;
};

// The BSDF times |n.wi| for unit wo (towards the viewer) and wi (towards the
// light), n the shading normal on wo's side; 0 when wi is under it.
glm::vec3 bsdfTimesCosine(const SurfaceBsdf& m, glm::vec3 n, glm::vec3 wo, glm::vec3 wi);
// The density per steradian with which sampleBsdf draws wi.
float bsdfPdf(const SurfaceBsdf& m, glm::vec3 n, glm::vec3 wo, glm::vec3 wi);

struct BsdfSample {
  glm::vec3 wi{0.0f};
  glm::vec3 weight{0.0f};  // bsdfTimesCosine / pdf
  float pdf = 0.0f;        // 0: no direction drawn
};
// A direction drawn from the mixture: the lobe with probability `specular`
// (D(h) n.h of the half vector), else the cosine; u3 uniform in [0, 1)^3.
BsdfSample sampleBsdf(const SurfaceBsdf& m, glm::vec3 n, glm::vec3 wo, glm::vec3 u3);

// GGX's distribution of normals and Smith's G1, alpha = roughness^2.
float ggxD(float alpha, float cosH);
float ggxG1(float alpha, float cosV);

}  // namespace tp::render
