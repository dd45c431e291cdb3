// boreas tests: a forest's records in one call (boreas_world_enqueue_tree_records). Its
// records are the per-tree calls' bits for the trees it draws; it culls exactly the trees
// whose bounds lie outside the view (against a double-precision check of their geometry),
// draws those that straddle it; far trees keep fewer leaves but their coverage; the
// indirect counts are what it wrote; a buffer too small is filled up to its end and the
// needed counts say how much more; bad input writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "support/small_world.h"

namespace boreas {
namespace {

constexpr size_t kBranchFloats = BOREAS_BRANCH_RECORD_FLOATS, kLeafFloats = BOREAS_LEAF_RECORD_FLOATS;
constexpr float kSentinel = -12345.0f;

// What one call wrote, read back.
struct Written {
  std::vector<float> branches, leaves, impostors;
  std::vector<int32_t> ranges;
  std::vector<uint32_t> indirect;
};

class TreeRecords : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(test::create_small_windy_world(&world_), BOREAS_OK) << boreas_last_error();
    ASSERT_EQ(boreas_world_get_cl(world_, &cl_), BOREAS_OK);
  }
  void TearDown() override {
    for (cl_mem m : buffers_) clReleaseMemObject(m);
    boreas_world_destroy(world_);
  }

  // Trees along x every `spacing` m from x0 (seeds 1 and 2 alternating; every third in
  // exact mode when `modes`).
  void add_row(int count, float x0, float spacing, bool modes = false) {
    for (int i = 0; i < count; ++i) {
      boreas_tree_def def = boreas_default_tree_def();
      def.position[0] = x0 + spacing * float(i);
      def.position[2] = 1.0f;
      def.seed = uint64_t(1 + i % 2);
      def.rotation = 0.3f * float(i);
      def.scale = 0.8f + 0.05f * float(i % 3);
      if (modes && i % 3 == 2) def.mode = BOREAS_TREE_EXACT;
      boreas_tree_id id{};
      ASSERT_EQ(boreas_world_add_tree(world_, &def, &id), BOREAS_OK) << boreas_last_error();
      trees_.push_back(id);
    }
  }
  void step(int steps) {
    for (int s = 0; s < steps; ++s) ASSERT_EQ(boreas_world_step(world_, 1.0f / 30.0f), BOREAS_OK);
  }

  cl_mem buffer(size_t bytes) {
    cl_int err = CL_SUCCESS;
    cl_mem m = clCreateBuffer(cl_.context, CL_MEM_READ_WRITE, std::max<size_t>(bytes, 4), nullptr, &err);
    EXPECT_EQ(err, CL_SUCCESS);
    std::vector<float> fill(std::max<size_t>(bytes, 4) / sizeof(float), kSentinel);
    EXPECT_EQ(clEnqueueWriteBuffer(cl_.queue, m, CL_TRUE, 0, fill.size() * sizeof(float), fill.data(), 0,
                                   nullptr, nullptr),
              CL_SUCCESS);
    buffers_.push_back(m);
    return m;
  }
  template <typename T>
  std::vector<T> read(cl_mem m) {
    size_t bytes = 0;
    EXPECT_EQ(clGetMemObjectInfo(m, CL_MEM_SIZE, sizeof bytes, &bytes, nullptr), CL_SUCCESS);
    std::vector<T> out(bytes / sizeof(T));
    EXPECT_EQ(clFinish(cl_.queue), CL_SUCCESS);
    EXPECT_EQ(clEnqueueReadBuffer(cl_.queue, m, CL_TRUE, 0, out.size() * sizeof(T), out.data(), 0, nullptr, nullptr),
              CL_SUCCESS);
    return out;
  }

