// boreas: a batch of trees on the device — blocks, growth, holes, levels of detail, the
// step launches, readbacks.
#include "trees/tree_batch.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>

#include "errors.h"
#include "shared/tree_types.h"
#include "wind/wind_params.h"

namespace boreas::impl {

namespace {

std::string count_text(int64_t n) { return std::to_string(n); }

}  // namespace

TreeBatch::TreeBatch(Runtime& runtime, boreas_tree_mode mode) : runtime_(runtime), mode_(mode) {}

const TreeBatch::Slot& TreeBatch::slot_of(uint64_t key) const {
  auto it = by_key_.find(key);
  if (it == by_key_.end())
    fail(BOREAS_ERROR_INTERNAL, "tree batch has no tree with key " + std::to_string(key));
  return slots_[size_t(it->second)];
}

int32_t TreeBatch::branch_index(uint64_t key, int b) const {
  return slot_of(key).first + block_index(b);
}

std::string TreeBatch::plane_defines() const {
  // The widest planes: shape's 16 per branch entry, the leaf output's 9 per leaf.
  const bool wide =
      wide_planes_ || BOREAS_TREE_SHAPE_PLANES * capacity_ > std::numeric_limits<int32_t>::max() ||
      BOREAS_TREE_LEAF_OUT_PLANES * leaf_capacity_ > std::numeric_limits<int32_t>::max();
  return wide ? "#define BOREAS_WIDE_PLANES 1\n" : "";
}

void TreeBatch::relayout(int64_t capacity, int64_t leaf_capacity, bool compact) {
  // Sizes are checked against what an int index reaches (the kernels' indices) before
  // anything is allocated; the device's memory is checked by Runtime::buffer.
  if (capacity > std::numeric_limits<int32_t>::max() ||
      leaf_capacity > std::numeric_limits<int32_t>::max())
    fail(BOREAS_ERROR_OUT_OF_MEMORY, "trees: " + count_text(capacity) + " branch entries and " +
                                         count_text(leaf_capacity) +
                                         " leaves pass one batch's 2^31 indices");
  const size_t c = size_t(capacity), lc = size_t(leaf_capacity);
  cl::Buffer state[2], motion[2], parents, shape, response, radius, leaf_parents, leaf_shape,
      leaf_out;
  const std::string label = "trees (" + count_text(capacity) + " branch entries, " +
                            count_text(leaf_capacity) + " leaves)";
  auto make = [&](cl::Buffer& b, cl_mem_flags flags, size_t bytes) {
    b = runtime_.buffer(flags, bytes, label.c_str());
  };
  for (int k = 0; k < 2; ++k) {
    make(state[k], CL_MEM_READ_WRITE, size_t(BOREAS_TREE_STATE_PLANES) * c * sizeof(float));
    make(motion[k], CL_MEM_READ_WRITE, size_t(BOREAS_TREE_MOTION_PLANES) * c * sizeof(float));
  }
  make(parents, CL_MEM_READ_ONLY, c * sizeof(int32_t));
  make(shape, CL_MEM_READ_ONLY, size_t(BOREAS_TREE_SHAPE_PLANES) * c * sizeof(float));
  make(response, CL_MEM_READ_ONLY, size_t(BOREAS_TREE_RESPONSE_PLANES) * c * sizeof(float));
  make(radius, CL_MEM_READ_ONLY, size_t(BOREAS_TREE_RADIUS_PLANES) * c * sizeof(float));
  make(leaf_parents, CL_MEM_READ_ONLY, lc * sizeof(int32_t));
  make(leaf_shape, CL_MEM_READ_ONLY, size_t(BOREAS_TREE_LEAF_PLANES) * lc * sizeof(float));
  make(leaf_out, CL_MEM_READ_WRITE, size_t(BOREAS_TREE_LEAF_OUT_PLANES) * lc * sizeof(float));

  struct PlanePair {
    cl::Buffer* from;
    cl::Buffer* to;
    int planes;
    size_t elem;
  };
  const PlanePair branch_sets[] = {
      {&state_[0], &state[0], BOREAS_TREE_STATE_PLANES, sizeof(float)},
      {&state_[1], &state[1], BOREAS_TREE_STATE_PLANES, sizeof(float)},
      {&motion_[0], &motion[0], BOREAS_TREE_MOTION_PLANES, sizeof(float)},
      {&motion_[1], &motion[1], BOREAS_TREE_MOTION_PLANES, sizeof(float)},
      {&parents_, &parents, 1, sizeof(int32_t)},
      {&shape_, &shape, BOREAS_TREE_SHAPE_PLANES, sizeof(float)},
      {&response_, &response, BOREAS_TREE_RESPONSE_PLANES, sizeof(float)},
      {&radius_, &radius, BOREAS_TREE_RADIUS_PLANES, sizeof(float)},
  };
  const PlanePair leaf_sets[] = {
      {&leaf_parents_, &leaf_parents, 1, sizeof(int32_t)},
      {&leaf_shape_, &leaf_shape, BOREAS_TREE_LEAF_PLANES, sizeof(float)},
      {&leaf_out_, &leaf_out, BOREAS_TREE_LEAF_OUT_PLANES, sizeof(float)},
  };

  // Where every block goes: packed after the sinks in the order of the old indices, or
  // where it is.
  std::vector<int32_t> order;
  for (size_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].tree) order.push_back(int32_t(s));
  std::sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
    return slots_[size_t(a)].first < slots_[size_t(b)].first;
  });
  std::vector<int32_t> new_first(slots_.size(), 0);
  std::vector<int64_t> new_leaf_first(slots_.size(), 0);
  int64_t at = 1, leaf_at = 1;
  for (int32_t s : order) {
    new_first[size_t(s)] = compact ? int32_t(at) : slots_[size_t(s)].first;
    new_leaf_first[size_t(s)] = compact ? leaf_at : slots_[size_t(s)].leaf_first;
    at += slots_[size_t(s)].count;
    leaf_at += slots_[size_t(s)].leaf_count;
  }
  if (capacity_ == 0) {
    // A new batch: the sinks (the layout of no trees).
    TreeLayout sink = tree_layout({});
    runtime_.write_planes(state[0], c, 0, sink.state.data(), 1, 1, BOREAS_TREE_STATE_PLANES);
    runtime_.write_planes(state[1], c, 0, sink.state.data(), 1, 1, BOREAS_TREE_STATE_PLANES);
    runtime_.write_planes(motion[0], c, 0, sink.motion.data(), 1, 1, BOREAS_TREE_MOTION_PLANES);
    runtime_.write_planes(motion[1], c, 0, sink.motion.data(), 1, 1, BOREAS_TREE_MOTION_PLANES);
    runtime_.write_planes(parents, c, 0, sink.parents.data(), 1, 1, 1, sizeof(int32_t));
    runtime_.write_planes(shape, c, 0, sink.shape.data(), 1, 1, BOREAS_TREE_SHAPE_PLANES);
    std::vector<float> zeros(BOREAS_TREE_RESPONSE_PLANES + BOREAS_TREE_RADIUS_PLANES, 0.0f);
    runtime_.write_planes(response, c, 0, zeros.data(), 1, 1, BOREAS_TREE_RESPONSE_PLANES);
    runtime_.write_planes(radius, c, 0, zeros.data(), 1, 1, BOREAS_TREE_RADIUS_PLANES);
    runtime_.write_planes(leaf_parents, lc, 0, sink.leaf_parents.data(), 1, 1, 1, sizeof(int32_t));
    runtime_.write_planes(leaf_shape, lc, 0, sink.leaf_shape.data(), 1, 1, BOREAS_TREE_LEAF_PLANES);
  } else {
    // Device copies: the sinks, then one per buffer for each run of blocks that moves by
    // the same amount.
    auto copy = [&](bool leaves, int64_t from, int64_t to, int64_t length) {
      if (length <= 0) return;
      const PlanePair* sets = leaves ? leaf_sets : branch_sets;
      const size_t set_count = leaves ? std::size(leaf_sets) : std::size(branch_sets);
      for (const PlanePair* set = sets; set != sets + set_count; ++set)
        runtime_.copy_planes(*set->from, size_t(leaves ? leaf_capacity_ : capacity_), size_t(from),
                             *set->to, leaves ? lc : c, size_t(to), size_t(length),
                             size_t(set->planes), set->elem);
    };
    for (bool leaves : {false, true}) {
      copy(leaves, 0, 0, 1);
      size_t k = 0;
      while (k < order.size()) {
        const size_t s = size_t(order[k]);
        const int64_t from = leaves ? slots_[s].leaf_first : slots_[s].first;
        const int64_t to = leaves ? new_leaf_first[s] : new_first[s];
        int64_t length = leaves ? slots_[s].leaf_count : slots_[s].count;
        for (++k; k < order.size(); ++k) {
          const size_t t = size_t(order[k]);
          const int64_t next_from = leaves ? slots_[t].leaf_first : slots_[t].first;
          const int64_t next_to = leaves ? new_leaf_first[t] : new_first[t];
          if (next_from != from + length || next_to != to + length) break;
          length += leaves ? slots_[t].leaf_count : slots_[t].count;
        }
        copy(leaves, from, to, length);
      }
    }
  }
  // Moved blocks' parent indices are global: write them again (the moved trees only).
  std::vector<int32_t> staged;
  for (int32_t s : order) {
    const Slot& slot = slots_[size_t(s)];
    const TreeModel& m = *slot.tree->model;
    const int32_t first = new_first[size_t(s)];
    if (first != slot.first) {
      staged.assign(size_t(slot.count), first);
      for (size_t b = 0; b < m.branches.size(); ++b)
        staged[size_t(block_index(int32_t(b)))] =
            first + (m.branches[b].parent < 0 ? 0 : block_index(m.branches[b].parent));
      runtime_.write_planes(parents, c, size_t(first), staged.data(), staged.size(), staged.size(),
                            1, sizeof(int32_t));
    }
    if (slot.leaf_count > 0 &&
        (new_leaf_first[size_t(s)] != slot.leaf_first || first != slot.first)) {
      staged.resize(size_t(slot.leaf_count));
      for (size_t j = 0; j < m.leaves.size(); ++j)
        staged[j] = first + block_index(m.leaves[j].parent);
      runtime_.write_planes(leaf_parents, lc, size_t(new_leaf_first[size_t(s)]), staged.data(),
                            staged.size(), staged.size(), 1, sizeof(int32_t));
    }
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());

  // Nothing failed: the batch takes the new buffers and indices.
  bool moved = false;
  for (int32_t s : order) {
    moved = moved || slots_[size_t(s)].first != new_first[size_t(s)] ||
            slots_[size_t(s)].leaf_first != new_leaf_first[size_t(s)];
    slots_[size_t(s)].first = new_first[size_t(s)];
    slots_[size_t(s)].leaf_first = new_leaf_first[size_t(s)];
  }
  if (compact) {
    end_ = at;
    leaf_end_ = leaf_at;
    dead_ = leaf_dead_ = 0;
  }
  capacity_ = capacity;
  leaf_capacity_ = leaf_capacity;
  for (int k = 0; k < 2; ++k) {
    state_[k] = state[k];
    motion_[k] = motion[k];
  }
  parents_ = parents;
  shape_ = shape;
  response_ = response;
  radius_ = radius;
  leaf_parents_ = leaf_parents;
  leaf_shape_ = leaf_shape;
  leaf_out_ = leaf_out;
  if (moved) rebuild_tiles_ = true;
}

