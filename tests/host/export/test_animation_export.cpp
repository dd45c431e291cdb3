// boreas tests: boreas_world_export_animation, read back with tinygltf (a reader boreas did
// not write): one mesh per template shared by its trees, the joint and key counts asked
// for, the joints at key k where a second world of the same inputs has them after k
// frames (within 1 mm), the skinned key-0 mesh where boreas_tree_get_mesh has each tree,
// and bad input refused by name before any step.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"

namespace {

using Mat4 = std::array<double, 16>;  // column-major

Mat4 mul(const Mat4& a, const Mat4& b) {
  Mat4 m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) m[size_t(4 * c + r)] += a[size_t(4 * k + r)] * b[size_t(4 * c + k)];
  return m;
}

Mat4 trs(const std::vector<double>& t, const std::vector<double>& q) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0,
          2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0,
          2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0,
          t[0], t[1], t[2], 1};
}

// Element i of an accessor as doubles, normalized integers brought to [-1, 1] / [0, 1].
std::vector<double> element(const tinygltf::Model& m, int index, size_t i) {
  const tinygltf::Accessor& a = m.accessors[size_t(index)];
  const tinygltf::BufferView& v = m.bufferViews[size_t(a.bufferView)];
  const int n = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  const int size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  const size_t stride = v.byteStride ? v.byteStride : size_t(n * size);
  const unsigned char* p = m.buffers[size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset + i * stride;
  std::vector<double> out(static_cast<size_t>(n), 0.0);
  for (int c = 0; c < n; ++c) {
    const unsigned char* e = p + c * size;
    double x = 0;
    switch (a.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, e, 4); x = f; break; }
      case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t s; std::memcpy(&s, e, 2); x = a.normalized ? std::max(s / 32767.0, -1.0) : s; break; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t s; std::memcpy(&s, e, 2); x = a.normalized ? s / 65535.0 : s; break; }
      case TINYGLTF_COMPONENT_TYPE_BYTE: { int8_t s; std::memcpy(&s, e, 1); x = a.normalized ? std::max(s / 127.0, -1.0) : s; break; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: x = a.normalized ? *e / 255.0 : *e; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t s; std::memcpy(&s, e, 4); x = s; break; }
      default: ADD_FAILURE() << "component type " << a.componentType;
    }
    out[size_t(c)] = x;
  }
  return out;
}

// Every node's world matrix with the animation at key k (LINEAR keys hit exactly).
std::vector<Mat4> world_matrices(const tinygltf::Model& m, size_t key) {
  std::vector<std::vector<double>> t(m.nodes.size()), r(m.nodes.size());
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    t[i] = m.nodes[i].translation.empty() ? std::vector<double>{0, 0, 0} : m.nodes[i].translation;
    r[i] = m.nodes[i].rotation.empty() ? std::vector<double>{0, 0, 0, 1} : m.nodes[i].rotation;
  }
  for (const tinygltf::AnimationChannel& c : m.animations.at(0).channels) {
    const std::vector<double> v = element(m, m.animations[0].samplers[size_t(c.sampler)].output, key);
    (c.target_path == "translation" ? t : r)[size_t(c.target_node)] = v;
  }
  std::vector<Mat4> world(m.nodes.size());
  std::vector<int> parent(m.nodes.size(), -1);
  for (size_t i = 0; i < m.nodes.size(); ++i)
    for (int child : m.nodes[i].children) parent[size_t(child)] = int(i);
  std::vector<bool> done(m.nodes.size(), false);
  std::function<const Mat4&(size_t)> get = [&](size_t i) -> const Mat4& {
    if (!done[i]) {
      world[i] = trs(t[i], r[i]);
      if (parent[i] >= 0) world[i] = mul(get(size_t(parent[i])), world[i]);
      done[i] = true;
    }
    return world[i];
  };
  for (size_t i = 0; i < m.nodes.size(); ++i) get(i);
  return world;
}

