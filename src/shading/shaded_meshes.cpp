#include "shading/shaded_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "shared/surface_pattern.h"

namespace tp::render {
namespace {

// Each vertex's (u, v) from where it lies on the square [-half, half]^2 of the
// x, z plane, seen from above: u along +x, v (up the image) along -z. An
// image's row 0 is its top, so row j lies at z = -half + (j + 1/2) 2 half / rows:
// the heightfield EXR (heightfield_output), looked up at the water's (u, v),
// gives each vertex its own height, in any DCC.
std::vector<glm::vec2> planarUvs(const std::vector<glm::vec3>& positions, float half) {
  std::vector<glm::vec2> uvs;
  uvs.reserve(positions.size());
  for (const glm::vec3& p : positions) uvs.push_back(glm::vec2(p.x + half, half - p.z) / (2.0f * half));
  return uvs;
}

glm::vec3 faceNormal(glm::vec3 a, glm::vec3 b, glm::vec3 c) { return glm::normalize(glm::cross(b - a, c - a)); }

scene::ShadedMesh groundMesh(scene::Mesh mesh, const scene::Scene& scene) {
  const scene::Ground& g = scene.ground;
  scene::ShadedMesh m;
  m.mesh = std::move(mesh);
  m.normals.assign(m.mesh.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
  m.uvs = planarUvs(m.mesh.positions, g.halfExtent);
  m.material.albedo = shader::patternMeanAlbedo(groundParams(scene));
  return m;
}

// Quads of four vertices each (addQuad's order: top of one edge, its bottom,
// the other edge's bottom, its top): each wall's texture spans it.
scene::ShadedMesh wallsMesh(scene::Mesh mesh, const scene::Scene& scene) {
  const scene::Pool& pool = scene.pool;
  scene::ShadedMesh m;
  m.mesh = std::move(mesh);
  const auto& p = m.mesh.positions;
  for (size_t q = 0; q + 3 < p.size(); q += 4) {
    m.normals.insert(m.normals.end(), 4, faceNormal(p[q], p[q + 1], p[q + 2]));
    m.uvs.insert(m.uvs.end(), {{0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}});
  }
  m.material.albedo = shader::poolWallMeanAlbedo(poolParams(scene));
  m.material.specular = pool.wallSpecular;
  m.material.roughness = pool.wallRoughness;
  return m;
}

scene::ShadedMesh floorMesh(scene::Mesh mesh, const scene::Scene& scene) {
  const PoolModel pool = poolModel(scene);
  scene::ShadedMesh m;
  m.mesh = std::move(mesh);
  for (const glm::vec4& v : pool.floorVertices) m.normals.push_back(glm::vec3(v));  // pool_floor.vert's
  m.uvs = planarUvs(m.mesh.positions, pool.params.box.x);
  m.material.albedo = shader::patternMeanAlbedo(pool.params.tiles);
  return m;
}

// Glass as the renderer draws it: clear (it filters no colour out of the
// light through it) and smooth, of index `ior`.
scene::SurfaceMaterial clearGlass(float ior) {
  return {.albedo = glm::vec3(1.0f), .specular = 1.0f, .roughness = 0.0f, .ior = ior};
}

// sphereMesh's grid of (stacks + 1) x (slices + 1) vertices: u the longitude
// from +x towards +z, v the latitude from the south pole (0) to the north (1).
scene::ShadedMesh sphereShaded(scene::Mesh mesh, const scene::Sphere& s) {
  scene::ShadedMesh m;
  m.mesh = std::move(mesh);
  const uint32_t row = kSphereSlices + 1;
  for (size_t k = 0; k < m.mesh.positions.size(); ++k) {
    m.normals.push_back((m.mesh.positions[k] - s.center) / s.radius);
    m.uvs.push_back({float(k % row) / float(kSphereSlices), 1.0f - float(k / row) / float(kSphereStacks)});
  }
  m.material = isGlass(s)
                   ? clearGlass(s.ior)
                   : scene::SurfaceMaterial{.albedo = s.albedo, .specular = s.specular, .roughness = s.roughness};
  return m;
}

// Every triangle its own corners, as box.vert draws the box: flat faces. Each
// face's texture spans it, along the box's own axes.
scene::ShadedMesh boxShaded(const scene::Mesh& mesh, const scene::Box& box) {
  const shader::BoxParams p = boxParams(box);
  const glm::vec3 center(p.center), half(p.halfSize);
  const glm::vec3 axes[3] = {shader::boxAxisX(p.center.w), {0.0f, 1.0f, 0.0f}, shader::boxAxisZ(p.center.w)};
  scene::ShadedMesh m;
  m.mesh = {mesh.name, {}, {}};
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                    c = mesh.positions[mesh.indices[t + 2]];
    const glm::vec3 n = faceNormal(a, b, c);
    int across = 0;  // the box axis the face is across
    for (int k = 1; k < 3; ++k)
      if (std::abs(glm::dot(n, axes[k])) > std::abs(glm::dot(n, axes[across]))) across = k;
    const int ua = (across + 1) % 3, va = (across + 2) % 3;
    for (const glm::vec3& q : {a, b, c}) {
      m.mesh.indices.push_back(uint32_t(m.mesh.positions.size()));
      m.mesh.positions.push_back(q);
      m.normals.push_back(n);
      m.uvs.push_back(0.5f + glm::vec2(glm::dot(q - center, axes[ua]) / (2.0f * half[ua]),
                                       glm::dot(q - center, axes[va]) / (2.0f * half[va])));
    }
  }
  m.material = isGlass(box) ? clearGlass(box.ior) : scene::SurfaceMaterial{.albedo = box.albedo};
  return m;
}

}  // namespace

scene::ShadedMesh exportedWaterMesh(const scene::Scene& scene, const sim::WaterState& water) {
  const float half = 0.5f * scene.water.extent;
  WaterToTheWalls toTheWalls = waterSurfaceToTheWalls(scene, water);
  scene::ShadedMesh m;
  m.mesh = std::move(toTheWalls.mesh);
  m.mesh.name = "water";
  m.normals = std::move(toTheWalls.normals);
  m.uvs = planarUvs(m.mesh.positions, half);
  // What a metre of water lets through: the colour it takes on in depth.
  m.material.albedo = glm::exp(-scene.water.absorption);
  m.material.specular = 1.0f;
  m.material.roughness = 0.0f;
  m.material.ior = scene.water.ior;
  return m;
}

std::vector<scene::ShadedMesh> shadedSceneMeshes(const scene::Scene& scene, const sim::WaterState* water, float time) {
  const scene::Scene placed = scene::sceneAt(scene, time);
  std::vector<scene::ShadedMesh> shaded;
  for (scene::Mesh& mesh : sceneMeshes(scene, water, time)) {
    // sceneMeshes' names say what each mesh is ("sphere3": the fourth sphere).
    const std::string& name = mesh.name;
    if (name == "ground") {
      shaded.push_back(groundMesh(std::move(mesh), scene));
    } else if (name == "pool_walls") {
      shaded.push_back(wallsMesh(std::move(mesh), scene));
    } else if (name == "pool_floor") {
      shaded.push_back(floorMesh(std::move(mesh), scene));
    } else if (name.starts_with("sphere")) {
      const scene::Sphere& sphere = placed.spheres[std::stoul(name.substr(6))];
      shaded.push_back(sphereShaded(std::move(mesh), sphere));
    } else if (name.starts_with("box")) {
      shaded.push_back(boxShaded(mesh, placed.boxes[std::stoul(name.substr(3))]));
    } else if (name == "water" && water) {
      shaded.push_back(exportedWaterMesh(scene, *water));
    } else {
      // A mesh sceneMeshes gained without its shading here: refused, not left out of the file.
      throw std::logic_error("shadedSceneMeshes: no normals, UVs or material for mesh " + name);
    }
  }
  return shaded;
}

}  // namespace tp::render
