#include "io/gltf_writer.hpp"

#include <tiny_gltf.h>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "base/atomic_file.hpp"

namespace tp::io {
namespace {

// Appends `values` to the model's one buffer as a view and an accessor of
// `count` elements of `type` (TINYGLTF_TYPE_*); returns the accessor's index.
template <typename T>
int addAccessor(tinygltf::Model& model, const std::vector<T>& values, size_t count, int type, int componentType,
                int target) {
  std::vector<unsigned char>& data = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();  // every element is 4-byte aligned: floats and uint32s only
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  data.resize(data.size() + view.byteLength);
  std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size() - 1);
  accessor.componentType = componentType;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return int(model.accessors.size() - 1);
}

tinygltf::Material material(const std::string& name, const scene::SurfaceMaterial& m) {
  tinygltf::Material out;
  out.name = name;
  out.doubleSided = true;  // the walls and the water are seen from both sides
  out.pbrMetallicRoughness.baseColorFactor = {m.albedo.r, m.albedo.g, m.albedo.b, 1.0};
  out.pbrMetallicRoughness.metallicFactor = 0.0;
  out.pbrMetallicRoughness.roughnessFactor = m.roughness;
  if (m.ior > 0.0f) {
    out.extensions["KHR_materials_transmission"] =
        tinygltf::Value(tinygltf::Value::Object{{"transmissionFactor", tinygltf::Value(1.0)}});
    out.extensions["KHR_materials_ior"] =
        tinygltf::Value(tinygltf::Value::Object{{"ior", tinygltf::Value(double(m.ior))}});
  }
  return out;
}

void addMesh(tinygltf::Model& model, const scene::ShadedMesh& s) {
  const scene::Mesh& m = s.mesh;
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  const size_t n = m.positions.size();
  const int position = addAccessor(model, m.positions, n, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                   TINYGLTF_TARGET_ARRAY_BUFFER);
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : m.positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  model.accessors[size_t(position)].minValues = {low.x, low.y, low.z};  // the format requires POSITION's bounds
  model.accessors[size_t(position)].maxValues = {high.x, high.y, high.z};
  primitive.attributes["POSITION"] = position;
  primitive.attributes["NORMAL"] =
      addAccessor(model, s.normals, n, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
  std::vector<glm::vec2> uvs;  // glTF's v runs down the image, the OBJ's (and ShadedMesh's) up
  for (const glm::vec2& t : s.uvs) uvs.push_back({t.x, 1.0f - t.y});
  primitive.attributes["TEXCOORD_0"] =
      addAccessor(model, uvs, n, TINYGLTF_TYPE_VEC2, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.indices = addAccessor(model, m.indices, m.indices.size(), TINYGLTF_TYPE_SCALAR,
                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  model.materials.push_back(material(m.name, s.material));
  primitive.material = int(model.materials.size() - 1);

  tinygltf::Mesh mesh;
  mesh.name = m.name;
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.name = m.name;
  node.mesh = int(model.meshes.size() - 1);
  model.nodes.push_back(node);
  model.scenes[0].nodes.push_back(int(model.nodes.size() - 1));
}

}  // namespace

void writeGlb(const std::string& path, const std::vector<scene::ShadedMesh>& meshes) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "tidepool";
  model.buffers.resize(1);
  model.scenes.resize(1);
  model.defaultScene = 0;
  for (const auto& s : meshes) addMesh(model, s);
  for (const auto& m : model.materials) {
    if (!m.extensions.empty()) {
      model.extensionsUsed = {"KHR_materials_transmission", "KHR_materials_ior"};
      break;
    }
  }
  base::AtomicFile file(path);
  std::ofstream out(file.tempPath(), std::ios::binary);
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true) || !out.flush())
    throw std::runtime_error("cannot write " + path + ": disk full?");
  out.close();
  file.commit();
}

}  // namespace tp::io