boreas_world_def small_world() {
  boreas_world_def def = boreas_default_world_def();
  def.grid.origin[0] = -20.0f;
  def.grid.origin[2] = -20.0f;
  def.grid.cell_size = 2.0f;
  def.grid.resolution[0] = def.grid.resolution[1] = def.grid.resolution[2] = 20;
  def.wave_count = 0;
  return def;
}

// Two aspens of one template (one turned and scaled) and an oak, in a steady wind.
std::vector<boreas_tree_id> plant(boreas::World& world) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 1.0f;
  w.amplitude = 12.0f;
  w.sharpness = 0.0f;
  world.wind_set_waves({w});
  boreas_tree_def a = boreas_default_tree_def();
  boreas_tree_def b = a;
  b.position[0] = 6.0f;
  b.position[2] = -4.0f;
  b.rotation = 1.2f;
  b.scale = 1.3f;
  boreas_tree_def c = a;
  c.species = "ca_black_oak";
  c.position[0] = -8.0f;
  c.seed = 6;
  return world.add_trees({a, b, c});
}

boreas_animation_def small_def() {
  boreas_animation_def def = boreas_default_animation_def();
  def.frames = 10;
  def.steps_per_frame = 2;
  def.skin.max_level = 1;
  def.skin.segments = 3;
  return def;
}

// Tree t's joint j: the node the writer names so (-1: none).
int joint_node(const tinygltf::Model& m, int t, size_t j) {
  const std::string name = "tree" + std::to_string(t) + "_joint" + std::to_string(j);
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].name == name) return int(i);
  return -1;
}

// The joints in the file at key k against a second world of the same inputs (plant's),
// stepped warmup_steps and then k frames: the farthest joint and branch-end joint (its tip).
struct JointOffsets {
  double worst = 0, worst_tip = 0;
};
JointOffsets joints_against_a_twin(const tinygltf::Model& m, const boreas_animation_def& def, int warmup_steps) {
  boreas::World twin(small_world());
  const std::vector<boreas_tree_id> twins = plant(twin);
  for (int t = 0; t < 3; ++t) {
    const size_t joints = twin.tree_get_joints(twins[size_t(t)], def.skin).size();
    EXPECT_GE(joint_node(m, t, joints - 1), 0);
    EXPECT_EQ(joint_node(m, t, joints), -1) << "tree " << t << ": " << joints << " joints";
  }
  const float dt = def.frame_time / float(def.steps_per_frame);
  for (int s = 0; s < warmup_steps; ++s) twin.step(dt);
  JointOffsets out;
  for (int k = 0; k < def.frames; ++k) {
    if (k > 0)
      for (int s = 0; s < def.steps_per_frame; ++s) twin.step(dt);
    if (k % 3 != 0 && k != def.frames - 1) continue;
    const std::vector<Mat4> at = world_matrices(m, size_t(k));
    for (int t = 0; t < 3; ++t) {
      const std::vector<boreas_joint> joints = twin.tree_get_joints(twins[size_t(t)], def.skin);
      const std::vector<boreas_branch> branches = twin.tree_get_branches(twins[size_t(t)]);
      for (size_t j = 0; j < joints.size(); ++j) {
        const int node = joint_node(m, t, j);
        if (node < 0) continue;
        const Mat4& w = at[size_t(node)];
        double d = 0, tip = 0;
        for (int a = 0; a < 3; ++a) {
          d += std::pow(w[size_t(12 + a)] - joints[j].position[a], 2);
          tip += std::pow(w[size_t(12 + a)] - branches[size_t(joints[j].branch)].control_points[3][a], 2);
        }
        out.worst = std::max(out.worst, std::sqrt(d));
        if (joints[j].u == 1.0f) out.worst_tip = std::max(out.worst_tip, std::sqrt(tip));
      }
    }
  }
  return out;
}

