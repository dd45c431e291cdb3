// boreas: a tree batch's step — the damped templates' response for the step's dt, the tile
// launches of tree_step.cl into the next state, and the commit that makes it current.
#include <algorithm>
#include <cmath>
#include <string>

#include "runtime/launch.h"
#include "shared/tree_types.h"
#include "trees/tree_batch.h"

namespace boreas::impl {

void TreeBatch::upload_response(double dt) {
  if (dt == response_dt_ || !holds_rates()) return;
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

void TreeBatch::enqueue_step(double dt, const PlantWind& wind, const StepColliders& colliders,
                             TreeStepEvents* events) {
  if (by_key_.empty()) return;
  drop_settled();
  // Derived branches posed for readers since the last step get their marks back: their
  // poses are of the state this step replaces (cl/tree_derive.cl).
  mark_posed();
  unpose_settled();  // a posed window an error left open (tree_batch_posed.cpp)
  upload_response(dt);
  // The trees colliders touch are stepped at full detail: known before the levels are.
  find_touches(colliders);
  update_lods(dt);
  for (const Touch& t : pending_.touches) slots_[size_t(t.slot)].touching = false;
  if (rebuild_tiles_ || tiles_.wants_rebuild()) rebuild_tiles();
  tiles_.flush(runtime_);
  prepare_contacts(colliders);
  upload_places(wind);
  const int next = 1 - current_;
  const std::string defines = step_defines(wind);
  cl::Kernel& step = runtime_.kernel("tree_step.cl", "boreas_tree_step", defines);
  cl::Kernel& carry = runtime_.kernel("tree_step.cl", "boreas_tree_step",
                                      defines + "#define BOREAS_TREE_CARRY 1\n");
  cl::Kernel* contact = pending_.touches.empty() ? nullptr : &contact_kernel(defines);
  // step_width() branches per work-item (tree_step.cl), a tile of group_size() per group.
  const size_t width = size_t(step_width());
  if (!breaks_()) breaks_ = runtime_.buffer(CL_MEM_READ_WRITE, sizeof(cl_int), "tree breaks");
  BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(breaks_, cl_int(0), 0, sizeof(cl_int)));
  auto step_list = [&](cl::Kernel& k, const cl::Buffer& parent_state, int list, float carry_hold) {
    const size_t tiles = tiles_.size(list);
    if (tiles == 0) return;
    cl::Event event =
        launch(runtime_, k, Items(tiles * runtime_.group_size()).per_work_item(width), parent_state,
               state_[next], parents_, shape_, response_planes(), motion_[current_], motion_[next],
               state_[current_], motion_[current_], int(entries_.capacity),
               int(static_entries_.capacity), tiles_.buffer(list), 0, carry_hold, *wind.waves,
               wind.wave_count, *wind.grid, wind.grid_layout, places_, breaks_);
    if (events) events->branches.push_back(event);
    // The touched trees' branches of this list again, pushed out of their colliders.
    if (contact && &k == &step) enqueue_contacts(*contact, wind, parent_state, list, events);
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
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(breaks_, CL_FALSE, 0, sizeof(cl_int),
                                                     &breaks_read_));
  // Which touched trees were pushed (BOREAS_TREE_TOUCH_PUSHED), taken by commit().
  if (!pending_.touches.empty()) {
    pending_.flags.assign(pending_.touches.size() * BOREAS_TREE_TOUCH_INTS, 0);
    BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(
        touches_buffer_, CL_FALSE, 0, pending_.flags.size() * sizeof(int32_t),
        pending_.flags.data()));
  }
}

void TreeBatch::commit() {
  broken_ = 0;
  if (by_key_.empty()) return;
  broken_ = breaks_read_;
  current_ = 1 - current_;
  ++step_index_;
  // The touched trees' contact planes are live from now on (their next touch reads them).
  for (const Touch& t : committed_.touches)
    if (size_t(t.slot) < slots_.size()) slots_[size_t(t.slot)].touched = slots_[size_t(t.slot)].pushed = false;
  committed_ = pending_;
  for (size_t k = 0; k < committed_.touches.size(); ++k) {
    Slot& slot = slots_[size_t(committed_.touches[k].slot)];
    slot.touched = true;
    slot.pushed = committed_.flags[k * BOREAS_TREE_TOUCH_INTS + BOREAS_TREE_TOUCH_PUSHED] != 0;
  }
}

}  // namespace boreas::impl