TreeLod TreeBatch::lod_of(const TreeParams& params) const {
  const size_t points = focus_.size() / 3;
  if (points == 0) return TreeLod::kFull;
  const auto& p = params.position;
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t f = 0; f < points; ++f) {
    const double dx = p[0] - focus_[3 * f], dy = p[1] - focus_[3 * f + 1],
                 dz = p[2] - focus_[3 * f + 2];
    nearest = std::min(nearest, dx * dx + dy * dy + dz * dz);
  }
  return tree_lod_at(params, std::sqrt(nearest));
}

void TreeBatch::tile(Slot& slot) {
  if (slot.frozen) return;
  add_tree_tiles(tiles_, mode_, *slot.tree->model, slot.first, slot.leaf_first, slot.lod, slot.hold,
                 slot.first, int(runtime_.group_size()), &slot.tiles);
}

void TreeBatch::untile(Slot& slot) {
  for (const TileLists::Segment& s : slot.tiles) tiles_.kill(s);
  slot.tiles.clear();
}

void TreeBatch::rebuild_tiles() {
  tiles_.clear();
  for (Slot& slot : slots_) {
    if (!slot.tree) continue;
    slot.tiles.clear();
    tile(slot);
  }
  rebuild_tiles_ = false;
}

void TreeBatch::add(const std::vector<std::shared_ptr<const TreeInstance>>& trees) {
  if (trees.empty()) return;
  for (const auto& t : trees)
    if (by_key_.count(t->key))
      fail(BOREAS_ERROR_INTERNAL, "tree key " + std::to_string(t->key) + " added twice");
  // The new blocks, packed as one layout: one upload per buffer for all of them.
  std::vector<TreeLayoutSource> sources;
  sources.reserve(trees.size());
  for (const auto& t : trees) sources.push_back({&t->params, t->model.get()});
  TreeLayout layout = tree_layout(sources);
  // The layout's entries and leaves after its sinks are the new blocks.
  const int64_t need = layout.n - 1, leaf_need = layout.leaf_n - 1;
  if (end_ + need > capacity_ || leaf_end_ + leaf_need > leaf_capacity_) {
    // Grow by doubling; holes are squeezed out on the way when there are any.
    const bool compact = dead_ > 0 || leaf_dead_ > 0;
    const int64_t base = compact ? end_ - dead_ : end_,
                  leaf_base = compact ? leaf_end_ - leaf_dead_ : leaf_end_;
    int64_t cap = std::max<int64_t>(capacity_, 256),
            leaf_cap = std::max<int64_t>(leaf_capacity_, 1024);
    while (cap < base + need) cap *= 2;
    while (leaf_cap < leaf_base + leaf_need) leaf_cap *= 2;
    relayout(cap, leaf_cap, compact);
  }
  const size_t c = size_t(capacity_), lc = size_t(leaf_capacity_);
  // Layout entry e (e >= 1) goes to batch entry shift + e.
  const int32_t shift = int32_t(end_ - 1);
  const int64_t leaf_shift = leaf_end_ - 1;
  const size_t n = size_t(layout.n), ln = size_t(layout.leaf_n);
  for (int32_t& p : layout.parents) p += shift;
  for (int32_t& p : layout.leaf_parents) p += shift;
  auto write = [&](const cl::Buffer& b, size_t stride, int64_t at, const void* host,
                   size_t host_stride, size_t count, int planes, size_t elem) {
    // Skips the layout's sink (its entry 0): rows start one element in.
    runtime_.write_planes(b, stride, size_t(at), static_cast<const char*>(host) + elem, host_stride,
                          count, size_t(planes), elem);
  };
  write(state_[current_], c, end_, layout.state.data(), n, size_t(need), BOREAS_TREE_STATE_PLANES,
        sizeof(float));
  runtime_.copy_planes(state_[current_], c, size_t(end_), state_[1 - current_], c, size_t(end_),
                       size_t(need), BOREAS_TREE_STATE_PLANES);
  // At rest the motion is zero: filled on the device, nothing to upload.
  for (int k = 0; k < 2; ++k)
    for (int p = 0; p < BOREAS_TREE_MOTION_PLANES; ++p)
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          motion_[k], 0.0f, (size_t(p) * c + size_t(end_)) * sizeof(float),
          size_t(need) * sizeof(float)));
  write(parents_, c, end_, layout.parents.data(), n, size_t(need), 1, sizeof(int32_t));
  write(shape_, c, end_, layout.shape.data(), n, size_t(need), BOREAS_TREE_SHAPE_PLANES,
        sizeof(float));
  write(radius_, c, end_, layout.radius.data(), n, size_t(need), BOREAS_TREE_RADIUS_PLANES,
        sizeof(float));
  if (response_dt_ > 0.0) {
    std::vector<float> response = tree_response_planes(layout.omega, layout.zeta, response_dt_);
    write(response_, c, end_, response.data(), n, size_t(need), BOREAS_TREE_RESPONSE_PLANES,
          sizeof(float));
  }
  if (leaf_need > 0) {
    write(leaf_parents_, lc, leaf_end_, layout.leaf_parents.data(), ln, size_t(leaf_need), 1,
          sizeof(int32_t));
    write(leaf_shape_, lc, leaf_end_, layout.leaf_shape.data(), ln, size_t(leaf_need),
          BOREAS_TREE_LEAF_PLANES, sizeof(float));
    // The new leaves on their new branches, now: one launch over all of them.
    TileLists tiles(1);
    tiles.add(0, leaf_end_, leaf_need, int(runtime_.group_size()));
    tiles.flush(runtime_);
    cl::Kernel& k = runtime_.kernel("tree_leaves.cl", "boreas_tree_leaves", plane_defines());
    bind_args(k, state_[current_], int(c), leaf_parents_, leaf_shape_, leaf_out_, int(lc),
              tiles.buffer(0), 0);
    runtime_.launch_groups(k, tiles.size(0));
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());

  // Everything is on the device: the batch takes the trees.
  for (size_t t = 0; t < trees.size(); ++t) {
    Slot slot;
    slot.tree = trees[t];
    slot.first = shift + layout.tree_first[t];
    slot.count = 1 + int32_t(trees[t]->model->branches.size());
    slot.leaf_first = leaf_shift + layout.tree_leaf_first[t];
    slot.leaf_count = int32_t(trees[t]->model->leaves.size());
    slot.lod = lod_of(trees[t]->params);
    if (slot.lod == TreeLod::kFrozen) slot.settle_left = kSettleTime;
    int32_t s;
    if (!free_slots_.empty()) {
      s = free_slots_.back();
      free_slots_.pop_back();
      slots_[size_t(s)] = std::move(slot);
    } else {
      s = int32_t(slots_.size());
      slots_.push_back(std::move(slot));
    }
    by_key_.emplace(trees[t]->key, s);
    if (!rebuild_tiles_) tile(slots_[size_t(s)]);
  }
  end_ += need;
  leaf_end_ += leaf_need;
  branch_count_ += layout.branch_count;
  leaf_count_ += leaf_need;
}

