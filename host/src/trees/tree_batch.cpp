// boreas: a batch of trees on the device — layout, upload, the step launches, readbacks.
#include "trees/tree_batch.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "wind/wind_params.h"

#include "shared/tree_types.h"

namespace boreas::impl {

TreeBatch::TreeBatch(Runtime& runtime, boreas_tree_mode mode) : runtime_(runtime), mode_(mode) {}

const TreeBatch::Placed& TreeBatch::placed(uint64_t key) const {
  for (const Placed& p : trees_)
    if (p.tree->key == key) return p;
  fail(BOREAS_ERROR_INTERNAL, "tree batch has no tree with key " + std::to_string(key));
}

int TreeBatch::level_first(uint64_t key, int level) const { return placed(key).level_first[level]; }

void TreeBatch::add(std::shared_ptr<const TreeInstance> tree) {
  std::vector<std::shared_ptr<const TreeInstance>> next;
  for (const Placed& p : trees_) next.push_back(p.tree);
  next.push_back(std::move(tree));
  rebuild(std::move(next));
}

void TreeBatch::remove(uint64_t key) {
  std::vector<std::shared_ptr<const TreeInstance>> next;
  for (const Placed& p : trees_)
    if (p.tree->key != key) next.push_back(p.tree);
  rebuild(std::move(next));
}

std::vector<float> TreeBatch::read_state() {
  std::vector<float> out(size_t(BOREAS_TREE_STATE_PLANES) * stride_);
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(state_[current_], CL_TRUE, 0, out.size() * sizeof(float),
                                                     out.data()));
  return out;
}

std::vector<float> TreeBatch::read_motion() {
  std::vector<float> out(size_t(BOREAS_TREE_MOTION_PLANES) * stride_);
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(motion_[current_], CL_TRUE, 0, out.size() * sizeof(float),
                                                     out.data()));
  return out;
}

void TreeBatch::rebuild(std::vector<std::shared_ptr<const TreeInstance>> trees) {
  cl::CommandQueue& q = runtime_.queue();
  // The current state of the trees that stay, read before anything changes.
  std::vector<float> old_state, old_motion;
  if (!trees_.empty()) {
    old_state = read_state();
    old_motion = read_motion();
  }
  const int old_stride = stride_;

  std::vector<TreeLayoutSource> sources;
  for (const auto& tree : trees) sources.push_back({&tree->params, &tree->model});
  TreeLayout layout = tree_layout(sources);
  const int n = layout.n;
  std::vector<Placed> placed(trees.size());
  for (size_t t = 0; t < trees.size(); ++t) {
    placed[t].tree = trees[t];
    placed[t].level_first = layout.tree_level_first[t];
    placed[t].leaf_first = layout.tree_leaf_first[t];
    // A tree that stays keeps its state and motion; a new one starts at rest.
    for (const Placed& old : trees_) {
      if (old.tree->key != trees[t]->key) continue;
      const TreeModel& m = trees[t]->model;
      for (int b = 0; b < static_cast<int>(m.branches.size()); ++b) {
        int level = m.branches[b].level;
        int i = layout.branch_index(t, m, b);
        int oi = old.level_first[level] + (b - m.level_begin[level]);
        for (int k = 0; k < BOREAS_TREE_STATE_PLANES; ++k)
          layout.state[size_t(k) * n + i] = old_state[size_t(k) * old_stride + oi];
        for (int k = 0; k < BOREAS_TREE_MOTION_PLANES; ++k)
          layout.motion[size_t(k) * n + i] = old_motion[size_t(k) * old_stride + oi];
      }
    }
  }
  // Device buffers: all made and filled before any member changes.
  cl::Buffer state_buffers[2], motion_buffers[2];
  for (int k = 0; k < 2; ++k) {
    state_buffers[k] = runtime_.buffer(CL_MEM_READ_WRITE, layout.state.size() * sizeof(float));
    motion_buffers[k] = runtime_.buffer(CL_MEM_READ_WRITE, layout.motion.size() * sizeof(float));
    runtime_.upload(state_buffers[k], layout.state);
    runtime_.upload(motion_buffers[k], layout.motion);
  }
  cl::Buffer parents_buffer = runtime_.buffer(CL_MEM_READ_ONLY, layout.parents.size() * sizeof(int32_t));
  cl::Buffer shape_buffer = runtime_.buffer(CL_MEM_READ_ONLY, layout.shape.size() * sizeof(float));
  cl::Buffer radius_buffer = runtime_.buffer(CL_MEM_READ_ONLY, layout.radius.size() * sizeof(float));
  cl::Buffer response_buffer =
      runtime_.buffer(CL_MEM_READ_ONLY, size_t(BOREAS_TREE_RESPONSE_PLANES) * n * sizeof(float));
  cl::Buffer leaf_parents_buffer = runtime_.buffer(CL_MEM_READ_ONLY, layout.leaf_parents.size() * sizeof(int32_t));
  cl::Buffer leaf_shape_buffer = runtime_.buffer(CL_MEM_READ_ONLY, layout.leaf_shape.size() * sizeof(float));
  cl::Buffer leaf_out_buffer =
      runtime_.buffer(CL_MEM_READ_WRITE, size_t(BOREAS_TREE_LEAF_OUT_PLANES) * layout.leaf_n * sizeof(float));
  runtime_.upload(parents_buffer, layout.parents);
  runtime_.upload(shape_buffer, layout.shape);
  runtime_.upload(radius_buffer, layout.radius);
  runtime_.upload(leaf_parents_buffer, layout.leaf_parents);
  runtime_.upload(leaf_shape_buffer, layout.leaf_shape);

  trees_ = std::move(placed);
  branch_count_ = layout.branch_count;
  leaf_count_ = layout.leaf_count;
  stride_ = n;
  leaf_stride_ = layout.leaf_n;
  level_first_ = layout.level_first;
  level_count_ = layout.level_count;
  response_dt_ = -1.0;
  current_ = 0;
  for (int k = 0; k < 2; ++k) {
    state_[k] = state_buffers[k];
    motion_[k] = motion_buffers[k];
  }
  parents_ = parents_buffer;
  shape_ = shape_buffer;
  radius_ = radius_buffer;
  response_ = response_buffer;
  leaf_parents_ = leaf_parents_buffer;
  leaf_shape_ = leaf_shape_buffer;
  leaf_out_ = leaf_out_buffer;
  omega_ = std::move(layout.omega);
  zeta_ = std::move(layout.zeta);
  if (leaf_count_ > 0) {
    enqueue_leaves(state_[current_]);
    BOREAS_CL_CHECK(q.finish());
  }
}

