// Library tests: ids that carry their kind, where zero means none. Each check is made the
// way a C caller gets it wrong: a zero-initialized id, an id of one kind cast to another,
// an id of another world, an id kept after its object was removed. Every one must be
// BOREAS_ERROR_NOT_FOUND with a message naming the kind and the fault, and leave the world
// exactly as it was (its state hash unchanged).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <unordered_set>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"
#include "support/small_world.h"

namespace {

// Reinterprets an id's bytes as another kind's, as a C cast through a pointer would.
template <typename To, typename From>
To cast_id(From id) {
  static_assert(sizeof(To) == sizeof(From), "ids share one layout");
  To out;
  std::memcpy(&out, &id, sizeof out);
  return out;
}

uint64_t hash_of(boreas_world world) {
  uint64_t hash = 0;
  EXPECT_EQ(boreas_world_get_state_hash(world, &hash), BOREAS_OK) << boreas_last_error();
  return hash;
}

void expect_not_found(boreas_status status, const std::string& message_part) {
  EXPECT_EQ(status, BOREAS_ERROR_NOT_FOUND) << boreas_last_error();
  EXPECT_NE(std::string(boreas_last_error()).find(message_part), std::string::npos)
      << "wanted '" << message_part << "' in: " << boreas_last_error();
}

class TypedIds : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(boreas::test::create_small_windy_world(&world_), BOREAS_OK) << boreas_last_error();
    boreas_tree_def tree = boreas_default_tree_def();
    ASSERT_EQ(boreas_world_add_tree(world_, &tree, &tree_), BOREAS_OK) << boreas_last_error();
    boreas_meadow_def meadow = boreas_default_meadow_def();
    meadow.size[0] = meadow.size[1] = 2.0f;
    meadow.density = 100.0f;
    ASSERT_EQ(boreas_world_add_meadow(world_, &meadow, &meadow_), BOREAS_OK) << boreas_last_error();
    boreas_collider_def ball = boreas_default_collider_def();
    ASSERT_EQ(boreas_world_add_collider(world_, &ball, &collider_), BOREAS_OK)
        << boreas_last_error();
    ASSERT_EQ(boreas_world_step(world_, 0.05f), BOREAS_OK) << boreas_last_error();
  }
  void TearDown() override { boreas_world_destroy(world_); }

  boreas_world world_ = nullptr;
  boreas_tree_id tree_ = BOREAS_NULL_ID;
  boreas_meadow_id meadow_ = BOREAS_NULL_ID;
  boreas_collider_id collider_ = BOREAS_NULL_ID;
};

TEST_F(TypedIds, TheFirstObjectOfEveryKindHasAnIdThatIsNotNull) {
  // The issue this fixes: a tree, a meadow and a collider added to a new world all had the
  // id {0, 0}, the same as a zero-initialized struct.
  EXPECT_FALSE(boreas_tree_id_is_null(tree_));
  EXPECT_FALSE(boreas_meadow_id_is_null(meadow_));
  EXPECT_FALSE(boreas_collider_id_is_null(collider_));
  EXPECT_GE(tree_.generation, 1u);
  EXPECT_GE(meadow_.generation, 1u);
  boreas_tree_id none = BOREAS_NULL_ID;
  EXPECT_TRUE(boreas_tree_id_is_null(none));
  boreas_meadow_id zeroed;
  std::memset(&zeroed, 0, sizeof zeroed);
  EXPECT_TRUE(boreas_meadow_id_is_null(zeroed));
  EXPECT_TRUE(boreas_tree_id_equal(tree_, tree_));
  EXPECT_FALSE(boreas_tree_id_equal(tree_, none));
}

TEST_F(TypedIds, AZeroInitializedIdOfEveryKindIsRefusedAsNull) {
  const uint64_t before = hash_of(world_);
  expect_not_found(boreas_world_remove_tree(world_, boreas_tree_id{}), "null tree id");
  expect_not_found(boreas_world_remove_meadow(world_, boreas_meadow_id{}), "null meadow id");
  expect_not_found(boreas_world_remove_collider(world_, boreas_collider_id{}), "null collider id");
  expect_not_found(boreas_world_remove_emitter(world_, boreas_emitter_id{}), "null emitter id");
  expect_not_found(boreas_world_remove_mesh_tree(world_, boreas_mesh_tree_id{}),
                   "null mesh tree id");
  expect_not_found(boreas_world_remove_blobtree(world_, boreas_blobtree_id{}), "null blobtree id");
  expect_not_found(boreas_wind_remove_primitive(world_, boreas_primitive_id{}),
                   "null flow primitive id");
  expect_not_found(boreas_wind_remove_gust(world_, boreas_gust_id{}), "null gust id");
  const float at[3] = {0.0f, 0.1f, 0.0f};
  expect_not_found(boreas_collider_set_position(world_, boreas_collider_id{}, at), "null collider");
  int count = 0;
  expect_not_found(boreas_tree_get_branches(world_, boreas_tree_id{}, nullptr, 0, &count),
                   "null tree");
  expect_not_found(boreas_meadow_get_components(world_, boreas_meadow_id{}, nullptr, 0, &count),
                   "null meadow");
  EXPECT_EQ(hash_of(world_), before) << "a refused id changed the world";
  // Everything is still there, under its own id.
  EXPECT_EQ(boreas_tree_get_branches(world_, tree_, nullptr, 0, &count), BOREAS_OK);
  EXPECT_GT(count, 0);
}

