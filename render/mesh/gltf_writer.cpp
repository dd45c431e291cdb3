// boreas meshes: binary glTF through tinygltf (its implementation is compiled once, in
// host's boreas_tinygltf).
//
// The file: one buffer; per part (branches, leaves) a mesh with one triangle primitive
// whose POSITION (with min and max), NORMAL and TEXCOORD_0 accessors and its indices each
// have their own buffer view; a node per mesh under one scene; a bark and a (double-sided)
// leaf material.
#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <sstream>

#include "mesh/tree_mesh.h"

namespace boreas::render {

namespace {

// Appends data to the model's only buffer as a new view; returns the view's index.
template <typename T>
int add_view(tinygltf::Model& model, const std::vector<T>& data, int target) {
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  // Every component is 4 bytes wide, so views stay 4-byte aligned as the spec asks.
  size_t offset = buffer.size();
  buffer.resize(offset + data.size() * sizeof(T));
  std::memcpy(buffer.data() + offset, data.data(), data.size() * sizeof(T));
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = data.size() * sizeof(T);
  view.target = target;
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component_type, int type, size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

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

void add_part(tinygltf::Model& model, const MeshPart& part, int material) {
  // glTF has no empty accessors: a part without vertices (a leafless tree) is left out.
  if (part.vertex_count() == 0 || part.indices.empty()) return;
  size_t n = part.vertex_count();
  int position = add_accessor(model, add_view(model, part.positions, TINYGLTF_TARGET_ARRAY_BUFFER),
                              TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  tinygltf::Accessor& bounds = model.accessors[size_t(position)];
  bounds.minValues.assign(3, std::numeric_limits<double>::max());
  bounds.maxValues.assign(3, std::numeric_limits<double>::lowest());
  for (size_t i = 0; i < n; ++i) {
    for (size_t a = 0; a < 3; ++a) {
      double v = part.positions[3 * i + a];
      bounds.minValues[a] = std::min(bounds.minValues[a], v);
      bounds.maxValues[a] = std::max(bounds.maxValues[a], v);
    }
  }
  int normal = add_accessor(model, add_view(model, part.normals, TINYGLTF_TARGET_ARRAY_BUFFER),
                            TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  int uv = add_accessor(model, add_view(model, part.uvs, TINYGLTF_TARGET_ARRAY_BUFFER),
                        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n);
  int indices =
      add_accessor(model, add_view(model, part.indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, part.indices.size());

  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = position;
  primitive.attributes["NORMAL"] = normal;
  primitive.attributes["TEXCOORD_0"] = uv;
  primitive.indices = indices;
  primitive.material = material;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = part.name;
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = part.name;
  node.mesh = int(model.meshes.size()) - 1;
  model.nodes.push_back(node);
  model.scenes[0].nodes.push_back(int(model.nodes.size()) - 1);
}

}  // namespace

std::string glb_bytes(const TreeMesh& mesh) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "boreas export-mesh";
  model.asset.extras = tinygltf::Value(tinygltf::Value::Object{
      {"description", tinygltf::Value(mesh.description)}});
  model.buffers.emplace_back();
  model.scenes.emplace_back();
  model.scenes[0].name = "tree";
  model.defaultScene = 0;
  int bark = add_material(model, "bark", {0.36, 0.25, 0.16, 1.0}, false);
  int leaf = add_material(model, "leaf", {0.28, 0.55, 0.18, 1.0}, true);
  add_part(model, mesh.branches, bark);
  add_part(model, mesh.leaves, leaf);

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true)) {
    throw MeshWriteError("glTF: tinygltf could not serialize the model");
  }
  return out.str();
}

}  // namespace boreas::render