void TreeBatch::remove(uint64_t key) {
  auto it = by_key_.find(key);
  if (it == by_key_.end())
    fail(BOREAS_ERROR_INTERNAL, "tree batch has no tree with key " + std::to_string(key));
  const int32_t s = it->second;
  Slot& slot = slots_[size_t(s)];
  untile(slot);
  // The last block shortens the batch; any other leaves a hole no launch covers.
  if (slot.first + slot.count == end_)
    end_ -= slot.count;
  else
    dead_ += slot.count;
  if (slot.leaf_first + slot.leaf_count == leaf_end_)
    leaf_end_ -= slot.leaf_count;
  else
    leaf_dead_ += slot.leaf_count;
  branch_count_ -= slot.count - 1;
  leaf_count_ -= slot.leaf_count;
  slot = Slot{};
  free_slots_.push_back(s);
  by_key_.erase(it);
  if (by_key_.empty()) {
    end_ = leaf_end_ = 1;
    dead_ = leaf_dead_ = 0;
    tiles_.clear();
    return;
  }
  // Holes past half the batch: pack the blocks (device copies, amortized over the removals
  // that made the holes). A failure here only leaves the holes where they were.
  if ((dead_ > 0 && 2 * dead_ > end_) || (leaf_dead_ > 0 && 2 * leaf_dead_ > leaf_end_)) {
    try {
      relayout(capacity_, leaf_capacity_, true);
    } catch (const Error&) {
    }
  }
}

