// boreas: the trees of a world that share one animation mode, on the device as planes
// (cl/shared/tree_types.h), stepped together: one launch per step (lagged) or one per
// level (exact), then one for the leaves.
//
// The buffers follow trees/tree_layout.h. Adding or removing a tree rebuilds the layout,
// carrying the current state of the trees that stay.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "runtime/runtime.h"
#include "trees/tree_layout.h"
#include "trees/tree_model.h"
#include "trees/tree_params.h"
#include "wind/wind_grid.h"

namespace boreas::impl {

struct TreeInstance {
  uint64_t key = 0;  // unique within the world
  TreeParams params;
  TreeModel model;
};

// The wind as the step kernels read it.
struct TreeWindInput {
  const cl::Buffer* waves = nullptr;
  int wave_count = 0;
  int wave_slots = 0;
  const cl::Buffer* grid = nullptr;
  BoreasGpuGrid grid_layout{};
};

class TreeBatch {
 public:
  TreeBatch(Runtime& runtime, boreas_tree_mode mode);

  bool empty() const { return trees_.empty(); }
  int branch_count() const { return branch_count_; }
  int leaf_count() const { return leaf_count_; }

  // Adds a tree, placed unbent at rest. Rebuilds the layout.
  void add(std::shared_ptr<const TreeInstance> tree);
  // Removes the tree with this key (it must be present). Rebuilds the layout.
  void remove(uint64_t key);

  // Enqueues one step: branches, then leaves, into the next state. Nothing is visible
  // until commit(); without it (a failure), the batch stays as it was.
  void enqueue_step(double dt, const TreeWindInput& wind);
  void commit() { current_ = 1 - current_; }

  // Blocking readbacks of one tree (as of the last commit).
  std::vector<boreas_branch> branches(uint64_t key);
  std::vector<boreas_leaf> leaves(uint64_t key);
  // Enqueues the gather of one tree's branch or leaf records (cl/export_records.cl) into
  // out from record first_record; out must hold them (boreas_cl.h).
  void enqueue_branch_records(uint64_t key, const cl::Buffer& out, size_t first_record);
  void enqueue_leaf_records(uint64_t key, const cl::Buffer& out, size_t first_record);
  // The deformed mesh of one tree (vertices), with indices built on the host.
  void mesh(uint64_t key, std::vector<boreas_vertex>* vertices, std::vector<uint32_t>* indices);

  // For benchmarks and tests: the state planes of the whole batch (15 x stride floats).
  std::vector<float> read_state();
  // The response state planes (F, dF/dt: 6 x stride floats), for tests.
  std::vector<float> read_motion();
  int stride() const { return stride_; }
  const cl::Buffer& state_buffer() const { return state_[current_]; }
  const cl::Buffer& radius_buffer() const { return radius_; }
  // First global index of (tree, level), and the tree's branch count on that level.
  int level_first(uint64_t key, int level) const;

 private:
  struct Placed {
    std::shared_ptr<const TreeInstance> tree;
    std::array<int32_t, kMaxTreeLevels> level_first{};  // global index of the level's first branch
    int32_t leaf_first = 0;
  };
  const Placed& placed(uint64_t key) const;
  void rebuild(std::vector<std::shared_ptr<const TreeInstance>> trees);
  void upload_response(double dt);
  void enqueue_leaves(const cl::Buffer& state);

  Runtime& runtime_;
  boreas_tree_mode mode_;
  std::vector<Placed> trees_;
  int branch_count_ = 0;  // real branches, roots excluded
  int leaf_count_ = 0;
  int stride_ = 1;        // planes' stride: roots + branches (at least 1)
  int leaf_stride_ = 1;
  std::array<int32_t, kMaxTreeLevels> level_first_{};  // global range of each level
  std::array<int32_t, kMaxTreeLevels> level_count_{};
  double response_dt_ = -1.0;  // dt the device's response planes were made for
  int current_ = 0;
  cl::Buffer state_[2], motion_[2];
  cl::Buffer parents_, shape_, response_, radius_;
  cl::Buffer leaf_parents_, leaf_shape_, leaf_out_;
  std::vector<double> omega_, zeta_;  // per global index (0 for quasi-static and roots)
};

}  // namespace boreas::impl