void TreeBatch::upload_response(double dt) {
  if (dt == response_dt_) return;
  runtime_.upload(response_, tree_response_planes(omega_, zeta_, dt));
  response_dt_ = dt;
}

void TreeBatch::enqueue_leaves(const cl::Buffer& state) {
  cl::Kernel& k = runtime_.kernel("tree_leaves.cl", "boreas_tree_leaves");
  BOREAS_CL_CHECK(k.setArg(0, state));
  BOREAS_CL_CHECK(k.setArg(1, stride_));
  BOREAS_CL_CHECK(k.setArg(2, leaf_parents_));
  BOREAS_CL_CHECK(k.setArg(3, leaf_shape_));
  BOREAS_CL_CHECK(k.setArg(4, leaf_out_));
  BOREAS_CL_CHECK(k.setArg(5, leaf_count_));
  BOREAS_CL_CHECK(k.setArg(6, leaf_stride_));
  runtime_.launch(k, leaf_count_);
}

void TreeBatch::enqueue_step(double dt, const TreeWindInput& wind) {
  if (trees_.empty()) return;
  upload_response(dt);
  const int next = 1 - current_;
  cl::Kernel& k = runtime_.kernel("tree_step.cl", "boreas_tree_step",
                                  slot_define("BOREAS_WAVE_SLOTS", wind.wave_slots));
  auto launch = [&](const cl::Buffer& parent_state, int first, int count) {
    if (count <= 0) return;
    BOREAS_CL_CHECK(k.setArg(0, parent_state));
    BOREAS_CL_CHECK(k.setArg(1, state_[next]));
    BOREAS_CL_CHECK(k.setArg(2, parents_));
    BOREAS_CL_CHECK(k.setArg(3, shape_));
    BOREAS_CL_CHECK(k.setArg(4, response_));
    BOREAS_CL_CHECK(k.setArg(5, motion_[current_]));
    BOREAS_CL_CHECK(k.setArg(6, motion_[next]));
    BOREAS_CL_CHECK(k.setArg(7, first));
    BOREAS_CL_CHECK(k.setArg(8, count));
    BOREAS_CL_CHECK(k.setArg(9, stride_));
    BOREAS_CL_CHECK(k.setArg(10, *wind.waves));
    BOREAS_CL_CHECK(k.setArg(11, wind.wave_count));
    BOREAS_CL_CHECK(k.setArg(12, *wind.grid));
    BOREAS_CL_CHECK(k.setArg(13, wind.grid_layout));
    runtime_.launch(k, count);
  };
  if (mode_ == BOREAS_TREE_LAGGED) {
    launch(state_[current_], level_first_[0], branch_count_);
  } else {
    for (int l = 0; l < kMaxTreeLevels; ++l) launch(state_[next], level_first_[l], level_count_[l]);
  }
  if (leaf_count_ > 0) enqueue_leaves(state_[next]);
}