void TreeBatch::set_focus(const std::vector<double>& xyz) { focus_ = xyz; }

std::array<int64_t, kTreeLodCount> TreeBatch::lod_counts() const {
  std::array<int64_t, kTreeLodCount> counts{};
  for (const Slot& s : slots_)
    if (s.tree) ++counts[size_t(s.lod)];
  return counts;
}

void TreeBatch::update_lods(double dt) {
  const float resume_hold = float(std::exp(-dt / kResumeTimeConstant));
  const bool new_dt = dt != hold_dt_;
  hold_dt_ = dt;
  stepped_ = carried_ = 0;
  const int next = 1 - current_;
  for (Slot& slot : slots_) {
    if (!slot.tree) continue;
    bool retile = false;
    const TreeLod lod = lod_of(slot.tree->params);
    if (lod != slot.lod) {
      // Finer than before: the branches that start again ease into the wind.
      if (lod < slot.lod) slot.resume_left = kResumeTime;
      slot.settle_left = lod == TreeLod::kFrozen ? kSettleTime : 0.0;
      slot.frozen = false;
      slot.lod = lod;
      retile = true;
    } else if (lod == TreeLod::kFrozen && !slot.frozen) {
      slot.settle_left -= dt;
      if (slot.settle_left <= 0.0) {
        // Settled: its last state goes to both halves of the ping-pong state, so leaving
        // it alone from now on shows it still.
        runtime_.copy_planes(state_[current_], size_t(capacity_), size_t(slot.first), state_[next],
                             size_t(capacity_), size_t(slot.first), size_t(slot.count),
                             BOREAS_TREE_STATE_PLANES);
        runtime_.copy_planes(motion_[current_], size_t(capacity_), size_t(slot.first),
                             motion_[next], size_t(capacity_), size_t(slot.first),
                             size_t(slot.count), BOREAS_TREE_MOTION_PLANES);
        slot.frozen = true;
        retile = true;
      }
    }
    const float hold = slot.resume_left > 0.0 ? resume_hold : 0.0f;
    if (hold != slot.hold && (hold == 0.0f || slot.hold == 0.0f || new_dt)) retile = true;
    slot.hold = hold;
    slot.resume_left = std::max(0.0, slot.resume_left - dt);
    if (retile && !rebuild_tiles_) {
      untile(slot);
      tile(slot);
    }
    if (!slot.frozen) {
      const TreeModel& m = *slot.tree->model;
      const int64_t stepped = m.level_begin[size_t(stepped_levels(m, slot.lod))];
      stepped_ += stepped;
      carried_ += int64_t(m.branches.size()) - stepped;
    }
  }
}

