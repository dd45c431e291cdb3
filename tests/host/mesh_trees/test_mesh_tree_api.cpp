// boreas tests: imported trees through the public C API — add from a file, read back,
// sway in wind, the cache beside the model, and clear errors for bad models and defs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "host/mesh_trees/tube_trees.h"
#include "support/small_world.h"
#include "support/test_support.h"

namespace boreas {
namespace {

class MeshTreeApi : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(test::create_small_windy_world(&world_, 12.0f), BOREAS_OK) << boreas_last_error();
  }
  void TearDown() override { boreas_world_destroy(world_); }
  boreas_world world_ = nullptr;
  test::TempDir dir_;
};

TEST_F(MeshTreeApi, AddsReadsAndSwaysAnObjTree) {
  std::string path = test::write_tube_tree_obj(dir_.path());
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = path.c_str();
  boreas_mesh_tree_id id{};
  ASSERT_EQ(boreas_world_add_mesh_tree(world_, &def, &id), BOREAS_OK) << boreas_last_error();
  boreas_mesh_tree_info info{};
  ASSERT_EQ(boreas_mesh_tree_get_info(world_, id, &info), BOREAS_OK);
  EXPECT_EQ(info.branches, 17);
  EXPECT_EQ(info.levels, 5);
  EXPECT_EQ(info.leaves, 6);
  EXPECT_EQ(info.orphans, 0);
  EXPECT_EQ(info.from_cache, 0);
  int count = 0;
  ASSERT_EQ(boreas_mesh_tree_get_indices(world_, id, BOREAS_MESH_TRUNK, nullptr, 0, &count),
            BOREAS_OK);
  EXPECT_EQ(count, 3 * info.trunk_triangles);
  std::vector<boreas_vertex> rest(size_t(info.trunk_vertices)), moved(rest.size());
  ASSERT_EQ(boreas_mesh_tree_get_vertices(world_, id, BOREAS_MESH_TRUNK, rest.data(),
                                          int(rest.size()), &count),
            BOREAS_OK);
  for (int s = 0; s < 10; ++s) ASSERT_EQ(boreas_world_step(world_, 0.05f), BOREAS_OK);
  ASSERT_EQ(boreas_mesh_tree_get_vertices(world_, id, BOREAS_MESH_TRUNK, moved.data(),
                                          int(moved.size()), &count),
            BOREAS_OK);
  double largest = 0.0;
  for (size_t v = 0; v < rest.size(); ++v)
    largest = std::max(largest, double(std::hypot(moved[v].position[0] - rest[v].position[0],
                                                  moved[v].position[1] - rest[v].position[1],
                                                  moved[v].position[2] - rest[v].position[2])));
  EXPECT_GT(largest, 0.05);  // 12 m/s of wind moves the crown
  // The preprocessing was kept beside the model: a second tree reads it.
  EXPECT_TRUE(std::filesystem::exists(path + ".boreas.glb"));
  boreas_mesh_tree_id again{};
  ASSERT_EQ(boreas_world_add_mesh_tree(world_, &def, &again), BOREAS_OK) << boreas_last_error();
  ASSERT_EQ(boreas_mesh_tree_get_info(world_, again, &info), BOREAS_OK);
  EXPECT_EQ(info.from_cache, 1);
  EXPECT_EQ(info.branches, 17);
  ASSERT_EQ(boreas_world_remove_mesh_tree(world_, id), BOREAS_OK);
  EXPECT_EQ(boreas_mesh_tree_get_info(world_, id, &info), BOREAS_ERROR_NOT_FOUND);
  ASSERT_EQ(boreas_world_step(world_, 0.05f), BOREAS_OK);  // the other one still steps
}