std::vector<boreas_branch> TreeBatch::branches(uint64_t key) {
  const Placed& p = placed(key);
  const TreeModel& m = p.tree->model;
  std::vector<float> state = read_state();
  std::vector<boreas_branch> out(m.branches.size());
  for (size_t b = 0; b < m.branches.size(); ++b) {
    const BranchModel& br = m.branches[b];
    int i = p.level_first[br.level] + (static_cast<int>(b) - m.level_begin[br.level]);
    boreas_branch& o = out[b];
    for (int k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a) o.control_points[k][a] = state[size_t(3 * k + a) * stride_ + i];
    for (int a = 0; a < 3; ++a) o.orientation[a] = state[size_t(BOREAS_TREE_STATE_O + a) * stride_ + i];
    o.level = br.level;
    o.parent = br.parent;
    o.parent_v = float(br.v);
    o.radius = float(br.radius);
    o.length = float(br.length);
  }
  return out;
}

void TreeBatch::enqueue_branch_records(uint64_t key, const cl::Buffer& out, size_t first_record) {
  const Placed& p = placed(key);
  const TreeModel& m = p.tree->model;
  cl::Kernel& k = runtime_.kernel("export_records.cl", "boreas_export_branch_records");
  size_t at = first_record;
  // One launch per level: the tree's branches are contiguous within each level's range.
  for (int level = 0; level < kMaxTreeLevels; ++level) {
    const int count = m.level_begin[level + 1] - m.level_begin[level];
    if (count == 0) continue;
    int arg = 0;
    BOREAS_CL_CHECK(k.setArg(arg++, state_[current_]));
    BOREAS_CL_CHECK(k.setArg(arg++, radius_));
    BOREAS_CL_CHECK(k.setArg(arg++, stride_));
    BOREAS_CL_CHECK(k.setArg(arg++, p.level_first[level]));
    BOREAS_CL_CHECK(k.setArg(arg++, count));
    BOREAS_CL_CHECK(k.setArg(arg++, out));
    BOREAS_CL_CHECK(k.setArg(arg++, static_cast<int>(at)));
    runtime_.launch(k, size_t(count));
    at += size_t(count);
  }
}

void TreeBatch::enqueue_leaf_records(uint64_t key, const cl::Buffer& out, size_t first_record) {
  const Placed& p = placed(key);
  const int count = static_cast<int>(p.tree->model.leaves.size());
  if (count == 0) return;
  cl::Kernel& k = runtime_.kernel("export_records.cl", "boreas_export_leaf_records");
  int arg = 0;
  BOREAS_CL_CHECK(k.setArg(arg++, leaf_out_));
  BOREAS_CL_CHECK(k.setArg(arg++, leaf_stride_));
  BOREAS_CL_CHECK(k.setArg(arg++, p.leaf_first));
  BOREAS_CL_CHECK(k.setArg(arg++, count));
  BOREAS_CL_CHECK(k.setArg(arg++, out));
  BOREAS_CL_CHECK(k.setArg(arg++, static_cast<int>(first_record)));
  runtime_.launch(k, size_t(count));
}