  // Buffers for `branches`, `leaves`, `impostors` and `ranges` records.
  boreas_tree_record_buffers buffers(size_t branches, size_t leaves, size_t impostors, size_t ranges) {
    boreas_tree_record_buffers b{};
    b.branches = buffer(branches * kBranchFloats * sizeof(float));
    b.leaves = buffer(leaves * kLeafFloats * sizeof(float));
    b.impostors = buffer(impostors * BOREAS_TREE_IMPOSTOR_RECORD_FLOATS * sizeof(float));
    b.ranges = buffer(ranges * BOREAS_TREE_RANGE_RECORD_INTS * sizeof(int32_t));
    b.indirect = buffer(BOREAS_TREE_INDIRECT_UINTS * sizeof(uint32_t));
    return b;
  }
  // Buffers that hold every tree's records.
  boreas_tree_record_buffers roomy_buffers() {
    size_t branches = 0, leaves = 0;
    for (boreas_tree_id t : trees_) {
      branches += size_t(count_branches(t));
      leaves += size_t(count_leaves(t));
    }
    return buffers(branches, leaves, trees_.size(), trees_.size());
  }
  Written call(const boreas_tree_view_def& view, const boreas_tree_record_buffers& b) {
    EXPECT_EQ(boreas_world_enqueue_tree_records(world_, &view, &b), BOREAS_OK) << boreas_last_error();
    Written w;
    w.branches = read<float>(b.branches);
    w.leaves = read<float>(b.leaves);
    w.impostors = read<float>(b.impostors);
    w.ranges = read<int32_t>(b.ranges);
    w.indirect = read<uint32_t>(b.indirect);
    return w;
  }

  int count_branches(boreas_tree_id t) {
    int n = 0;
    EXPECT_EQ(boreas_tree_get_branches(world_, t, nullptr, 0, &n), BOREAS_OK);
    return n;
  }
  int count_leaves(boreas_tree_id t) {
    int n = 0;
    EXPECT_EQ(boreas_tree_get_leaves(world_, t, nullptr, 0, &n), BOREAS_OK);
    return n;
  }
  std::vector<boreas_branch> branches_of(boreas_tree_id t) {
    int n = count_branches(t);
    std::vector<boreas_branch> out(static_cast<size_t>(n));
    EXPECT_EQ(boreas_tree_get_branches(world_, t, out.data(), n, &n), BOREAS_OK);
    return out;
  }
  std::vector<boreas_leaf> leaves_of(boreas_tree_id t) {
    int n = count_leaves(t);
    std::vector<boreas_leaf> out(static_cast<size_t>(n));
    EXPECT_EQ(boreas_tree_get_leaves(world_, t, out.data(), n, &n), BOREAS_OK);
    return out;
  }
  // The per-tree calls' records of one tree.
  std::vector<float> per_tree_branches(boreas_tree_id t) {
    cl_mem out = buffer(size_t(count_branches(t)) * kBranchFloats * sizeof(float));
    EXPECT_EQ(boreas_tree_enqueue_branch_records(world_, t, out, 0), BOREAS_OK) << boreas_last_error();
    return read<float>(out);
  }
  std::vector<float> per_tree_leaves(boreas_tree_id t) {
    cl_mem out = buffer(size_t(count_leaves(t)) * kLeafFloats * sizeof(float));
    EXPECT_EQ(boreas_tree_enqueue_leaf_records(world_, t, out, 0), BOREAS_OK) << boreas_last_error();
    return read<float>(out);
  }
  // The tree a range record names.
  boreas_tree_id tree_of(const int32_t* range) const {
    for (boreas_tree_id t : trees_)
      if (int32_t(t.index) == range[0] && int32_t(t.generation) == range[1]) return t;
    ADD_FAILURE() << "a range names no tree of the world: index " << range[0];
    return boreas_tree_id{};
  }
  const int32_t* range(const Written& w, uint32_t r) const { return &w.ranges[size_t(r) * BOREAS_TREE_RANGE_RECORD_INTS]; }

  // Every drawn tree's records equal the per-tree calls' (all its leaves kept).
  void expect_per_tree_bits(const Written& w) {
    for (uint32_t r = 0; r < w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN]; ++r) {
      const int32_t* rg = range(w, r);
      const boreas_tree_id t = tree_of(rg);
      std::vector<float> b = per_tree_branches(t), l = per_tree_leaves(t);
      ASSERT_EQ(rg[3], count_branches(t));
      ASSERT_EQ(rg[5], count_leaves(t));
      ASSERT_EQ(rg[7], 1);
      EXPECT_EQ(std::memcmp(&w.branches[size_t(rg[2]) * kBranchFloats], b.data(), size_t(rg[3]) * kBranchFloats * 4), 0)
          << "branch records of range " << r;
      EXPECT_EQ(std::memcmp(&w.leaves[size_t(rg[4]) * kLeafFloats], l.data(), size_t(rg[5]) * kLeafFloats * 4), 0)
          << "leaf records of range " << r;
    }
  }

  boreas_world world_ = nullptr;
  boreas_cl_objects cl_{};
  std::vector<boreas_tree_id> trees_;
  std::vector<cl_mem> buffers_;
};