TEST_F(TypedIds, AnIdCastToAnotherKindIsRefusedNamingBothKinds) {
  // The case: boreas_world_remove_meadow(world, tree_id) returned BOREAS_OK and
  // removed the meadow. With typed ids it does not compile; a cast still gets here.
  const uint64_t before = hash_of(world_);
  expect_not_found(boreas_world_remove_meadow(world_, cast_id<boreas_meadow_id>(tree_)),
                   "not a meadow id but a tree id");
  expect_not_found(boreas_world_remove_collider(world_, cast_id<boreas_collider_id>(meadow_)),
                   "not a collider id but a meadow id");
  expect_not_found(boreas_world_remove_tree(world_, cast_id<boreas_tree_id>(collider_)),
                   "not a tree id but a collider id");
  EXPECT_EQ(hash_of(world_), before);
  int count = 0;
  EXPECT_EQ(boreas_meadow_get_components(world_, meadow_, nullptr, 0, &count), BOREAS_OK)
      << "the meadow is still there";
  EXPECT_GT(count, 0);
  boreas_tree_id garbled = tree_;
  garbled.tag = (garbled.tag & ~15u) | 15u;  // a kind no id has
  expect_not_found(boreas_world_remove_tree(world_, garbled), "kind is unknown");
}

TEST_F(TypedIds, AnIdOfAnotherWorldIsRefused) {
  boreas_world other = nullptr;
  ASSERT_EQ(boreas::test::create_small_windy_world(&other), BOREAS_OK) << boreas_last_error();
  boreas_tree_def tree = boreas_default_tree_def();
  boreas_tree_id theirs = BOREAS_NULL_ID;
  ASSERT_EQ(boreas_world_add_tree(other, &tree, &theirs), BOREAS_OK) << boreas_last_error();
  // Same slot and generation (both worlds' first tree), different world.
  EXPECT_EQ(theirs.index, tree_.index);
  EXPECT_EQ(theirs.generation, tree_.generation);
  const uint64_t before = hash_of(world_);
  expect_not_found(boreas_world_remove_tree(world_, theirs), "another world");
  EXPECT_EQ(hash_of(world_), before);
  EXPECT_EQ(boreas_world_remove_tree(other, theirs), BOREAS_OK) << boreas_last_error();
  boreas_world_destroy(other);
}

TEST_F(TypedIds, ARemovedIdStaysDeadWhenItsSlotIsReused) {
  ASSERT_EQ(boreas_world_remove_collider(world_, collider_), BOREAS_OK);
  expect_not_found(boreas_world_remove_collider(world_, collider_), "no collider with id");
  boreas_collider_def ball = boreas_default_collider_def();
  boreas_collider_id reused = BOREAS_NULL_ID;
  ASSERT_EQ(boreas_world_add_collider(world_, &ball, &reused), BOREAS_OK);
  EXPECT_EQ(reused.index, collider_.index) << "the freed slot is taken again";
  EXPECT_NE(reused.generation, collider_.generation);
  expect_not_found(boreas_world_remove_collider(world_, collider_), "removed, or never added");
  EXPECT_EQ(boreas_world_remove_collider(world_, reused), BOREAS_OK);
}

TEST_F(TypedIds, PrimitivesAndGustsHaveIdsOfTheirOwn) {
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  boreas_primitive_id primitive = BOREAS_NULL_ID;
  ASSERT_EQ(boreas_wind_add_primitive(world_, &p, &primitive), BOREAS_OK) << boreas_last_error();
  boreas_gust_def g = boreas_default_gust_def();
  boreas_gust_id gust = BOREAS_NULL_ID;
  ASSERT_EQ(boreas_wind_add_gust(world_, &g, &gust), BOREAS_OK) << boreas_last_error();
  expect_not_found(boreas_wind_remove_gust(world_, cast_id<boreas_gust_id>(primitive)),
                   "not a gust id but a flow primitive id");
  EXPECT_EQ(boreas_wind_remove_gust(world_, gust), BOREAS_OK) << boreas_last_error();
  expect_not_found(boreas_wind_remove_gust(world_, gust), "removed, expired, or never added");
  EXPECT_EQ(boreas_wind_remove_primitive(world_, primitive), BOREAS_OK) << boreas_last_error();
}

TEST(TypedIdsCpp, IdsCompareAndHashAsValues) {
  boreas::World world([] {
    boreas_world_def def = boreas_default_world_def();
    def.grid.resolution[0] = def.grid.resolution[2] = 8;
    def.grid.resolution[1] = 4;
    return def;
  }());
  boreas_collider_def ball = boreas_default_collider_def();
  boreas::ColliderId a = world.add_collider(ball);
  boreas::ColliderId b = world.add_collider(ball);
  EXPECT_TRUE(a == a);
  EXPECT_TRUE(a != b);
  std::unordered_set<boreas::ColliderId> set{a, b, a};
  EXPECT_EQ(set.size(), 2u);
  world.remove_collider(a);
  try {
    world.remove_collider(a);
    FAIL() << "a removed id was accepted";
  } catch (const boreas::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_NOT_FOUND);
    EXPECT_NE(std::string(e.what()).find("collider"), std::string::npos) << e.what();
  }
}

}  // namespace
