// boreas: a view's records of every tree of a batch in one call (boreas_world_enqueue_tree_
// records, boreas_cl.h; the layouts in cl/shared/tree_records.h). Per call, at most six
// launches per batch (a chunk of one mode) that holds trees, whatever their number, and one
// (1) for a world with none; tests/host/trees/test_view_costs.cpp counts them:
//  1. tree_record_offsets.cl, one group: each slot culled (drawn, with how many leaves,
//     impostor, or culled: shared/tree_cull.h), the records' offsets, packed in slot
//     order, the impostor and range records, the indirect commands;
//  2. tree_derive.cl over the batch's derive tiles, where it has derived branches: the
//     drawn trees' derived branches posed once each, for the leaves' many reads;
//  3. tree_derive_settled.cl over its settled trees' tiles, where it has settled entries:
//     the drawn ones posed into the posed scratch (tree_batch_posed.cpp) ...
//  4. export_records.cl over the batch's branch record tiles;
//  5. tree_leaves.cl over its leaf record tiles (a culled tree's tiles return at once);
//  6. ... and 3's scales restored (tree_derive_settled.cl again).
// What the launches read is kept as trees come and go, at the cost of the change: a tree's
// record tiles (a segment of each list, cl/shared/launch_tiles.h) and its row of the view
// table (uploaded by dirty range). Rows and tiles name a slot as row slot + 1: row 0 is a
// sink that is never drawn, which the no-op tiles of removed trees point to. The tables
// built over every slot (the readers' offsets, the posed tiles) are built again only when a
// row was written since (view_generation_), so a call per frame over an unchanged forest
// walks no tree on the host and waits for nothing.
#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/cl_check.h"
#include "runtime/launch.h"
#include "shared/tree_types.h"
#include "trees/tree_batch.h"
#include "trees/tree_record_tiles.h"

