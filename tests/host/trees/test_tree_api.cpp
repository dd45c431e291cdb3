// boreas tests: trees through the public C and C++ API — adding, reading, removing, the
// contract on bad input (clear error, world unchanged), and motion in wind.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"
#include "support/test_support.h"

namespace {

using boreas::test::bytes_of;
using boreas::test::TempDir;

struct D3 {
  double x, y, z;
};

D3 bezier(const boreas_branch& b, double u) {
  double w = 1.0 - u;
  double k[4] = {w * w * w, 3 * u * w * w, 3 * u * u * w, u * u * u};
  D3 r{0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    r.x += k[i] * b.control_points[i][0];
    r.y += k[i] * b.control_points[i][1];
    r.z += k[i] * b.control_points[i][2];
  }
  return r;
}

double distance(D3 a, const float* p) {
  return std::sqrt((a.x - p[0]) * (a.x - p[0]) + (a.y - p[1]) * (a.y - p[1]) + (a.z - p[2]) * (a.z - p[2]));
}

// A world whose grid spans a tree at the origin (40 m wide, 40 m high).
boreas_world_def tree_world_def() {
  boreas_world_def def = boreas_default_world_def();
  def.grid.origin[0] = -20.0f;
  def.grid.origin[1] = 0.0f;
  def.grid.origin[2] = -20.0f;
  def.grid.cell_size = 2.0f;
  def.grid.resolution[0] = 20;
  def.grid.resolution[1] = 20;
  def.grid.resolution[2] = 20;
  return def;
}

boreas_wave gusty_wave(float amplitude) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 1.0f;
  w.direction[1] = 0.3f;
  w.amplitude = amplitude;
  w.wavelength = 30.0f;
  w.speed = 8.0f;
  w.sharpness = 2.0f;
  return w;
}

TEST(TreeApi, BuiltinSpeciesIncludeThePresets) {
  std::vector<std::string> names = boreas::builtin_species();
  for (const char* want : {"quaking_aspen", "black_tupelo", "weeping_willow", "ca_black_oak"})
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  EXPECT_EQ(boreas_builtin_species(-1), nullptr);
  EXPECT_EQ(boreas_builtin_species(static_cast<int>(names.size())), nullptr);
}

TEST(TreeApi, AddedTreeIsPlacedUnbentWithChildrenOnTheirParents) {
  boreas::World world(tree_world_def());
  boreas_tree_def def = boreas_default_tree_def();
  def.position[0] = 3.0f;
  def.position[2] = -2.0f;
  boreas_tree_id id = world.add_tree(def);

  int count = -1;
  ASSERT_EQ(boreas_tree_get_branches(world.handle(), id, nullptr, 0, &count), BOREAS_OK);
  std::vector<boreas_branch> branches = world.tree_get_branches(id);
  ASSERT_EQ(static_cast<int>(branches.size()), count);
  ASSERT_GT(count, 10);

  const boreas_branch& trunk = branches[0];
  EXPECT_EQ(trunk.parent, -1);
  EXPECT_EQ(trunk.level, 0);
  EXPECT_FLOAT_EQ(trunk.control_points[0][0], 3.0f);
  EXPECT_FLOAT_EQ(trunk.control_points[0][1], 0.0f);
  EXPECT_FLOAT_EQ(trunk.control_points[0][2], -2.0f);
  // The trunk grows up: its first segment is vertical (P1 on local +x, mapped to +Y).
  EXPECT_NEAR(trunk.control_points[1][0], 3.0f, 1e-5);
  EXPECT_GT(trunk.control_points[1][1], 0.0f);

  int previous_level = 0;
  for (size_t i = 1; i < branches.size(); ++i) {
    const boreas_branch& b = branches[i];
    ASSERT_GE(b.parent, 0);
    ASSERT_LT(b.parent, static_cast<int>(i));
    EXPECT_EQ(branches[b.parent].level, b.level - 1);
    EXPECT_GE(b.level, previous_level) << "levels in order";
    previous_level = b.level;
    // P0 on the parent's curve at parent_v (float placement: ~1e-6 of the tree's size).
    EXPECT_LT(distance(bezier(branches[b.parent], b.parent_v), b.control_points[0]), 1e-4) << "branch " << i;
  }
}

