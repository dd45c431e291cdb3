// boreas: a batch of trees on the device — layout, upload, the step launches, readbacks.
#include "trees/tree_batch.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "wind/wind_params.h"

// The host places new trees with the kernels' own geometry (float, C++ build of the
// shared header); its polynomial math is only reached by the deformer's radius functions.
#define BOREAS_FAST_MATH 1
#include "shared/tree_math.h"
#include "shared/tree_types.h"

namespace boreas::impl {
namespace {

constexpr int kLocalGroup = 64;

size_t round_up(size_t n) { return (n + kLocalGroup - 1) / kLocalGroup * kLocalGroup; }

BoreasV3 load3(const std::vector<float>& planes, int n, int plane, int i) {
  return boreas_v3(planes[size_t(plane) * n + i], planes[size_t(plane + 1) * n + i],
                   planes[size_t(plane + 2) * n + i]);
}

void store3(std::vector<float>& planes, int n, int plane, int i, BoreasV3 v) {
  planes[size_t(plane) * n + i] = v.x;
  planes[size_t(plane + 1) * n + i] = v.y;
  planes[size_t(plane + 2) * n + i] = v.z;
}

BoreasBezier load_curve(const std::vector<float>& state, int n, int i) {
  BoreasBezier c;
  c.p0 = load3(state, n, BOREAS_TREE_STATE_P0, i);
  c.p1 = load3(state, n, BOREAS_TREE_STATE_P1, i);
  c.p2 = load3(state, n, BOREAS_TREE_STATE_P2, i);
  c.p3 = load3(state, n, BOREAS_TREE_STATE_P3, i);
  return c;
}

template <typename T>
void write(cl::CommandQueue& q, const cl::Buffer& buffer, const std::vector<T>& data) {
  if (!data.empty())
    BOREAS_CL_CHECK(q.enqueueWriteBuffer(buffer, CL_TRUE, 0, data.size() * sizeof(T), data.data()));
}

}  // namespace

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

