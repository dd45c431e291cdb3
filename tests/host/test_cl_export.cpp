// boreas tests: the OpenCL side of a world (boreas_cl.h). The device records a renderer
// draws from are the same numbers the host readbacks give, wherever in the buffer they go;
// buffers that cannot hold them are refused before anything is written.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "support/small_world.h"

namespace boreas {
namespace {

class ClExport : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(test::create_small_windy_world(&world_), BOREAS_OK) << boreas_last_error();
    boreas_tree_def tree = boreas_default_tree_def();
    ASSERT_EQ(boreas_world_add_tree(world_, &tree, &tree_), BOREAS_OK) << boreas_last_error();
    boreas_meadow_def meadow = boreas_default_meadow_def();
    meadow.size[0] = meadow.size[1] = 3.0f;
    ASSERT_EQ(boreas_world_add_meadow(world_, &meadow, &meadow_), BOREAS_OK) << boreas_last_error();
    for (int s = 0; s < 5; ++s) ASSERT_EQ(boreas_world_step(world_, 1.0f / 30.0f), BOREAS_OK);
    ASSERT_EQ(boreas_world_get_cl(world_, &cl_), BOREAS_OK);
  }
  void TearDown() override { boreas_world_destroy(world_); }

  // A device buffer of `floats` floats, filled with a sentinel.
  cl_mem buffer(size_t floats) {
    cl_int err = CL_SUCCESS;
    cl_mem m = clCreateBuffer(cl_.context, CL_MEM_READ_WRITE, floats * sizeof(float), nullptr, &err);
    EXPECT_EQ(err, CL_SUCCESS);
    std::vector<float> fill(floats, kSentinel);
    EXPECT_EQ(clEnqueueWriteBuffer(cl_.queue, m, CL_TRUE, 0, floats * sizeof(float), fill.data(), 0, nullptr, nullptr),
              CL_SUCCESS);
    buffers_.push_back(m);
    return m;
  }
  std::vector<float> read(cl_mem m, size_t floats) {
    std::vector<float> out(floats);
    EXPECT_EQ(clFinish(cl_.queue), CL_SUCCESS);
    EXPECT_EQ(clEnqueueReadBuffer(cl_.queue, m, CL_TRUE, 0, floats * sizeof(float), out.data(), 0, nullptr, nullptr),
              CL_SUCCESS);
    return out;
  }

  static constexpr float kSentinel = -12345.0f;
  boreas_world world_ = nullptr;
  boreas_tree_id tree_{};
  boreas_meadow_id meadow_{};
  boreas_cl_objects cl_{};
  std::vector<cl_mem> buffers_;

 public:
  ~ClExport() override {
    for (cl_mem m : buffers_) clReleaseMemObject(m);
  }
};

