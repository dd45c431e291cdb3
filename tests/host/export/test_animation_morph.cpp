// boreas tests: meadows and imported trees in boreas_world_export_animation, read back with
// tinygltf (a reader boreas did not write) and played as a viewer plays morph targets: at
// key k every strip vertex of the meadow and every vertex of the imported trees where a
// second world of the same inputs has it after k frames, within the def's tolerance; two
// trees of one model on one geometry; bad input refused by name before any step.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"
#include "host/export/gltf_replay.h"

namespace {

const std::string kModel = std::string(BOREAS_TEST_SOURCE_DIR) + "/fuzz/corpus/obj/branched_tree.obj";

// A world in a steady 12 m/s wind with a 3 x 2 m meadow and two imported trees of one model (the
// second turned and scaled).
struct Scene {
  boreas::World world;
  boreas_meadow_id meadow{};
  std::vector<boreas_mesh_tree_id> trees;
  Scene() : world(make_def()) {
    boreas_wave wave = boreas_default_wave();  // steady: no trough that leaves a tree still
    wave.direction[0] = 1.0f;
    wave.direction[1] = 0.0f;
    wave.amplitude = 12.0f;
    wave.sharpness = 0.0f;
    world.wind_set_waves({wave});
    boreas_meadow_def m = boreas_default_meadow_def();
    m.center[0] = 2.0f;
    m.size[0] = 3.0f;
    m.size[1] = 2.0f;
    m.density = 60.0f;
    EXPECT_EQ(boreas_world_add_meadow(world.handle(), &m, &meadow), BOREAS_OK) << boreas_last_error();
    boreas_mesh_tree_def t = boreas_default_mesh_tree_def();
    t.model = kModel.c_str();
    t.cache = 0;
    t.position[0] = -3.0f;
    for (int i = 0; i < 2; ++i) {
      boreas_mesh_tree_id id{};
      EXPECT_EQ(boreas_world_add_mesh_tree(world.handle(), &t, &id), BOREAS_OK) << boreas_last_error();
      trees.push_back(id);
      t.position[2] = 4.0f;
      t.yaw = 0.9f;
      t.scale = 1.4f;
    }
  }
  static boreas_world_def make_def() {
    boreas_world_def def = boreas_default_world_def();
    def.grid.origin[0] = def.grid.origin[2] = -16.0f;
    def.grid.cell_size = 2.0f;
    def.grid.resolution[0] = def.grid.resolution[2] = 16;
    def.grid.resolution[1] = 8;
    return def;
  }
  std::vector<std::array<double, 3>> meadow_vertices() {
    int count = 0;
    EXPECT_EQ(boreas_meadow_get_vertices(world.handle(), meadow, nullptr, nullptr, 0, &count, nullptr), BOREAS_OK);
    std::vector<boreas_meadow_vertex> v(static_cast<size_t>(count));
    std::vector<int32_t> strips(static_cast<size_t>(count) / BOREAS_MEADOW_VERTEX_STRIDE);
    EXPECT_EQ(boreas_meadow_get_vertices(world.handle(), meadow, nullptr, v.data(), count, &count, strips.data()),
              BOREAS_OK);
    std::vector<std::array<double, 3>> out;
    for (size_t c = 0; c < strips.size(); ++c)
      for (int32_t i = 0; i < strips[c]; ++i) {
        const float* x = v[c * BOREAS_MEADOW_VERTEX_STRIDE + size_t(i)].position;
        out.push_back({x[0], x[1], x[2]});
      }
    return out;
  }
  std::vector<std::array<double, 3>> tree_vertices(size_t t, boreas_mesh_part part) {
    int count = 0;
    EXPECT_EQ(boreas_mesh_tree_get_vertices(world.handle(), trees[t], part, nullptr, 0, &count), BOREAS_OK);
    std::vector<boreas_vertex> v(static_cast<size_t>(count));
    EXPECT_EQ(boreas_mesh_tree_get_vertices(world.handle(), trees[t], part, v.data(), count, &count), BOREAS_OK);
    std::vector<std::array<double, 3>> out;
    for (const boreas_vertex& x : v) out.push_back({x.position[0], x.position[1], x.position[2]});
    return out;
  }
  boreas_animation_def def(int frames) {
    boreas_animation_def d = boreas_default_animation_def();
    d.frames = frames;
    d.steps_per_frame = 2;
    d.meadows = &meadow;
    d.meadow_count = 1;
    d.mesh_trees = trees.data();
    d.mesh_tree_count = int(trees.size());
    return d;
  }
};

double farthest(const std::vector<std::array<double, 3>>& a, const std::vector<std::array<double, 3>>& b) {
  EXPECT_EQ(a.size(), b.size());
  double most = 0.0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    most = std::max(most, std::hypot(a[i][0] - b[i][0], a[i][1] - b[i][1], a[i][2] - b[i][2]));
  return most;
}

TEST(AnimationMorph, MeadowAndImportedTreesPlayBackAsBoreasSimulated) {
  const std::string path = (std::filesystem::temp_directory_path() / "boreas_animation_morph.glb").string();
  Scene scene;
  boreas_animation_def def = boreas_default_animation_def();
  def.frames = 12;
  def.steps_per_frame = 2;
  scene.world.export_animation({}, {scene.meadow}, scene.trees, path, def);  // boreas.hpp's
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, path)) << err;
  std::filesystem::remove(path);
  const tinygltf::Node* piece = node_named(m, "meadow0_piece0");
  const tinygltf::Node* trunk0 = node_named(m, "mesh_tree0_trunk");
  const tinygltf::Node* trunk1 = node_named(m, "mesh_tree1_trunk");
  const tinygltf::Node* leaves1 = node_named(m, "mesh_tree1_leaves");
  ASSERT_TRUE(piece && trunk0 && trunk1 && leaves1);
  EXPECT_EQ(node_named(m, "meadow0_piece1"), nullptr) << "a small meadow is one piece";
  const tinygltf::Primitive& p0 = m.meshes[size_t(trunk0->mesh)].primitives.at(0);
  const tinygltf::Primitive& p1 = m.meshes[size_t(trunk1->mesh)].primitives.at(0);
  EXPECT_EQ(p0.attributes, p1.attributes) << "trees of one model share its geometry";
  EXPECT_EQ(p0.indices, p1.indices);
  EXPECT_NE(trunk0->mesh, trunk1->mesh) << "each its own motion";
  const size_t meadow_targets = m.meshes[size_t(piece->mesh)].primitives[0].targets.size();
  size_t narrow = 0;  // int8 targets
  for (const auto& target : m.meshes[size_t(piece->mesh)].primitives[0].targets)
    narrow += m.accessors[size_t(target.at("POSITION"))].componentType == TINYGLTF_COMPONENT_TYPE_BYTE;
  EXPECT_GT(meadow_targets, 0u);
  EXPECT_LE(meadow_targets, size_t(def.frames));

  // A second world of the same inputs, stepped alongside.
  Scene twin;
  const float dt = def.frame_time / float(def.steps_per_frame);
  double meadow_off = 0, tree_off = 0, meadow_moved = 0, tree_moved = 0;
  const std::vector<std::array<double, 3>> rest = twin.meadow_vertices();
  const std::vector<std::array<double, 3>> tree_rest = twin.tree_vertices(1, BOREAS_MESH_LEAVES);
  for (int k = 0; k < def.frames; ++k) {
    if (k > 0)
      for (int s = 0; s < def.steps_per_frame; ++s) twin.world.step(dt);
    const std::vector<std::array<double, 3>> meadow = twin.meadow_vertices();
    meadow_off = std::max(meadow_off, farthest(played(m, *piece, size_t(k)), meadow));
    meadow_moved = std::max(meadow_moved, farthest(rest, meadow));
    tree_off = std::max(tree_off, farthest(played(m, *trunk1, size_t(k)), twin.tree_vertices(1, BOREAS_MESH_TRUNK)));
    const std::vector<std::array<double, 3>> leaves = twin.tree_vertices(1, BOREAS_MESH_LEAVES);
    tree_off = std::max(tree_off, farthest(played(m, *leaves1, size_t(k)), leaves));
    tree_moved = std::max(tree_moved, farthest(tree_rest, leaves));
    tree_off = std::max(tree_off, farthest(played(m, *trunk0, size_t(k)), twin.tree_vertices(0, BOREAS_MESH_TRUNK)));
  }
  std::printf("meadow: %zu targets (%zu int8) for %d keys, moved up to %.4f m, played within %.5f m; "
              "trees moved up to %.4f m, played within %.5f m\n",
              meadow_targets, narrow, def.frames, meadow_moved, meadow_off, tree_moved, tree_off);
  EXPECT_GT(meadow_moved, 10 * def.morph_tolerance) << "the wind moved the meadow";
  EXPECT_GT(tree_moved, 10 * def.morph_tolerance) << "and the imported trees' leaves";
  EXPECT_LE(meadow_off, def.morph_tolerance + 1e-5) << "every strip vertex at every key";
  EXPECT_LE(tree_off, def.morph_tolerance + 1e-5) << "every imported tree vertex at every key";
}

