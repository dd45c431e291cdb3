// boreas tests: a morphed glTF node played back as a viewer plays it, read with tinygltf
// (test_animation_morph.cpp, test_animation_clumps.cpp).
#pragma once

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

namespace {

// Element i of a float or normalized int16 / int8 accessor, as doubles.
inline std::vector<double> element(const tinygltf::Model& m, int index, size_t i) {
  const tinygltf::Accessor& a = m.accessors[size_t(index)];
  const tinygltf::BufferView& v = m.bufferViews[size_t(a.bufferView)];
  const int n = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  const int size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  const size_t stride = v.byteStride ? v.byteStride : size_t(n * size);
  const unsigned char* p = m.buffers[size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset + i * stride;
  std::vector<double> out(static_cast<size_t>(n));
  for (int c = 0; c < n; ++c) {
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
      float f;
      std::memcpy(&f, p + 4 * c, 4);
      out[size_t(c)] = f;
    } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE) {
      EXPECT_TRUE(a.normalized);
      out[size_t(c)] = std::max(int8_t(p[c]) / 127.0, -1.0);
    } else {
      EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_SHORT);
      EXPECT_TRUE(a.normalized);
      int16_t s;
      std::memcpy(&s, p + 2 * c, 2);
      out[size_t(c)] = std::max(s / 32767.0, -1.0);
    }
  }
  return out;
}

inline const tinygltf::Node* node_named(const tinygltf::Model& m, const std::string& name) {
  for (const tinygltf::Node& n : m.nodes)
    if (n.name == name) return &n;
  return nullptr;
}

// The node's vertices at key k in world, as a viewer draws them: matrix * (base + sum of
// the targets at their key-k weights, in single precision as a GPU adds them).
inline std::vector<std::array<double, 3>> played(const tinygltf::Model& m, const tinygltf::Node& node, size_t k) {
  const tinygltf::Primitive& p = m.meshes[size_t(node.mesh)].primitives.at(0);
  std::vector<float> w(p.targets.size(), 0.0f);
  const int index = int(&node - m.nodes.data());
  for (const tinygltf::AnimationChannel& c : m.animations.at(0).channels)
    if (c.target_node == index && c.target_path == "weights")
      for (size_t i = 0; i < w.size(); ++i)
        w[i] = float(element(m, m.animations[0].samplers[size_t(c.sampler)].output, k * w.size() + i)[0]);
  const size_t n = m.accessors[size_t(p.attributes.at("POSITION"))].count;
  std::vector<std::array<double, 3>> out(n);
  for (size_t v = 0; v < n; ++v) {
    std::vector<double> q = element(m, p.attributes.at("POSITION"), v);
    for (size_t i = 0; i < w.size(); ++i) {
      const std::vector<double> t = element(m, p.targets[i].at("POSITION"), v);
      for (size_t a = 0; a < 3; ++a) q[a] = float(q[a] + double(w[i]) * t[a]);
    }
    const std::vector<double>& x = node.matrix;
    for (size_t a = 0; a < 3; ++a) out[v][a] = x[a] * q[0] + x[4 + a] * q[1] + x[8 + a] * q[2] + x[12 + a];
  }
  return out;
}

}  // namespace
