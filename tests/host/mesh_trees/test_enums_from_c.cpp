// boreas tests: a C caller may pass any int where the API takes an enum. Each such value is
// refused with INVALID_ARGUMENT naming it, and the world keeps what it had; the calls are
// made from C (enums_from_c.c) and the library reads the bits as an int before checking
// them, so a UBSan build stays quiet too.
#include <gtest/gtest.h>

#include <climits>
#include <string>

#include "host/enums_from_c.h"
#include "host/mesh_trees/tube_trees.h"
#include "support/small_world.h"
#include "support/temp_dir.h"

namespace {

constexpr int kBadValues[] = {7, -1, INT_MIN, INT_MAX};

void expect_refused_naming(boreas_status status, int value, const char* field) {
  EXPECT_EQ(status, BOREAS_ERROR_INVALID_ARGUMENT);
  const std::string message = boreas_last_error();
  EXPECT_NE(message.find(field), std::string::npos) << message;
  EXPECT_NE(message.find(std::to_string(value)), std::string::npos) << message;
}

class EnumsFromC : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(boreas::test::create_small_windy_world(&world_, 8.0f), BOREAS_OK)
        << boreas_last_error();
  }
  void TearDown() override { boreas_world_destroy(world_); }
  boreas_world world_ = nullptr;
  boreas::test::TempDir dir_;
};

TEST_F(EnumsFromC, StatusNamesOfAnyIntAreUnknown) {
  EXPECT_STREQ(c_status_name(BOREAS_OK), "BOREAS_OK");
  // Statuses are 0..8 (7 is BOREAS_ERROR_IO).
  for (int value : {9, -1, INT_MIN, INT_MAX})
    EXPECT_STREQ(c_status_name(value), "BOREAS_ERROR_UNKNOWN");
}

TEST_F(EnumsFromC, TreeDefEnumsOutOfRangeAreRefused) {
  boreas_tree_id id{};
  for (int value : kBadValues) {
    SCOPED_TRACE(value);
    expect_refused_naming(
        c_add_tree_with(world_, value, BOREAS_TREE_QUASI_STATIC, BOREAS_TREE_LOAD_DRAG, &id), value,
        "tree_def.mode");
    expect_refused_naming(
        c_add_tree_with(world_, BOREAS_TREE_LAGGED, value, BOREAS_TREE_LOAD_DRAG, &id), value,
        "tree_def.response");
    expect_refused_naming(
        c_add_tree_with(world_, BOREAS_TREE_LAGGED, BOREAS_TREE_QUASI_STATIC, value, &id), value,
        "tree_def.load");
  }
  boreas_step_stats stats{};
  ASSERT_EQ(boreas_world_step(world_, 1.0f / 60.0f), BOREAS_OK);
  ASSERT_EQ(boreas_world_get_step_stats(world_, &stats), BOREAS_OK);
  EXPECT_EQ(stats.branches_stepped, 0) << "no refused tree was added";
  ASSERT_EQ(
      c_add_tree_with(world_, BOREAS_TREE_EXACT, BOREAS_TREE_DAMPED, BOREAS_TREE_LOAD_LINEAR, &id),
      BOREAS_OK)
      << boreas_last_error();
}

TEST_F(EnumsFromC, FlowTypeOutOfRangeIsRefused) {
  boreas_primitive_id id{};
  for (int value : kBadValues) {
    SCOPED_TRACE(value);
    expect_refused_naming(c_add_primitive_of_type(world_, value, &id), value, ".type");
  }
  EXPECT_EQ(c_add_primitive_of_type(world_, BOREAS_FLOW_UNIFORM, &id), BOREAS_OK)
      << boreas_last_error();
}

TEST_F(EnumsFromC, MeshPartOutOfRangeIsRefused) {
  const std::string path = boreas::test::write_tube_tree_obj(dir_.path());
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = path.c_str();
  boreas_mesh_tree_id tree{};
  ASSERT_EQ(boreas_world_add_mesh_tree(world_, &def, &tree), BOREAS_OK) << boreas_last_error();
  int count = -1;
  for (int value : kBadValues) {
    SCOPED_TRACE(value);
    expect_refused_naming(c_mesh_tree_indices(world_, tree, value, &count), value, "part");
  }
  ASSERT_EQ(c_mesh_tree_indices(world_, tree, BOREAS_MESH_TRUNK, &count), BOREAS_OK)
      << boreas_last_error();
  EXPECT_GT(count, 0);
}

}  // namespace