void TreeBatch::upload_response(double dt) {
  if (dt == response_dt_) return;
  // Every live block's response for the new dt (a fixed time step computes it once).
  std::vector<double> omega, zeta;
  for (const Slot& slot : slots_) {
    if (!slot.tree) continue;
    const TreeParams& params = slot.tree->params;
    const TreeModel& m = *slot.tree->model;
    if (params.response != BOREAS_TREE_DAMPED) {
      // Quasi-static: all zero.
      for (int p = 0; p < BOREAS_TREE_RESPONSE_PLANES; ++p)
        BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
            response_, 0.0f, (size_t(p) * size_t(capacity_) + size_t(slot.first)) * sizeof(float),
            size_t(slot.count) * sizeof(float)));
      continue;
    }
    omega.assign(size_t(slot.count), 0.0);
    zeta.assign(size_t(slot.count), 0.0);
    for (size_t b = 0; b < m.branches.size(); ++b) {
      const BranchModel br = scaled_branch(m.branches[b], params.scale);
      omega[size_t(block_index(int32_t(b)))] =
          natural_frequency(br, params.levels[size_t(br.level)]);
      zeta[size_t(block_index(int32_t(b)))] = params.levels[size_t(br.level)].damping_ratio;
    }
    std::vector<float> planes = tree_response_planes(omega, zeta, dt);
    runtime_.write_planes(response_, size_t(capacity_), size_t(slot.first), planes.data(),
                          size_t(slot.count), size_t(slot.count), BOREAS_TREE_RESPONSE_PLANES);
  }
  response_dt_ = dt;
}