TEST_F(ClExport, BranchRecordsAreTheReadBackBranches) {
  int n = 0;
  ASSERT_EQ(boreas_tree_get_branches(world_, tree_, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_branch> branches(static_cast<size_t>(n));
  ASSERT_EQ(boreas_tree_get_branches(world_, tree_, branches.data(), n, &n), BOREAS_OK);
  const size_t first = 3, R = BOREAS_BRANCH_RECORD_FLOATS;
  cl_mem out = buffer((first + size_t(n)) * R);
  ASSERT_EQ(boreas_tree_enqueue_branch_records(world_, tree_, out, first), BOREAS_OK) << boreas_last_error();
  std::vector<float> got = read(out, (first + size_t(n)) * R);
  for (size_t k = 0; k < first * R; ++k) ASSERT_EQ(got[k], kSentinel) << "record before first_record touched";
  bool moved = false;
  for (int b = 0; b < n; ++b) {
    const float* r = &got[(first + size_t(b)) * R];
    const boreas_branch& br = branches[size_t(b)];
    for (int p = 0; p < 4; ++p)
      for (int a = 0; a < 3; ++a) ASSERT_EQ(r[3 * p + a], br.control_points[p][a]) << "branch " << b;
    for (int a = 0; a < 3; ++a) ASSERT_EQ(r[12 + a], br.orientation[a]) << "branch " << b;
    // The radius function starts with the base radius; the rest are its shape factors.
    EXPECT_FLOAT_EQ(r[15], br.radius) << "branch " << b;
    moved = moved || r[9] != 0.0f;
  }
  EXPECT_TRUE(moved);
}

TEST_F(ClExport, LeafRecordsAreTheReadBackLeaves) {
  int n = 0;
  ASSERT_EQ(boreas_tree_get_leaves(world_, tree_, nullptr, 0, &n), BOREAS_OK);
  ASSERT_GT(n, 0);
  std::vector<boreas_leaf> leaves(static_cast<size_t>(n));
  ASSERT_EQ(boreas_tree_get_leaves(world_, tree_, leaves.data(), n, &n), BOREAS_OK);
  const size_t R = BOREAS_LEAF_RECORD_FLOATS;
  cl_mem out = buffer(size_t(n) * R);
  ASSERT_EQ(boreas_tree_enqueue_leaf_records(world_, tree_, out, 0), BOREAS_OK) << boreas_last_error();
  std::vector<float> got = read(out, size_t(n) * R);
  for (int j = 0; j < n; ++j) {
    const float* r = &got[size_t(j) * R];
    for (int a = 0; a < 3; ++a) {
      ASSERT_EQ(r[a], leaves[size_t(j)].position[a]) << "leaf " << j;
      ASSERT_EQ(r[3 + a], leaves[size_t(j)].axis[a]) << "leaf " << j;
      ASSERT_EQ(r[6 + a], leaves[size_t(j)].normal[a]) << "leaf " << j;
    }
  }
}

TEST_F(ClExport, MeadowVerticesAreTheReadBackStripsAtAnyOffset) {
  const float camera[3] = {2.0f, 1.7f, 2.0f};
  int vertex_count = 0;
  ASSERT_EQ(boreas_meadow_get_vertices(world_, meadow_, camera, nullptr, 0, &vertex_count, nullptr), BOREAS_OK);
  const size_t components = size_t(vertex_count) / BOREAS_MEADOW_VERTEX_STRIDE;
  ASSERT_GT(components, 0u);
  std::vector<boreas_meadow_vertex> want(static_cast<size_t>(vertex_count));
  std::vector<int32_t> want_counts(components);
  ASSERT_EQ(boreas_meadow_get_vertices(world_, meadow_, camera, want.data(), vertex_count, &vertex_count,
                                       want_counts.data()),
            BOREAS_OK)
      << boreas_last_error();
  const size_t first = 7, V = BOREAS_MEADOW_VERTEX_STRIDE * 8;
  cl_mem vertices = buffer((first + components) * V);
  cl_mem counts = buffer(first + components);
  ASSERT_EQ(boreas_meadow_enqueue_vertices(world_, meadow_, camera, vertices, counts, first), BOREAS_OK)
      << boreas_last_error();
  std::vector<float> got = read(vertices, (first + components) * V);
  std::vector<float> got_counts = read(counts, first + components);
  EXPECT_EQ(std::memcmp(&got[first * V], want.data(), components * V * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(&got_counts[first], want_counts.data(), components * sizeof(int32_t)), 0);
  for (size_t k = 0; k < first * V; ++k) ASSERT_EQ(got[k], kSentinel);
}

// Several meadows in one call land where the list says, in any order and with gaps, each
// the strips its getter gives; the slots between them stay untouched.
TEST_F(ClExport, MeadowListInOneCallIsEachMeadowsStrips) {
  boreas_meadow_def second = boreas_default_meadow_def();
  second.size[0] = 2.0f;
  second.size[1] = 1.0f;
  second.center[0] = 6.0f;
  boreas_meadow_id other{};
  ASSERT_EQ(boreas_world_add_meadow(world_, &second, &other), BOREAS_OK) << boreas_last_error();
  ASSERT_EQ(boreas_world_step(world_, 1.0f / 30.0f), BOREAS_OK);
  const float camera[3] = {2.0f, 1.7f, 2.0f};
  const boreas_meadow_id ids[2] = {other, meadow_};
  std::vector<float> want[2];
  std::vector<int32_t> want_counts[2];
  for (int k = 0; k < 2; ++k) {
    int n = 0;
    ASSERT_EQ(boreas_meadow_get_vertices(world_, ids[k], camera, nullptr, 0, &n, nullptr), BOREAS_OK);
    want[k].resize(size_t(n) * 8);
    want_counts[k].resize(size_t(n) / BOREAS_MEADOW_VERTEX_STRIDE);
    ASSERT_EQ(boreas_meadow_get_vertices(world_, ids[k], camera,
                                         reinterpret_cast<boreas_meadow_vertex*>(want[k].data()), n, &n,
                                         want_counts[k].data()),
              BOREAS_OK);
    ASSERT_GT(want_counts[k].size(), 0u);
  }
  // The second meadow first in the buffer, the first after a gap of 5 slots.
  const size_t c0 = want_counts[0].size(), c1 = want_counts[1].size();
  const size_t firsts[2] = {0, c0 + 5}, slots = c0 + 5 + c1;
  const size_t V = BOREAS_MEADOW_VERTEX_STRIDE * 8;
  cl_mem vertices = buffer(slots * V);
  cl_mem counts = buffer(slots);
  ASSERT_EQ(boreas_world_enqueue_meadow_vertices(world_, ids, firsts, 2, camera, vertices, counts), BOREAS_OK)
      << boreas_last_error();
  std::vector<float> got = read(vertices, slots * V);
  std::vector<float> got_counts = read(counts, slots);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(std::memcmp(&got[firsts[k] * V], want[k].data(), want[k].size() * sizeof(float)), 0) << k;
    EXPECT_EQ(std::memcmp(&got_counts[firsts[k]], want_counts[k].data(), want_counts[k].size() * sizeof(int32_t)),
              0)
        << k;
  }
  for (size_t slot = c0; slot < c0 + 5; ++slot) {
    ASSERT_EQ(got_counts[slot], kSentinel) << "gap slot " << slot;
    for (size_t f = 0; f < V; ++f) ASSERT_EQ(got[slot * V + f], kSentinel) << "gap slot " << slot;
  }
}

// A bad list is refused naming the entry, and nothing is written.
TEST_F(ClExport, BadMeadowListsAreRefusedNamingTheEntry) {
  int n = 0;
  ASSERT_EQ(boreas_meadow_get_vertices(world_, meadow_, nullptr, nullptr, 0, &n, nullptr), BOREAS_OK);
  const size_t c = size_t(n) / BOREAS_MEADOW_VERTEX_STRIDE, V = BOREAS_MEADOW_VERTEX_STRIDE * 8;
  cl_mem vertices = buffer(3 * c * V);
  cl_mem counts = buffer(3 * c);
  const auto refused = [&](const boreas_meadow_id* ids, const size_t* firsts, int count, boreas_status want,
                           const char* says) {
    EXPECT_EQ(boreas_world_enqueue_meadow_vertices(world_, ids, firsts, count, nullptr, vertices, counts), want);
    EXPECT_NE(std::string(boreas_last_error()).find(says), std::string::npos) << boreas_last_error();
  };
  const boreas_meadow_id ids[3] = {meadow_, meadow_, meadow_};
  const size_t firsts[3] = {0, c, 2 * c};
  refused(ids, firsts, -1, BOREAS_ERROR_INVALID_ARGUMENT, "count must be >= 0");
  refused(nullptr, firsts, 1, BOREAS_ERROR_INVALID_ARGUMENT, "meadows is NULL");
  refused(ids, nullptr, 1, BOREAS_ERROR_INVALID_ARGUMENT, "first_components is NULL");
  const boreas_meadow_id with_null[3] = {meadow_, boreas_meadow_id{}, meadow_};
  refused(with_null, firsts, 3, BOREAS_ERROR_NOT_FOUND, "meadows[1]: the null meadow id");
  const size_t past[2] = {0, 2 * c + 1};
  refused(ids, past, 2, BOREAS_ERROR_INVALID_ARGUMENT, "meadows[1]: meadow vertex buffer holds");
  const size_t overlapping[3] = {0, 2 * c, c + 1};
  refused(ids, overlapping, 3, BOREAS_ERROR_INVALID_ARGUMENT,
          ("meadows[1] (records " + std::to_string(2 * c) + ".." + std::to_string(3 * c) + ") and meadows[2] (records " +
           std::to_string(c + 1) + ".." + std::to_string(2 * c + 1) + ") overlap")
              .c_str());
  for (float f : read(vertices, 3 * c * V)) ASSERT_EQ(f, kSentinel) << "a refused call wrote";
  for (float f : read(counts, 3 * c)) ASSERT_EQ(f, kSentinel) << "a refused call wrote";
  // The same meadow three times over, side by side, is a good list; an empty one does nothing.
  EXPECT_EQ(boreas_world_enqueue_meadow_vertices(world_, ids, firsts, 3, nullptr, vertices, counts), BOREAS_OK)
      << boreas_last_error();
  EXPECT_EQ(boreas_world_enqueue_meadow_vertices(world_, nullptr, nullptr, 0, nullptr, vertices, counts), BOREAS_OK);
  std::vector<float> got = read(vertices, 3 * c * V);
  EXPECT_EQ(std::memcmp(&got[0], &got[c * V], c * V * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(&got[0], &got[2 * c * V], c * V * sizeof(float)), 0);
}

TEST_F(ClExport, BuffersTooSmallOrMissingAreRefusedAndStayUntouched) {
  int n = 0;
  ASSERT_EQ(boreas_tree_get_branches(world_, tree_, nullptr, 0, &n), BOREAS_OK);
  const size_t R = BOREAS_BRANCH_RECORD_FLOATS;
  cl_mem small = buffer(size_t(n) * R);
  EXPECT_EQ(boreas_tree_enqueue_branch_records(world_, tree_, small, 1), BOREAS_ERROR_INVALID_ARGUMENT);
  const std::string message = boreas_last_error();
  EXPECT_NE(message.find("branch record buffer holds " + std::to_string(size_t(n) * R * sizeof(float)) + " bytes"),
            std::string::npos)
      << message;
  for (float f : read(small, size_t(n) * R)) ASSERT_EQ(f, kSentinel);

  EXPECT_EQ(boreas_tree_enqueue_leaf_records(world_, tree_, nullptr, 0), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("out is NULL"), std::string::npos);
  cl_mem tiny = buffer(4);
  EXPECT_EQ(boreas_meadow_enqueue_vertices(world_, meadow_, nullptr, tiny, tiny, 0), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("meadow vertex buffer"), std::string::npos);
  boreas_tree_id stale = tree_;
  ASSERT_EQ(boreas_world_remove_tree(world_, tree_), BOREAS_OK);
  EXPECT_EQ(boreas_tree_enqueue_branch_records(world_, stale, small, 0), BOREAS_ERROR_NOT_FOUND);
  EXPECT_EQ(boreas_world_get_cl(world_, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
}

// Context properties the driver refuses (here: sharing with an OpenGL context that does not
// exist) fail world creation with a message that says so, and nothing leaks or crashes.
TEST(ClContext, RefusedContextPropertiesGiveAClearError) {
  boreas_world_def def = boreas_default_world_def();
  const intptr_t props[] = {0x2008 /* CL_GL_CONTEXT_KHR */, 0x1234, 0};
  def.cl_context_properties = props;
  boreas_world world = nullptr;
  boreas_status s = boreas_world_create(&def, &world);
  EXPECT_NE(s, BOREAS_OK);
  EXPECT_EQ(world, nullptr);
  EXPECT_NE(std::string(boreas_last_error()).find("cl_context_properties"), std::string::npos) << boreas_last_error();

  const intptr_t unterminated[40] = {0x2008, 1, 0x2008, 1, 0x2008, 1, 0x2008, 1, 0x2008, 1, 0x2008, 1, 0x2008,
                                     1,      0x2008, 1, 0x2008, 1, 0x2008, 1, 0x2008, 1, 0x2008, 1, 0x2008, 1,
                                     0x2008, 1, 0x2008, 1, 0x2008, 1, 0x2008, 1, 0, 0};
  def.cl_context_properties = unterminated;
  EXPECT_EQ(boreas_world_create(&def, &world), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("16 pairs"), std::string::npos) << boreas_last_error();
}

}  // namespace
}  // namespace boreas