TEST_F(TreeRecords, OneCallWritesThePerTreeRecordsBitForBit) {
  add_row(6, -10.0f, 4.0f, true);
  step(5);
  // A removed tree leaves a hole that its tiles no longer cover; a new one takes its slot.
  ASSERT_EQ(boreas_world_remove_tree(world_, trees_[1]), BOREAS_OK);
  trees_.erase(trees_.begin() + 1);
  add_row(1, 20.0f, 1.0f);
  step(3);
  boreas_tree_view_def view = boreas_default_tree_view_def();
  const Written w = call(view, roomy_buffers());
  ASSERT_EQ(w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], trees_.size());
  expect_per_tree_bits(w);
  // The indirect commands count the records written, which are all of them.
  uint32_t branches = 0, leaves = 0;
  std::vector<bool> seen(trees_.size(), false);
  for (uint32_t r = 0; r < trees_.size(); ++r) {
    const int32_t* rg = range(w, r);
    EXPECT_EQ(uint32_t(rg[2]), branches) << "branch records packed in range order";
    EXPECT_EQ(uint32_t(rg[4]), leaves) << "leaf records packed in range order";
    branches += uint32_t(rg[3]);
    leaves += uint32_t(rg[5]);
    const boreas_tree_id t = tree_of(rg);
    for (size_t k = 0; k < trees_.size(); ++k)
      if (boreas_tree_id_equal(trees_[k], t)) seen[k] = true;
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), true), long(trees_.size()));
  const uint32_t* cmd = w.indirect.data();
  EXPECT_EQ(cmd[BOREAS_TREE_INDIRECT_BRANCH_COMMAND + 0], uint32_t(view.vertices_per_branch));
  EXPECT_EQ(cmd[BOREAS_TREE_INDIRECT_BRANCH_COMMAND + 1], branches);
  EXPECT_EQ(cmd[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 0], 4u);
  EXPECT_EQ(cmd[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1], leaves);
  EXPECT_EQ(cmd[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1], 0u);
  for (int k : {2, 3, 6, 7, 10, 11}) EXPECT_EQ(cmd[k], 0u) << "first and baseInstance are 0";
  EXPECT_EQ(cmd[BOREAS_TREE_INDIRECT_NEEDED + 0], branches);
  EXPECT_EQ(cmd[BOREAS_TREE_INDIRECT_NEEDED + 1], leaves);
  EXPECT_EQ(cmd[BOREAS_TREE_INDIRECT_NEEDED + 3], trees_.size());
  // Nothing written past the records counted.
  for (size_t k = size_t(leaves) * kLeafFloats; k < w.leaves.size(); ++k) ASSERT_EQ(w.leaves[k], kSentinel);
}

// The distance (m) from the plane (n, d) to p, in double, with n normalized.
double plane_distance(const float plane[4], const double p[3]) {
  const double n = std::sqrt(double(plane[0]) * plane[0] + double(plane[1]) * plane[1] + double(plane[2]) * plane[2]);
  return (plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + double(plane[3])) / n;
}

