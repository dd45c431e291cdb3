// boreas: a batch of trees on the device — template blocks and the trees' own blocks,
// growth, holes, levels of detail, the step launches, readbacks.
#include "trees/tree_batch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>

#include "errors.h"
#include "parallel_for.h"
#include "runtime/kernel_defines.h"
#include "runtime/launch.h"
#include "runtime/mapped_planes.h"
#include "shared/tree_types.h"

namespace boreas::impl {

namespace {

std::string text(int64_t n) { return std::to_string(n); }

// An exact, short text of a double for keys.
std::string exact(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%a", v);
  return buffer;
}

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

std::string TreeBatch::template_block_key(const TreeInstance& tree) {
  const TreeParams& p = tree.params;
  // The model (its template key; trees built by hand share by pointer), and what the block
  // holds beyond it: compliance (load, stiffness), w2 (bend exponent), the response
  // (frequencies at the tree's scale when damped).
  std::string key = tree.template_key.empty()
                        ? "model:" + std::to_string(reinterpret_cast<uintptr_t>(tree.model.get()))
                        : tree.template_key;
  key += p.load == BOREAS_TREE_LOAD_DRAG ? "|drag" : "|linear";
  key += "|" + exact(p.bend_exponent);
  for (const TreeLevelParams& l : p.levels) key += "|" + exact(l.stiffness);
  if (p.response == BOREAS_TREE_DAMPED) {
    key += "|damped|" + exact(p.scale);
    for (const TreeLevelParams& l : p.levels)
      key += "|" + exact(l.frequency_scale) + "|" + exact(l.damping_ratio);
  }
  return key;
}

TreeTileSource TreeBatch::tile_source(const Slot& slot) const {
  const Template& t = template_of(slot);
  TreeTileSource at;
  at.first = slot.first;
  at.static_first = t.first;
  at.scale = slot.tree->params.scale;
  return at;
}

bool TreeBatch::uses_wide_planes() const {
  // The widest planes: the template's shape (16 per entry) and leaves (6 per leaf), the
  // trees' state (15 per entry).
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

void TreeBatch::relayout_trees(int64_t capacity, bool pack) {
  if (capacity > std::numeric_limits<int32_t>::max())
    fail(BOREAS_ERROR_OUT_OF_MEMORY,
         "trees: " + text(capacity) + " branch entries pass one batch's 2^31 indices");
  const size_t c = size_t(capacity);
  const std::string label = "trees (" + text(capacity) + " branch entries)";
  cl::Buffer state[2], motion[2];
  for (int k = 0; k < 2; ++k) {
    state[k] = runtime_.buffer(CL_MEM_READ_WRITE,
                               size_t(BOREAS_TREE_STATE_PLANES) * c * sizeof(float), label.c_str());
    motion[k] = runtime_.buffer(
        CL_MEM_READ_WRITE, size_t(BOREAS_TREE_MOTION_PLANES) * c * sizeof(float), label.c_str());
  }
  const PlanePair sets[] = {
      {&state_[0], &state[0], BOREAS_TREE_STATE_PLANES, sizeof(float)},
      {&state_[1], &state[1], BOREAS_TREE_STATE_PLANES, sizeof(float)},
      {&motion_[0], &motion[0], BOREAS_TREE_MOTION_PLANES, sizeof(float)},
      {&motion_[1], &motion[1], BOREAS_TREE_MOTION_PLANES, sizeof(float)},
  };
  // Where every tree goes: packed after the sink in the order of the old indices, or
  // where it is.
  std::vector<Slot*> live;
  std::vector<std::pair<int64_t, int64_t>> blocks;
  for (Slot& slot : slots_)
    if (slot.tree) {
      live.push_back(&slot);
      blocks.push_back({slot.first, slot.count});
    }
  const BlockPlan plan = plan_block_moves(blocks, pack);
  if (entries_.capacity == 0) {
    // A new batch: the sink (the layout of no trees).
    TreeLayout sink = tree_layout({});
    for (int k = 0; k < 2; ++k) {
      runtime_.write_planes(state[k], c, 0, sink.state.data(), 1, 1, BOREAS_TREE_STATE_PLANES);
      runtime_.write_planes(motion[k], c, 0, sink.motion.data(), 1, 1, BOREAS_TREE_MOTION_PLANES);
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
  if (plan.moves_any) rebuild_tiles_ = true;
}

void TreeBatch::relayout_templates(int64_t capacity, int64_t leaf_capacity, bool pack) {
  if (capacity > std::numeric_limits<int32_t>::max() ||
      leaf_capacity > std::numeric_limits<int32_t>::max())
    fail(BOREAS_ERROR_OUT_OF_MEMORY, "tree templates: " + text(capacity) + " branch entries and " +
                                         text(leaf_capacity) +
                                         " leaves pass one batch's 2^31 indices");
  const size_t c = size_t(capacity), lc = size_t(leaf_capacity);
  const std::string label =
      "tree templates (" + text(capacity) + " branch entries, " + text(leaf_capacity) + " leaves)";
  cl::Buffer parents, shape, response, radius, leaf_parents, leaf_shape;
  parents = runtime_.buffer(CL_MEM_READ_ONLY, c * sizeof(int32_t), label.c_str());
  shape = runtime_.buffer(CL_MEM_READ_ONLY, size_t(BOREAS_TREE_SHAPE_PLANES) * c * sizeof(float),
                          label.c_str());
  response = runtime_.buffer(
      CL_MEM_READ_ONLY, size_t(BOREAS_TREE_RESPONSE_PLANES) * c * sizeof(float), label.c_str());
  radius = runtime_.buffer(CL_MEM_READ_ONLY, size_t(BOREAS_TREE_RADIUS_PLANES) * c * sizeof(float),
                           label.c_str());
  leaf_parents = runtime_.buffer(CL_MEM_READ_ONLY, lc * sizeof(int32_t), label.c_str());
  leaf_shape = runtime_.buffer(CL_MEM_READ_ONLY,
                               size_t(BOREAS_TREE_LEAF_PLANES) * lc * sizeof(float), label.c_str());
  const PlanePair sets[] = {
      {&parents_, &parents, 1, sizeof(int32_t)},
      {&shape_, &shape, BOREAS_TREE_SHAPE_PLANES, sizeof(float)},
      {&response_, &response, BOREAS_TREE_RESPONSE_PLANES, sizeof(float)},
      {&radius_, &radius, BOREAS_TREE_RADIUS_PLANES, sizeof(float)},
  };
  const PlanePair leaf_sets[] = {
      {&leaf_parents_, &leaf_parents, 1, sizeof(int32_t)},
      {&leaf_shape_, &leaf_shape, BOREAS_TREE_LEAF_PLANES, sizeof(float)},
  };
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
  if (static_entries_.capacity == 0) {
    // A new batch: the sink's template entry and leaf.
    TreeLayout sink = tree_layout({});
    std::vector<float> zeros(BOREAS_TREE_RESPONSE_PLANES + BOREAS_TREE_RADIUS_PLANES, 0.0f);
    runtime_.write_planes(parents, c, 0, sink.parents.data(), 1, 1, 1, sizeof(int32_t));
    runtime_.write_planes(shape, c, 0, sink.shape.data(), 1, 1, BOREAS_TREE_SHAPE_PLANES);
    runtime_.write_planes(response, c, 0, zeros.data(), 1, 1, BOREAS_TREE_RESPONSE_PLANES);
    runtime_.write_planes(radius, c, 0, zeros.data(), 1, 1, BOREAS_TREE_RADIUS_PLANES);
    runtime_.write_planes(leaf_parents, lc, 0, sink.leaf_parents.data(), 1, 1, 1, sizeof(int32_t));
    runtime_.write_planes(leaf_shape, lc, 0, sink.leaf_shape.data(), 1, 1, BOREAS_TREE_LEAF_PLANES);
  } else {
    copy_block_moves(runtime_, plan.moves, sets, std::size(sets), size_t(static_entries_.capacity),
                     c);
    copy_block_moves(runtime_, leaf_plan.moves, leaf_sets, std::size(leaf_sets),
                     size_t(static_leaves_.capacity), lc);
  }
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
  parents_ = parents;
  shape_ = shape;
  response_ = response;
  radius_ = radius;
  leaf_parents_ = leaf_parents;
  leaf_shape_ = leaf_shape;
  if (plan.moves_any || leaf_plan.moves_any) rebuild_tiles_ = true;
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
  // The phase of its carried branches: its slot, which moves never change.
  const int phase = int(&slot - slots_.data());
  add_tree_tiles(tiles_, mode_, *slot.tree->model, tile_source(slot), slot.lod, slot.hold, phase,
                 int(runtime_.group_size()), &slot.tiles);
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

  // 1. Template blocks: the known ones found, the new ones listed (built in 3, once each).
  struct NewTemplate {
    std::string key;
    size_t tree = 0;  // the first tree that has it
    std::shared_ptr<const TreeTemplateBlock> block;
    int64_t count = 0, leaf_count = 0;  // its entries (root and branches) and leaves
    int64_t first = 0, leaf_first = 0;  // offsets among the new blocks
  };
  std::vector<NewTemplate> fresh;
  std::unordered_map<std::string, size_t> fresh_by_key;
  std::vector<int64_t> tree_template(trees.size());  // >= 0: known index; < 0: -(1 + fresh index)
  int64_t static_need = 0, static_leaf_need = 0;
  for (size_t t = 0; t < trees.size(); ++t) {
    const std::string key = template_block_key(*trees[t]);
    if (auto it = template_by_key_.find(key); it != template_by_key_.end()) {
      tree_template[t] = it->second;
      continue;
    }
    auto it = fresh_by_key.find(key);
    if (it == fresh_by_key.end()) {
      NewTemplate n;
      n.key = key;
      n.tree = t;
      it = fresh_by_key.emplace(key, fresh.size()).first;
      fresh.push_back(std::move(n));
    }
    tree_template[t] = -1 - int64_t(it->second);
  }
  // 2. Room, from the new templates' sizes (a block holds the root, every branch and every
  //    leaf of its model): the spaces grow by doubling (holes squeezed out on the way).
  for (NewTemplate& n : fresh) {
    const TreeModel& m = *trees[n.tree]->model;
    n.count = block_entries(m);
    n.leaf_count = int64_t(m.leaves.size());
    n.first = static_need;
    n.leaf_first = static_leaf_need;
    static_need += n.count;
    static_leaf_need += n.leaf_count;
  }
  int64_t need = 0;
  for (size_t t = 0; t < trees.size(); ++t)
    need += tree_template[t] >= 0 ? templates_[size_t(tree_template[t])].block->count
                                  : fresh[size_t(-1 - tree_template[t])].count;
  if (!static_entries_.fits(static_need) || !static_leaves_.fits(static_leaf_need)) {
    const bool pack = static_entries_.dead > 0 || static_leaves_.dead > 0;
    relayout_templates(static_entries_.grown(static_need, 256),
                       static_leaves_.grown(static_leaf_need, 1024), pack);
  }
  if (!entries_.fits(need)) relayout_trees(entries_.grown(need, 256), entries_.dead > 0);

  // 3. The new template blocks, laid out on every core (each from its template alone) and
  //    copied straight into the buffers, mapped past their ends: on a CPU device that is
  //    the buffers' own memory, so a batch of distinct trees (over a gigabyte of leaves)
  //    is neither staged nor copied by one thread. The host keeps of each block what later
  //    adds and a new dt read: its rest pose and frequencies.
  const size_t sc = size_t(static_entries_.capacity), slc = size_t(static_leaves_.capacity);
  const int64_t static_at = static_entries_.end, static_leaf_at = static_leaves_.end;
  if (!fresh.empty()) {
    const size_t n = size_t(static_need), ln = size_t(static_leaf_need);
    MappedPlanes parents(runtime_, parents_, sc, size_t(static_at), n, 1, sizeof(int32_t));
    MappedPlanes shape(runtime_, shape_, sc, size_t(static_at), n, BOREAS_TREE_SHAPE_PLANES);
    MappedPlanes radius(runtime_, radius_, sc, size_t(static_at), n, BOREAS_TREE_RADIUS_PLANES);
    MappedPlanes leaf_parents(runtime_, leaf_parents_, slc, size_t(static_leaf_at), ln, 1,
                              sizeof(int32_t));
    MappedPlanes leaf_shape(runtime_, leaf_shape_, slc, size_t(static_leaf_at), ln,
                            BOREAS_TREE_LEAF_PLANES);
    // A block's planes into the mapped ones, from its offset among the new blocks.
    auto place = [](const MappedPlanes& to, int64_t first, const auto& from, int64_t count,
                    int planes) {
      using T = typename std::decay_t<decltype(from)>::value_type;
      if (count == 0) return;  // nothing mapped: a leafless block has no leaf planes
      for (int k = 0; k < planes; ++k)
        std::copy_n(from.begin() + ptrdiff_t(k * count), count, to.plane<T>(size_t(k)) + first);
    };
    parallel_for(fresh.size(), [&](size_t f) {
      NewTemplate& nt = fresh[f];
      const TreeInstance& tree = *trees[nt.tree];
      TreeTemplateBlock b = tree_template_block(tree.params, *tree.model);
      place(parents, nt.first, b.parents, b.count, 1);
      place(shape, nt.first, b.shape, b.count, BOREAS_TREE_SHAPE_PLANES);
      place(radius, nt.first, b.radius, b.count, BOREAS_TREE_RADIUS_PLANES);
      place(leaf_parents, nt.leaf_first, b.leaf_parents, b.leaf_count, 1);
      place(leaf_shape, nt.leaf_first, b.leaf_shape, b.leaf_count, BOREAS_TREE_LEAF_PLANES);
      std::vector<int32_t>().swap(b.parents);
      std::vector<float>().swap(b.shape);
      std::vector<float>().swap(b.radius);
      std::vector<int32_t>().swap(b.leaf_parents);
      std::vector<float>().swap(b.leaf_shape);
      nt.block = std::make_shared<const TreeTemplateBlock>(std::move(b));
    });
    parents.unmap();
    shape.unmap();
    radius.unmap();
    leaf_parents.unmap();
    leaf_shape.unmap();
    // The response for the current step (zero for quasi-static branches, and until a
    // first step sets dt).
    std::vector<double> omega(n), zeta(n);
    for (const NewTemplate& f : fresh) {
      std::copy(f.block->omega.begin(), f.block->omega.end(), omega.begin() + ptrdiff_t(f.first));
      std::copy(f.block->zeta.begin(), f.block->zeta.end(), zeta.begin() + ptrdiff_t(f.first));
    }
    const std::vector<float> response =
        tree_response_planes(omega, zeta, response_dt_ > 0.0 ? response_dt_ : 1.0);
    runtime_.write_planes(response_, sc, size_t(static_at), response.data(), n, n,
                          BOREAS_TREE_RESPONSE_PLANES);
  }
  auto block_of = [&](size_t t) -> const TreeTemplateBlock& {
    return tree_template[t] >= 0 ? *templates_[size_t(tree_template[t])].block
                                 : *fresh[size_t(-1 - tree_template[t])].block;
  };

  // 4. The trees' own state: each its template's rest pose, placed; one upload.
  const size_t c = size_t(entries_.capacity);
  const int64_t first = entries_.end;
  std::vector<int64_t> tree_first(trees.size());
  {
    std::vector<float> rest(size_t(BOREAS_TREE_STATE_PLANES) * size_t(need));
    int64_t at = 0;
    for (size_t t = 0; t < trees.size(); ++t) {
      const TreeTemplateBlock& b = block_of(t);
      place_rest(b, trees[t]->params, rest.data(), size_t(need), size_t(at));
      tree_first[t] = first + at;
      at += b.count;
    }
    runtime_.write_planes(state_[current_], c, size_t(first), rest.data(), size_t(need),
                          size_t(need), BOREAS_TREE_STATE_PLANES);
  }
  runtime_.copy_planes(state_[current_], c, size_t(first), state_[1 - current_], c, size_t(first),
                       size_t(need), BOREAS_TREE_STATE_PLANES);
  // At rest the motion is zero: filled on the device, nothing to upload.
  for (int k = 0; k < 2; ++k)
    for (int p = 0; p < BOREAS_TREE_MOTION_PLANES; ++p)
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          motion_[k], 0.0f, (size_t(p) * c + size_t(first)) * sizeof(float),
          size_t(need) * sizeof(float)));

  BOREAS_CL_CHECK(runtime_.queue().finish());

  // 5. Everything is on the device: the batch takes the templates and the trees.
  std::vector<int32_t> fresh_index(fresh.size());
  for (size_t f = 0; f < fresh.size(); ++f) {
    Template tp;
    tp.key = fresh[f].key;
    tp.block = fresh[f].block;
    tp.first = int32_t(static_at + fresh[f].first);
    tp.leaf_first = static_leaf_at + fresh[f].leaf_first;
    int32_t index;
    if (!free_templates_.empty()) {
      index = free_templates_.back();
      free_templates_.pop_back();
      templates_[size_t(index)] = std::move(tp);
    } else {
      index = int32_t(templates_.size());
      templates_.push_back(std::move(tp));
    }
    template_by_key_.emplace(fresh[f].key, index);
    fresh_index[f] = index;
  }
  static_entries_.end += static_need;
  static_leaves_.end += static_leaf_need;
  for (size_t t = 0; t < trees.size(); ++t) {
    Slot slot;
    slot.tree = trees[t];
    slot.template_index = tree_template[t] >= 0 ? int32_t(tree_template[t])
                                                : fresh_index[size_t(-1 - tree_template[t])];
    ++templates_[size_t(slot.template_index)].users;
    slot.first = int32_t(tree_first[t]);
    slot.count = block_of(t).count;
    slot.leaf_count = block_of(t).leaf_count;
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
  entries_.end += need;
  branch_count_ += need - int64_t(trees.size());
  for (size_t t = 0; t < trees.size(); ++t) leaf_count_ += block_of(t).leaf_count;
}

void TreeBatch::remove(uint64_t key) {
  auto it = by_key_.find(key);
  if (it == by_key_.end())
    fail(BOREAS_ERROR_INTERNAL, "tree batch has no tree with key " + std::to_string(key));
  const int32_t s = it->second;
  Slot& slot = slots_[size_t(s)];
  untile(slot);
  entries_.release(slot.first, slot.count);
  branch_count_ -= slot.count - 1;
  leaf_count_ -= slot.leaf_count;
  // The last tree of a template block lets it go.
  Template& tp = templates_[size_t(slot.template_index)];
  if (--tp.users == 0) {
    static_entries_.release(tp.first, tp.block->count);
    static_leaves_.release(tp.leaf_first, tp.block->leaf_count);
    template_by_key_.erase(tp.key);
    free_templates_.push_back(slot.template_index);
    tp = Template{};
  }
  slot = Slot{};
  free_slots_.push_back(s);
  by_key_.erase(it);
  if (by_key_.empty()) {
    entries_.clear();
    static_entries_.clear();
    static_leaves_.clear();
    tiles_.clear();
    return;
  }
  // Holes past half a space: pack it (device copies, amortized over the removals that
  // made the holes). A failure here only leaves the holes where they were.
  try {
    if (entries_.wants_packing()) relayout_trees(entries_.capacity, true);
    if (static_entries_.wants_packing() || static_leaves_.wants_packing())
      relayout_templates(static_entries_.capacity, static_leaves_.capacity, true);
  } catch (const Error&) {
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
  const size_t c = size_t(entries_.capacity);
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
        runtime_.copy_planes(state_[current_], c, size_t(slot.first), state_[next], c,
                             size_t(slot.first), size_t(slot.count), BOREAS_TREE_STATE_PLANES);
        runtime_.copy_planes(motion_[current_], c, size_t(slot.first), motion_[next], c,
                             size_t(slot.first), size_t(slot.count), BOREAS_TREE_MOTION_PLANES);
        slot.frozen = true;
        retile = true;
      }
    }
    const float hold = slot.resume_left > 0.0 ? resume_hold : 0.0f;
    if (hold != slot.hold && (hold == 0.0f || slot.hold == 0.0f || new_dt)) retile = true;
    slot.hold = hold;
    slot.resume_left = std::max(0.0, slot.resume_left - dt);
    if (retile) {
      // Its branches may be updated in other steps from now on: both halves of the state
      // start equal, so none shows an older value whatever its new rate and phase.
      if (!slot.frozen) {
        runtime_.copy_planes(state_[current_], c, size_t(slot.first), state_[next], c,
                             size_t(slot.first), size_t(slot.count), BOREAS_TREE_STATE_PLANES);
        runtime_.copy_planes(motion_[current_], c, size_t(slot.first), motion_[next], c,
                             size_t(slot.first), size_t(slot.count), BOREAS_TREE_MOTION_PLANES);
      }
      if (!rebuild_tiles_) {
        untile(slot);
        tile(slot);
      }
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
  // The damped template blocks' response for the new dt (quasi-static ones stay zero; a
  // fixed time step computes it once).
  for (const Template& tp : templates_) {
    if (!tp.block) continue;
    const TreeTemplateBlock& b = *tp.block;
    if (std::none_of(b.omega.begin(), b.omega.end(), [](double w) { return w > 0.0; })) continue;
    const std::vector<float> planes = tree_response_planes(b.omega, b.zeta, dt);
    runtime_.write_planes(response_, size_t(static_entries_.capacity), size_t(tp.first),
                          planes.data(), size_t(b.count), size_t(b.count),
                          BOREAS_TREE_RESPONSE_PLANES);
  }
  response_dt_ = dt;
}

void TreeBatch::enqueue_leaves(const Slot& slot, const cl::Buffer& out, size_t first_record) {
  if (slot.leaf_count == 0) return;
  const Template& tp = template_of(slot);
  cl::Kernel& k = runtime_.kernel("tree_leaves.cl", "boreas_tree_leaves", plane_defines());
  // step_width() leaves per work-item (tree_leaves.cl).
  launch(runtime_, k, Items(size_t(slot.leaf_count)).per_work_item(size_t(step_width())),
         state_[current_], int(entries_.capacity), leaf_parents_, leaf_shape_,
         int(static_leaves_.capacity), int(tp.leaf_first), slot.leaf_count, slot.first,
         float(slot.tree->params.scale), out, static_cast<int>(first_record));
}

void TreeBatch::enqueue_step(double dt, const PlantWind& wind, TreeStepEvents* events) {
  if (by_key_.empty()) return;
  upload_response(dt);
  update_lods(dt);
  if (rebuild_tiles_ || tiles_.wants_rebuild()) rebuild_tiles();
  tiles_.flush(runtime_);
  const int next = 1 - current_;
  const std::string defines = wind.defines() + plane_defines();
  cl::Kernel& step = runtime_.kernel("tree_step.cl", "boreas_tree_step", defines);
  cl::Kernel& carry = runtime_.kernel("tree_step.cl", "boreas_tree_step",
                                      defines + "#define BOREAS_TREE_CARRY 1\n");
  // step_width() branches per work-item (tree_step.cl), a tile of group_size() per group.
  const size_t width = size_t(step_width());
  auto step_list = [&](cl::Kernel& k, const cl::Buffer& parent_state, int list, float carry_hold) {
    const size_t tiles = tiles_.size(list);
    if (tiles == 0) return;
    cl::Event event =
        launch(runtime_, k, Items(tiles * runtime_.group_size()).per_work_item(width), parent_state,
               state_[next], parents_, shape_, response_, motion_[current_], motion_[next],
               state_[current_], motion_[current_], int(entries_.capacity),
               int(static_entries_.capacity), tiles_.buffer(list), 0, carry_hold, *wind.waves,
               wind.wave_count, *wind.grid, wind.grid_layout);
    if (events) events->branches.push_back(event);
  };
  // Stepped branches: one launch (lagged, parents from the committed state) or one per
  // step tier (exact). Carried ones of rate r in the steps of their phase, with r dt (their
  // bend decays by exp(-r dt / tau)), tier by tier after the stepped ones, on their
  // parents' new state in both modes. Empty lists launch nothing.
  if (mode_ == BOREAS_TREE_LAGGED) step_list(step, state_[current_], tree_step_list(0), 0.0f);
  for (int t = 0; t < kMaxTreeTiers; ++t) {
    if (mode_ == BOREAS_TREE_EXACT) step_list(step, state_[next], tree_step_list(t), 0.0f);
    for (int rate : kCarryRates)
      step_list(carry, state_[next], tree_carry_list(t, rate, int(step_index_ % uint64_t(rate))),
                float(std::exp(-double(rate) * dt / kCarryTimeConstant)));
  }
}

void TreeBatch::commit() {
  if (by_key_.empty()) return;
  current_ = 1 - current_;
  ++step_index_;
}

std::vector<float> TreeBatch::read_state_prefix(int64_t count) {
  const size_t n = size_t(std::min(count, entries_.capacity));
  std::vector<float> out(size_t(BOREAS_TREE_STATE_PLANES) * n);
  runtime_.read_planes(state_[current_], size_t(entries_.capacity), 0, out.data(), n, n,
                       BOREAS_TREE_STATE_PLANES);
  return out;
}

std::vector<float> TreeBatch::read_tree_planes(const cl::Buffer& buffer, uint64_t key,
                                               int planes) {
  const Slot& s = slot_of(key);
  std::vector<float> out(size_t(planes) * size_t(s.count));
  runtime_.read_planes(buffer, size_t(entries_.capacity), size_t(s.first), out.data(),
                       size_t(s.count), size_t(s.count), size_t(planes));
  return out;
}

std::vector<float> TreeBatch::read_tree_state(uint64_t key) {
  return read_tree_planes(state_[current_], key, BOREAS_TREE_STATE_PLANES);
}

std::vector<float> TreeBatch::read_tree_motion(uint64_t key) {
  return read_tree_planes(motion_[current_], key, BOREAS_TREE_MOTION_PLANES);
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
  launch(runtime_, k, Items(size_t(count)), state_[current_], int(entries_.capacity), radius_,
         int(static_entries_.capacity), s.first + 1, template_of(s).first + 1, count,
         float(s.tree->params.scale), out, static_cast<int>(first_record));
}

void TreeBatch::enqueue_leaf_records(uint64_t key, const cl::Buffer& out, size_t first_record) {
  enqueue_leaves(slot_of(key), out, first_record);
}

std::vector<boreas_leaf> TreeBatch::leaves(uint64_t key) {
  const Slot& s = slot_of(key);
  const TreeModel& m = *s.tree->model;
  const double scale = s.tree->params.scale;
  std::vector<boreas_leaf> out(m.leaves.size());
  if (out.empty()) return out;
  const size_t n = size_t(s.leaf_count);
  std::vector<float> records(size_t(BOREAS_TREE_LEAF_OUT_PLANES) * n);
  cl::Buffer made =
      runtime_.buffer(CL_MEM_WRITE_ONLY, records.size() * sizeof(float), "tree leaves");
  enqueue_leaves(s, made, 0);
  runtime_.read(made, 0, records.size() * sizeof(float), records.data());
  for (size_t j = 0; j < n; ++j) {
    boreas_leaf& o = out[j];
    const float* r = &records[j * BOREAS_TREE_LEAF_OUT_PLANES];
    for (int a = 0; a < 3; ++a) {
      o.position[a] = r[BOREAS_TREE_LEAF_OUT_POSITION + a];
      o.axis[a] = r[BOREAS_TREE_LEAF_OUT_AXIS + a];
      o.normal[a] = r[BOREAS_TREE_LEAF_OUT_NORMAL + a];
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
    const int offset = block_index(m.level_begin[size_t(l)]);
    // step_width() vertices per work-item (tree_deform.cl).
    const size_t vertices = size_t(count) * (lp.rings + 1) * (lp.sides + 1);
    launch(runtime_, k, Items(vertices).per_work_item(size_t(step_width())), state_[current_],
           int(entries_.capacity), radius_, int(static_entries_.capacity), s.first + offset,
           template_of(s).first + offset, count, float(params.scale), lp.rings, lp.sides, out,
           total, first_vertex[size_t(l)]);
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