// The file of plant's trees exported after warmup_steps (the def's warm-up: the bind pose
// taken before them), read back and checked.
void trees_share_and_follow(int warmup_steps) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "boreas_animation_export_test.glb").string();
  boreas_animation_def def = small_def();
  def.warmup = float(warmup_steps) * def.frame_time / float(def.steps_per_frame);
  boreas::World world(small_world());
  const std::vector<boreas_tree_id> trees = plant(world);
  const boreas::World::Mesh rest_b = world.tree_get_mesh(trees[1]);
  const std::vector<boreas_joint> rest_joints = world.tree_get_joints(trees[1], def.skin);
  world.export_animation(trees, path, def);
  EXPECT_NEAR(world.get_time(), (def.frames - 1 + double(warmup_steps) / def.steps_per_frame) * def.frame_time, 1e-4);

  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, path)) << err;
  std::filesystem::remove(path);
  ASSERT_EQ(joint_node(m, 1, rest_joints.size()), -1);
  // Each tree a node per piece of its template's mesh (pieces of 16-bit indices and at
  // most 256 joints), each with a skin of its own, named treeT_pieceK.
  std::vector<std::vector<int>> pieces_of(3);  // node indices of tree t's pieces
  for (int t = 0; t < 3; ++t)
    for (int k = 0;; ++k) {
      const std::string name = "tree" + std::to_string(t) + "_piece" + std::to_string(k);
      const auto n = std::find_if(m.nodes.begin(), m.nodes.end(),
                                  [&](const tinygltf::Node& node) { return node.name == name; });
      if (n == m.nodes.end()) break;
      ASSERT_GE(n->skin, 0);
      pieces_of[size_t(t)].push_back(int(n - m.nodes.begin()));
    }
  ASSERT_FALSE(pieces_of[0].empty());
  auto meshes = [&](int t) {
    std::vector<int> out;
    for (int c : pieces_of[size_t(t)]) out.push_back(m.nodes[size_t(c)].mesh);
    return out;
  };
  const std::vector<int> aspen = meshes(0);
  EXPECT_EQ(aspen, meshes(1)) << "two aspens of one template share its meshes";
  for (int mesh : meshes(2))
    EXPECT_EQ(std::count(aspen.begin(), aspen.end(), mesh), 0) << "the oak has its own";
  EXPECT_EQ(m.meshes.size(), meshes(0).size() + meshes(2).size()) << "no mesh but the templates'";
  for (const tinygltf::Skin& skin : m.skins) EXPECT_LE(skin.joints.size(), 256u);
  const tinygltf::Accessor& times = m.accessors[size_t(m.animations.at(0).samplers.at(0).input)];
  EXPECT_EQ(times.count, size_t(def.frames)) << "a key per frame";
  EXPECT_NEAR(times.maxValues.at(0), (def.frames - 1) * def.frame_time, 1e-6);
  const JointOffsets joints = joints_against_a_twin(m, def, warmup_steps);
  EXPECT_LT(joints.worst, 1e-3) << "joints in the file at key k within 1 mm of boreas's after the warm-up and k frames";
  EXPECT_LT(joints.worst_tip, 1e-3) << "each branch's end joint at its tip";

  // The bind pose is the trees' at the call (before any warm-up): the shared mesh, skinned
  // for the turned and scaled aspen with its joints where boreas had them then, lands on
  // that tree's own mesh then (quantization: int16 over the crown's box). The bark is
  // cut into pieces: its triangles, piece after piece, are the tree's.
  std::vector<Mat4> bind(m.nodes.size());
  for (size_t j = 0; j < rest_joints.size(); ++j) {
    const boreas_joint& r = rest_joints[j];
    bind.at(size_t(joint_node(m, 1, j))) = trs({r.position[0], r.position[1], r.position[2]},
                                               {r.rotation[0], r.rotation[1], r.rotation[2], r.rotation[3]});
  }
  const int bark_material = m.meshes[size_t(meshes(1)[0])].primitives.at(0).material;
  // The skinned key-0 position of vertex v of primitive p under skin.
  auto skinned = [&](const tinygltf::Primitive& p, const tinygltf::Skin& skin, size_t v) {
    const std::vector<double> q = element(m, p.attributes.at("POSITION"), v);
    const std::vector<double> jv = element(m, p.attributes.at("JOINTS_0"), v);
    const std::vector<double> wv = element(m, p.attributes.at("WEIGHTS_0"), v);
    std::array<double, 3> out{0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      if (wv[size_t(i)] == 0) continue;
      const std::vector<double> ibm = element(m, skin.inverseBindMatrices, size_t(jv[size_t(i)]));
      Mat4 inv;
      std::copy(ibm.begin(), ibm.end(), inv.begin());
      const Mat4 s = mul(bind[size_t(skin.joints[size_t(jv[size_t(i)])])], inv);
      for (int a = 0; a < 3; ++a)
        out[size_t(a)] += wv[size_t(i)] * (s[size_t(a)] * q[0] + s[size_t(4 + a)] * q[1] +
                                           s[size_t(8 + a)] * q[2] + s[size_t(12 + a)]);
    }
    return out;
  };
  double off = 0;
  size_t corner = 0, pieces = 0;  // the bark's corners read so far, over all its pieces
  for (int node : pieces_of[1]) {
    const tinygltf::Primitive& p = m.meshes[size_t(m.nodes[size_t(node)].mesh)].primitives.at(0);
    const tinygltf::Skin& skin = m.skins[size_t(m.nodes[size_t(node)].skin)];
    EXPECT_EQ(m.accessors[size_t(p.attributes.at("JOINTS_0"))].componentType,
              TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
    if (p.material != bark_material) continue;
    ++pieces;
    const tinygltf::Accessor& indices = m.accessors[size_t(p.indices)];
    EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) << "16-bit indices";
    EXPECT_LE(m.accessors[size_t(p.attributes.at("POSITION"))].count, 65535u);
    for (size_t i = 0; i < indices.count; ++i, ++corner) {
      if (corner % 7 != 0 || corner >= rest_b.indices.size()) continue;
      const std::array<double, 3> at = skinned(p, skin, size_t(element(m, p.indices, i)[0]));
      const float* want = rest_b.vertices[rest_b.indices[corner]].position;
      double d = 0;
      for (int a = 0; a < 3; ++a) d += std::pow(at[size_t(a)] - want[a], 2);
      off = std::max(off, std::sqrt(d));
    }
  }
  EXPECT_EQ(corner, rest_b.indices.size()) << "the bark's triangles, all of them, in order";
  EXPECT_GE(pieces, 1u);
  EXPECT_LT(off, 2e-3) << "the shared mesh lands on the second aspen within 2 mm";
}

