// boreas: a batch of trees on the device — which trees and template blocks it holds:
// adding trees (all or none) and removing them. The other ideas of TreeBatch are in the
// tree_batch_*.cpp beside it (tree_batch.h lists them).
#include "trees/tree_batch.h"
#include "trees/tree_batch_new_trees.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "errors.h"
#include "free_places.h"
#include "parallel_for.h"
#include "runtime/mapped_planes.h"
#include "shared/tree_types.h"
#include "trees/tree_templates.h"

namespace boreas::impl {

namespace {

// An exact, short text of a double for keys.
std::string exact(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%a", v);
  return buffer;
}

// A block's planes into the mapped ones, from its offset among the new blocks.
template <typename Planes>
void place(const MappedPlanes& to, int64_t first, const Planes& from, int64_t count, int planes) {
  using T = typename Planes::value_type;
  if (count == 0) return;  // nothing mapped: a leafless block has no leaf planes
  for (int k = 0; k < planes; ++k)
    std::copy_n(from.begin() + ptrdiff_t(k * count), count, to.plane<T>(size_t(k)) + first);
}

}  // namespace

TreeBatch::TreeBatch(Runtime& runtime, boreas_tree_mode mode,
                     std::shared_ptr<TemplateNumbers> numbers)
    : runtime_(runtime),
      mode_(mode),
      numbers_(numbers ? std::move(numbers) : std::make_shared<TemplateNumbers>()) {
  // BOREAS_TREE_DERIVATION=0 carries settled finest levels as before (benchmarks' A/B).
  if (const char* env = std::getenv("BOREAS_TREE_DERIVATION")) derivation_ = std::string(env) != "0";
  // BOREAS_TREE_SETTLING=0 keeps derived levels in the own planes (benchmarks' A/B).
  if (const char* env = std::getenv("BOREAS_TREE_SETTLING")) settling_ = std::string(env) != "0";
}

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

void TreeBatch::add(const Trees& trees) {
  if (trees.empty()) return;
  check_new_keys(trees);
  NewTrees n = find_templates(trees);
  count_entries(trees, n);
  // The first damped tree brings the planes its response needs (hold_rates).
  if (std::any_of(trees.begin(), trees.end(), [](const auto& t) {
        return t->params.response == BOREAS_TREE_DAMPED;
      }))
    hold_rates();
  plan_settling(trees, n);
  make_room(n);
  // Written past the used ends of the device's buffers, and finished, before the batch
  // takes anything: a failure up to here leaves it as it was (a relayout only moved its
  // blocks, with their contents, into bigger buffers).
  if (!n.fresh.empty()) {
    write_new_templates(trees, n);
    if (holds_rates()) write_new_response(n);
  }
  write_new_states(trees, n);
  write_new_settled(trees, n);
  BOREAS_CL_CHECK(runtime_.queue().finish());

  // Everything is on the device: the batch takes the templates and the trees.
  const std::vector<int32_t> fresh_index = take_new_templates(n);
  for (size_t t = 0; t < trees.size(); ++t) {
    const int32_t index = n.tree_template[t] >= 0 ? int32_t(n.tree_template[t])
                                                  : fresh_index[size_t(-1 - n.tree_template[t])];
    const int64_t settled = n.tree_settled[t] < 0 ? -1 : n.settled_at + n.tree_settled[t];
    take_tree(trees[t], index, n.tree_first[t], block_of(n, t), settled);
  }
  entries_.end += n.need;
  settled_entries_.end += n.settled_need;
  branch_count_ += n.need + n.settled_need - int64_t(trees.size());
  for (size_t t = 0; t < trees.size(); ++t) leaf_count_ += block_of(n, t).leaf_count;
}

void TreeBatch::check_new_keys(const Trees& trees) const {
  for (const auto& t : trees)
    if (by_key_.count(t->key))
      fail(BOREAS_ERROR_INTERNAL, "tree key " + std::to_string(t->key) + " added twice");
}

TreeBatch::NewTrees TreeBatch::find_templates(const Trees& trees) const {
  // Template blocks: the known ones found, the new ones listed (built in
  // write_new_templates, once each).
  NewTrees n;
  std::unordered_map<std::string, size_t> fresh_by_key;
  n.tree_template.resize(trees.size());
  for (size_t t = 0; t < trees.size(); ++t) {
    const std::string key = template_block_key(*trees[t]);
    if (auto it = template_by_key_.find(key); it != template_by_key_.end()) {
      n.tree_template[t] = it->second;
      continue;
    }
    auto it = fresh_by_key.find(key);
    if (it == fresh_by_key.end()) {
      NewTrees::Template nt;
      nt.key = key;
      nt.tree = t;
      it = fresh_by_key.emplace(key, n.fresh.size()).first;
      n.fresh.push_back(std::move(nt));
    }
    n.tree_template[t] = -1 - int64_t(it->second);
  }
  return n;
}

void TreeBatch::count_entries(const Trees& trees, NewTrees& n) const {
  // The new templates' sizes (a block holds the root, every branch and every leaf of its
  // model), then the trees' own entries.
  for (NewTrees::Template& nt : n.fresh) {
    const TreeModel& m = *trees[nt.tree]->model;
    nt.count = block_entries(m);
    nt.leaf_count = m.leaf_count();
    nt.first = n.static_need;
    nt.leaf_first = n.static_leaf_need;
    n.static_need += nt.count;
    n.static_leaf_need += nt.leaf_count;
  }
  n.tree_count.resize(trees.size());
  for (size_t t = 0; t < trees.size(); ++t) {
    n.tree_count[t] = n.tree_template[t] >= 0 ? templates_[size_t(n.tree_template[t])].block->count
                                              : n.fresh[size_t(-1 - n.tree_template[t])].count;
    n.need += n.tree_count[t];
  }
}

void TreeBatch::make_room(NewTrees& n) {
  // The spaces grow (runtime/block_space.h: packed in place where the holes leave room,
  // else by doubling, holes squeezed out on the way); the new template blocks go after the
  // used ends.
  // Growing stops at the chunk's limits (space_limits); past them the new buffer is refused
  // (the world asks fitting() first and puts the rest in another chunk).
  const SpaceLimits most = space_limits();
  if (!static_entries_.fits(n.static_need) || !static_leaves_.fits(n.static_leaf_need)) {
    const bool pack = static_entries_.dead > 0 || static_leaves_.dead > 0;
    relayout_templates(
        static_entries_.grown(n.static_need, kMinTemplateEntries, most.template_entries),
        static_leaves_.grown(n.static_leaf_need, kMinTemplateLeaves, most.template_leaves), pack);
  }
  if (!entries_.fits(n.need))
    relayout_trees(entries_.grown(n.need, kMinEntries, most.entries), entries_.dead > 0);
  n.static_at = static_entries_.end;
  n.static_leaf_at = static_leaves_.end;
}

const TreeTemplateBlock& TreeBatch::block_of(const NewTrees& n, size_t t) const {
  return n.tree_template[t] >= 0 ? *templates_[size_t(n.tree_template[t])].block
                                 : *n.fresh[size_t(-1 - n.tree_template[t])].block;
}

void TreeBatch::write_new_templates(const Trees& trees, NewTrees& n) {
  // The new template blocks, laid out on every core (each from its template alone) and
  // copied straight into the buffers, mapped past their ends: on a CPU device that is
  // the buffers' own memory, so a batch of distinct trees (over a gigabyte of leaves)
  // is neither staged nor copied by one thread. The host keeps of each block what a new
  // dt reads: its frequencies, where it has any (a damped response). The rest pose that
  // later adds and heal place is made again from the device's copy of the block
  // (template_rest: 74 KB an aspen not kept).
  const size_t sc = size_t(static_entries_.capacity), slc = size_t(static_leaves_.capacity);
  const size_t at = size_t(n.static_at), leaf_at = size_t(n.static_leaf_at);
  const size_t count = size_t(n.static_need), leaf_count = size_t(n.static_leaf_need);
  MappedPlanes parents(runtime_, parents_, sc, at, count, 1, sizeof(int32_t));
  // Children only where a contact made the batch's (make_children).
  std::optional<MappedPlanes> children;
  if (children_()) children.emplace(runtime_, children_, sc, at, count, BOREAS_TREE_CHILD_PLANES, sizeof(int32_t));
  MappedPlanes shape(runtime_, shape_, sc, at, count, BOREAS_TREE_SHAPE_PLANES);
  MappedPlanes radius(runtime_, radius_, sc, at, count, BOREAS_TREE_RADIUS_PLANES);
  MappedPlanes leaves(runtime_, leaves_, slc, leaf_at, leaf_count, BOREAS_TREE_LEAF_PLANES,
                      sizeof(int32_t));
  parallel_for(n.fresh.size(), [&](size_t f) {
    NewTrees::Template& nt = n.fresh[f];
    const TreeInstance& tree = *trees[nt.tree];
    // A kept model is packed: a new block of it (other physics) grows its leaves again.
    TreeTemplateBlock b = tree_template_block(tree.params, *whole_model(tree.model));
    place(parents, nt.first, b.parents, b.count, 1);
    if (children) place(*children, nt.first, b.children, b.count, BOREAS_TREE_CHILD_PLANES);
    place(shape, nt.first, b.shape, b.count, BOREAS_TREE_SHAPE_PLANES);
    place(radius, nt.first, b.radius, b.count, BOREAS_TREE_RADIUS_PLANES);
    place(leaves, nt.leaf_first, b.leaves, b.leaf_count, BOREAS_TREE_LEAF_PLANES);
    std::vector<int32_t>().swap(b.parents);
    std::vector<int32_t>().swap(b.children);
    std::vector<float>().swap(b.shape);
    std::vector<float>().swap(b.radius);
    std::vector<int32_t>().swap(b.leaves);
    nt.rest = std::move(b.rest);
    std::vector<float>().swap(b.rest);
    if (std::none_of(b.omega.begin(), b.omega.end(), [](double w) { return w > 0.0; })) {
      std::vector<double>().swap(b.omega);  // quasi-static: a zero response for every dt
      std::vector<double>().swap(b.zeta);
    }
    nt.block = std::make_shared<const TreeTemplateBlock>(std::move(b));
  });
  parents.unmap();
  if (children) children->unmap();
  shape.unmap();
  radius.unmap();
  leaves.unmap();
}

void TreeBatch::write_new_response(const NewTrees& n) {
  // The response for the current step (zero for quasi-static branches, and until a
  // first step sets dt).
  const size_t sc = size_t(static_entries_.capacity), count = size_t(n.static_need);
  std::vector<double> omega(count), zeta(count);
  for (const NewTrees::Template& f : n.fresh) {
    std::copy(f.block->omega.begin(), f.block->omega.end(), omega.begin() + ptrdiff_t(f.first));
    std::copy(f.block->zeta.begin(), f.block->zeta.end(), zeta.begin() + ptrdiff_t(f.first));
  }
  const std::vector<float> response =
      tree_response_planes(omega, zeta, response_dt_ > 0.0 ? response_dt_ : 1.0);
  runtime_.write_planes(response_, sc, size_t(n.static_at), response.data(), count, count,
                        BOREAS_TREE_RESPONSE_PLANES);
}

void TreeBatch::write_new_states(const Trees& trees, NewTrees& n) {
  // The trees' own state: each its template's rest pose, placed (the entries it keeps in
  // the own planes); uploaded in pieces of at most add_piece_ entries, so that a large add
  // stages one piece on the host, not the whole forest (60 bytes an entry).
  const size_t c = size_t(entries_.capacity);
  const int64_t first = entries_.end;
  n.tree_first.resize(trees.size());
  // Each known template's rest state made once for the call; the new ones have theirs.
  std::unordered_map<int64_t, std::vector<float>> known_rest;
  auto rest_of = [&](size_t t) -> const std::vector<float>& {
    const int64_t tp = n.tree_template[t];
    if (tp < 0) return n.fresh[size_t(-1 - tp)].rest;
    auto it = known_rest.find(tp);
    if (it == known_rest.end()) it = known_rest.emplace(tp, template_rest(templates_[size_t(tp)])).first;
    return it->second;
  };
  std::vector<float> rest;
  int64_t at = 0;
  for (size_t t = 0; t < trees.size();) {
    size_t end = t;
    int64_t count = 0;
    while (end < trees.size() && (end == t || count + n.tree_own[end] <= add_piece_))
      count += n.tree_own[end++];
    rest.assign(size_t(BOREAS_TREE_STATE_PLANES) * size_t(count), 0.0f);
    for (int64_t k = 0; t < end; ++t) {
      place_rest(rest_of(t), at_own_base(trees[t]->params), rest.data(), size_t(count), size_t(k),
                 size_t(n.tree_own[t]));
      n.tree_first[t] = first + at + k;
      k += n.tree_own[t];
    }
    runtime_.write_planes(state_[current_], c, size_t(first + at), rest.data(), size_t(count),
                          size_t(count), BOREAS_TREE_STATE_PLANES);
    at += count;
  }
  runtime_.copy_planes(state_[current_], c, size_t(first), state_[1 - current_], c, size_t(first),
                       size_t(n.need), BOREAS_TREE_STATE_PLANES);
  // At rest the motion is zero: filled on the device, nothing to upload.
  for (int k = 0; k < 2; ++k)
    for (int p = 0; p < motion_planes_; ++p)
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          motion_[k], 0.0f, (size_t(p) * c + size_t(first)) * sizeof(float),
          size_t(n.need) * sizeof(float)));
}

