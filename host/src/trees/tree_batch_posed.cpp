// boreas: the posed scratch (cl/tree_derive_settled.cl, cl/shared/tree_state.h): settled
// branches posed for the readers of many items a branch (the deformer, the leaf records)
// around their launch, in memory that follows what they read: a one-tree reader's settled
// entries, or the view's drawn ones (as many as the last view call's cull drew).
#include <algorithm>
#include <cstring>

#include "runtime/cl_check.h"
#include "runtime/launch.h"
#include "trees/tree_batch.h"

namespace boreas::impl {

namespace {

int32_t float_bits(float f) {
  int32_t b = 0;
  std::memcpy(&b, &f, sizeof b);
  return b;
}

}  // namespace

void TreeBatch::add_settled_pose_tiles(const Slot& slot, std::vector<int32_t>* ints,
                                       int64_t* asked) const {
  if (!slot.tree || slot.settled_first < 0) return;
  const int32_t count = slot.count - settled_begin(slot);
  // A group's work-items' entries, step_width() each (cl/tree_derive_settled.cl): most
  // tiles are of trees the cull does not draw, and a group costs PoCL some microseconds.
  const int32_t most = int32_t(runtime_.group_size()) * step_width();
  for (int32_t at = 0; at < count; at += most) {
    int32_t t[BOREAS_TILE_INTS] = {};
    t[BOREAS_TILE_FIRST] = slot.settled_first + at;
    t[BOREAS_TILE_COUNT] = std::min(most, count - at);
    t[BOREAS_TILE_SCALE] = float_bits(float(slot.tree->params.scale));
    t[BOREAS_TILE_OBJECT] = int32_t(&slot - slots_.data()) + 1;
    ints->insert(ints->end(), t, t + BOREAS_TILE_INTS);
  }
  *asked += count;
}

void TreeBatch::fit_posed_planes(int64_t need) {
  // Grown with an eighth to spare (the drawn set moves a little from call to call), shrunk
  // below a quarter used.
  if (need <= posed_rows_ && need >= posed_rows_ / 4) return;
  const int64_t rows = need + need / 8;
  posed_planes_ = rows > 0 ? runtime_.buffer(CL_MEM_READ_WRITE,
                                             size_t(BOREAS_TREE_STATE_PLANES) * size_t(rows) * sizeof(float),
                                             "tree posed settled planes")
                           : cl::Buffer();
  posed_rows_ = rows;
}

void TreeBatch::pose_settled(const Slot* one) {
  unpose_settled();  // a window an error left open
  if (!posing_ || settled_entries_.capacity == 0) return;
  std::vector<int32_t> one_ints;
  int64_t asked = 0;
  if (one) add_settled_pose_tiles(*one, &one_ints, &asked);
  // A view call's tiles are kept while no tree changes (tree_batch_view.cpp).
  const std::vector<int32_t>& ints = one ? one_ints : view_pose_tiles(&asked);
  if (asked == 0) return;
  // A view call's rows: what the last one's cull drew, as far as its read has landed.
  if (!one) take_posed_count();
  fit_posed_planes(one ? asked : std::min<int64_t>(asked, posed_asked_));
  if (!posed_counter_()) posed_counter_ = runtime_.buffer(CL_MEM_READ_WRITE, sizeof(cl_int), "tree posed count");
  upload_posed_tiles(ints, one == nullptr);
  BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(posed_counter_, cl_int(0), 0, sizeof(cl_int)));
  launch_settled_poses(one == nullptr, 0);
  posed_live_ = true;
  if (!one) read_posed_count();
}

void TreeBatch::upload_posed_tiles(const std::vector<int32_t>& ints, bool view) {
  // The tiles change only when trees settle, wake, come or go, or blocks move: a view
  // call after a step usually finds the last call's tiles on the device already (the
  // view's as view_pose_tiles last built them, one tree's compared).
  posed_tile_count_ = ints.size() / BOREAS_TILE_INTS;
  if (posed_tiles_() && (view ? posed_tiles_hold_view_ : !posed_tiles_hold_view_ && ints == posed_tile_ints_))
    return;
  if (ints.size() > posed_tile_capacity_) {
    posed_tile_capacity_ = ints.size();
    posed_tiles_ = runtime_.buffer(CL_MEM_READ_ONLY, ints.size() * sizeof(int32_t), "tree posed tiles");
  }
  runtime_.write(posed_tiles_, 0, ints.size() * sizeof(int32_t), ints.data());
  posed_tiles_hold_view_ = view;
  if (view) posed_tile_ints_.clear();
  else posed_tile_ints_ = ints;
}

void TreeBatch::unpose_settled() {
  if (!posed_live_) return;
  launch_settled_poses(false, 1);
  posed_live_ = false;
}

void TreeBatch::launch_settled_poses(bool use_table, int restore) {
  cl::Kernel& k = runtime_.kernel("tree_derive_settled.cl", "boreas_tree_derive_settled", plane_defines());
  launch(runtime_, k, Items(posed_tile_count_ * runtime_.group_size()), state_[current_],
         motion_[current_], int(entries_.capacity), shape_, int(static_entries_.capacity), settled_,
         int(settled_entries_.capacity), posed_buffer(), posed_stride(), posed_counter_,
         posed_tiles_, use_table ? table_buffer_ : posed_counter_, int(use_table), restore);
}

}  // namespace boreas::impl