std::vector<boreas_leaf> TreeBatch::leaves(uint64_t key) {
  const Placed& p = placed(key);
  const TreeModel& m = p.tree->model;
  std::vector<boreas_leaf> out(m.leaves.size());
  if (out.empty()) return out;
  std::vector<float> planes(size_t(BOREAS_TREE_LEAF_OUT_PLANES) * leaf_stride_);
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(leaf_out_, CL_TRUE, 0, planes.size() * sizeof(float),
                                                     planes.data()));
  for (size_t j = 0; j < m.leaves.size(); ++j) {
    int li = p.leaf_first + static_cast<int>(j);
    boreas_leaf& o = out[j];
    for (int a = 0; a < 3; ++a) {
      o.position[a] = planes[size_t(BOREAS_TREE_LEAF_OUT_POSITION + a) * leaf_stride_ + li];
      o.axis[a] = planes[size_t(BOREAS_TREE_LEAF_OUT_AXIS + a) * leaf_stride_ + li];
      o.normal[a] = planes[size_t(BOREAS_TREE_LEAF_OUT_NORMAL + a) * leaf_stride_ + li];
    }
    o.length = float(m.leaves[j].length);
    o.width = float(m.leaves[j].width);
    o.branch = m.leaves[j].parent;
  }
  return out;
}

void TreeBatch::mesh(uint64_t key, std::vector<boreas_vertex>* vertices, std::vector<uint32_t>* indices) {
  const Placed& p = placed(key);
  const TreeModel& m = p.tree->model;
  // Vertices per level, then one launch per level into one output.
  std::array<int, kMaxTreeLevels> first_vertex{};
  int total = 0;
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    const TreeLevelParams& lp = p.tree->params.levels[l];
    first_vertex[l] = total;
    total += (m.level_begin[l + 1] - m.level_begin[l]) * (lp.rings + 1) * (lp.sides + 1);
  }
  vertices->assign(size_t(total), boreas_vertex{});
  indices->clear();
  if (total == 0) return;
  cl::Buffer out = runtime_.buffer(CL_MEM_WRITE_ONLY, size_t(BOREAS_TREE_VERTEX_PLANES) * total * sizeof(float));
  cl::Kernel& k = runtime_.kernel("tree_deform.cl", "boreas_tree_deform");
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    int count = m.level_begin[l + 1] - m.level_begin[l];
    if (count == 0) continue;
    const TreeLevelParams& lp = p.tree->params.levels[l];
    BOREAS_CL_CHECK(k.setArg(0, state_[current_]));
    BOREAS_CL_CHECK(k.setArg(1, stride_));
    BOREAS_CL_CHECK(k.setArg(2, radius_));
    BOREAS_CL_CHECK(k.setArg(3, p.level_first[l]));
    BOREAS_CL_CHECK(k.setArg(4, count));
    BOREAS_CL_CHECK(k.setArg(5, lp.rings));
    BOREAS_CL_CHECK(k.setArg(6, lp.sides));
    BOREAS_CL_CHECK(k.setArg(7, out));
    BOREAS_CL_CHECK(k.setArg(8, total));
    BOREAS_CL_CHECK(k.setArg(9, first_vertex[l]));
    size_t work = size_t(count) * (lp.rings + 1) * (lp.sides + 1);
    runtime_.launch(k, work);
  }
  std::vector<float> planes(size_t(BOREAS_TREE_VERTEX_PLANES) * total);
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(out, CL_TRUE, 0, planes.size() * sizeof(float), planes.data()));
  for (int v = 0; v < total; ++v) {
    boreas_vertex& o = (*vertices)[v];
    for (int a = 0; a < 3; ++a) {
      o.position[a] = planes[size_t(BOREAS_TREE_VERTEX_POSITION + a) * total + v];
      o.normal[a] = planes[size_t(BOREAS_TREE_VERTEX_NORMAL + a) * total + v];
    }
    o.uv[0] = planes[size_t(BOREAS_TREE_VERTEX_UV) * total + v];
    o.uv[1] = planes[size_t(BOREAS_TREE_VERTEX_UV + 1) * total + v];
  }
  // Two triangles per quad, counter-clockwise seen from outside (the normal is
  // X_theta x X_v, so (side+1, ring+1) turns counter-clockwise from (side, ring)).
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    const TreeLevelParams& lp = p.tree->params.levels[l];
    int count = m.level_begin[l + 1] - m.level_begin[l];
    int row = lp.sides + 1;
    for (int b = 0; b < count; ++b) {
      uint32_t base = uint32_t(first_vertex[l] + b * (lp.rings + 1) * row);
      for (int r = 0; r < lp.rings; ++r)
        for (int s = 0; s < lp.sides; ++s) {
          uint32_t i0 = base + uint32_t(r * row + s), i1 = i0 + 1, i2 = i0 + uint32_t(row), i3 = i2 + 1;
          indices->insert(indices->end(), {i0, i1, i2, i1, i3, i2});
        }
    }
  }
}

}  // namespace boreas::impl
