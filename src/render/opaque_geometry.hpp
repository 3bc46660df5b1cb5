#pragma once
// What the opaque surfaces' depth and view-space normals follow from: the
// camera's matrices (a sample's jitter included), the spheres and boxes drawn
// and where, and the step of the pool floor's grid. The ground and the pool
// are fixed for a renderer's life. Two frames with equal keys draw the same
// depth and normals, to the bit, so the SSAO computed from them is the same
// too, and a frame may keep the last one's (render/ambient_occlusion.hpp).
#include <cstddef>
#include <vector>

#include "render/objects.hpp"
#include "shared/frame.h"

namespace tp::render {

struct OpaqueGeometry {
  std::vector<std::byte> bytes;  // what it follows from, laid end to end
  bool operator==(const OpaqueGeometry&) const = default;
};

OpaqueGeometry opaqueGeometry(const shader::FrameUniforms& uniforms, const ObjectsInView& objects, uint32_t floorStep);

}  // namespace tp::render