namespace boreas::impl {

namespace {

constexpr size_t kTableRowBytes = BOREAS_TREE_OUT_INTS * sizeof(int32_t);

}  // namespace

BoreasTreeView TreeBatch::tree_view(int32_t s) const {
  const Slot& slot = slots_[size_t(s)];
  const TreeParams& p = slot.tree->params;
  const Template& tp = template_of(slot);
  const TreeTemplateBlock& block = *tp.block;
  BoreasTreeView v{};
  for (int a = 0; a < 3; ++a) v.base[a] = float(p.position[a]);
  v.radius = float((block.reach + block.leaf_reach) * p.scale);
  // The trunk's rest tip relative to the base, placed as place_rest places it in the state
  // (the same float operations, so a tree at rest has a zero displacement).
  const float c = float(std::cos(p.rotation)), sn = float(std::sin(p.rotation));
  const float k = float(p.scale);
  if (block.count > 1) {
    const float px = k * block.trunk_rest_tip[0];
    const float py = k * block.trunk_rest_tip[1];
    const float pz = k * block.trunk_rest_tip[2];
    const float rx = c * px + sn * pz, rz = -sn * px + c * pz;
    v.rest_tip[0] = rx;
    v.rest_tip[1] = py;
    v.rest_tip[2] = rz;
  }
  v.scale = float(p.scale);
  v.rotation = float(p.rotation);
  v.leaf_area = float(block.leaf_area * p.scale * p.scale);
  v.live = 1;
  v.template_index = template_number(slot);
  v.root = slot.first;
  v.branches = slot.count - 1;
  v.leaves = slot.leaf_count;
  const LeafPermutation perm = leaf_permutation(slot.leaf_count);
  v.leaf_stride = perm.stride;
  v.leaf_inverse = perm.inverse;
  if (size_t(s) < tree_ids_.size()) {
    v.id_index = int32_t(tree_ids_[size_t(s)].first);
    v.id_generation = int32_t(tree_ids_[size_t(s)].second);
  }
  return v;
}

void TreeBatch::record_tree(int32_t s) {
  Slot& slot = slots_[size_t(s)];
  Template& tp = templates_[size_t(slot.template_index)];
  write_view(s, tree_view(s));
  if (records_stale_) return;
  const int width = int(runtime_.group_size());
  TileLists::Shared shared;
  shared.root = slot.first;
  shared.scale = float(slot.tree->params.scale);
  shared.object = s + 1;
  shared.static_first = tp.first + 1;
  // Branches from the own planes up to its settled entries (all where none is), then those.
  const int32_t own = settled_begin(slot);
  slot.record_tiles[kRecordBranchList] =
      record_tiles_.add(kRecordBranchList, slot.first + 1, own - 1, width, shared);
  if (own < slot.count) {
    shared.root = settled_root(slot);
    shared.static_first = tp.first + own;
    slot.record_tiles[kRecordBranchList].count +=
        record_tiles_.add(kRecordBranchList, shared.root + own, slot.count - own, width, shared).count;
  }
  // The leaves' parents are the finest level's: settled ones count from its settled root.
  shared.root = settled_root(slot);
  shared.static_first = tp.leaf_first;
  // The leaves' petiole at the tree's scale (tree_leaves.cl): the product the kernel once
  // made per leaf.
  shared.value = tp.block->leaf_petiole * shared.scale;
  // A leaf tile is a group's work-items' leaves, step_width() each (tree_leaves.cl): an
  // aspen's 22,000 leaves take 22 tiles at width 16, not 344 (11 KB a tree on the host
  // and, once records are asked for, on the device).
  slot.record_tiles[kRecordLeafList] =
      record_tiles_.add(kRecordLeafList, 0, slot.leaf_count, width * step_width(), shared);
}

void TreeBatch::unrecord_tree(int32_t s) {
  Slot& slot = slots_[size_t(s)];
  for (TileLists::Segment& segment : slot.record_tiles) {
    if (!records_stale_) record_tiles_.kill(segment);
    segment = TileLists::Segment{};
  }
  write_view(s, BoreasTreeView{});
  if (size_t(s) < tree_ids_.size()) tree_ids_[size_t(s)] = {0, 0};
}

void TreeBatch::write_view(int32_t s, const BoreasTreeView& view) {
  const int32_t row = s + 1;
  if (views_.size() <= size_t(row)) views_.resize(size_t(row) + 1, BoreasTreeView{});
  views_[size_t(row)] = view;
  views_dirty_first_ =
      views_dirty_end_ > views_dirty_first_ ? std::min(views_dirty_first_, row) : row;
  views_dirty_end_ = std::max(views_dirty_end_, row + 1);
  ++view_generation_;
}

void TreeBatch::set_tree_id(uint64_t key, uint32_t index, uint32_t generation) {
  const size_t s = size_t(by_key_.at(key));
  if (tree_ids_.size() <= s) tree_ids_.resize(s + 1);
  tree_ids_[s] = {index, generation};
  write_view(int32_t(s), tree_view(int32_t(s)));
}

void TreeBatch::refresh_records() {
  if (records_stale_ || record_tiles_.wants_rebuild()) {
    // Blocks moved (or dead tiles piled up): every tree's tiles and rows anew.
    records_stale_ = false;
    record_tiles_.clear();
    views_.assign(slots_.size() + 1, BoreasTreeView{});
    for (size_t s = 0; s < slots_.size(); ++s)
      if (slots_[s].tree) record_tree(int32_t(s));
    views_dirty_first_ = 0;
    views_dirty_end_ = int32_t(views_.size());
  }
  record_tiles_.flush(runtime_);
  if (views_.size() < slots_.size() + 1) views_.resize(slots_.size() + 1, BoreasTreeView{});
  if (views_capacity_ < views_.size()) {
    views_capacity_ = std::max(views_.size(), 2 * views_capacity_);
    views_buffer_ = runtime_.buffer(CL_MEM_READ_ONLY, views_capacity_ * sizeof(BoreasTreeView),
                                    "tree view table");
    views_dirty_first_ = 0;
    views_dirty_end_ = int32_t(views_.size());
  }
  if (views_dirty_end_ > views_dirty_first_) {
    runtime_.write(views_buffer_, size_t(views_dirty_first_) * sizeof(BoreasTreeView),
                   size_t(views_dirty_end_ - views_dirty_first_) * sizeof(BoreasTreeView),
                   &views_[size_t(views_dirty_first_)]);
    views_dirty_first_ = views_dirty_end_ = 0;
  }
  if (table_capacity_ < views_.size()) {
    table_capacity_ = std::max(views_.size(), 2 * table_capacity_);
    table_buffer_ =
        runtime_.buffer(CL_MEM_READ_WRITE, table_capacity_ * kTableRowBytes, "tree out table");
  }
}

const std::vector<int32_t>& TreeBatch::view_pose_tiles(int64_t* asked) {
  if (view_pose_generation_ != view_generation_) {
    view_pose_ints_.clear();
    view_pose_asked_ = 0;
    for (const Slot& slot : slots_) add_settled_pose_tiles(slot, &view_pose_ints_, &view_pose_asked_);
    runtime_.count_table_rows(slots_.size());
    view_pose_generation_ = view_generation_;
    posed_tiles_hold_view_ = false;
  }
  *asked = view_pose_asked_;
  return view_pose_ints_;
}

bool TreeBatch::take_posed_count() {
  if (!posed_counted_()) return true;
  if (posed_counted_.getInfo<CL_EVENT_COMMAND_EXECUTION_STATUS>() != CL_COMPLETE) return false;
  posed_asked_ = posed_count_read_;
  posed_counted_ = cl::Event();
  return true;
}

void TreeBatch::read_posed_count() {
  // One read in flight at a time: a call that finds the last one still running leaves it
  // (its count is taken by a later call). A scratch sized by an older count poses only the
  // tiles that fit; the readers of the others derive theirs (cl/tree_derive_settled.cl).
  if (!take_posed_count()) return;
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(posed_counter_, CL_FALSE, 0, sizeof(cl_int),
                                                     &posed_count_read_, nullptr, &posed_counted_));
}

void TreeBatch::enqueue_view_records(const BoreasRecordView& view, const RecordOutputs& out,
                                     const Origin& output_origin) {
  refresh_records();
  reader_offsets(&output_origin);
  const int rows = int(views_.size());
  const std::string defines = plane_defines();
  cl::Kernel& offsets =
      runtime_.kernel("tree_record_offsets.cl", "boreas_tree_record_offsets", defines);
  // A batch that never held a tree has no state; nothing reads it then.
  const cl::Buffer& state = state_[current_]() ? state_[current_] : views_buffer_;
  launch(runtime_, offsets, Items(BOREAS_TREE_OFFSETS_GROUP), views_buffer_, rows, view,
         table_buffer_, state, int(entries_.capacity), out.impostors, out.ranges, out.indirect,
         offsets_);
  // The drawn trees' derived branches posed once each, for the leaves' many reads of them.
  pose_derived(0, int32_t(derive_tiles_.size(0)), true);
  // ... and their settled branches, around both record launches: the leaves read a branch
  // many times, and the branch records then read the poses rather than derive each again.
  pose_settled(nullptr);
  launch_branch_records(0, int32_t(record_tiles_.size(kRecordBranchList)), false, out.branches, 0);
  launch_leaf_records(0, int32_t(record_tiles_.size(kRecordLeafList)), false, out.leaves, 0);
  unpose_settled();
}

}  // namespace boreas::impl