TEST(AnimationExport, TreesShareTheirTemplatesMeshAndJointsFollowTheWorld) { trees_share_and_follow(0); }

// A warm-up of 30 steps (0.625 s): the keys start bent in the wind, the skin still binds
// the mesh at rest, and the joints at key k are boreas's after 30 + 2 k steps.
TEST(AnimationExport, AfterAWarmUpJointsFollowTheWorldAndTheSkinBindsTheRest) { trees_share_and_follow(30); }

TEST(AnimationExport, BadInputIsNamedAndTheWorldStaysPut) {
  boreas::World world(small_world());
  std::vector<boreas_tree_id> trees = plant(world);
  const std::string path =
      (std::filesystem::temp_directory_path() / "boreas_animation_bad.glb").string();
  boreas_animation_def def = small_def();
  def.frames = 0;
  EXPECT_EQ(boreas_world_export_animation(world.handle(), &def, trees.data(), 3, path.c_str()),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("frames"), std::string::npos);
  def = small_def();
  def.skin.segments = 0;
  EXPECT_EQ(boreas_world_export_animation(world.handle(), &def, trees.data(), 3, path.c_str()),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("segments"), std::string::npos);
  world.remove_tree(trees[1]);
  def = small_def();
  EXPECT_EQ(boreas_world_export_animation(world.handle(), &def, trees.data(), 3, path.c_str()),
            BOREAS_ERROR_NOT_FOUND);
  EXPECT_NE(std::string(boreas_last_error()).find("trees[1]"), std::string::npos);
  EXPECT_EQ(world.get_time(), 0.0) << "nothing stepped";
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