TEST(TreeApi, CalmWindLeavesTheTreeAtRestAndWindMovesIt) {
  boreas::World world(tree_world_def());
  boreas_tree_id id = world.add_tree(boreas_default_tree_def());
  std::vector<boreas_branch> rest = world.tree_get_branches(id);
  for (int s = 0; s < 10; ++s) world.step(1.0f / 30.0f);
  std::vector<boreas_branch> calm = world.tree_get_branches(id);
  double max_move = 0.0;
  for (size_t i = 0; i < rest.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      D3 r{rest[i].control_points[k][0], rest[i].control_points[k][1], rest[i].control_points[k][2]};
      max_move = std::max(max_move, distance(r, calm[i].control_points[k]));
    }
  EXPECT_LT(max_move, 1e-4) << "no wind, no motion";

  boreas_wave steady = gusty_wave(15.0f);  // 15 m/s everywhere, always
  steady.sharpness = 0.0f;
  world.wind_set_waves({steady});
  for (int s = 0; s < 10; ++s) world.step(1.0f / 30.0f);
  std::vector<boreas_branch> windy = world.tree_get_branches(id);
  double tip_move = 0.0;
  for (size_t i = 0; i < rest.size(); ++i) {
    D3 r{rest[i].control_points[3][0], rest[i].control_points[3][1], rest[i].control_points[3][2]};
    tip_move = std::max(tip_move, distance(r, windy[i].control_points[3]));
  }
  EXPECT_GT(tip_move, 0.05) << "a 15 m/s wind bends some branch tip by more than 5 cm";
}

TEST(TreeApi, SameInputsGiveBitIdenticalTrees) {
  auto run = [] {
    boreas::World world(tree_world_def());
    boreas_tree_def def = boreas_default_tree_def();
    def.seed = 42;
    def.response = BOREAS_TREE_DAMPED;
    boreas_tree_id id = world.add_tree(def);
    world.wind_set_waves({gusty_wave(12.0f)});
    for (int s = 0; s < 20; ++s) world.step(1.0f / 60.0f);
    return bytes_of(world.tree_get_branches(id));
  };
  EXPECT_EQ(run(), run());
}

TEST(TreeApi, AddingAndRemovingTreesKeepsTheOthersState) {
  boreas::World world(tree_world_def());
  world.wind_set_waves({gusty_wave(12.0f)});
  boreas_tree_def def = boreas_default_tree_def();
  def.response = BOREAS_TREE_DAMPED;
  boreas_tree_id a = world.add_tree(def);
  for (int s = 0; s < 5; ++s) world.step(1.0f / 60.0f);
  std::vector<unsigned char> before = bytes_of(world.tree_get_branches(a));

  def.position[0] = 8.0f;
  def.species = "black_tupelo";
  boreas_tree_id b = world.add_tree(def);
  EXPECT_EQ(bytes_of(world.tree_get_branches(a)), before) << "adding a tree moved another";
  world.remove_tree(b);
  EXPECT_EQ(bytes_of(world.tree_get_branches(a)), before) << "removing a tree moved another";

  int count = 0;
  EXPECT_EQ(boreas_tree_get_branches(world.handle(), b, nullptr, 0, &count), BOREAS_ERROR_NOT_FOUND);
  EXPECT_EQ(boreas_world_remove_tree(world.handle(), b), BOREAS_ERROR_NOT_FOUND);
  // The slot is reused with a new generation: the stale id still fails.
  boreas_tree_id c = world.add_tree(def);
  EXPECT_EQ(c.index, b.index);
  EXPECT_NE(c.generation, b.generation);
  EXPECT_EQ(boreas_tree_get_branches(world.handle(), b, nullptr, 0, &count), BOREAS_ERROR_NOT_FOUND);
  world.step(1.0f / 60.0f);
}