// What a renderer draws from (boreas_cl.h): the same numbers the readback gives, wherever
// in the buffer they go; a buffer too small or a bad part is refused and left untouched.
TEST_F(MeshTreeApi, EnqueuedVerticesAreTheReadBackVerticesAtAnyOffset) {
  std::string path = test::write_tube_tree_obj(dir_.path());
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = path.c_str();
  boreas_mesh_tree_id id{};
  ASSERT_EQ(boreas_world_add_mesh_tree(world_, &def, &id), BOREAS_OK) << boreas_last_error();
  for (int s = 0; s < 5; ++s) ASSERT_EQ(boreas_world_step(world_, 0.05f), BOREAS_OK);
  boreas_cl_objects cl{};
  ASSERT_EQ(boreas_world_get_cl(world_, &cl), BOREAS_OK);
  constexpr float kSentinel = -12345.0f;
  const struct {
    boreas_mesh_part part;
    size_t floats, first;
  } cases[] = {{BOREAS_MESH_TRUNK, BOREAS_MESH_TRUNK_VERTEX_FLOATS, 2},
               {BOREAS_MESH_LEAVES, BOREAS_MESH_LEAF_VERTEX_FLOATS, 1}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.part == BOREAS_MESH_TRUNK ? "trunk" : "leaves");
    int n = 0;
    ASSERT_EQ(boreas_mesh_tree_get_vertices(world_, id, c.part, nullptr, 0, &n), BOREAS_OK);
    ASSERT_GT(n, 0);
    std::vector<boreas_vertex> expected(size_t(n), boreas_vertex{});
    ASSERT_EQ(boreas_mesh_tree_get_vertices(world_, id, c.part, expected.data(), n, &n), BOREAS_OK);
    const size_t floats = (c.first + size_t(n)) * c.floats;
    std::vector<float> fill(floats, kSentinel), got(floats);
    cl_int err = CL_SUCCESS;
    cl_mem out = clCreateBuffer(cl.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR,
                                floats * sizeof(float), fill.data(), &err);
    ASSERT_EQ(err, CL_SUCCESS);
    cl_mem small = clCreateBuffer(cl.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR,
                                  (floats - 1) * sizeof(float), fill.data(), &err);
    ASSERT_EQ(err, CL_SUCCESS);
    EXPECT_EQ(boreas_mesh_tree_enqueue_vertices(world_, id, c.part, small, c.first),
              BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(boreas_last_error()).find("holds"), std::string::npos)
        << boreas_last_error();
    EXPECT_EQ(boreas_mesh_tree_enqueue_vertices(world_, id, boreas_mesh_part(7), out, c.first),
              BOREAS_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(boreas_mesh_tree_enqueue_vertices(world_, id, c.part, out, c.first), BOREAS_OK)
        << boreas_last_error();
    ASSERT_EQ(clEnqueueReadBuffer(cl.queue, out, CL_TRUE, 0, floats * sizeof(float), got.data(), 0,
                                  nullptr, nullptr),
              CL_SUCCESS);
    std::vector<float> untouched(floats - 1);
    ASSERT_EQ(clEnqueueReadBuffer(cl.queue, small, CL_TRUE, 0, untouched.size() * sizeof(float),
                                  untouched.data(), 0, nullptr, nullptr),
              CL_SUCCESS);
    for (float v : untouched) ASSERT_EQ(v, kSentinel) << "the refused buffer was written";
    for (size_t k = 0; k < c.first * c.floats; ++k)
      ASSERT_EQ(got[k], kSentinel) << "written before first_vertex";
    for (size_t v = 0; v < size_t(n); ++v) {
      const float* r = &got[(c.first + v) * c.floats];
      for (int a = 0; a < 3; ++a) ASSERT_EQ(r[a], expected[v].position[a]) << "vertex " << v;
      if (c.part == BOREAS_MESH_LEAVES)
        for (int a = 0; a < 3; ++a) ASSERT_EQ(r[3 + a], expected[v].normal[a]) << "vertex " << v;
    }
    clReleaseMemObject(small);
    clReleaseMemObject(out);
  }
}

