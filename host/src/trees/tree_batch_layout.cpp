// boreas: where a tree batch's planes lie — the trees' own blocks and the template blocks
// moved into new buffers (grown, or packed past holes) on the device, the index width
// that the buffers' sizes ask of the kernels, and how many trees a batch takes with every
// buffer within the device's largest allocation (a world's chunks: world_chunks.cpp).
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "errors.h"
#include "shared/tree_types.h"
#include "trees/tree_batch.h"

namespace boreas::impl {

// The template blocks' buffers (TreeBatch's parents_ to leaves_) of one capacity.
struct TreeBatch::TemplateBuffers {
  cl::Buffer parents, children, shape, response, radius, leaves;
};

namespace {

std::string text(int64_t n) { return std::to_string(n); }

}  // namespace

TreeBatch::SpaceLimits TreeBatch::space_limits() const {
  // A zero max_allocation (a driver that does not say) limits nothing but the indices.
  const uint64_t largest = runtime_.max_allocation();
  auto most = [&](uint64_t planes, uint64_t elem) {
    const uint64_t by_bytes = largest > 0 ? largest / (planes * elem) : UINT64_MAX;
    return int64_t(std::min<uint64_t>(by_bytes, std::numeric_limits<int32_t>::max()));
  };
  return {most(std::max(BOREAS_TREE_STATE_PLANES, BOREAS_TREE_MOTION_PLANES), sizeof(float)),
          most(BOREAS_TREE_SHAPE_PLANES, sizeof(float)),
          most(BOREAS_TREE_LEAF_PLANES, sizeof(float))};
}

size_t TreeBatch::fitting(const Trees& trees, size_t first) const {
  // The spaces as make_room would find them once packed (used(): the live entries and the
  // sink), the trees taken in order while each space stays within its limit; a template
  // block counts once, and not at all where the batch holds it already.
  const SpaceLimits most = space_limits();
  // Settled entries count as own: they come back into the own planes when stepped.
  int64_t entries = entries_.used() + branches_settled(), statics = static_entries_.used(),
          leaves = static_leaves_.used();
  std::unordered_set<std::string> fresh;
  size_t t = first;
  for (; t < trees.size(); ++t) {
    const TreeModel& m = *trees[t]->model;
    const std::string key = template_block_key(*trees[t]);
    const bool known = template_by_key_.count(key) || fresh.count(key);
    const int64_t count = block_entries(m);
    const int64_t s = statics + (known ? 0 : count), l = leaves + (known ? 0 : m.leaf_count());
    if (entries + count > most.entries || s > most.template_entries || l > most.template_leaves)
      break;
    entries += count;
    statics = s;
    leaves = l;
    if (!known) fresh.insert(key);
  }
  return t - first;
}

bool TreeBatch::uses_wide_planes() const {
  // The widest planes: the template's shape (25 per entry) and leaves (2 ints per leaf),
  // the trees' state (15 per entry).
  constexpr int64_t kMax = std::numeric_limits<int32_t>::max();
  return wide_planes_ || BOREAS_TREE_SHAPE_PLANES * static_entries_.capacity > kMax ||
         BOREAS_TREE_STATE_PLANES * entries_.capacity > kMax ||
         BOREAS_TREE_LEAF_PLANES * static_leaves_.capacity > kMax;
}

std::string TreeBatch::plane_defines() const {
  // Kernels at a SIMD width above 1 index in int (cl/shared/tree_state.h): with 64-bit
  // offsets they are built at width 1.
  return uses_wide_planes() ? "#define BOREAS_WIDE_PLANES 1\n#define BOREAS_W 1\n" : "";
}

int TreeBatch::step_width() const { return uses_wide_planes() ? 1 : runtime_.simd_width(); }

void TreeBatch::relayout_trees(int64_t capacity, bool pack, const std::vector<int32_t>* whole) {
  drop_settled();
  // Readers index settled entries past the own planes' stride (tree_state.h): both in int.
  if (capacity + settled_entries_.capacity > std::numeric_limits<int32_t>::max())
    fail(BOREAS_ERROR_OUT_OF_MEMORY,
         "trees: " + text(capacity) + " branch entries and " + text(settled_entries_.capacity) +
             " settled ones pass one batch's 2^31 indices");
  const size_t c = size_t(capacity), old_stride = size_t(entries_.capacity);
  const bool wide = uses_wide_planes();
  const std::string label = "trees (" + text(capacity) + " branch entries)";
  cl::Buffer state[2], motion[2];
  for (int k = 0; k < 2; ++k) {
    state[k] = runtime_.buffer(CL_MEM_READ_WRITE,
                               size_t(BOREAS_TREE_STATE_PLANES) * c * sizeof(float), label.c_str());
    motion[k] = runtime_.buffer(CL_MEM_READ_WRITE, size_t(motion_planes_) * c * sizeof(float),
                                label.c_str());
  }
  const PlanePair sets[] = {
      {&state_[0], &state[0], BOREAS_TREE_STATE_PLANES, sizeof(float)},
      {&state_[1], &state[1], BOREAS_TREE_STATE_PLANES, sizeof(float)},
      {&motion_[0], &motion[0], motion_planes_, sizeof(float)},
      {&motion_[1], &motion[1], motion_planes_, sizeof(float)},
  };
  // Where every tree goes: packed after the sink in the order of the old indices, or
  // where it is.
  // A settled tree's block ends at its settled entries.
  std::vector<Slot*> live;
  std::vector<std::pair<int64_t, int64_t>> blocks;
  for (Slot& slot : slots_)
    if (slot.tree) {
      live.push_back(&slot);
      blocks.push_back({slot.first, own_count(slot)});
    }
  BlockPlan plan = plan_block_moves(blocks, pack);
  if (whole) lay_whole_blocks(*whole, &plan);
  if (entries_.capacity == 0) {
    // A new batch: the sink (the layout of no trees).
    TreeLayout sink = tree_layout({});
    for (int k = 0; k < 2; ++k) {
      runtime_.write_planes(state[k], c, 0, sink.state.data(), 1, 1, BOREAS_TREE_STATE_PLANES);
      runtime_.write_planes(motion[k], c, 0, sink.motion.data(), 1, 1, size_t(motion_planes_));
    }
  } else {
    copy_block_moves(runtime_, plan.moves, sets, std::size(sets), size_t(entries_.capacity), c);
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());

  // Nothing failed: the batch takes the new buffers and indices.
  for (size_t k = 0; k < live.size(); ++k) live[k]->first = int32_t(plan.to[k]);
  if (pack) entries_.packed(plan.end);
  entries_.capacity = capacity;
  for (int k = 0; k < 2; ++k) {
    state_[k] = state[k];
    motion_[k] = motion[k];
  }
  if (plan.moves_any) rebuild_tiles_ = records_stale_ = true;
  if (uses_wide_planes() != wide) records_stale_ = true;  // leaf tiles follow step_width()
  if (plan.moves_any) rewrite_derived_marks();  // they name entries
  // Settled readers' indices count from the stride (tree_state.h): their tiles anew.
  if (settled_entries_.capacity > 0 && c != old_stride) records_stale_ = true;
  // The contact loads are not moved: touched trees start from none again (a step's lag).
  contact_stale_ = true;
}

void TreeBatch::lay_whole_blocks(const std::vector<int32_t>& whole, BlockPlan* plan) const {
  // Packed again with these blocks whole: each keeps its own entries' copy, and the next
  // block starts after its whole length.
  std::vector<std::pair<int64_t, int64_t>> blocks;
  std::unordered_set<int32_t> firsts;
  for (int32_t s : whole) firsts.insert(slots_[size_t(s)].first);
  for (const Slot& slot : slots_)
    if (slot.tree)
      blocks.push_back({slot.first, firsts.count(slot.first) ? slot.count : own_count(slot)});
  BlockPlan laid = plan_block_moves(blocks, true);
  for (BlockMove& m : laid.moves)
    if (firsts.count(int32_t(m.from))) {
      const Slot* slot = nullptr;
      for (int32_t s : whole)
        if (slots_[size_t(s)].first == m.from) slot = &slots_[size_t(s)];
      m.length = own_count(*slot);
    }
  *plan = laid;
}

void TreeBatch::relayout_templates(int64_t capacity, int64_t leaf_capacity, bool pack) {
  if (capacity > std::numeric_limits<int32_t>::max() ||
      leaf_capacity > std::numeric_limits<int32_t>::max())
    fail(BOREAS_ERROR_OUT_OF_MEMORY, "tree templates: " + text(capacity) + " branch entries and " +
                                         text(leaf_capacity) +
                                         " leaves pass one batch's 2^31 indices");
  const size_t c = size_t(capacity), lc = size_t(leaf_capacity);
  const bool wide = uses_wide_planes();
  TemplateBuffers b = template_buffers(c, lc);
  // Blocks are placed in the same order in both spaces, so packing keeps them in step.
  std::vector<Template*> live;
  std::vector<std::pair<int64_t, int64_t>> blocks, leaf_blocks;
  for (Template& tp : templates_)
    if (tp.block) {
      live.push_back(&tp);
      blocks.push_back({tp.first, tp.block->count});
      leaf_blocks.push_back({tp.leaf_first, tp.block->leaf_count});
    }
  const BlockPlan plan = plan_block_moves(blocks, pack),
                  leaf_plan = plan_block_moves(leaf_blocks, pack);
  if (static_entries_.capacity == 0)
    write_template_sink(b, c, lc);
  else
    copy_template_blocks(b, plan, leaf_plan, c, lc);
  BOREAS_CL_CHECK(runtime_.queue().finish());

  for (size_t k = 0; k < live.size(); ++k) {
    live[k]->first = int32_t(plan.to[k]);
    live[k]->leaf_first = leaf_plan.to[k];
  }
  if (pack) {
    static_entries_.packed(plan.end);
    static_leaves_.packed(leaf_plan.end);
  }
  static_entries_.capacity = capacity;
  static_leaves_.capacity = leaf_capacity;
  parents_ = b.parents;
  children_ = b.children;
  shape_ = b.shape;
  response_ = b.response;
  radius_ = b.radius;
  leaves_ = b.leaves;
  if (plan.moves_any || leaf_plan.moves_any) rebuild_tiles_ = records_stale_ = true;
  if (uses_wide_planes() != wide) records_stale_ = true;  // leaf tiles follow step_width()
  if (plan.moves_any) rewrite_derived_marks();  // they name template entries
}

TreeBatch::TemplateBuffers TreeBatch::template_buffers(size_t c, size_t lc) {
  const std::string label =
      "tree templates (" + text(int64_t(c)) + " branch entries, " + text(int64_t(lc)) + " leaves)";
  TemplateBuffers b;
  b.parents = runtime_.buffer(CL_MEM_READ_ONLY, c * sizeof(int32_t), label.c_str());
  if (children_())
    b.children = runtime_.buffer(
        CL_MEM_READ_ONLY, size_t(BOREAS_TREE_CHILD_PLANES) * c * sizeof(int32_t), label.c_str());
  b.shape = runtime_.buffer(CL_MEM_READ_ONLY, size_t(BOREAS_TREE_SHAPE_PLANES) * c * sizeof(float),
                            label.c_str());
  if (holds_rates())
    b.response = runtime_.buffer(
        CL_MEM_READ_ONLY, size_t(BOREAS_TREE_RESPONSE_PLANES) * c * sizeof(float), label.c_str());
  b.radius = runtime_.buffer(CL_MEM_READ_ONLY,
                             size_t(BOREAS_TREE_RADIUS_PLANES) * c * sizeof(float), label.c_str());
  b.leaves = runtime_.buffer(
      CL_MEM_READ_ONLY, size_t(BOREAS_TREE_LEAF_PLANES) * lc * sizeof(int32_t), label.c_str());
  return b;
}

void TreeBatch::write_template_sink(const TemplateBuffers& b, size_t c, size_t lc) {
  // A new batch: the sink's template entry and leaf.
  TreeLayout sink = tree_layout({});
  std::vector<float> zeros(BOREAS_TREE_RESPONSE_PLANES + BOREAS_TREE_RADIUS_PLANES, 0.0f);
  runtime_.write_planes(b.parents, c, 0, sink.parents.data(), 1, 1, 1, sizeof(int32_t));
  const int32_t no_children[BOREAS_TREE_CHILD_PLANES] = {};
  if (b.children())
    runtime_.write_planes(b.children, c, 0, no_children, 1, 1, BOREAS_TREE_CHILD_PLANES,
                          sizeof(int32_t));
  runtime_.write_planes(b.shape, c, 0, sink.shape.data(), 1, 1, BOREAS_TREE_SHAPE_PLANES);
  if (b.response()) runtime_.write_planes(b.response, c, 0, zeros.data(), 1, 1, BOREAS_TREE_RESPONSE_PLANES);
  runtime_.write_planes(b.radius, c, 0, zeros.data(), 1, 1, BOREAS_TREE_RADIUS_PLANES);
  runtime_.write_planes(b.leaves, lc, 0, sink.leaves.data(), 1, 1, BOREAS_TREE_LEAF_PLANES,
                        sizeof(int32_t));
}

void TreeBatch::copy_template_blocks(TemplateBuffers& b, const BlockPlan& plan,
                                     const BlockPlan& leaf_plan, size_t c, size_t lc) {
  // The children and response planes where the batch has them (make_children, hold_rates).
  std::vector<PlanePair> sets = {
      {&parents_, &b.parents, 1, sizeof(int32_t)},
      {&shape_, &b.shape, BOREAS_TREE_SHAPE_PLANES, sizeof(float)},
      {&radius_, &b.radius, BOREAS_TREE_RADIUS_PLANES, sizeof(float)},
  };
  if (b.children()) sets.push_back({&children_, &b.children, BOREAS_TREE_CHILD_PLANES, sizeof(int32_t)});
  if (b.response()) sets.push_back({&response_, &b.response, BOREAS_TREE_RESPONSE_PLANES, sizeof(float)});
  const PlanePair leaf_sets[] = {
      {&leaves_, &b.leaves, BOREAS_TREE_LEAF_PLANES, sizeof(int32_t)},
  };
  copy_block_moves(runtime_, plan.moves, sets.data(), sets.size(), size_t(static_entries_.capacity),
                   c);
  copy_block_moves(runtime_, leaf_plan.moves, leaf_sets, std::size(leaf_sets),
                   size_t(static_leaves_.capacity), lc);
}

void TreeBatch::hold_rates() {
  // A batch of quasi-static trees holds neither dF/dt nor response planes (both 0 for its
  // branches): the first damped template brings them, zero, for every entry. Its buffers
  // exist where the batch has any: new motion buffers with the still planes copied and
  // dF/dt zeroed, and a zeroed response buffer; made and filled before the batch takes
  // them, so a failure leaves it as it was.
  if (holds_rates()) return;
  const size_t c = size_t(entries_.capacity), sc = size_t(static_entries_.capacity);
  constexpr int kStill = BOREAS_TREE_MOTION_STILL_PLANES;
  cl::Buffer motion[2], response;
  if (c > 0)
    for (int k = 0; k < 2; ++k) {
      motion[k] = runtime_.buffer(CL_MEM_READ_WRITE,
                                  size_t(BOREAS_TREE_MOTION_PLANES) * c * sizeof(float),
                                  ("trees (" + text(int64_t(c)) + " branch entries)").c_str());
      runtime_.copy_planes(motion_[k], c, 0, motion[k], c, 0, c, kStill);
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          motion[k], 0.0f, size_t(kStill) * c * sizeof(float),
          size_t(BOREAS_TREE_MOTION_PLANES - kStill) * c * sizeof(float)));
    }
  if (sc > 0) {
    response = runtime_.buffer(CL_MEM_READ_ONLY,
                               size_t(BOREAS_TREE_RESPONSE_PLANES) * sc * sizeof(float),
                               ("tree templates (" + text(int64_t(sc)) + " response entries)").c_str());
    BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
        response, 0.0f, 0, size_t(BOREAS_TREE_RESPONSE_PLANES) * sc * sizeof(float)));
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());
  if (c > 0)
    for (int k = 0; k < 2; ++k) motion_[k] = motion[k];
  response_ = response;
  response_dt_ = -1.0;  // the damped blocks' response written by the next step
  motion_planes_ = BOREAS_TREE_MOTION_PLANES;
}

void TreeBatch::release_rates() {
  const size_t c = size_t(entries_.capacity);
  constexpr int kStill = BOREAS_TREE_MOTION_STILL_PLANES;
  cl::Buffer motion[2];
  if (c > 0) {
    for (int k = 0; k < 2; ++k) {
      motion[k] = runtime_.buffer(CL_MEM_READ_WRITE, size_t(kStill) * c * sizeof(float),
                                  ("trees (" + text(int64_t(c)) + " branch entries)").c_str());
      runtime_.copy_planes(motion_[k], c, 0, motion[k], c, 0, c, kStill);
    }
    BOREAS_CL_CHECK(runtime_.queue().finish());
    for (int k = 0; k < 2; ++k) motion_[k] = motion[k];
  }
  response_ = cl::Buffer();
  motion_planes_ = kStill;
}

std::string TreeBatch::step_defines(const PlantWind& wind) const {
  return wind.defines() + plane_defines() + (holds_rates() ? "" : "#define BOREAS_TREE_STILL 1\n");
}

}  // namespace boreas::impl