void TreeBatch::enqueue_leaves(const cl::Buffer& state, int list, TreeStepEvents* events) {
  const size_t groups = tiles_.size(list);
  if (groups == 0) return;
  cl::Kernel& k = runtime_.kernel("tree_leaves.cl", "boreas_tree_leaves", plane_defines());
  bind_args(k, state, int(capacity_), leaf_parents_, leaf_shape_, leaf_out_, int(leaf_capacity_),
            tiles_.buffer(list), 0);
  cl::Event event;
  runtime_.launch_groups(k, groups, events ? &event : nullptr);
  if (events) events->leaves.push_back(event);
}

void TreeBatch::enqueue_step(double dt, const TreeWindInput& wind, TreeStepEvents* events) {
  if (by_key_.empty()) return;
  upload_response(dt);
  update_lods(dt);
  if (rebuild_tiles_ || tiles_.wants_rebuild()) rebuild_tiles();
  tiles_.flush(runtime_);
  const int next = 1 - current_;
  const std::string defines = slot_define("BOREAS_WAVE_SLOTS", wind.wave_slots) + plane_defines();
  cl::Kernel& step = runtime_.kernel("tree_step.cl", "boreas_tree_step", defines);
  cl::Kernel& carry = runtime_.kernel("tree_step.cl", "boreas_tree_step",
                                      defines + "#define BOREAS_TREE_CARRY 1\n");
  const float carry_hold = float(std::exp(-dt / kCarryTimeConstant));
  auto launch = [&](cl::Kernel& k, const cl::Buffer& parent_state, int list) {
    const size_t groups = tiles_.size(list);
    if (groups == 0) return;
    bind_args(k, parent_state, state_[next], parents_, shape_, response_, motion_[current_],
              motion_[next], int(capacity_), tiles_.buffer(list), 0, carry_hold, *wind.waves,
              wind.wave_count, *wind.grid, wind.grid_layout);
    cl::Event event;
    runtime_.launch_groups(k, groups, events ? &event : nullptr);
    if (events) events->branches.push_back(event);
  };
  if (mode_ == BOREAS_TREE_LAGGED) {
    launch(step, state_[current_], tree_step_list(0));
    launch(carry, state_[current_], tree_carry_list(0));
  } else {
    for (int l = 0; l < kMaxTreeLevels; ++l) {
      launch(step, state_[next], tree_step_list(l));
      launch(carry, state_[next], tree_carry_list(l));
    }
  }
  enqueue_leaves(state_[next], tree_leaf_list(0, 0), events);
  enqueue_leaves(state_[next], tree_leaf_list(1, int(step_index_ & 1)), events);
  enqueue_leaves(state_[next], tree_leaf_list(2, int(step_index_ & 3)), events);
}