// Several imported trees in one call (boreas_world_enqueue_mesh_tree_vertices): each where
// the list puts it, in any order and with gaps, the vertices its getter gives; a bad list
// is refused naming the entry, and writes nothing.
TEST_F(MeshTreeApi, TreeListInOneCallIsEachTreesVertices) {
  std::string path = test::write_tube_tree_obj(dir_.path());
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = path.c_str();
  boreas_mesh_tree_id ids[3]{};
  for (int t = 0; t < 3; ++t) {
    def.position[0] = 3.0f * float(t) - 3.0f;
    def.position[2] = float(t);
    ASSERT_EQ(boreas_world_add_mesh_tree(world_, &def, &ids[t]), BOREAS_OK) << boreas_last_error();
  }
  for (int s = 0; s < 5; ++s) ASSERT_EQ(boreas_world_step(world_, 0.05f), BOREAS_OK);
  boreas_cl_objects cl{};
  ASSERT_EQ(boreas_world_get_cl(world_, &cl), BOREAS_OK);
  constexpr float kSentinel = -12345.0f;
  for (boreas_mesh_part part : {BOREAS_MESH_TRUNK, BOREAS_MESH_LEAVES}) {
    SCOPED_TRACE(part == BOREAS_MESH_TRUNK ? "trunk" : "leaves");
    const size_t floats = part == BOREAS_MESH_TRUNK ? BOREAS_MESH_TRUNK_VERTEX_FLOATS : BOREAS_MESH_LEAF_VERTEX_FLOATS;
    int n = 0;
    ASSERT_EQ(boreas_mesh_tree_get_vertices(world_, ids[0], part, nullptr, 0, &n), BOREAS_OK);
    const size_t v = size_t(n);
    // Trees 2, 0, 1 at vertices 0, v + 3 and 2 v + 7: gaps of 3 and 4 vertices.
    const boreas_mesh_tree_id order[3] = {ids[2], ids[0], ids[1]};
    const size_t firsts[3] = {0, v + 3, 2 * v + 7}, total = (3 * v + 7) * floats;
    std::vector<float> fill(total, kSentinel), got(total);
    cl_int err = CL_SUCCESS;
    cl_mem out = clCreateBuffer(cl.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, total * sizeof(float),
                                fill.data(), &err);
    ASSERT_EQ(err, CL_SUCCESS);
    const size_t overlapping[3] = {0, v + 3, v + 4};
    EXPECT_EQ(boreas_world_enqueue_mesh_tree_vertices(world_, order, overlapping, 3, part, out),
              BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(boreas_last_error()).find("trees[1] (records"), std::string::npos) << boreas_last_error();
    EXPECT_NE(std::string(boreas_last_error()).find("overlap"), std::string::npos) << boreas_last_error();
    const size_t past[1] = {2 * v + 8};
    EXPECT_EQ(boreas_world_enqueue_mesh_tree_vertices(world_, order, past, 1, part, out),
              BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(boreas_last_error()).find("trees[0]: mesh"), std::string::npos) << boreas_last_error();
    ASSERT_EQ(clEnqueueReadBuffer(cl.queue, out, CL_TRUE, 0, total * sizeof(float), got.data(), 0, nullptr, nullptr),
              CL_SUCCESS);
    for (float f : got) ASSERT_EQ(f, kSentinel) << "a refused call wrote";
    ASSERT_EQ(boreas_world_enqueue_mesh_tree_vertices(world_, order, firsts, 3, part, out), BOREAS_OK)
        << boreas_last_error();
    ASSERT_EQ(clEnqueueReadBuffer(cl.queue, out, CL_TRUE, 0, total * sizeof(float), got.data(), 0, nullptr, nullptr),
              CL_SUCCESS);
    std::vector<bool> written(3 * v + 7, false);
    for (int k = 0; k < 3; ++k) {
      std::vector<boreas_vertex> expected(v);
      ASSERT_EQ(boreas_mesh_tree_get_vertices(world_, order[k], part, expected.data(), n, &n), BOREAS_OK);
      for (size_t j = 0; j < v; ++j) {
        const float* r = &got[(firsts[k] + j) * floats];
        written[firsts[k] + j] = true;
        for (int a = 0; a < 3; ++a) ASSERT_EQ(r[a], expected[j].position[a]) << "tree " << k << " vertex " << j;
        if (part == BOREAS_MESH_LEAVES)
          for (int a = 0; a < 3; ++a) ASSERT_EQ(r[3 + a], expected[j].normal[a]) << "tree " << k << " vertex " << j;
      }
    }
    for (size_t j = 0; j < written.size(); ++j)
      if (!written[j])
        for (size_t f = 0; f < floats; ++f) ASSERT_EQ(got[j * floats + f], kSentinel) << "gap vertex " << j;
    clReleaseMemObject(out);
  }
  ASSERT_EQ(boreas_world_remove_mesh_tree(world_, ids[1]), BOREAS_OK);
  const size_t firsts[2] = {0, 1000};
  EXPECT_EQ(boreas_world_enqueue_mesh_tree_vertices(world_, ids, firsts, 2, BOREAS_MESH_TRUNK, nullptr),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("out"), std::string::npos) << boreas_last_error();
  EXPECT_EQ(boreas_world_enqueue_mesh_tree_vertices(world_, ids, firsts, -2, BOREAS_MESH_TRUNK, nullptr),
            BOREAS_ERROR_INVALID_ARGUMENT);
}

