#include "reference/reference_scene.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace tp::render {

struct ReferenceScene::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<int> meshOfGeometry;  // Embree geometry ID to mesh index
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

void check(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " + std::to_string(int(error)) + ")");
}

}  // namespace

ReferenceScene::ReferenceScene(const std::vector<scene::Mesh>& meshes, const std::vector<scene::Sphere>& spheres)
    : embree_(std::make_unique<Embree>()) {
  for (const auto& s : spheres) spheres_.push_back(glm::vec4(s.center, s.radius));
  embree_->device = rtcNewDevice(nullptr);
  if (!embree_->device) throw std::runtime_error("Embree: cannot create a device");
  embree_->scene = rtcNewScene(embree_->device);
  // Robust: rays cast from a surface must not slip through shared edges.
  rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
  for (size_t m = 0; m < meshes.size(); ++m) {
    const scene::Mesh& mesh = meshes[m];
    if (mesh.indices.empty()) continue;
    RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.indices.size() / 3));
    check(embree_->device, "allocating a mesh");
    std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    std::memcpy(indices, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(embree_->scene, geometry);
    rtcReleaseGeometry(geometry);
    if (embree_->meshOfGeometry.size() <= id) embree_->meshOfGeometry.resize(id + 1, -1);
    embree_->meshOfGeometry[id] = int(m);
  }
  rtcCommitScene(embree_->scene);
  check(embree_->device, "building the BVH");
}

ReferenceScene::~ReferenceScene() = default;

ReferenceHit ReferenceScene::intersect(glm::vec3 origin, glm::vec3 dir, float tNear) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray.org_x = origin.x;
  query.ray.org_y = origin.y;
  query.ray.org_z = origin.z;
  query.ray.dir_x = dir.x;
  query.ray.dir_y = dir.y;
  query.ray.dir_z = dir.z;
  query.ray.tnear = tNear;
  query.ray.tfar = std::numeric_limits<float>::infinity();
  query.ray.mask = ~0u;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(embree_->scene, &context, &query);

  ReferenceHit hit;
  hit.distance = std::numeric_limits<float>::infinity();
  if (query.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    hit.distance = query.ray.tfar;
    hit.mesh = embree_->meshOfGeometry[query.hit.geomID];
    hit.triangle = query.hit.primID;
    hit.barycentric = {query.hit.u, query.hit.v};
    hit.geometricNormal = glm::normalize(glm::vec3(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z));
  }
  // Spheres exactly, in double precision: the nearest root beyond tNear.
  for (size_t s = 0; s < spheres_.size(); ++s) {
    const glm::dvec3 oc = glm::dvec3(origin) - glm::dvec3(spheres_[s]);
    const double b = glm::dot(oc, glm::dvec3(dir));
    const double c = glm::dot(oc, oc) - double(spheres_[s].w) * spheres_[s].w;
    const double discriminant = b * b - c;
    if (discriminant < 0.0) continue;
    const double root = std::sqrt(discriminant);
    double t = -b - root;
    if (t <= tNear) t = -b + root;
    if (t <= tNear || t >= hit.distance) continue;
    hit.distance = float(t);
    hit.mesh = -1;
    hit.sphere = int(s);
    hit.geometricNormal = glm::normalize(glm::vec3(glm::dvec3(origin) + t * glm::dvec3(dir) - glm::dvec3(spheres_[s])));
  }
  return hit;
}

bool underTheWaterSurface(const ReferenceScene* surface, float poolHalf, glm::vec3 p) {
  if (!surface || std::max(std::abs(p.x), std::abs(p.z)) > poolHalf) return false;
  const float inside = poolHalf - kSurfaceOffset;
  const glm::vec3 from(std::clamp(p.x, -inside, inside), p.y, std::clamp(p.z, -inside, inside));
  return surface->intersect(from, glm::vec3(0.0f, 1.0f, 0.0f), 0.0f).hit();
}

}  // namespace tp::render