  const int tree_count = static_cast<int>(trees.size());
  std::vector<Placed> placed(trees.size());
  std::array<int32_t, kMaxTreeLevels> level_first{}, level_count{};
  int g = tree_count;
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    level_first[l] = g;
    for (int t = 0; t < tree_count; ++t) {
      const TreeModel& m = trees[t]->model;
      placed[t].tree = trees[t];
      placed[t].level_first[l] = g;
      g += m.level_begin[l + 1] - m.level_begin[l];
    }
    level_count[l] = g - level_first[l];
  }
  int leaves = 0;
  for (int t = 0; t < tree_count; ++t) {
    placed[t].leaf_first = leaves;
    leaves += static_cast<int>(trees[t]->model.leaves.size());
  }
  const int n = std::max(g, 1);
  const int ln = std::max(leaves, 1);

  std::vector<int32_t> parents(n, 0);
  std::vector<float> shape(size_t(BOREAS_TREE_SHAPE_PLANES) * n, 0.0f);
  std::vector<float> radius(size_t(BOREAS_TREE_RADIUS_PLANES) * n, 0.0f);
  std::vector<float> state(size_t(BOREAS_TREE_STATE_PLANES) * n, 0.0f);
  std::vector<float> motion(size_t(BOREAS_TREE_MOTION_PLANES) * n, 0.0f);
  std::vector<double> omega(n, 0.0), zeta(n, 0.0);
  std::vector<int32_t> leaf_parents(ln, 0);
  std::vector<float> leaf_shape(size_t(BOREAS_TREE_LEAF_PLANES) * ln, 0.0f);

  auto global_of = [&](int t, int b) {
    const TreeModel& m = trees[t]->model;
    int level = m.branches[b].level;
    return placed[t].level_first[level] + (b - m.level_begin[level]);
  };

  for (int t = 0; t < tree_count; ++t) {
    const TreeInstance& tree = *trees[t];
    const TreeModel& m = tree.model;
    // The root: a vertical unit segment at the tree's position; O along +x.
    BoreasV3 base = boreas_v3(float(tree.params.position[0]), float(tree.params.position[1]),
                              float(tree.params.position[2]));
    parents[t] = t;
    store3(state, n, BOREAS_TREE_STATE_P0, t, base);
    store3(state, n, BOREAS_TREE_STATE_P1, t, boreas_v3_add(base, boreas_v3(0, 1.0f / 3.0f, 0)));
    store3(state, n, BOREAS_TREE_STATE_P2, t, boreas_v3_add(base, boreas_v3(0, 2.0f / 3.0f, 0)));
    store3(state, n, BOREAS_TREE_STATE_P3, t, boreas_v3_add(base, boreas_v3(0, 1.0f, 0)));
    store3(state, n, BOREAS_TREE_STATE_O, t, boreas_v3(1, 0, 0));

    const Placed* old = nullptr;
    for (const Placed& p : trees_)
      if (p.tree->key == tree.key) old = &p;

    const double w2 = std::pow(2.0 / 3.0, tree.params.bend_exponent);
    for (int b = 0; b < static_cast<int>(m.branches.size()); ++b) {
      const BranchModel& br = m.branches[b];
      const TreeLevelParams& lp = tree.params.levels[br.level];
      int i = global_of(t, b);
      int p = br.parent < 0 ? t : global_of(t, br.parent);
      parents[i] = p;
      for (int k = 1; k <= 3; ++k)
        for (int a = 0; a < 3; ++a) shape[size_t(3 * (k - 1) + a) * n + i] = float(br.local[k][a]);
      shape[size_t(BOREAS_TREE_SHAPE_V) * n + i] = float(br.v);
      shape[size_t(BOREAS_TREE_SHAPE_COS_THETA) * n + i] = float(std::cos(br.theta));
      shape[size_t(BOREAS_TREE_SHAPE_SIN_THETA) * n + i] = float(std::sin(br.theta));
      shape[size_t(BOREAS_TREE_SHAPE_COS_ALPHA) * n + i] = float(std::cos(br.alpha));
      shape[size_t(BOREAS_TREE_SHAPE_SIN_ALPHA) * n + i] = float(std::sin(br.alpha));
      shape[size_t(BOREAS_TREE_SHAPE_COMPLIANCE) * n + i] = float(bend_compliance(br, lp));
      shape[size_t(BOREAS_TREE_SHAPE_W2) * n + i] = float(w2);
      const double radius_fields[BOREAS_TREE_RADIUS_PLANES] = {
          br.radius,      br.taper_depth, std::max(br.taper_exponent, 1.0), br.flare,     br.bulge_count,
          br.bulge_depth, br.lobe_count,  br.lobe_depth,                    br.lobe_taper};
      for (int k = 0; k < BOREAS_TREE_RADIUS_PLANES; ++k) radius[size_t(k) * n + i] = float(radius_fields[k]);
      if (tree.params.response == BOREAS_TREE_DAMPED) {
        omega[i] = natural_frequency(br, lp);
        zeta[i] = lp.damping_ratio;
      }

      if (old != nullptr) {
        int oi = old->level_first[br.level] + (b - m.level_begin[br.level]);
        for (int k = 0; k < BOREAS_TREE_STATE_PLANES; ++k)
          state[size_t(k) * n + i] = old_state[size_t(k) * old_stride + oi];
        for (int k = 0; k < BOREAS_TREE_MOTION_PLANES; ++k)
          motion[size_t(k) * n + i] = old_motion[size_t(k) * old_stride + oi];
        continue;
      }
      // New: placed unbent on its parent, which (levels in order) is placed already.
      BoreasAttachFrame a = boreas_attach(load_curve(state, n, p), load3(state, n, BOREAS_TREE_STATE_O, p),
                                          float(br.v), float(std::cos(br.theta)), float(std::sin(br.theta)),
                                          float(std::cos(br.alpha)), float(std::sin(br.alpha)));
      store3(state, n, BOREAS_TREE_STATE_P0, i, a.origin);
      for (int k = 1; k <= 3; ++k)
        store3(state, n, BOREAS_TREE_STATE_P0 + 3 * k, i,
               boreas_attach_place(a, float(br.local[k][0]), float(br.local[k][1]), float(br.local[k][2])));
      store3(state, n, BOREAS_TREE_STATE_O, i, a.y);
    }
    for (size_t j = 0; j < m.leaves.size(); ++j) {
      const LeafModel& leaf = m.leaves[j];
      int li = placed[t].leaf_first + static_cast<int>(j);
      leaf_parents[li] = global_of(t, leaf.parent);
      leaf_shape[size_t(BOREAS_TREE_LEAF_V) * ln + li] = float(leaf.v);
      leaf_shape[size_t(BOREAS_TREE_LEAF_COS_THETA) * ln + li] = float(std::cos(leaf.theta));
      leaf_shape[size_t(BOREAS_TREE_LEAF_SIN_THETA) * ln + li] = float(std::sin(leaf.theta));
      leaf_shape[size_t(BOREAS_TREE_LEAF_COS_ALPHA) * ln + li] = float(std::cos(leaf.alpha));
      leaf_shape[size_t(BOREAS_TREE_LEAF_SIN_ALPHA) * ln + li] = float(std::sin(leaf.alpha));
      leaf_shape[size_t(BOREAS_TREE_LEAF_STEM) * ln + li] = float(leaf.stem);
    }
  }

  // Device buffers: all made and filled before any member changes.
  cl::Buffer state_buffers[2], motion_buffers[2];
  for (int k = 0; k < 2; ++k) {
    state_buffers[k] = runtime_.buffer(CL_MEM_READ_WRITE, state.size() * sizeof(float));
    motion_buffers[k] = runtime_.buffer(CL_MEM_READ_WRITE, motion.size() * sizeof(float));
    write(q, state_buffers[k], state);
    write(q, motion_buffers[k], motion);
  }
  cl::Buffer parents_buffer = runtime_.buffer(CL_MEM_READ_ONLY, parents.size() * sizeof(int32_t));
  cl::Buffer shape_buffer = runtime_.buffer(CL_MEM_READ_ONLY, shape.size() * sizeof(float));
  cl::Buffer radius_buffer = runtime_.buffer(CL_MEM_READ_ONLY, radius.size() * sizeof(float));
  cl::Buffer response_buffer =
      runtime_.buffer(CL_MEM_READ_ONLY, size_t(BOREAS_TREE_RESPONSE_PLANES) * n * sizeof(float));
  cl::Buffer leaf_parents_buffer = runtime_.buffer(CL_MEM_READ_ONLY, leaf_parents.size() * sizeof(int32_t));
  cl::Buffer leaf_shape_buffer = runtime_.buffer(CL_MEM_READ_ONLY, leaf_shape.size() * sizeof(float));
  cl::Buffer leaf_out_buffer =
      runtime_.buffer(CL_MEM_READ_WRITE, size_t(BOREAS_TREE_LEAF_OUT_PLANES) * ln * sizeof(float));
  write(q, parents_buffer, parents);
  write(q, shape_buffer, shape);
  write(q, radius_buffer, radius);
  write(q, leaf_parents_buffer, leaf_parents);
  write(q, leaf_shape_buffer, leaf_shape);

  trees_ = std::move(placed);
  branch_count_ = g - tree_count;
  leaf_count_ = leaves;
  stride_ = n;
  leaf_stride_ = ln;
  level_first_ = level_first;
  level_count_ = level_count;
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
  omega_ = std::move(omega);
  zeta_ = std::move(zeta);
  if (leaf_count_ > 0) {
    enqueue_leaves(state_[current_]);
    BOREAS_CL_CHECK(q.finish());
  }
}

void TreeBatch::upload_response(double dt) {
  if (dt == response_dt_) return;
  const int n = stride_;
  std::vector<float> response(size_t(BOREAS_TREE_RESPONSE_PLANES) * n, 0.0f);
  for (int i = 0; i < n; ++i) {
    if (omega_[i] <= 0.0) continue;  // quasi-static: a = b = c = d = 0, F = F*
    std::array<double, 4> m = oscillator_step(omega_[i], zeta_[i], dt);
    for (int k = 0; k < 4; ++k) response[size_t(k) * n + i] = float(m[k]);
  }
  write(runtime_.queue(), response_, response);
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
  BOREAS_CL_CHECK(runtime_.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(round_up(leaf_count_)),
                                                        cl::NDRange(kLocalGroup)));
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
    BOREAS_CL_CHECK(runtime_.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(round_up(count)),
                                                          cl::NDRange(kLocalGroup)));
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
    BOREAS_CL_CHECK(runtime_.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(round_up(work)),
                                                          cl::NDRange(kLocalGroup)));
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