std::vector<int32_t> TreeBatch::take_new_templates(const NewTrees& n) {
  std::vector<int32_t> fresh_index(n.fresh.size());
  for (size_t f = 0; f < n.fresh.size(); ++f) {
    Template tp;
    tp.key = n.fresh[f].key;
    tp.block = n.fresh[f].block;
    tp.first = int32_t(n.static_at + n.fresh[f].first);
    tp.leaf_first = n.static_leaf_at + n.fresh[f].leaf_first;
    tp.number = numbers_->claim(tp.key);
    const int32_t index = claim_place(templates_, free_templates_, std::move(tp));
    template_by_key_.emplace(n.fresh[f].key, index);
    fresh_index[f] = index;
  }
  static_entries_.end += n.static_need;
  static_leaves_.end += n.static_leaf_need;
  return fresh_index;
}

void TreeBatch::take_tree(const std::shared_ptr<const TreeInstance>& tree, int32_t template_index,
                          int64_t first, const TreeTemplateBlock& block, int64_t settled_first) {
  Slot slot;
  slot.tree = tree;
  slot.template_index = template_index;
  ++templates_[size_t(slot.template_index)].users;
  slot.first = int32_t(first);
  slot.count = block.count;
  slot.leaf_count = block.leaf_count;
  slot.reach = block.reach * tree->params.scale;
  slot.lod = lod_of(tree->params);
  if (slot.lod == TreeLod::kFrozen) slot.settle_left = kSettleTime;
  if (settled_first >= 0) {
    // Settled at add (plan_settling): derived from the first step, its finest level there.
    slot.derived = true;
    slot.derive_left = 0.0;
    slot.settled_first = int32_t(settled_first);
  }
  const int32_t s = claim_place(slots_, free_slots_, std::move(slot));
  by_key_.emplace(tree->key, s);
  if (!rebuild_tiles_) tile(slots_[size_t(s)]);
  record_tree(s);
}