TEST(AnimationMorph, BadInputIsNamedAndTheWorldStaysPut) {
  Scene scene;
  const std::string path = (std::filesystem::temp_directory_path() / "boreas_animation_morph_bad.glb").string();
  auto refused = [&](const boreas_animation_def& d, boreas_status status, const char* named) {
    EXPECT_EQ(boreas_world_export_animation(scene.world.handle(), &d, nullptr, 0, path.c_str()), status);
    EXPECT_NE(std::string(boreas_last_error()).find(named), std::string::npos) << boreas_last_error();
  };
  boreas_animation_def d = scene.def(4);
  d.meadows = nullptr;
  refused(d, BOREAS_ERROR_INVALID_ARGUMENT, "meadows is NULL");
  d = scene.def(4);
  d.mesh_tree_count = -1;
  refused(d, BOREAS_ERROR_INVALID_ARGUMENT, "mesh_tree_count -1");
  d = scene.def(4);
  d.morph_tolerance = 0.0f;
  refused(d, BOREAS_ERROR_INVALID_ARGUMENT, "morph_tolerance");
  d = scene.def(BOREAS_ANIMATION_MAX_MORPH_FRAMES + 1);
  refused(d, BOREAS_ERROR_INVALID_ARGUMENT, "BOREAS_ANIMATION_MAX_MORPH_FRAMES");
  ASSERT_EQ(boreas_world_remove_mesh_tree(scene.world.handle(), scene.trees[1]), BOREAS_OK);
  refused(scene.def(4), BOREAS_ERROR_NOT_FOUND, "mesh_trees[1]");
  ASSERT_EQ(boreas_world_remove_meadow(scene.world.handle(), scene.meadow), BOREAS_OK);
  refused(scene.def(4), BOREAS_ERROR_NOT_FOUND, "meadows[0]");
  EXPECT_EQ(scene.world.get_time(), 0.0) << "nothing stepped";
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(AnimationMorph, AFileThatCannotBeWrittenIsNamed) {
  Scene scene;
  const std::string path = (std::filesystem::temp_directory_path() / "boreas_no_such_dir" / "a.glb").string();
  const boreas_animation_def d = scene.def(2);
  EXPECT_EQ(boreas_world_export_animation(scene.world.handle(), &d, nullptr, 0, path.c_str()), BOREAS_ERROR_IO);
  EXPECT_NE(std::string(boreas_last_error()).find(path), std::string::npos) << boreas_last_error();
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
