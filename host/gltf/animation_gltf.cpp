// boreas gltf: an animated forest as binary glTF (boreas_gltf/animation_gltf.h).
//
// Per template: its bark and leaves cut into pieces (part_split.h: 16-bit indices, at most
// 256 joints), a mesh each, positions quantized to int16 in the template's bounding box
// (D: box center + half extent, per axis). Per tree: a node per joint (local TRS under its
// parent joint, world TRS at a root), and a node per piece: the shared mesh and a skin
// over the piece's joints whose inverse bind matrices are bind_j^-1 * P * D (P
// the tree's placement), so the quantized template mesh lands where the tree stands.
#include "boreas_gltf/animation_gltf.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "boreas_gltf/gltf_building.h"
#include "gltf_views.h"
#include "morph_gltf.h"
#include "part_split.h"

namespace boreas::gltf {
namespace {

using Quat = std::array<double, 4>;   // x, y, z, w
using Vec3 = std::array<double, 3>;

Quat conj(const Quat& q) { return {-q[0], -q[1], -q[2], q[3]}; }
Quat qmul(const Quat& a, const Quat& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
          a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
          a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}
Vec3 rotate(const Quat& q, const Vec3& v) {
  const Quat p = qmul(qmul(q, {v[0], v[1], v[2], 0}), conj(q));
  return {p[0], p[1], p[2]};
}
// The rotation matrix's columns.
std::array<Vec3, 3> axes(const Quat& q) {
  return {rotate(q, {1, 0, 0}), rotate(q, {0, 1, 0}), rotate(q, {0, 0, 1})};
}

// The inverse of the joint's rigid frame: [R^T | -R^T o].
Mat4 inverse_frame(const JointPose& p) {
  const std::array<Vec3, 3> a = axes(p.rotation);
  Mat4 m{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m[size_t(4 * c + r)] = a[size_t(r)][size_t(c)];
    m[size_t(12 + r)] = -(a[size_t(r)][0] * p.position[0] + a[size_t(r)][1] * p.position[1] +
                          a[size_t(r)][2] * p.position[2]);
  }
  m[15] = 1;
  return m;
}

Mat4 placement(const AnimatedTree& t) { return placement_matrix(t.position, t.rotation, t.scale); }

using Box = QuantizationBox;

Box bounding_box(const TreeTemplate& t) {
  BoundingBox b;
  b.add(t.bark.positions);
  b.add(t.leaves.positions);
  return b.quantization();
}

template <typename T>
T quantize(double v, double limit) {
  return T(std::lround(std::clamp(v, -1.0, 1.0) * limit));
}

// One primitive of a template's mesh: quantized attributes and its indices.
tinygltf::Primitive add_primitive(tinygltf::Model& model, const SkinnedPart& part, const Box& box,
                                  int material) {
  const size_t n = part.vertex_count();
  tinygltf::Primitive p;
  p.material = material;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  // POSITION: int16 in the box, padded to 8 bytes a vertex.
  std::vector<int16_t> pos(4 * n, 0);
  Vec3 lo{32767, 32767, 32767}, hi{-32767, -32767, -32767};
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 3; ++a) {
      const int16_t q = quantize<int16_t>(
          (part.positions[3 * i + a] - box.center[a]) / box.half[a], 32767.0);
      pos[4 * i + a] = q;
      lo[a] = std::min(lo[a], double(q)), hi[a] = std::max(hi[a], double(q));
    }
  int a = accessor(model, add_values(model, pos, TINYGLTF_TARGET_ARRAY_BUFFER, 8),
                   TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_TYPE_VEC3, n, true);
  model.accessors[size_t(a)].minValues.assign(lo.begin(), lo.end());
  model.accessors[size_t(a)].maxValues.assign(hi.begin(), hi.end());
  p.attributes["POSITION"] = a;
  // NORMAL: int8, 4 bytes a vertex; none for flat parts (clients then compute flat normals).
  if (!part.normals.empty()) {
    std::vector<int8_t> nor(4 * n, 0);
    for (size_t i = 0; i < n; ++i)
      for (size_t c = 0; c < 3; ++c) nor[4 * i + c] = quantize<int8_t>(part.normals[3 * i + c], 127.0);
    p.attributes["NORMAL"] = accessor(model, add_values(model, nor, TINYGLTF_TARGET_ARRAY_BUFFER, 4),
                                      TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_TYPE_VEC3, n, true);
  }
  if (!part.uvs.empty()) {
    std::vector<uint16_t> uv(2 * n);
    for (size_t i = 0; i < 2 * n; ++i)
      uv[i] = uint16_t(std::lround(std::clamp(double(part.uvs[i]), 0.0, 1.0) * 65535.0));
    p.attributes["TEXCOORD_0"] =
        accessor(model, add_values(model, uv, TINYGLTF_TARGET_ARRAY_BUFFER),
                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC2, n, true);
  }
  // JOINTS_0 (uint8: a piece's skin holds at most 256 joints) and WEIGHTS_0 (uint8,
  // summing to exactly 255).
  std::vector<uint8_t> weights(4 * n), joints(4 * n);
  for (size_t i = 0; i < n; ++i) {
    int left = 255;
    for (size_t k = 1; k < 4; ++k) {
      const int q = int(std::lround(std::clamp(double(part.weights[4 * i + k]), 0.0, 1.0) * 255));
      weights[4 * i + k] = uint8_t(std::min(q, left));
      left -= weights[4 * i + k];
    }
    weights[4 * i] = uint8_t(left);
    for (size_t k = 0; k < 4; ++k) joints[4 * i + k] = uint8_t(weights[4 * i + k] ? part.joints[4 * i + k] : 0);
  }
  p.attributes["JOINTS_0"] = accessor(model, add_values(model, joints, TINYGLTF_TARGET_ARRAY_BUFFER),
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4, n, false);
  p.attributes["WEIGHTS_0"] =
      accessor(model, add_values(model, weights, TINYGLTF_TARGET_ARRAY_BUFFER),
               TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4, n, true);
  // Indices: 16 bits where the vertices allow.
  if (n <= 65535) {
    std::vector<uint16_t> idx(part.indices.begin(), part.indices.end());
    if (idx.size() % 2) idx.push_back(0);  // keep the view's length a multiple of 4
    p.indices = accessor(model, add_values(model, idx, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR,
                         part.indices.size(), false);
  } else {
    p.indices = accessor(model, add_values(model, part.indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                         part.indices.size(), false);
  }
  return p;
}

Quat unit(Quat q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= n;
  return q;
}

// A joint's pose in its parent's frame (world for a root); its rotation unit in double
// (the library's float quaternions are unit to 1e-7, past the validator's range checks).
JointPose local_pose(const AnimatedTree& t, const std::vector<JointPose>& frame, size_t j) {
  const int parent = t.joint_parents[j];
  if (parent < 0) return {frame[j].position, unit(frame[j].rotation)};
  const JointPose& p = frame[size_t(parent)];
  const Quat inv = conj(p.rotation);
  const Vec3 d{frame[j].position[0] - p.position[0], frame[j].position[1] - p.position[1],
               frame[j].position[2] - p.position[2]};
  JointPose l;
  l.position = rotate(inv, d);
  l.rotation = unit(qmul(inv, frame[j].rotation));
  return l;
}

// The tree's joint nodes (their indices returned), their inverse bind matrices (16 floats
// a joint, into *ibm) and their channels.
std::vector<int> add_skeleton(tinygltf::Model& model, const AnimatedTree& t, const Box& box,
                              int times, tinygltf::Animation* animation, std::vector<float>* ibm_out) {
  const size_t joints = t.joint_parents.size(), frames = t.frames.size();
  std::vector<int> nodes(joints);
  for (size_t j = 0; j < joints; ++j) nodes[j] = int(model.nodes.size() + j);
  std::vector<std::vector<JointPose>> local(frames, std::vector<JointPose>(joints));
  for (size_t f = 0; f < frames; ++f)
    for (size_t j = 0; j < joints; ++j) {
      local[f][j] = local_pose(t, t.frames[f], j);
      // The short way between frames: q and -q are one rotation, interpolation is not.
      const Quat& prev = f ? local[f - 1][j].rotation : local[f][j].rotation;
      Quat& q = local[f][j].rotation;
      if (q[0] * prev[0] + q[1] * prev[1] + q[2] * prev[2] + q[3] * prev[3] < 0)
        for (double& c : q) c = -c;
    }
  for (size_t j = 0; j < joints; ++j) {
    tinygltf::Node node;
    node.name = t.name + "_joint" + std::to_string(j);
    node.translation.assign(local[0][j].position.begin(), local[0][j].position.end());
    node.rotation.assign(local[0][j].rotation.begin(), local[0][j].rotation.end());
    model.nodes.push_back(node);
  }
  for (size_t j = 0; j < joints; ++j)
    if (t.joint_parents[j] >= 0)
      model.nodes[size_t(nodes[size_t(t.joint_parents[j])])].children.push_back(nodes[j]);
  // Inverse bind matrices: bind^-1 * placement * dequantization.
  const Mat4 pd = mul(placement(t), dequantization(box));
  std::vector<float>& ibm = *ibm_out;
  ibm.clear();
  ibm.reserve(16 * joints);
  const std::vector<JointPose>& bind = t.bind.empty() ? t.frames[0] : t.bind;
  for (size_t j = 0; j < joints; ++j)
    for (double v : mul(inverse_frame(bind[j]), pd)) ibm.push_back(float(v));
  if (frames < 2) return nodes;
  // Channels: translations (dropped where a joint keeps its offset to 0.01 mm) and
  // rotations, as floats: a joint's place is its parents' chain, and normalized int16
  // rotations (1/32767 rad) compound to millimetres over a 15 m tree.
  std::vector<float> translations;
  std::vector<float> rotations;
  translations.reserve(3 * frames * joints);
  rotations.reserve(4 * frames * joints);
  std::vector<std::pair<size_t, size_t>> moving;  // (joint, offset in translations)
  for (size_t j = 0; j < joints; ++j) {
    double drift = 0;
    for (size_t f = 1; f < frames; ++f)
      for (size_t a = 0; a < 3; ++a)
        drift = std::max(drift, std::abs(local[f][j].position[a] - local[0][j].position[a]));
    if (drift <= 1e-5) continue;
    moving.push_back({j, translations.size() * sizeof(float)});
    for (size_t f = 0; f < frames; ++f)
      for (size_t a = 0; a < 3; ++a) translations.push_back(float(local[f][j].position[a]));
  }
  for (size_t j = 0; j < joints; ++j)
    for (size_t f = 0; f < frames; ++f)
      for (size_t c = 0; c < 4; ++c)
        rotations.push_back(float(local[f][j].rotation[c]));
  auto channel = [&](int output, int node, const char* path) {
    tinygltf::AnimationSampler sampler;
    sampler.input = times;
    sampler.output = output;
    sampler.interpolation = "LINEAR";
    animation->samplers.push_back(sampler);
    tinygltf::AnimationChannel c;
    c.sampler = int(animation->samplers.size()) - 1;
    c.target_node = node;
    c.target_path = path;
    animation->channels.push_back(c);
  };
  if (!translations.empty()) {
    const int view = add_values(model, translations, 0);
    for (const auto& [j, offset] : moving)
      channel(accessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, frames,
                       false, offset),
              nodes[j], "translation");
  }
  const int view = add_values(model, rotations, 0);
  for (size_t j = 0; j < joints; ++j)
    channel(accessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, frames, false,
                     j * frames * 4 * sizeof(float)),
            nodes[j], "rotation");
  return nodes;
}

// A template's meshes: one a piece (part_split.h), each with the joints its skin holds.
struct TemplateMeshes {
  std::vector<int> meshes;
  std::vector<std::vector<int32_t>> joint_maps;
};

TemplateMeshes add_template(tinygltf::Model& model, const TreeTemplate& t, const Box& box, int bark,
                            int leaf) {
  TemplateMeshes out;
  for (const auto& [part, material] : {std::pair{&t.bark, bark}, std::pair{&t.leaves, leaf}}) {
    if (!part->vertex_count()) continue;
    const std::vector<SkinnedPiece> pieces = split_part(*part);
    for (size_t k = 0; k < pieces.size(); ++k) {
      tinygltf::Mesh mesh;
      mesh.name = t.name + (material == bark ? "_bark" : "_leaves") + std::to_string(k);
      mesh.primitives.push_back(add_primitive(model, pieces[k].part, box, material));
      model.meshes.push_back(mesh);
      out.meshes.push_back(int(model.meshes.size()) - 1);
      out.joint_maps.push_back(pieces[k].joint_map);
    }
  }
  return out;
}

// The tree's nodes, one a piece of its template (named tree_pieceK; skinned meshes are
// root nodes, as parents would not move them), each skinned by a skin over the piece's
// joints (their inverse bind matrices gathered from the tree's), rooted at joint 0.
void add_tree_nodes(tinygltf::Model& model, const AnimatedTree& t, const TemplateMeshes& m,
                    const std::vector<int>& joint_nodes, const std::vector<float>& ibm) {
  for (size_t k = 0; k < m.meshes.size(); ++k) {
    tinygltf::Skin skin;
    skin.name = t.name + "_skin" + std::to_string(k);
    std::vector<float> bind;
    for (int32_t j : m.joint_maps[k]) {
      skin.joints.push_back(joint_nodes[size_t(j)]);
      bind.insert(bind.end(), ibm.begin() + 16 * j, ibm.begin() + 16 * j + 16);
    }
    skin.skeleton = joint_nodes[0];
    skin.inverseBindMatrices = accessor(model, add_values(model, bind, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                        TINYGLTF_TYPE_MAT4, skin.joints.size(), false);
    model.skins.push_back(skin);
    tinygltf::Node piece;
    piece.name = t.name + "_piece" + std::to_string(k);
    piece.mesh = m.meshes[k];
    piece.skin = int(model.skins.size()) - 1;
    model.nodes.push_back(piece);
    model.scenes[0].nodes.push_back(int(model.nodes.size()) - 1);
  }
}

// Every morphed mesh on a base of its vertex count, and every tree and copy with `frames` keys.
bool morphs_fit(const ForestAnimation& a, size_t frames, std::string* error) {
  for (const MorphedMesh& m : a.morphed) {
    if (m.base < 0 || size_t(m.base) >= a.morph_bases.size()) {
      *error = "morphed mesh " + m.name + ": no base";
      return false;
    }
    const size_t values = a.morph_bases[size_t(m.base)].positions.size();
    bool fits = m.keys.size() == frames && m.scale > 0;
    for (const std::vector<float>& key : m.keys) fits = fits && key.size() == values;
    if (!fits) {
      *error = "morphed mesh " + m.name + ": " + std::to_string(m.keys.size()) + " keys, not " +
               std::to_string(frames) + ", or a key not of its base's vertices";
      return false;
    }
  }
  return true;
}

}  // namespace

bool write_animation_glb(ForestAnimation a, std::ostream& out, std::string* error,
                         std::vector<MorphReport>* report) {
  int bark = 0, leaf = 0;
  tinygltf::Model model = new_tree_model(a.generator, &bark, &leaf);
  model.scenes[0].name = "forest";
  model.extensionsUsed.push_back("KHR_mesh_quantization");
  model.extensionsRequired.push_back("KHR_mesh_quantization");
  for (const AnimatedTree& t : a.trees)
    if (t.template_index < 0 || size_t(t.template_index) >= a.templates.size() || t.frames.empty() ||
        t.frames[0].size() != t.joint_parents.size() || t.joint_parents.empty() ||
        (!t.bind.empty() && t.bind.size() != t.joint_parents.size()) ||
        t.joint_parents[0] >= 0) {
      *error = "tree " + t.name + ": no template, frames or joints (joint 0 the root)";
      return false;
    }
  std::vector<Box> boxes;
  std::vector<TemplateMeshes> meshes;
  for (const TreeTemplate& t : a.templates) {
    boxes.push_back(bounding_box(t));
    meshes.push_back(add_template(model, t, boxes.back(), bark, leaf));
  }
  tinygltf::Animation animation;
  animation.name = "wind";
  const size_t frames = !a.trees.empty()     ? a.trees[0].frames.size()
                        : !a.morphed.empty() ? a.morphed[0].keys.size()
                                             : 0;
  if (!morphs_fit(a, frames, error)) return false;
  int times = -1;
  if (frames > 1) {
    std::vector<float> t(frames);
    for (size_t f = 0; f < frames; ++f) t[f] = float(double(f) * a.frame_time);
    times = accessor(model, add_values(model, t, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                     TINYGLTF_TYPE_SCALAR, frames, false);
    model.accessors[size_t(times)].minValues = {double(t.front())};
    model.accessors[size_t(times)].maxValues = {double(t.back())};
  }
  for (const AnimatedTree& t : a.trees) {
    if (t.frames.size() != frames) {
      *error = "tree " + t.name + " has " + std::to_string(t.frames.size()) + " frames, not " +
               std::to_string(frames);
      return false;
    }
    std::vector<float> ibm;
    const std::vector<int> nodes =
        add_skeleton(model, t, boxes[size_t(t.template_index)], times, &animation, &ibm);
    for (size_t j = 0; j < nodes.size(); ++j)
      if (t.joint_parents[j] < 0) model.scenes[0].nodes.push_back(nodes[j]);
    add_tree_nodes(model, t, meshes[size_t(t.template_index)], nodes, ibm);
  }
  add_morphed_meshes(model, a, times, bark, leaf, &animation, report);
  if (!animation.channels.empty()) model.animations.push_back(animation);
  if (!glb_write(model, out)) {
    *error = "tinygltf could not serialize the model";
    return false;
  }
  return true;
}

}  // namespace boreas::gltf