TEST_F(TreeRecords, CullsTheTreesOutsideTheViewAndDrawsThoseOnItsEdge) {
  // A view looking down -z from (0, 5, 30): a frustum of four slanted side planes and a far
  // plane; trees in a grid in and around it.
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) {
      boreas_tree_def def = boreas_default_tree_def();
      def.position[0] = -60.0f + 30.0f * float(i);
      def.position[2] = 20.0f - 35.0f * float(j);
      def.seed = uint64_t(1 + (i + j) % 2);
      boreas_tree_id id{};
      ASSERT_EQ(boreas_world_add_tree(world_, &def, &id), BOREAS_OK) << boreas_last_error();
      trees_.push_back(id);
    }
  // Two on its edges: bases on the left side plane and on the far plane.
  const float edges[2][2] = {{std::tan(0.61f) * (-20.0f - 30.0f), -20.0f}, {5.0f, -70.0f}};
  for (const auto& e : edges) {
    boreas_tree_def def = boreas_default_tree_def();
    def.position[0] = e[0];
    def.position[2] = e[1];
    boreas_tree_id id{};
    ASSERT_EQ(boreas_world_add_tree(world_, &def, &id), BOREAS_OK) << boreas_last_error();
    trees_.push_back(id);
  }
  step(2);
  boreas_tree_view_def view = boreas_default_tree_view_def();
  view.eye[0] = 0.0f, view.eye[1] = 5.0f, view.eye[2] = 30.0f;
  // Side planes through the eye, turned 35 degrees from -z; the far plane 100 m out.
  const float c = std::cos(0.61f), s = std::sin(0.61f);
  const float normals[5][3] = {{c, 0, -s}, {-c, 0, -s}, {0, c, -s}, {0, -c, -s}, {0, 0, 1}};
  for (int p = 0; p < 5; ++p) {
    for (int a = 0; a < 3; ++a) view.planes[p][a] = normals[p][a];
    const float* e = view.eye;
    view.planes[p][3] = -(normals[p][0] * e[0] + normals[p][1] * e[1] + normals[p][2] * e[2]);
  }
  view.planes[4][3] = 70.0f;  // n.p + d >= 0 for z >= -70
  const Written w = call(view, roomy_buffers());
  std::vector<bool> drawn(trees_.size(), false);
  for (uint32_t r = 0; r < w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN]; ++r) {
    const boreas_tree_id t = tree_of(range(w, r));
    for (size_t k = 0; k < trees_.size(); ++k)
      if (boreas_tree_id_equal(trees_[k], t)) drawn[k] = true;
  }
  expect_per_tree_bits(w);
  // In double: a tree any of whose points (branch control points, leaves) is inside every
  // plane must be drawn; one whose base is outside a plane by more than twice its extent
  // (how far any of its points lies from its base: its bounding sphere, however it bends,
  // is far within that) must be culled. The grid has both kinds, and trees on the edges.
  int inside = 0, straddling = 0, outside = 0;
  for (size_t k = 0; k < trees_.size(); ++k) {
    const std::vector<boreas_branch> b = branches_of(trees_[k]);
    const std::vector<boreas_leaf> l = leaves_of(trees_[k]);
    std::vector<std::array<double, 3>> points;
    for (const boreas_branch& x : b)
      for (const auto& p : x.control_points) points.push_back({p[0], p[1], p[2]});
    for (const boreas_leaf& x : l) points.push_back({x.position[0], x.position[1], x.position[2]});
    const double base[3] = {b[0].control_points[0][0], b[0].control_points[0][1], b[0].control_points[0][2]};
    double extent = 0.0;
    for (const auto& p : points)
      extent = std::max(extent, std::hypot(p[0] - base[0], p[1] - base[1], p[2] - base[2]));
    bool any_inside = false, any_outside = false, far_outside = false;
    for (const auto& p : points) {
      bool in = true;
      for (int q = 0; q < 6; ++q) in = in && plane_distance(view.planes[q], p.data()) >= 0.0;
      any_inside = any_inside || in;
      any_outside = any_outside || !in;
    }
    for (int q = 0; q < 6; ++q) far_outside = far_outside || plane_distance(view.planes[q], base) < -2.0 * extent;
    if (any_inside) {
      EXPECT_TRUE(drawn[k]) << "tree " << k << " has points in the view";
      ++(any_outside ? straddling : inside);
    } else if (far_outside) {
      EXPECT_FALSE(drawn[k]) << "tree " << k << " lies far outside the view";
      ++outside;
    }
  }
  EXPECT_GT(inside, 0);
  EXPECT_GE(straddling, 2) << "the trees on the view's edges do not straddle it";
  EXPECT_GT(outside, 0);
  EXPECT_EQ(w.indirect[BOREAS_TREE_INDIRECT_NEEDED + 3], w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN]);
}