std::vector<float> TreeBatch::template_rest(const Template& tp) {
  // What the placement reads of the block: its parents, the shape planes up to the
  // attachment's angles and the base's (LOCAL_P0: trunks standing apart), read back (a few
  // floats an entry, once per template per call).
  const size_t count = size_t(tp.block->count), sc = size_t(static_entries_.capacity);
  constexpr size_t kPlanes = BOREAS_TREE_SHAPE_SIN_ALPHA + 1;
  std::vector<int32_t> parents(count);
  std::vector<float> shape(size_t(BOREAS_TREE_SHAPE_PLANES) * count);
  runtime_.read(parents_, size_t(tp.first) * sizeof(int32_t), count * sizeof(int32_t),
                parents.data());
  runtime_.read_planes(shape_, sc, size_t(tp.first), shape.data(), count, count, kPlanes);
  runtime_.read_planes(shape_, sc, size_t(BOREAS_TREE_SHAPE_LOCAL_P0) * sc + size_t(tp.first),
                       shape.data() + size_t(BOREAS_TREE_SHAPE_LOCAL_P0) * count, count, count, 3);
  return rest_state(shape, parents);
}

void TreeBatch::heal(uint64_t key) {
  drop_settled();
  // Settled, it comes back first (its whole block written here).
  if (own_count(slot_of(key)) < slot_of(key).count) unsettle({by_key_.at(key)});
  const Slot& slot = slot_of(key);
  const size_t c = size_t(entries_.capacity), first = size_t(slot.first),
               count = size_t(slot.count);
  // Both halves of the ping-pong, so neither a carried branch (which reads the current
  // half) nor the next step finds the broken state again.
  std::vector<float> rest(size_t(BOREAS_TREE_STATE_PLANES) * count);
  place_rest(template_rest(template_of(slot)), at_own_base(slot.tree->params), rest.data(), count, 0);
  for (int k = 0; k < 2; ++k) {
    runtime_.write_planes(state_[k], c, first, rest.data(), count, count,
                          BOREAS_TREE_STATE_PLANES);
    for (int p = 0; p < motion_planes_; ++p)
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          motion_[k], 0.0f, (size_t(p) * c + first) * sizeof(float), count * sizeof(float)));
  }
  // Its derived branches stay derived: from the rest now.
  if (slot.derived) write_derived_marks(slot);
  BOREAS_CL_CHECK(runtime_.queue().finish());
}

