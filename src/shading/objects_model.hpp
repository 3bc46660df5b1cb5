#pragma once
#include <limits>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"
#include "shared/glass.h"
#include "shared/object_cast.h"
#include "shared/objects.h"

namespace tp::render {

// Tessellation of every sphere, in the shader and in exported meshes alike.
inline constexpr uint32_t kSphereStacks = 32;
inline constexpr uint32_t kSphereSlices = 64;
inline constexpr uint32_t kBoxVertices = 36;  // box.vert: six faces of two triangles
// The vertices sphere.vert draws for a tessellation (x stacks, y slices of
// SphereParams or GlassSphereParams): two triangles a cell.
inline uint32_t sphereVertexCount(glm::uvec4 tessellation) { return tessellation.x * tessellation.y * 6; }

// The one place where the scene's objects become shader parameters. Objects
// whose lowest point is below `waterTop` come first and are counted in
// count.zw: only they can meet a ray under the water surface (the default
// counts every object in). Glass spheres are in, their index of refraction
// in sphereMaterial.z.
shader::SceneObjects sceneObjects(const scene::Scene& scene, float waterTop = std::numeric_limits<float>::infinity());
// Where `sphere` is among `objects`' spheres (their centre and radius are
// copied from the same floats, so they match exactly), or
// shader::kSkipNoSphere when it is not there.
uint32_t sphereSlot(const shader::SceneObjects& objects, const scene::Sphere& sphere);
shader::SphereParams sphereParams(const scene::Sphere& sphere);
shader::BoxParams boxParams(const scene::Box& box);
// The boxes that are not glass: what stands still and blocks light (the pool's bake sees them).
std::vector<shader::BoxParams> opaqueBoxes(const scene::Scene& scene);
// A glass sphere's draw, with the binary search's steps (render.glass_search_steps)
// and its slot among the objects the glass's own rays pass by (sphereSlot).
shader::GlassSphereParams glassSphereParams(const scene::Sphere& sphere, unsigned searchSteps, uint32_t slot);
// A glass box's draw.
shader::GlassBoxParams glassBoxParams(const scene::Box& box);
// The sphere as sphere.vert tessellates it, the box as box.vert draws it.
scene::Mesh sphereMesh(const scene::Sphere& sphere, const std::string& name);
scene::Mesh boxMesh(const scene::Box& box, const std::string& name);

}  // namespace tp::render