TEST_F(TreeRecords, FarTreesKeepFewerLeavesAndTheirCoverage) {
  add_row(3, 0.0f, 40.0f);
  step(3);
  boreas_tree_view_def view = boreas_default_tree_view_def();
  view.eye[0] = -20.0f, view.eye[1] = 2.0f, view.eye[2] = 1.0f;  // 20, 60 and 100 m from the trees
  view.pixel_angle = 1.0f / 1000.0f;
  const Written w = call(view, roomy_buffers());
  ASSERT_EQ(w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 3u);
  int thinned = 0;
  int32_t last_count = INT32_MAX;
  for (uint32_t r = 0; r < 3; ++r) {
    const int32_t* rg = range(w, r);
    const boreas_tree_id t = tree_of(rg);
    const std::vector<boreas_leaf> all = leaves_of(t);
    const std::vector<float> full = per_tree_leaves(t);
    const int32_t n = rg[6], kept = rg[5], stride = rg[7];
    ASSERT_EQ(size_t(n), all.size());
    EXPECT_LE(kept, last_count) << "farther trees keep no more leaves";
    last_count = kept;
    double area_all = 0.0, area_kept = 0.0;
    for (const boreas_leaf& x : all) area_all += double(x.length) * x.width;
    for (int32_t m = 0; m < kept; ++m) {
      const int32_t j = int32_t((int64_t(m) * stride) % n);
      const float* got = &w.leaves[size_t(rg[4] + m) * kLeafFloats];
      const float* want = &full[size_t(j) * kLeafFloats];
      // Position and normal are the leaf's; its axis carries its size factor.
      for (int a : {0, 1, 2, 6, 7, 8}) ASSERT_EQ(got[a], want[a]) << "record " << m << " is leaf " << j;
      const double f = std::sqrt(double(got[3]) * got[3] + double(got[4]) * got[4] + double(got[5]) * got[5]);
      EXPECT_NEAR(f, kept < n ? std::sqrt(double(n) / kept) : 1.0, 1e-3);
      area_kept += double(all[size_t(j)].length) * all[size_t(j)].width * f * f;
    }
    if (kept < n) ++thinned;
    EXPECT_NEAR(area_kept / area_all, 1.0, 0.15) << "tree " << r << ": " << kept << " of " << n << " leaves";
  }
  EXPECT_GE(thinned, 2) << "the far trees were not thinned: lower pixel_angle's reach";
  EXPECT_EQ(w.indirect[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1],
            uint32_t(range(w, 0)[5] + range(w, 1)[5] + range(w, 2)[5]));
}

// A tree of a (species, seed) the world already keeps, in the other mode: its template
// block is grown again from the kept (packed) model, and its view facts (leaves' mean area
// and reach, trunk's rest tip) must be the first's: the same thinning at the same distance,
// and, at rest, impostors that do not sway.
TEST_F(TreeRecords, ATemplateGrownAgainFromAKeptModelDrawsAsTheFirst) {
  for (int i = 0; i < 2; ++i) {
    boreas_tree_def def = boreas_default_tree_def();
    def.position[0] = i == 0 ? 60.0f : -60.0f;
    def.mode = i == 0 ? BOREAS_TREE_LAGGED : BOREAS_TREE_EXACT;
    boreas_tree_id id{};
    ASSERT_EQ(boreas_world_add_tree(world_, &def, &id), BOREAS_OK) << boreas_last_error();
    trees_.push_back(id);
  }
  boreas_tree_view_def view = boreas_default_tree_view_def();
  view.eye[1] = 2.0f;
  view.pixel_angle = 1.0f / 1000.0f;
  const Written w = call(view, roomy_buffers());
  ASSERT_EQ(w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 2u);
  const int32_t *a = range(w, 0), *b = range(w, 1);
  EXPECT_EQ(a[6], b[6]);
  EXPECT_LT(a[5], a[6]) << "60 m away, the leaves are thinned";
  EXPECT_EQ(a[5], b[5]) << "the same leaves kept at the same distance";
  EXPECT_EQ(a[7], b[7]);
  view.impostor_distance = 30.0f;
  const Written far = call(view, roomy_buffers());
  ASSERT_EQ(far.indirect[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1], 2u);
  for (int k = 0; k < 2; ++k)
    for (int c = 6; c < 9; ++c)
      EXPECT_EQ(far.impostors[size_t(k) * BOREAS_TREE_IMPOSTOR_RECORD_FLOATS + size_t(c)], 0.0f)
          << "impostor " << k << ": a tree at rest does not sway";
}

