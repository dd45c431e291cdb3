// boreas: a batch of trees on the device — which trees and template blocks it holds:
// adding trees (all or none) and removing them. The other ideas of TreeBatch are in the
// tree_batch_*.cpp beside it (tree_batch.h lists them).
#include "trees/tree_batch.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>

#include "errors.h"
#include "parallel_for.h"
#include "runtime/mapped_planes.h"
#include "shared/tree_types.h"

namespace boreas::impl {

namespace {

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

}  // namespace boreas::impl
