// boreas gltf: meadows and imported trees as morphed meshes (morph_gltf.h).
#include "morph_gltf.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "gltf_views.h"
#include "morph_basis.h"

namespace boreas::gltf {
namespace {

using Vec3 = std::array<double, 3>;

// The base's quantization box: every position of the base and of its copies' keys.
using MorphBox = QuantizationBox;

MorphBox morph_box(const MorphBase& base, const std::vector<MorphedMesh*>& copies) {
  BoundingBox b;
  b.add(base.positions);
  for (const MorphedMesh* m : copies)
    for (const std::vector<float>& key : m->keys) b.add(key);
  return b.quantization();
}

// Normalized int16 (or int8) x 3 padded to 8 (4) bytes a vertex, with its min and max.
template <typename T>
int add_int3(tinygltf::Model& model, const std::vector<int16_t>& xyz) {
  const size_t n = xyz.size() / 3;
  std::vector<T> padded(4 * n, 0);
  std::vector<double> lo(3, 32767), hi(3, -32767);
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 3; ++a) {
      padded[4 * i + a] = T(xyz[3 * i + a]);
      lo[a] = std::min(lo[a], double(xyz[3 * i + a]));
      hi[a] = std::max(hi[a], double(xyz[3 * i + a]));
    }
  if (n == 0) lo = hi = {0, 0, 0};
  const int component = sizeof(T) == 2 ? TINYGLTF_COMPONENT_TYPE_SHORT : TINYGLTF_COMPONENT_TYPE_BYTE;
  const int a = accessor(model, add_values(model, padded, TINYGLTF_TARGET_ARRAY_BUFFER, 4 * sizeof(T)),
                         component, TINYGLTF_TYPE_VEC3, n, true);
  model.accessors[size_t(a)].minValues = lo;
  model.accessors[size_t(a)].maxValues = hi;
  return a;
}

// Three bytes a vertex padded to four: int8 normals or uint8 colors.
template <typename T>
int add_byte3(tinygltf::Model& model, const std::vector<float>& xyz, double limit, int component) {
  const size_t n = xyz.size() / 3;
  std::vector<T> packed(4 * n, 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 3; ++c)
      packed[4 * i + c] = T(std::lround(std::clamp(double(xyz[3 * i + c]), -1.0, 1.0) * limit));
  return accessor(model, add_values(model, packed, TINYGLTF_TARGET_ARRAY_BUFFER, 4), component,
                  TINYGLTF_TYPE_VEC3, n, true);
}

// The base's primitive (shared by its copies' meshes) and its dequantized positions.
tinygltf::Primitive add_base(tinygltf::Model& model, const MorphBase& base, const MorphBox& box,
                             int material, std::vector<float>* dequantized) {
  const size_t n = base.vertex_count();
  std::vector<int16_t> q(3 * n);
  dequantized->resize(3 * n);
  for (size_t i = 0; i < 3 * n; ++i) {
    const size_t a = i % 3;
    q[i] = int16_t(std::lround(std::clamp((base.positions[i] - box.center[a]) / box.half[a], -1.0, 1.0) * 32767.0));
    (*dequantized)[i] = float(box.center[a] + box.half[a] * (q[i] / 32767.0));
  }
  tinygltf::Primitive p;
  p.material = material;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  p.attributes["POSITION"] = add_int3<int16_t>(model, q);
  if (!base.normals.empty())
    p.attributes["NORMAL"] = add_byte3<int8_t>(model, base.normals, 127.0, TINYGLTF_COMPONENT_TYPE_BYTE);
  if (!base.colors.empty())
    p.attributes["COLOR_0"] = add_byte3<uint8_t>(model, base.colors, 255.0, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
  if (n <= 65535) {
    std::vector<uint16_t> idx(base.indices.begin(), base.indices.end());
    if (idx.size() % 2) idx.push_back(0);  // keep the view's length a multiple of 4
    p.indices = accessor(model, add_values(model, idx, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, base.indices.size(), false);
  } else {
    p.indices = accessor(model, add_values(model, base.indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, base.indices.size(), false);
  }
  return p;
}

// The weights of every key, key after key; phase >= 0: read as a loop started `phase` keys
// in (key k is the fit's key (k + phase) mod (keys - 1), the last key being the first).
int add_weights(tinygltf::Model& model, const MorphTargets& fit, int phase) {
  const size_t n = fit.weights.size(), loop = n > 1 ? n - 1 : 1;
  std::vector<float> w;
  for (size_t k = 0; k < n; ++k) {
    const std::vector<float>& key = fit.weights[phase < 0 ? k : (k + size_t(phase)) % loop];
    w.insert(w.end(), key.begin(), key.end());
  }
  return accessor(model, add_values(model, w, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                  TINYGLTF_TYPE_SCALAR, w.size(), false);
}

// A node's weights channel: a key per frame, every target's weight at each (output: the
// weights' accessor, shared by nodes of one mesh and phase).
void add_weights_channel(tinygltf::Model& model, int output, int times, int node,
                         tinygltf::Animation* animation) {
  tinygltf::AnimationSampler sampler;
  sampler.input = times;
  sampler.output = output;
  sampler.interpolation = "LINEAR";
  animation->samplers.push_back(sampler);
  tinygltf::AnimationChannel c;
  c.sampler = int(animation->samplers.size()) - 1;
  c.target_node = node;
  c.target_path = "weights";
  animation->channels.push_back(c);
}

// A node of the scene drawing mesh at matrix; its index.
int add_node(tinygltf::Model& model, const std::string& name, int mesh, const Mat4& matrix) {
  tinygltf::Node node;
  node.name = name;
  node.mesh = mesh;
  node.matrix.assign(matrix.begin(), matrix.end());
  model.nodes.push_back(node);
  const int index = int(model.nodes.size()) - 1;
  model.scenes[0].nodes.push_back(index);
  return index;
}

// One copy: its targets fitted, its mesh on the base's primitive, its node and channel.
MorphReport add_copy(tinygltf::Model& model, MorphedMesh& m, const tinygltf::Primitive& base,
                     const std::vector<float>& dequantized, const MorphBox& box, double tolerance,
                     int times, tinygltf::Animation* animation) {
  std::vector<std::vector<float>> residual = std::move(m.keys);
  m.keys.clear();
  for (std::vector<float>& key : residual)
    for (size_t i = 0; i < key.size(); ++i) key[i] -= dequantized[i];
  const MorphTargets fit = fit_morph_targets(std::move(residual), box.half, tolerance / m.scale);
  tinygltf::Mesh mesh;
  mesh.name = m.name;
  mesh.primitives.push_back(base);
  for (size_t i = 0; i < fit.targets.size(); ++i)
    mesh.primitives[0].targets.push_back(
        {{"POSITION", fit.levels[i] == 127 ? add_int3<int8_t>(model, fit.targets[i])
                                           : add_int3<int16_t>(model, fit.targets[i])}});
  if (!fit.targets.empty()) mesh.weights.assign(fit.weights[0].begin(), fit.weights[0].end());
  model.meshes.push_back(mesh);
  const int mesh_index = int(model.meshes.size()) - 1;
  const bool animated = !fit.targets.empty() && times >= 0;
  const Mat4 dequantize = dequantization(box);
  if (m.instances.empty()) {
    const int node = add_node(model, m.name, mesh_index, mul(placement_matrix(m.position, m.rotation, m.scale), dequantize));
    if (animated) add_weights_channel(model, add_weights(model, fit, -1), times, node, animation);
  }
  std::map<int, int> phase_weights;  // phase -> its weights' accessor
  for (const MorphedMesh::Instance& in : m.instances) {
    const int node = add_node(model, in.name, mesh_index, mul(placement_matrix(in.position, 0.0, 1.0), dequantize));
    if (!animated) continue;
    auto [it, added] = phase_weights.emplace(in.phase, -1);
    if (added) it->second = add_weights(model, fit, in.phase);
    add_weights_channel(model, it->second, times, node, animation);
  }
  return {m.name, fit.targets.size(), fit.max_error * m.scale};
}

// The material of colored bases: white and double-sided, so COLOR_0 is the color.
int colored_material(tinygltf::Model& model) {
  tinygltf::Material m;
  m.name = "underbrush";
  m.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
  m.pbrMetallicRoughness.metallicFactor = 0.0;
  m.pbrMetallicRoughness.roughnessFactor = 0.9;
  m.doubleSided = true;
  model.materials.push_back(m);
  return int(model.materials.size()) - 1;
}

}  // namespace

void add_morphed_meshes(tinygltf::Model& model, ForestAnimation& a, int times, int bark,
                        int leaf, tinygltf::Animation* animation, std::vector<MorphReport>* report) {
  int colored = -1;
  for (size_t b = 0; b < a.morph_bases.size(); ++b) {
    std::vector<MorphedMesh*> copies;
    for (MorphedMesh& m : a.morphed)
      if (m.base == int(b)) copies.push_back(&m);
    if (copies.empty()) continue;
    const MorphBase& base = a.morph_bases[b];
    const MorphBox box = morph_box(base, copies);
    std::vector<float> dequantized;
    if (!base.colors.empty() && colored < 0) colored = colored_material(model);
    const int material = !base.colors.empty() ? colored : base.leaf_material ? leaf : bark;
    const tinygltf::Primitive primitive = add_base(model, base, box, material, &dequantized);
    for (MorphedMesh* m : copies) {
      const MorphReport r = add_copy(model, *m, primitive, dequantized, box, a.morph_tolerance, times, animation);
      if (report) report->push_back(r);
    }
  }
}

}  // namespace boreas::gltf