TEST_F(TreeRecords, TreesPastTheImpostorDistanceWriteOneImpostorRecord) {
  add_row(4, 0.0f, 30.0f);
  std::vector<std::array<float, 3>> rest_tip;
  for (boreas_tree_id t : trees_) {
    const auto b = branches_of(t);
    rest_tip.push_back({b[0].control_points[3][0], b[0].control_points[3][1], b[0].control_points[3][2]});
  }
  step(10);
  boreas_tree_view_def view = boreas_default_tree_view_def();
  view.impostor_distance = 45.0f;  // trees 2 and 3 (60 and 90 m from the eye at 0)
  const Written w = call(view, roomy_buffers());
  EXPECT_EQ(w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 2u);
  ASSERT_EQ(w.indirect[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1], 2u);
  EXPECT_EQ(w.indirect[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 0], 4u);
  expect_per_tree_bits(w);
  for (int i = 0; i < 2; ++i) {
    const float* r = &w.impostors[size_t(i) * BOREAS_TREE_IMPOSTOR_RECORD_FLOATS];
    const size_t k = size_t(2 + i);  // slot order: the order they were added
    // As add_row placed it.
    EXPECT_EQ(r[0], 30.0f * float(k));
    EXPECT_EQ(r[1], 0.0f);
    EXPECT_EQ(r[2], 1.0f);
    EXPECT_EQ(r[3], 0.8f + 0.05f * float(k % 3));
    EXPECT_EQ(r[4], 0.3f * float(k));
    int tmpl = -1;
    ASSERT_EQ(boreas_tree_get_template(world_, trees_[k], &tmpl), BOREAS_OK);
    EXPECT_EQ(r[5], float(tmpl));
    const auto b = branches_of(trees_[k]);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(r[6 + a], double(b[0].control_points[3][a]) - rest_tip[k][a], 1e-5) << "the trunk tip's sway";
      EXPECT_EQ(r[9 + a], 0.0f);
    }
  }
  // Trees of one species and seed share a template; another seed is another.
  int t0 = -1, t1 = -1, t2 = -1;
  ASSERT_EQ(boreas_tree_get_template(world_, trees_[0], &t0), BOREAS_OK);
  ASSERT_EQ(boreas_tree_get_template(world_, trees_[1], &t1), BOREAS_OK);
  ASSERT_EQ(boreas_tree_get_template(world_, trees_[2], &t2), BOREAS_OK);
  EXPECT_EQ(t0, t2);
  EXPECT_NE(t0, t1);
}

// boreas_world_set_output_origin applies to every tree record (README "Far from the
// origin"): a row 100 km out read relative to a point near it. The one call writes the
// per-tree calls' bits, the getters give the same points, a trunk stands at its base less
// the origin, and an impostor's base is that difference too. The view stays in world
// coordinates (its eye, here at 100 km, picks the impostors).
TEST_F(TreeRecords, RecordsAndImpostorsFollowTheOutputOrigin) {
  const double origin[3] = {1.0e5, 0.0, 0.0};
  add_row(4, 1.0e5f - 30.0f, 30.0f);  // x = 99970, 100000, 100030, 100060: exact floats
  step(5);
  ASSERT_EQ(boreas_world_set_output_origin(world_, origin), BOREAS_OK) << boreas_last_error();
  boreas_tree_view_def view = boreas_default_tree_view_def();
  view.eye[0] = 1.0e5f - 30.0f;
  view.impostor_distance = 45.0f;  // trees 2 and 3 (60 and 90 m from the eye)
  const Written w = call(view, roomy_buffers());
  ASSERT_EQ(w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 2u);
  ASSERT_EQ(w.indirect[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1], 2u);
  expect_per_tree_bits(w);
  for (uint32_t r = 0; r < 2; ++r) {
    const int32_t* rg = range(w, r);
    const std::vector<boreas_branch> b = branches_of(tree_of(rg));
    const float* rec = &w.branches[size_t(rg[2]) * kBranchFloats];
    for (size_t i = 0; i < b.size(); ++i)
      for (int c = 0; c < 4; ++c)
        for (int a = 0; a < 3; ++a)
          ASSERT_EQ(rec[i * kBranchFloats + size_t(3 * c + a)], b[i].control_points[c][a]) << "branch " << i;
    // The trunk's base: the tree's position less the origin, to the bit.
    EXPECT_EQ(rec[0], -30.0f + 30.0f * float(r));
    EXPECT_EQ(rec[2], 1.0f);
  }
  for (int i = 0; i < 2; ++i) {
    const float* imp = &w.impostors[size_t(i) * BOREAS_TREE_IMPOSTOR_RECORD_FLOATS];
    EXPECT_EQ(imp[0], 30.0f + 30.0f * float(i)) << "impostor " << i << "'s base less the origin";
    EXPECT_EQ(imp[1], 0.0f);
    EXPECT_EQ(imp[2], 1.0f);
  }
}

