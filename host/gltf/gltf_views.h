// boreas gltf: raw views and accessors of the animated file (animation_gltf.cpp,
// morph_gltf.cpp): every view 4-byte aligned, as attributes and KHR_mesh_quantization ask;
// and the placement both write their meshes with.
#pragma once

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "boreas_gltf/gltf_building.h"

namespace boreas::gltf {

// Raw bytes as a new view, 4-byte aligned (attributes need it, KHR_mesh_quantization too).
inline int add_bytes(tinygltf::Model& model, const void* data, size_t size, int target, int stride) {
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  const size_t offset = (buffer.size() + 3) & ~size_t(3);
  buffer.resize(offset + size);
  if (size) std::memcpy(buffer.data() + offset, data, size);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = size;
  if (target) view.target = target;
  if (stride) view.byteStride = size_t(stride);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

template <typename T>
int add_values(tinygltf::Model& model, const std::vector<T>& values, int target, int stride = 0) {
  return add_bytes(model, values.data(), values.size() * sizeof(T), target, stride);
}

inline int accessor(tinygltf::Model& model, int view, int component, int type, size_t count,
                    bool normalized, size_t byte_offset = 0) {
  const int index = add_accessor(model, view, component, type, count);
  model.accessors[size_t(index)].normalized = normalized;
  model.accessors[size_t(index)].byteOffset = byte_offset;
  return index;
}

using Mat4 = std::array<double, 16>;  // column-major, as glTF stores matrices

inline Mat4 mul(const Mat4& a, const Mat4& b) {
  Mat4 m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) m[size_t(4 * c + r)] += a[size_t(4 * k + r)] * b[size_t(4 * c + k)];
  return m;
}

// Template space to world: position + R_y(rotation) (scale p), as the library places trees.
inline Mat4 placement_matrix(const std::array<double, 3>& position, double rotation, double scale) {
  const double c = std::cos(rotation), s = std::sin(rotation), k = scale;
  return {c * k, 0, -s * k, 0, 0, k, 0, 0, s * k, 0, c * k, 0, position[0], position[1], position[2], 1};
}

// Quantized [-1, 1] box coordinates to the box's space.
inline Mat4 dequantization(const QuantizationBox& b) {
  return {b.half[0], 0, 0, 0, 0, b.half[1], 0, 0, 0, 0, b.half[2], 0, b.center[0], b.center[1], b.center[2], 1};
}

}  // namespace boreas::gltf