void TreeBatch::remove(uint64_t key) {
  drop_settled();
  auto it = by_key_.find(key);
  if (it == by_key_.end())
    fail(BOREAS_ERROR_INTERNAL, "tree batch has no tree with key " + std::to_string(key));
  const int32_t s = it->second;
  Slot& slot = slots_[size_t(s)];
  untile(slot);
  unrecord_tree(s);
  entries_.release(slot.first, own_count(slot));
  if (own_count(slot) < slot.count) settled_entries_.release(slot.settled_first, slot.count - own_count(slot));
  branch_count_ -= slot.count - 1;
  leaf_count_ -= slot.leaf_count;
  // The last tree of a template block lets it go.
  Template& tp = templates_[size_t(slot.template_index)];
  if (--tp.users == 0) {
    static_entries_.release(tp.first, tp.block->count);
    static_leaves_.release(tp.leaf_first, tp.block->leaf_count);
    template_by_key_.erase(tp.key);
    numbers_->release(tp.key);
    free_templates_.push_back(slot.template_index);
    tp = Template{};
  }
  slot = Slot{};
  free_slots_.push_back(s);
  by_key_.erase(it);
  if (by_key_.empty()) {
    entries_.clear();
    settled_entries_.clear();
    static_entries_.clear();
    static_leaves_.clear();
    tiles_.clear();
    record_tiles_.clear();
  }
  // Holes past half a space: pack it; live entries below a quarter of it: pack them into
  // a smaller one (runtime/block_space.h). Device copies, amortized over the removals that
  // made the holes. The last damped template gone, the batch is still again (release_rates).
  // A failure here only leaves the holes, or the planes, where they were.
  try {
    if (holds_rates() && std::none_of(templates_.begin(), templates_.end(), [](const Template& t) {
          return t.block && !t.block->omega.empty();
        }))
      release_rates();
    trim_settled();
    if (entries_.wants_shrinking(kMinEntries) || entries_.wants_packing())
      relayout_trees(entries_.shrunk(kMinEntries), true);
    if (static_entries_.wants_shrinking(kMinTemplateEntries) ||
        static_leaves_.wants_shrinking(kMinTemplateLeaves) || static_entries_.wants_packing() ||
        static_leaves_.wants_packing())
      relayout_templates(static_entries_.shrunk(kMinTemplateEntries),
                         static_leaves_.shrunk(kMinTemplateLeaves), true);
  } catch (const Error&) {
  }
}

}  // namespace boreas::impl