TEST_F(TreeRecords, BuffersTooSmallAreFilledUpToTheirEndAndTheNeedIsCounted) {
  add_row(4, 0.0f, 5.0f);
  step(2);
  const int nb = count_branches(trees_[0]), nl = count_leaves(trees_[0]);
  // Room for the leaves of two and a half trees (same species: near in size).
  size_t leaves = 0;
  for (int k = 0; k < 2; ++k) leaves += size_t(count_leaves(trees_[size_t(k)]));
  leaves += size_t(nl / 2);
  boreas_tree_record_buffers b = buffers(size_t(nb) * 10, leaves, 4, 4);
  const Written w = call(boreas_default_tree_view_def(), b);
  const uint32_t written = w.indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN];
  EXPECT_EQ(written, 2u);
  EXPECT_EQ(w.indirect[BOREAS_TREE_INDIRECT_NEEDED + 3], 4u);
  size_t all_leaves = 0, all_branches = 0;
  for (boreas_tree_id t : trees_) all_leaves += size_t(count_leaves(t)), all_branches += size_t(count_branches(t));
  EXPECT_EQ(w.indirect[BOREAS_TREE_INDIRECT_NEEDED + 1], all_leaves);
  EXPECT_EQ(w.indirect[BOREAS_TREE_INDIRECT_NEEDED + 0], all_branches);
  EXPECT_EQ(w.indirect[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1], uint32_t(range(w, 1)[4] + range(w, 1)[5]));
  expect_per_tree_bits(w);
  for (size_t k = size_t(range(w, 1)[4] + range(w, 1)[5]) * kLeafFloats; k < w.leaves.size(); ++k)
    ASSERT_EQ(w.leaves[k], kSentinel) << "a leaf record past the trees written";
}