TEST(TreeApi, BothModesAndResponsesRunTogether) {
  boreas::World world(tree_world_def());
  world.wind_set_waves({gusty_wave(10.0f)});
  std::vector<boreas_tree_id> ids;
  for (int mode = 0; mode < 2; ++mode)
    for (int response = 0; response < 2; ++response) {
      boreas_tree_def def = boreas_default_tree_def();
      def.position[0] = -12.0f + 8.0f * (2 * mode + response);
      def.mode = static_cast<boreas_tree_mode>(mode);
      def.response = static_cast<boreas_tree_response>(response);
      ids.push_back(world.add_tree(def));
    }
  for (int s = 0; s < 5; ++s) world.step(1.0f / 30.0f);
  for (boreas_tree_id id : ids) {
    std::vector<boreas_branch> branches = world.tree_get_branches(id);
    for (const boreas_branch& b : branches)
      for (int k = 0; k < 4; ++k)
        for (int a = 0; a < 3; ++a) ASSERT_TRUE(std::isfinite(b.control_points[k][a]));
  }
}

TEST(TreeApi, LeavesHangOnTheLastLevel) {
  boreas::World world(tree_world_def());
  boreas_tree_id id = world.add_tree(boreas_default_tree_def());
  world.wind_set_waves({gusty_wave(10.0f)});
  world.step(1.0f / 30.0f);
  std::vector<boreas_branch> branches = world.tree_get_branches(id);
  std::vector<boreas_leaf> leaves = world.tree_get_leaves(id);
  ASSERT_FALSE(leaves.empty()) << "quaking aspen has leaves";
  int last_level = 0;
  for (const boreas_branch& b : branches) last_level = std::max(last_level, b.level);
  for (const boreas_leaf& leaf : leaves) {
    ASSERT_GE(leaf.branch, 0);
    ASSERT_LT(leaf.branch, static_cast<int>(branches.size()));
    EXPECT_EQ(branches[leaf.branch].level, last_level);
    double axis = std::sqrt(leaf.axis[0] * leaf.axis[0] + leaf.axis[1] * leaf.axis[1] + leaf.axis[2] * leaf.axis[2]);
    EXPECT_NEAR(axis, 1.0, 1e-4);
    EXPECT_GT(leaf.length, 0.0f);
    EXPECT_GT(leaf.width, 0.0f);
  }
}

TEST(TreeApi, MeshCountsFollowTheLevelsResolution) {
  boreas::World world(tree_world_def());
  boreas_tree_def def = boreas_default_tree_def();
  boreas_tree_id id = world.add_tree(def);
  std::vector<boreas_branch> branches = world.tree_get_branches(id);
  long expect_vertices = 0, expect_indices = 0;
  for (const boreas_branch& b : branches) {
    const boreas_tree_level_def& l = def.levels[b.level];
    expect_vertices += (l.rings + 1) * (l.sides + 1);
    expect_indices += 6 * l.rings * l.sides;
  }
  boreas::World::Mesh mesh = world.tree_get_mesh(id);
  EXPECT_EQ(static_cast<long>(mesh.vertices.size()), expect_vertices);
  EXPECT_EQ(static_cast<long>(mesh.indices.size()), expect_indices);
  for (uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertices.size());

  int vertex_count = 0, index_count = 0;
  std::vector<boreas_vertex> small(10);
  std::vector<uint32_t> small_indices(10);
  EXPECT_EQ(boreas_tree_get_mesh(world.handle(), id, small.data(), 10, &vertex_count, small_indices.data(), 10,
                                 &index_count),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("capacities"), std::string::npos) << boreas_last_error();
}