void TreeBatch::commit() {
  if (by_key_.empty()) return;
  current_ = 1 - current_;
  ++step_index_;
}

std::vector<float> TreeBatch::read_state_prefix(int64_t count) {
  const size_t n = size_t(std::min(count, capacity_));
  std::vector<float> out(size_t(BOREAS_TREE_STATE_PLANES) * n);
  runtime_.read_planes(state_[current_], size_t(capacity_), 0, out.data(), n, n,
                       BOREAS_TREE_STATE_PLANES);
  return out;
}

std::vector<float> TreeBatch::read_tree_state(uint64_t key) {
  const Slot& s = slot_of(key);
  std::vector<float> out(size_t(BOREAS_TREE_STATE_PLANES) * size_t(s.count));
  runtime_.read_planes(state_[current_], size_t(capacity_), size_t(s.first), out.data(),
                       size_t(s.count), size_t(s.count), BOREAS_TREE_STATE_PLANES);
  return out;
}

std::vector<float> TreeBatch::read_tree_motion(uint64_t key) {
  const Slot& s = slot_of(key);
  std::vector<float> out(size_t(BOREAS_TREE_MOTION_PLANES) * size_t(s.count));
  runtime_.read_planes(motion_[current_], size_t(capacity_), size_t(s.first), out.data(),
                       size_t(s.count), size_t(s.count), BOREAS_TREE_MOTION_PLANES);
  return out;
}

std::vector<boreas_branch> TreeBatch::branches(uint64_t key) {
  const Slot& s = slot_of(key);
  const TreeModel& m = *s.tree->model;
  const double scale = s.tree->params.scale;
  const std::vector<float> state = read_tree_state(key);
  const size_t n = size_t(s.count);
  std::vector<boreas_branch> out(m.branches.size());
  for (size_t b = 0; b < m.branches.size(); ++b) {
    const BranchModel& br = m.branches[b];
    const size_t i = size_t(block_index(int32_t(b)));
    boreas_branch& o = out[b];
    for (int k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a) o.control_points[k][a] = state[size_t(3 * k + a) * n + i];
    for (int a = 0; a < 3; ++a) o.orientation[a] = state[size_t(BOREAS_TREE_STATE_O + a) * n + i];
    o.level = br.level;
    o.parent = br.parent;
    o.parent_v = float(br.v);
    o.radius = float(br.radius * scale);
    o.length = float(br.length * scale);
  }
  return out;
}

void TreeBatch::enqueue_branch_records(uint64_t key, const cl::Buffer& out, size_t first_record) {
  const Slot& s = slot_of(key);
  const int count = s.count - 1;
  if (count <= 0) return;
  // A tree's branches are one contiguous range, in its model's order: one launch.
  cl::Kernel& k =
      runtime_.kernel("export_records.cl", "boreas_export_branch_records", plane_defines());
  bind_args(k, state_[current_], radius_, int(capacity_), s.first + 1, count, out,
            static_cast<int>(first_record));
  runtime_.launch(k, size_t(count));
}

void TreeBatch::enqueue_leaf_records(uint64_t key, const cl::Buffer& out, size_t first_record) {
  const Slot& s = slot_of(key);
  if (s.leaf_count == 0) return;
  cl::Kernel& k =
      runtime_.kernel("export_records.cl", "boreas_export_leaf_records", plane_defines());
  bind_args(k, leaf_out_, int(leaf_capacity_), int(s.leaf_first), s.leaf_count, out,
            static_cast<int>(first_record));
  runtime_.launch(k, size_t(s.leaf_count));
}