TEST_F(TreeRecords, BadInputIsRefusedNamingItAndNothingIsWritten) {
  add_row(2, 0.0f, 5.0f);
  step(1);
  boreas_tree_record_buffers b = roomy_buffers();
  auto untouched = [&] {
    for (float f : read<float>(b.indirect)) ASSERT_EQ(f, kSentinel);
    for (float f : read<float>(b.leaves)) ASSERT_EQ(f, kSentinel);
  };
  auto refused = [&](const boreas_tree_view_def& view, const boreas_tree_record_buffers& out, const char* names) {
    EXPECT_EQ(boreas_world_enqueue_tree_records(world_, &view, &out), BOREAS_ERROR_INVALID_ARGUMENT) << names;
    EXPECT_NE(std::string(boreas_last_error()).find(names), std::string::npos) << boreas_last_error();
    untouched();
  };
  const boreas_tree_view_def good = boreas_default_tree_view_def();
  boreas_tree_view_def view = good;
  view.planes[2][1] = std::nanf("");
  refused(view, b, "planes[2][1]");
  view = good;
  view.planes[0][3] = -1.0f;
  refused(view, b, "planes[0]");
  view = good;
  view.eye[1] = INFINITY;
  refused(view, b, "eye[1]");
  view = good;
  view.min_keep = 0.0f;
  refused(view, b, "min_keep");
  view = good;
  view.vertices_per_leaf = -4;
  refused(view, b, "vertices_per_leaf");
  boreas_tree_record_buffers missing = b;
  missing.impostors = nullptr;
  refused(good, missing, "out->impostors");
  boreas_tree_record_buffers small = b;
  small.indirect = buffer(8);
  refused(good, small, "out->indirect holds 8 bytes");
  EXPECT_EQ(boreas_world_enqueue_tree_records(world_, nullptr, &b), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(boreas_world_enqueue_tree_records(world_, &good, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  int t = 0;
  EXPECT_EQ(boreas_tree_get_template(world_, trees_[0], nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  ASSERT_EQ(boreas_world_remove_tree(world_, trees_[0]), BOREAS_OK);
  EXPECT_EQ(boreas_tree_get_template(world_, trees_[0], &t), BOREAS_ERROR_NOT_FOUND);
}

TEST_F(TreeRecords, AnEmptyWorldWritesZeroCounts) {
  boreas_tree_record_buffers b = buffers(1, 1, 1, 1);
  const Written w = call(boreas_default_tree_view_def(), b);
  for (int k : {1, 5, 9, 12, 16, 17, 18, 19}) EXPECT_EQ(w.indirect[size_t(k)], 0u) << "word " << k;
}

// Determinism: two worlds built the same way write the same bytes, call after call.
TEST(TreeRecordsDeterminism, SameWorldSameBytes) {
  std::vector<std::vector<uint8_t>> runs;
  for (int run = 0; run < 2; ++run) {
    boreas_world world = nullptr;
    ASSERT_EQ(test::create_small_windy_world(&world), BOREAS_OK);
    for (int i = 0; i < 5; ++i) {
      boreas_tree_def def = boreas_default_tree_def();
      def.position[0] = 9.0f * float(i);
      def.seed = uint64_t(1 + i % 2);
      boreas_tree_id id{};
      ASSERT_EQ(boreas_world_add_tree(world, &def, &id), BOREAS_OK);
    }
    for (int s = 0; s < 4; ++s) ASSERT_EQ(boreas_world_step(world, 1.0f / 30.0f), BOREAS_OK);
    boreas_cl_objects cl{};
    ASSERT_EQ(boreas_world_get_cl(world, &cl), BOREAS_OK);
    const size_t sizes[5] = {1u << 20, 1u << 22, 1u << 10, 1u << 10, BOREAS_TREE_INDIRECT_UINTS * 4};
    cl_mem m[5];
    for (int k = 0; k < 5; ++k) {
      cl_int err = CL_SUCCESS;
      m[k] = clCreateBuffer(cl.context, CL_MEM_READ_WRITE, sizes[k], nullptr, &err);
      ASSERT_EQ(err, CL_SUCCESS);
      const uint8_t zero = 0;
      ASSERT_EQ(clEnqueueFillBuffer(cl.queue, m[k], &zero, 1, 0, sizes[k], 0, nullptr, nullptr), CL_SUCCESS);
    }
    boreas_tree_record_buffers b{m[0], m[1], m[2], m[3], m[4]};
    boreas_tree_view_def view = boreas_default_tree_view_def();
    view.pixel_angle = 1e-3f;
    view.impostor_distance = 30.0f;
    for (int call = 0; call < 2; ++call) {
      ASSERT_EQ(boreas_world_enqueue_tree_records(world, &view, &b), BOREAS_OK) << boreas_last_error();
      std::vector<uint8_t> bytes;
      for (int k = 0; k < 5; ++k) {
        std::vector<uint8_t> part(sizes[k]);
        ASSERT_EQ(clEnqueueReadBuffer(cl.queue, m[k], CL_TRUE, 0, sizes[k], part.data(), 0, nullptr, nullptr),
                  CL_SUCCESS);
        bytes.insert(bytes.end(), part.begin(), part.end());
      }
      runs.push_back(bytes);
    }
    for (cl_mem x : m) clReleaseMemObject(x);
    boreas_world_destroy(world);
  }
  ASSERT_EQ(runs.size(), 4u);
  for (size_t k = 1; k < runs.size(); ++k) EXPECT_TRUE(runs[k] == runs[0]) << "run " << k;
}

}  // namespace
}  // namespace boreas
