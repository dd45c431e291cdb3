// boreas gltf: building binary glTF models of trees with tinygltf — buffer views, accessors,
// the bark and leaf materials and triangle meshes — for the library's preprocessed trees and
// the renderer's export alike: the public header of boreas_gltf (host/CMakeLists.txt).
#pragma once

#include <tiny_gltf.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace boreas::gltf {

// Appends data to the model's only buffer as a new view; returns the view's index.
template <typename T>
int add_view(tinygltf::Model& model, const std::vector<T>& data, int target) {
  // Every component is 4 bytes wide, so views stay 4-byte aligned as the spec asks.
  static_assert(sizeof(T) == 4);
  std::vector<unsigned char>& buffer = model.buffers[0].data;
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

int add_accessor(tinygltf::Model& model, int view, int component_type, int type, size_t count);

// A vertex attribute of count elements of `type` (TINYGLTF_TYPE_VEC3, ...) in its own view.
int add_floats(tinygltf::Model& model, const std::vector<float>& values, int type, size_t count);

// An empty model: glTF 2.0 by `generator`, one buffer, one scene "tree" (the default), and
// the bark and (double-sided) leaf materials, whose indices it returns.
tinygltf::Model new_tree_model(const std::string& generator, int* bark, int* leaf);

// A mesh and a node, both named `name`, in the scene: one triangle primitive with
// POSITION (with its min and max), NORMAL, TEXCOORD_0 and indices. Returns the mesh's
// index, for callers that add attributes of their own.
int add_triangle_mesh(tinygltf::Model& model, const std::vector<float>& positions,
                      const std::vector<float>& normals, const std::vector<float>& uvs,
                      const std::vector<uint32_t>& indices, const std::string& name, int material);

// Where quantized positions (normalized int16 in [-1, 1] per axis) are taken to: a point's
// coordinate a is center[a] + half[a] q. The animated file's trees and morphed meshes both.
struct QuantizationBox {
  std::array<double, 3> center{}, half{1e-6, 1e-6, 1e-6};
};

// The bounding box of every point added (3 floats a point), as a QuantizationBox: half
// at least 1e-6 m, so a flat axis still divides; no points, the origin's.
class BoundingBox {
 public:
  void add(const std::vector<float>& xyz);
  QuantizationBox quantization() const;

 private:
  std::array<double, 3> lo_{1e300, 1e300, 1e300}, hi_{-1e300, -1e300, -1e300};
};

// The model as .glb bytes; false if tinygltf could not serialize it.
bool glb_bytes(tinygltf::Model& model, std::string* bytes);
// The model written as .glb to out, without a copy of its bytes in memory.
bool glb_write(tinygltf::Model& model, std::ostream& out);

}  // namespace boreas::gltf
