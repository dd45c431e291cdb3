// boreas tests: a tree's skin (boreas_tree_get_joints, boreas_tree_get_skin_weights,
// boreas_tree_get_leaf_skin_weights). Linear blend skinning, computed here in double from
// the joints at rest (the bind pose) and as of a step, must carry the rest mesh and the
// leaves to where boreas_tree_get_mesh and boreas_tree_get_leaves put them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"
#define BOREAS_FAST_MATH 1
#include "shared/tree_math.h"
#include "support/temp_dir.h"
#include "trees/tree_skin.h"

namespace {

struct D3 {
  double x = 0, y = 0, z = 0;
};
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double norm(D3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
D3 d3(const float* p) { return {p[0], p[1], p[2]}; }

// The joint's rotation as a matrix (columns: its axes in world), in double.
struct Frame {
  double m[3][3];
  D3 o;
  explicit Frame(const boreas_joint& j) : o(d3(j.position)) {
    const double x = j.rotation[0], y = j.rotation[1], z = j.rotation[2], w = j.rotation[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    std::copy(&r[0][0], &r[0][0] + 9, &m[0][0]);
  }
  D3 to_local(D3 p) const {  // R^T (p - o)
    const D3 d = p - o;
    return {m[0][0] * d.x + m[1][0] * d.y + m[2][0] * d.z,
            m[0][1] * d.x + m[1][1] * d.y + m[2][1] * d.z,
            m[0][2] * d.x + m[1][2] * d.y + m[2][2] * d.z};
  }
  D3 to_world(D3 l) const {
    return D3{m[0][0] * l.x + m[0][1] * l.y + m[0][2] * l.z,
              m[1][0] * l.x + m[1][1] * l.y + m[1][2] * l.z,
              m[2][0] * l.x + m[2][1] * l.y + m[2][2] * l.z} +
           o;
  }
};

// Linear blend skinning of a rest point.
D3 skinned(D3 rest, const boreas_skin_weight& w, const std::vector<boreas_joint>& bind,
           const std::vector<boreas_joint>& now) {
  D3 out;
  for (int i = 0; i < 4; ++i) {
    if (w.weights[i] == 0.0f) continue;
    const size_t j = size_t(w.joints[i]);
    out = out + Frame(now[j]).to_world(Frame(bind[j]).to_local(rest)) * w.weights[i];
  }
  return out;
}

boreas_world_def tree_world_def() {
  boreas_world_def def = boreas_default_world_def();
  def.grid.origin[0] = -20.0f;
  def.grid.origin[1] = 0.0f;
  def.grid.origin[2] = -20.0f;
  def.grid.cell_size = 2.0f;
  def.grid.resolution[0] = def.grid.resolution[1] = def.grid.resolution[2] = 20;
  return def;
}

// A steady 15 m/s wind along +x (and a little z), stepped for a second.
void blow(boreas::World& world) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 1.0f;
  w.direction[2] = 0.3f;
  w.amplitude = 15.0f;
  w.wavelength = 30.0f;
  w.speed = 8.0f;
  w.sharpness = 0.0f;
  world.wind_set_waves({w});
  for (int s = 0; s < 30; ++s) world.step(1.0f / 30.0f);
}

struct Errors {
  double max = 0, rms = 0, moved = 0;  // m; moved: the largest motion from rest
};

// Over every vertex, or those `only` marks.
Errors mesh_errors(const boreas::World::Mesh& rest, const boreas::World::Mesh& bent,
                   const std::vector<boreas_skin_weight>& weights,
                   const std::vector<boreas_joint>& bind, const std::vector<boreas_joint>& now,
                   const std::vector<bool>* only = nullptr) {
  Errors e;
  size_t n = 0;
  for (size_t v = 0; v < rest.vertices.size(); ++v) {
    if (only && !(*only)[v]) continue;
    ++n;
    const D3 r = d3(rest.vertices[v].position), b = d3(bent.vertices[v].position);
    const double d = norm(skinned(r, weights[v], bind, now) - b);
    e.max = std::max(e.max, d);
    e.rms += d * d;
    e.moved = std::max(e.moved, norm(b - r));
  }
  e.rms = std::sqrt(e.rms / double(std::max<size_t>(n, 1)));
  return e;
}

// The mesh's vertices on each branch's last BOREAS_CAP_RINGS rings and the rim below them
// (where a capped piece's rings go round its tip: boreas_ring_v), branches in order, each
// a grid of (rings + 1) x (sides + 1) of its level.
std::vector<bool> tip_rings(const std::vector<boreas_branch>& branches,
                            const boreas_tree_def& def) {
  std::vector<bool> out;
  for (const boreas_branch& b : branches) {
    const boreas_tree_level_def& l = def.levels[b.level];
    for (int r = 0; r <= l.rings; ++r)
      out.insert(out.end(), size_t(l.sides + 1), r >= l.rings - BOREAS_CAP_RINGS(l.rings));
  }
  return out;
}

// quaking_aspen.json with Arbaro's rounded tips: a trunk of beads (0Taper 2.6) and branches
// of 1Taper and 2Taper 1.5, every piece that reaches its stem's tip capped.
std::string capped_aspen(const boreas::test::TempDir& dir) {
  const std::filesystem::path from = std::filesystem::path(BOREAS_TEST_DATA_DIR) / ".." / ".." /
                                     "host" / "species" / "quaking_aspen.json";
  std::ifstream in(from);
  std::stringstream text;
  text << in.rdbuf();
  std::string json =
      std::regex_replace(text.str(), std::regex("\"0Taper\": [0-9.]+"), "\"0Taper\": 2.6");
  json = std::regex_replace(json, std::regex("\"([12])Taper\": [0-9.]+"), "\"$1Taper\": 1.5");
  const std::string to = (dir.path() / "capped_aspen.json").string();
  std::ofstream(to) << json;
  return to;
}

TEST(TreeSkin, JointsSitOnTheCurvesAndWeightsAreConvex) {
  boreas::World world(tree_world_def());
  const boreas_tree_id id = world.add_tree(boreas_default_tree_def());
  blow(world);
  const boreas_skin_def def = boreas_default_skin_def();
  const std::vector<boreas_branch> branches = world.tree_get_branches(id);
  const std::vector<boreas_joint> joints = world.tree_get_joints(id, def);
  ASSERT_EQ(joints.size(), branches.size() * size_t(def.segments + 1)) << "max_level 3: all";
  double worst_tip = 0, worst_base = 0;
  for (size_t i = 0; i < joints.size(); ++i) {
    const boreas_joint& j = joints[i];
    const boreas_branch& b = branches[size_t(j.branch)];
    ASSERT_LT(j.parent, int(i)) << "a joint comes after its parent";
    if (j.u == 1.0f) worst_tip = std::max(worst_tip, norm(d3(j.position) - d3(b.control_points[3])));
    if (j.u == 0.0f) worst_base = std::max(worst_base, norm(d3(j.position) - d3(b.control_points[0])));
    const double q = std::hypot(std::hypot(j.rotation[0], j.rotation[1]),
                                std::hypot(j.rotation[2], j.rotation[3]));
    EXPECT_NEAR(q, 1.0, 1e-6);
  }
  EXPECT_LT(worst_tip, 1e-3) << "each branch's end joint is its tip, bent";
  EXPECT_LT(worst_base, 1e-3);
  for (const boreas_skin_weight& w : world.tree_get_skin_weights(id, def)) {
    EXPECT_NEAR(w.weights[0] + w.weights[1] + w.weights[2] + w.weights[3], 1.0, 1e-6);
    EXPECT_GE(w.weights[0], w.weights[1]);
  }
}

// Every level skinned: the error is the bend within a segment, far below the motion.
TEST(TreeSkin, SkinnedRestMeshFollowsTheBentMesh) {
  boreas::World world(tree_world_def());
  const boreas_tree_id id = world.add_tree(boreas_default_tree_def());
  boreas_skin_def def = boreas_default_skin_def();
  const std::vector<boreas_joint> bind = world.tree_get_joints(id, def);
  const boreas::World::Mesh rest = world.tree_get_mesh(id);
  const std::vector<boreas_skin_weight> weights = world.tree_get_skin_weights(id, def);
  ASSERT_EQ(weights.size(), rest.vertices.size());
  // At rest the skin is the mesh (the bind pose itself; the weights sum to one).
  const Errors still = mesh_errors(rest, rest, weights, bind, bind);
  EXPECT_LT(still.max, 1e-5);

  const std::vector<boreas_leaf> leaves_rest = world.tree_get_leaves(id);
  const std::vector<boreas_skin_weight> leaf_weights = world.tree_get_leaf_skin_weights(id, def);
  ASSERT_EQ(leaf_weights.size(), leaves_rest.size());

  blow(world);
  const boreas::World::Mesh bent = world.tree_get_mesh(id);
  const std::vector<boreas_joint> now = world.tree_get_joints(id, def);
  const Errors e = mesh_errors(rest, bent, weights, bind, now);
  std::printf("segments 4, all levels: moved %.3f m, skin off by max %.4f m, rms %.5f m\n",
              e.moved, e.max, e.rms);
  EXPECT_GT(e.moved, 0.1) << "the wind bent the tree";
  // Measured: 1.1 cm at most and 0.8 mm rms where the crown moved 1.8 m.
  EXPECT_LT(e.max, 0.015) << "within 1.5 cm everywhere";
  EXPECT_LT(e.rms, 0.001) << "within 1 mm on average";

  // The leaves: each carried rigidly by the joints around its place.
  const std::vector<boreas_leaf> leaves_now = world.tree_get_leaves(id);
  double leaf_max = 0, leaf_moved = 0;
  for (size_t i = 0; i < leaves_rest.size(); ++i) {
    const D3 r = d3(leaves_rest[i].position), b = d3(leaves_now[i].position);
    leaf_max = std::max(leaf_max, norm(skinned(r, leaf_weights[i], bind, now) - b));
    leaf_moved = std::max(leaf_moved, norm(b - r));
  }
  std::printf("leaves: moved %.3f m, skin off by max %.4f m\n", leaf_moved, leaf_max);
  // Measured 2.4 cm (a blade's base sits a petiole off the axis, so it feels the turn).
  EXPECT_LT(leaf_max, 0.03);
}

// A capped tree: the last rings of each capped piece sit round its tip (boreas_ring_v), and
// their weights are those of that place, so the skin follows the mesh there as elsewhere,
// within the tolerance above. Weighted at r / rings instead (before issue 40's skincaps),
// the cap's rings took joints up to a quarter of the branch further in. Measured (crown
// moved 0.85 m): the tips' rings off by 2.0 mm at most and 0.07 mm rms; at r / rings by
// 3.1 cm and 2.3 mm rms, past both bounds.
TEST(TreeSkin, CappedTipsAreWeightedWhereTheirRingsSit) {
  boreas::test::TempDir dir;
  const std::string species = capped_aspen(dir);
  boreas::World world(tree_world_def());
  boreas_tree_def tree = boreas_default_tree_def();
  tree.species = species.c_str();
  const boreas_tree_id id = world.add_tree(tree);
  const boreas_skin_def def = boreas_default_skin_def();
  const std::vector<boreas_joint> bind = world.tree_get_joints(id, def);
  const boreas::World::Mesh rest = world.tree_get_mesh(id);
  const std::vector<boreas_skin_weight> weights = world.tree_get_skin_weights(id, def);
  ASSERT_EQ(weights.size(), rest.vertices.size());
  const std::vector<bool> tips = tip_rings(world.tree_get_branches(id), tree);
  ASSERT_EQ(tips.size(), rest.vertices.size());
  blow(world);
  const boreas::World::Mesh bent = world.tree_get_mesh(id);
  const std::vector<boreas_joint> now = world.tree_get_joints(id, def);
  const Errors all = mesh_errors(rest, bent, weights, bind, now);
  const Errors tip = mesh_errors(rest, bent, weights, bind, now, &tips);
  std::printf(
      "capped aspen: moved %.3f m, skin off by max %.4f m, rms %.5f m; "
      "on the tips' rings max %.4f m, rms %.5f m\n",
      all.moved, all.max, all.rms, tip.max, tip.rms);
  EXPECT_GT(all.moved, 0.1) << "the wind bent the tree";
  EXPECT_LT(all.max, 0.015) << "within 1.5 cm everywhere";
  EXPECT_LT(all.rms, 0.001) << "within 1 mm on average";
  EXPECT_LT(tip.max, 0.015) << "the tips' rings too";
  EXPECT_LT(tip.rms, 0.001);

  // The same skin with every ring at r / rings (no caps): the test sees the difference.
  boreas::impl::LevelGrids grids{};
  for (size_t l = 0; l < grids.size(); ++l) grids[l] = {tree.levels[l].rings, tree.levels[l].sides};
  const std::vector<boreas_branch> branches = world.tree_get_branches(id);
  const std::vector<boreas_skin_weight> even = boreas::impl::skin_vertex_weights(
      branches, std::vector<float>(branches.size(), 0.0f), grids, {def.max_level, def.segments});
  const Errors before = mesh_errors(rest, bent, even, bind, now, &tips);
  std::printf("rings at r / rings: on the tips' rings max %.4f m, rms %.5f m\n", before.max,
              before.rms);
  EXPECT_GT(before.max, 0.015);
}

TEST(TreeSkin, HealedTreeIsBackInTheBindPose) {
  boreas::World world(tree_world_def());
  const boreas_tree_id id = world.add_tree(boreas_default_tree_def());
  const std::vector<boreas_joint> bind = world.tree_get_joints(id);
  blow(world);
  world.tree_heal(id);
  const std::vector<boreas_joint> healed = world.tree_get_joints(id);
  ASSERT_EQ(healed.size(), bind.size());
  for (size_t i = 0; i < bind.size(); ++i)
    EXPECT_LT(norm(d3(healed[i].position) - d3(bind[i].position)), 1e-5) << i;
}

TEST(TreeSkin, CoarseSkinCarriesFinerBranchesOnTheirAncestors) {
  boreas::World world(tree_world_def());
  const boreas_tree_id id = world.add_tree(boreas_default_tree_def());
  boreas_skin_def def = boreas_default_skin_def();
  def.max_level = 1;
  def.segments = 3;
  const std::vector<boreas_branch> branches = world.tree_get_branches(id);
  const std::vector<boreas_joint> bind = world.tree_get_joints(id, def);
  for (const boreas_joint& j : bind) ASSERT_LE(branches[size_t(j.branch)].level, 1);
  const boreas::World::Mesh rest = world.tree_get_mesh(id);
  const std::vector<boreas_skin_weight> weights = world.tree_get_skin_weights(id, def);
  for (const boreas_skin_weight& w : weights)
    for (int i = 0; i < 4; ++i) ASSERT_LT(size_t(w.joints[i]), bind.size());
  blow(world);
  const Errors e =
      mesh_errors(rest, world.tree_get_mesh(id), weights, bind, world.tree_get_joints(id, def));
  std::printf("segments 3, levels 0-1: moved %.3f m, skin off by max %.4f m, rms %.5f m\n",
              e.moved, e.max, e.rms);
  // The finer branches' own bend is what a coarse skin leaves out.
  EXPECT_LT(e.rms, 0.5 * e.moved);
}

TEST(TreeSkin, BadDefIsRefusedByName) {
  boreas::World world(tree_world_def());
  const boreas_tree_id id = world.add_tree(boreas_default_tree_def());
  boreas_skin_def def = boreas_default_skin_def();
  int count = 0;
  def.segments = 0;
  EXPECT_EQ(boreas_tree_get_joints(world.handle(), id, &def, nullptr, 0, &count),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("segments"), std::string::npos);
  def.segments = BOREAS_SKIN_MAX_SEGMENTS + 1;
  EXPECT_EQ(boreas_tree_get_skin_weights(world.handle(), id, &def, nullptr, 0, &count),
            BOREAS_ERROR_INVALID_ARGUMENT);
  def = boreas_default_skin_def();
  def.max_level = 4;
  EXPECT_EQ(boreas_tree_get_leaf_skin_weights(world.handle(), id, &def, nullptr, 0, &count),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("max_level"), std::string::npos);
}

}  // namespace