std::vector<boreas_leaf> TreeBatch::leaves(uint64_t key) {
  const Slot& s = slot_of(key);
  const TreeModel& m = *s.tree->model;
  const double scale = s.tree->params.scale;
  std::vector<boreas_leaf> out(m.leaves.size());
  if (out.empty()) return out;
  const size_t n = size_t(s.leaf_count);
  std::vector<float> planes(size_t(BOREAS_TREE_LEAF_OUT_PLANES) * n);
  runtime_.read_planes(leaf_out_, size_t(leaf_capacity_), size_t(s.leaf_first), planes.data(), n, n,
                       BOREAS_TREE_LEAF_OUT_PLANES);
  for (size_t j = 0; j < n; ++j) {
    boreas_leaf& o = out[j];
    for (int a = 0; a < 3; ++a) {
      o.position[a] = planes[size_t(BOREAS_TREE_LEAF_OUT_POSITION + a) * n + j];
      o.axis[a] = planes[size_t(BOREAS_TREE_LEAF_OUT_AXIS + a) * n + j];
      o.normal[a] = planes[size_t(BOREAS_TREE_LEAF_OUT_NORMAL + a) * n + j];
    }
    o.length = float(m.leaves[j].length * scale);
    o.width = float(m.leaves[j].width * scale);
    o.branch = m.leaves[j].parent;
  }
  return out;
}

void TreeBatch::mesh(uint64_t key, std::vector<boreas_vertex>* vertices,
                     std::vector<uint32_t>* indices) {
  const Slot& s = slot_of(key);
  const TreeModel& m = *s.tree->model;
  const TreeParams& params = s.tree->params;
  // Vertices per level, then one launch per level into one output.
  std::array<int, kMaxTreeLevels> first_vertex{};
  int total = 0;
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    const TreeLevelParams& lp = params.levels[size_t(l)];
    first_vertex[size_t(l)] = total;
    total +=
        (m.level_begin[size_t(l) + 1] - m.level_begin[size_t(l)]) * (lp.rings + 1) * (lp.sides + 1);
  }
  vertices->assign(size_t(total), boreas_vertex{});
  indices->clear();
  if (total == 0) return;
  cl::Buffer out = runtime_.buffer(
      CL_MEM_WRITE_ONLY, size_t(BOREAS_TREE_VERTEX_PLANES) * total * sizeof(float), "tree mesh");
  cl::Kernel& k = runtime_.kernel("tree_deform.cl", "boreas_tree_deform", plane_defines());
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    int count = m.level_begin[size_t(l) + 1] - m.level_begin[size_t(l)];
    if (count == 0) continue;
    const TreeLevelParams& lp = params.levels[size_t(l)];
    bind_args(k, state_[current_], int(capacity_), radius_,
              s.first + block_index(m.level_begin[size_t(l)]), count, lp.rings, lp.sides, out,
              total, first_vertex[size_t(l)]);
    runtime_.launch(k, size_t(count) * (lp.rings + 1) * (lp.sides + 1));
  }
  std::vector<float> planes(size_t(BOREAS_TREE_VERTEX_PLANES) * total);
  runtime_.read(out, 0, planes.size() * sizeof(float), planes.data());
  for (int v = 0; v < total; ++v) {
    boreas_vertex& o = (*vertices)[size_t(v)];
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
    const TreeLevelParams& lp = params.levels[size_t(l)];
    int count = m.level_begin[size_t(l) + 1] - m.level_begin[size_t(l)];
    int row = lp.sides + 1;
    for (int b = 0; b < count; ++b) {
      uint32_t base = uint32_t(first_vertex[size_t(l)] + b * (lp.rings + 1) * row);
      for (int r = 0; r < lp.rings; ++r)
        for (int sd = 0; sd < lp.sides; ++sd) {
          uint32_t i0 = base + uint32_t(r * row + sd), i1 = i0 + 1, i2 = i0 + uint32_t(row),
                   i3 = i2 + 1;
          indices->insert(indices->end(), {i0, i1, i2, i1, i3, i2});
        }
    }
  }
}

}  // namespace boreas::impl
