// boreas gltf: binary glTF models of trees (see boreas_gltf/gltf_building.h).
#include "boreas_gltf/gltf_building.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace boreas::gltf {

int add_accessor(tinygltf::Model& model, int view, int component_type, int type, size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

int add_floats(tinygltf::Model& model, const std::vector<float>& values, int type, size_t count) {
  return add_accessor(model, add_view(model, values, TINYGLTF_TARGET_ARRAY_BUFFER),
                      TINYGLTF_COMPONENT_TYPE_FLOAT, type, count);
}

void BoundingBox::add(const std::vector<float>& xyz) {
  for (size_t i = 0; i < xyz.size(); ++i) {
    lo_[i % 3] = std::min(lo_[i % 3], double(xyz[i]));
    hi_[i % 3] = std::max(hi_[i % 3], double(xyz[i]));
  }
}

QuantizationBox BoundingBox::quantization() const {
  QuantizationBox b;
  for (size_t a = 0; a < 3; ++a) {
    const bool empty = lo_[a] > hi_[a];
    b.center[a] = empty ? 0.0 : 0.5 * (lo_[a] + hi_[a]);
    b.half[a] = std::max(empty ? 0.0 : 0.5 * (hi_[a] - lo_[a]), 1e-6);
  }
  return b;
}

namespace {

int add_material(tinygltf::Model& model, const std::string& name, std::vector<double> color,
                 bool double_sided) {
  tinygltf::Material material;
  material.name = name;
  material.pbrMetallicRoughness.baseColorFactor = std::move(color);
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.9;
  material.doubleSided = double_sided;
  model.materials.push_back(material);
  return int(model.materials.size()) - 1;
}

}  // namespace

tinygltf::Model new_tree_model(const std::string& generator, int* bark, int* leaf) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = generator;
  model.buffers.emplace_back();
  model.scenes.emplace_back();
  model.scenes[0].name = "tree";
  model.defaultScene = 0;
  *bark = add_material(model, "bark", {0.36, 0.25, 0.16, 1.0}, false);
  *leaf = add_material(model, "leaf", {0.28, 0.55, 0.18, 1.0}, true);
  return model;
}

int add_triangle_mesh(tinygltf::Model& model, const std::vector<float>& positions,
                      const std::vector<float>& normals, const std::vector<float>& uvs,
                      const std::vector<uint32_t>& indices, const std::string& name, int material) {
  const size_t n = positions.size() / 3;
  int position = add_floats(model, positions, TINYGLTF_TYPE_VEC3, n);
  tinygltf::Accessor& bounds = model.accessors[size_t(position)];
  bounds.minValues.assign(3, std::numeric_limits<double>::max());
  bounds.maxValues.assign(3, std::numeric_limits<double>::lowest());
  for (size_t i = 0; i < n; ++i) {
    for (size_t a = 0; a < 3; ++a) {
      double v = positions[3 * i + a];
      bounds.minValues[a] = std::min(bounds.minValues[a], v);
      bounds.maxValues[a] = std::max(bounds.maxValues[a], v);
    }
  }
  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = position;
  primitive.attributes["NORMAL"] = add_floats(model, normals, TINYGLTF_TYPE_VEC3, n);
  primitive.attributes["TEXCOORD_0"] = add_floats(model, uvs, TINYGLTF_TYPE_VEC2, n);
  primitive.indices =
      add_accessor(model, add_view(model, indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
  primitive.material = material;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = name;
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = name;
  node.mesh = int(model.meshes.size()) - 1;
  model.nodes.push_back(node);
  model.scenes[0].nodes.push_back(int(model.nodes.size()) - 1);
  return node.mesh;
}

bool glb_bytes(tinygltf::Model& model, std::string* bytes) {
  std::ostringstream out;
  if (!glb_write(model, out)) return false;
  *bytes = out.str();
  return true;
}

bool glb_write(tinygltf::Model& model, std::ostream& out) {
  tinygltf::TinyGLTF writer;
  return writer.WriteGltfSceneToStream(&model, out, false, true);
}

}  // namespace boreas::gltf
