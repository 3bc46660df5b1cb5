#include "render/opaque_geometry.hpp"

#include <cstring>

namespace tp::render {
namespace {

template <typename T>
void append(std::vector<std::byte>& bytes, const T* values, size_t count) {
  const size_t at = bytes.size();
  bytes.resize(at + sizeof(T) * count);
  if (count > 0) std::memcpy(bytes.data() + at, values, sizeof(T) * count);
}

}  // namespace

OpaqueGeometry opaqueGeometry(const shader::FrameUniforms& uniforms, const ObjectsInView& objects, uint32_t floorStep) {
  OpaqueGeometry key;
  append(key.bytes, &uniforms.view, 1);
  append(key.bytes, &uniforms.projection, 1);
  append(key.bytes, &floorStep, 1);
  // The counts too: the same bytes could be laid out by other lists.
  const uint32_t counts[] = {uint32_t(objects.spheres.size()), uint32_t(objects.boxes.size())};
  append(key.bytes, counts, 2);
  append(key.bytes, objects.spheres.data(), objects.spheres.size());
  append(key.bytes, objects.boxes.data(), objects.boxes.size());
  return key;
}

}  // namespace tp::render