// Every bad definition is refused with a message naming the field, and the world is left
// as it was: same trees, and it still steps.
TEST(TreeApi, BadDefinitionsAreRefusedAndChangeNothing) {
  boreas::World world(tree_world_def());
  boreas_tree_id keep = world.add_tree(boreas_default_tree_def());
  std::vector<unsigned char> before = bytes_of(world.tree_get_branches(keep));

  struct Case {
    const char* what;
    void (*edit)(boreas_tree_def&);
    boreas_status status;
    const char* message_part;
  };
  const Case cases[] = {
      {"null species", [](boreas_tree_def& d) { d.species = nullptr; }, BOREAS_ERROR_INVALID_ARGUMENT, "species"},
      {"unknown species", [](boreas_tree_def& d) { d.species = "no_such_tree"; }, BOREAS_ERROR_INVALID_ARGUMENT,
       "no_such_tree"},
      {"missing file", [](boreas_tree_def& d) { d.species = "/nonexistent/tree.xml"; }, BOREAS_ERROR_IO,
       "/nonexistent/tree.xml"},
      {"NaN position", [](boreas_tree_def& d) { d.position[1] = NAN; }, BOREAS_ERROR_INVALID_ARGUMENT, "position[1]"},
      {"negative scale", [](boreas_tree_def& d) { d.scale = -1.0f; }, BOREAS_ERROR_INVALID_ARGUMENT, "scale"},
      {"bad mode", [](boreas_tree_def& d) { d.mode = static_cast<boreas_tree_mode>(7); },
       BOREAS_ERROR_INVALID_ARGUMENT, "mode"},
      {"bad response", [](boreas_tree_def& d) { d.response = static_cast<boreas_tree_response>(-1); },
       BOREAS_ERROR_INVALID_ARGUMENT, "response"},
      {"bad load", [](boreas_tree_def& d) { d.load = static_cast<boreas_tree_load>(2); },
       BOREAS_ERROR_INVALID_ARGUMENT, "tree_def.load"},
      {"zero stiffness", [](boreas_tree_def& d) { d.levels[2].stiffness = 0.0f; }, BOREAS_ERROR_INVALID_ARGUMENT,
       "levels[2].stiffness"},
      {"too few sides", [](boreas_tree_def& d) { d.levels[1].sides = 2; }, BOREAS_ERROR_INVALID_ARGUMENT,
       "levels[1].sides"},
      {"bend exponent", [](boreas_tree_def& d) { d.bend_exponent = INFINITY; }, BOREAS_ERROR_INVALID_ARGUMENT,
       "bend_exponent"},
  };
  for (const Case& c : cases) {
    boreas_tree_def def = boreas_default_tree_def();
    c.edit(def);
    boreas_tree_id id{7u, 7u, 7u};  // a sentinel: must stay as it is
    EXPECT_EQ(boreas_world_add_tree(world.handle(), &def, &id), c.status) << c.what;
    EXPECT_NE(std::string(boreas_last_error()).find(c.message_part), std::string::npos)
        << c.what << ": " << boreas_last_error();
    EXPECT_EQ(id.index, 7u) << c.what << ": out written on failure";
  }
  EXPECT_EQ(boreas_world_add_tree(world.handle(), nullptr, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  int count = 0;
  EXPECT_EQ(boreas_tree_get_branches(world.handle(), keep, nullptr, 0, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(boreas_tree_get_branches(world.handle(), boreas_tree_id{99u, 1u, keep.tag}, nullptr, 0,
                                     &count),
            BOREAS_ERROR_NOT_FOUND);

  EXPECT_EQ(bytes_of(world.tree_get_branches(keep)), before);
  world.step(1.0f / 60.0f);
}

TEST(TreeApi, MalformedSpeciesFileNamesFileLineAndParameter) {
  TempDir dir;
  std::string path = dir.str() + "/broken.xml";
  {
    std::ofstream f(path);
    f << "<?xml version='1.0' ?>\n<arbaro>\n  <species name='broken'>\n    <param name='Shape' value='3'/>\n"
         "    <param name='1DownAngle' value='sideways'/>\n  </species>\n</arbaro>\n";
  }
  boreas::World world(tree_world_def());
  boreas_tree_def def = boreas_default_tree_def();
  def.species = path.c_str();
  boreas_tree_id id{};
  EXPECT_EQ(boreas_world_add_tree(world.handle(), &def, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  std::string message = boreas_last_error();
  EXPECT_NE(message.find("broken.xml"), std::string::npos) << message;
  EXPECT_NE(message.find("5"), std::string::npos) << "line 5: " << message;
  EXPECT_NE(message.find("1DownAngle"), std::string::npos) << message;
}

}  // namespace