TEST_F(MeshTreeApi, PreprocessWritesAGlbThatLoadsDirectly) {
  std::string path = test::write_tube_tree_obj(dir_.path());
  std::string out = (dir_.path() / "tubes.glb").string();
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = path.c_str();
  boreas_mesh_tree_info info{};
  ASSERT_EQ(boreas_preprocess_mesh_tree(&def, out.c_str(), &info), BOREAS_OK)
      << boreas_last_error();
  EXPECT_EQ(info.branches, 17);
  def.model = out.c_str();
  def.cache = 0;
  boreas_mesh_tree_id id{};
  ASSERT_EQ(boreas_world_add_mesh_tree(world_, &def, &id), BOREAS_OK) << boreas_last_error();
  ASSERT_EQ(boreas_mesh_tree_get_info(world_, id, &info), BOREAS_OK);
  EXPECT_EQ(info.from_cache, 1);
  EXPECT_EQ(info.leaves, 6);
}

TEST_F(MeshTreeApi, BadModelsAndDefsAreClearErrors) {
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  boreas_mesh_tree_id id{};
  EXPECT_EQ(boreas_world_add_mesh_tree(world_, &def, &id),
            BOREAS_ERROR_INVALID_ARGUMENT);  // no model
  std::string missing = (dir_.path() / "none.obj").string();
  def.model = missing.c_str();
  EXPECT_EQ(boreas_world_add_mesh_tree(world_, &def, &id), BOREAS_ERROR_IO);
  EXPECT_NE(std::string(boreas_last_error()).find("none.obj"), std::string::npos)
      << boreas_last_error();
  std::string empty = (dir_.path() / "empty.obj").string();
  std::ofstream(empty) << "# nothing\n";
  def.model = empty.c_str();
  EXPECT_EQ(boreas_world_add_mesh_tree(world_, &def, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("empty.obj"), std::string::npos)
      << boreas_last_error();
  std::string path = test::write_tube_tree_obj(dir_.path());
  def.model = path.c_str();
  def.position[1] = NAN;
  EXPECT_EQ(boreas_world_add_mesh_tree(world_, &def, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("position[1]"), std::string::npos)
      << boreas_last_error();
  def.position[1] = 0.0f;
  def.levels[2].frequency = -1.0f;
  EXPECT_EQ(boreas_world_add_mesh_tree(world_, &def, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("levels[2].frequency"), std::string::npos)
      << boreas_last_error();
  EXPECT_EQ(boreas_mesh_tree_get_vertices(world_, id, BOREAS_MESH_TRUNK, nullptr, 0, nullptr),
            BOREAS_ERROR_INVALID_ARGUMENT);
  // Nothing was added by the failures: the world steps with no imported tree.
  EXPECT_EQ(boreas_world_step(world_, 0.05f), BOREAS_OK);
}

}  // namespace
}  // namespace boreas
