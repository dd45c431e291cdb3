// boreas: a tree batch and the colliders — which trees a step's colliders can touch, the
// contact launches that push those trees' branches out of them (cl/shared/tree_contact.h),
// and the sums of what the branches push back with.
//
// Broadphase: a tree is tested when the box round the sphere that holds everything it can
// bend into (its base, and the reach of its branches: TreeTemplateBlock::reach times its
// scale) meets a collider's swept bounds; the others pay that box test and nothing else,
// and a world without colliders not even that. A tree a collider pushed in the last step
// is stepped at full detail while a collider reaches it (its carried branches would not be
// pushed), easing in as any tree that comes nearer; one a collider only reaches keeps its
// level of detail, stepped at least far (trunk and limbs): most trees a collider's box
// meets are never touched (a car under a crown), and full detail for them was most of the
// colliders' cost (bench/RESULTS.md, "Colliders and storms"). A twig carried when a
// collider first meets it is pushed from the next step on.
//
// A touched tree is stepped twice: with the rest, by the plain launch, and again by the
// contact variant of the same kernel over its tiles alone (width 1, right after the plain
// launch of each list), from the same inputs, which overwrites its results. So the plain
// launch stays as it is (and as fast), and the trees no collider meets give the same bits
// as in a world without colliders.
//
// Records: each touched branch writes one record per collider of its tree, its row counted
// from the tree's (Touch::record); add_contacts sums each (tree, collider) pair's records on
// the device in branch order (tree_contact_sums.cl) and adds the pairs in tree order, in
// double: the same bits every run.
#include <algorithm>
#include <string>
#include <vector>

#include "errors.h"
#include "runtime/launch.h"
#include "shared/tree_types.h"
#include "trees/tree_batch.h"

namespace boreas::impl {

void TreeBatch::find_touches(const StepColliders& colliders) {
  pending_ = Contacts{};
  if (colliders.empty()) return;
  for (size_t s = 0; s < slots_.size(); ++s) {
    Slot& slot = slots_[s];
    if (!slot.tree) continue;
    const auto& at = slot.tree->params.position;
    Bounds reach;
    for (size_t a = 0; a < 3; ++a) {
      reach.lo[a] = at[a] - slot.reach;
      reach.hi[a] = at[a] + slot.reach;
    }
    std::vector<int> met = colliders.touching(reach, 0.0);
    if (met.empty()) continue;
    slot.touching = true;
    pending_.touches.push_back(
        {int32_t(s), slot.count, std::vector<int32_t>(met.begin(), met.end()), 0});
  }
}

void TreeBatch::make_children() {
  if (children_()) return;
  const size_t sc = size_t(static_entries_.capacity);
  cl::Buffer children = runtime_.buffer(
      CL_MEM_READ_ONLY, size_t(BOREAS_TREE_CHILD_PLANES) * sc * sizeof(int32_t), "tree children");
  // The sink and the holes: no children (no tile reads a hole).
  BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
      children, cl_int(0), 0, size_t(BOREAS_TREE_CHILD_PLANES) * sc * sizeof(int32_t)));
  for (const Template& tp : templates_) {
    if (!tp.block) continue;
    const size_t count = size_t(tp.block->count);
    std::vector<int32_t> parents(count);
    runtime_.read(parents_, size_t(tp.first) * sizeof(int32_t), count * sizeof(int32_t),
                  parents.data());
    const std::vector<int32_t> planes = tree_children(parents, "tree template " + tp.key);
    runtime_.write_planes(children, sc, size_t(tp.first), planes.data(), count, count,
                          BOREAS_TREE_CHILD_PLANES, sizeof(int32_t));
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());
  children_ = children;
}

void TreeBatch::prepare_contacts(const StepColliders& colliders) {
  if (pending_.touches.empty()) return;
  make_children();
  const size_t c = size_t(entries_.capacity);
  if (contact_capacity_ != entries_.capacity) {
    // Zero loads for every tree: new planes (the first touch, or the trees' planes grew).
    for (int k = 0; k < 2; ++k) {
      contact_[k] = runtime_.buffer(CL_MEM_READ_WRITE,
                                    size_t(BOREAS_TREE_CONTACT_PLANES) * c * sizeof(float),
                                    "tree contact loads");
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          contact_[k], 0.0f, 0, size_t(BOREAS_TREE_CONTACT_PLANES) * c * sizeof(float)));
    }
    contact_capacity_ = entries_.capacity;
    contact_stale_ = false;
  }
  // The launch's touched trees (record row, colliders) and colliders, each tree's own run.
  std::vector<int32_t> touches;
  std::vector<BoreasGpuCollider> gpu;
  int64_t rows = 0;
  for (Touch& t : pending_.touches) {
    const Slot& slot = slots_[size_t(t.slot)];
    // A tree touched anew (or moved since) starts from no load: the planes' last values
    // are from an older touch, or another tree's.
    if (!slot.touched || contact_stale_)
      for (int p = 0; p < BOREAS_TREE_CONTACT_PLANES; ++p)
        BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
            contact_[current_], 0.0f, (size_t(p) * c + size_t(slot.first)) * sizeof(float),
            size_t(slot.count) * sizeof(float)));
    t.record = rows;
    rows += int64_t(slot.count) * int64_t(t.colliders.size());
    touches.insert(touches.end(), {int32_t(t.record), int32_t(gpu.size()),
                                   int32_t(t.colliders.size()), 0, place_row(slot)});
    for (int32_t j : t.colliders)
      gpu.push_back(relative_collider(colliders.gpu[size_t(j)], colliders.centers[size_t(j)], slot));
  }
  contact_stale_ = false;
  if (rows > INT32_MAX / BOREAS_TREE_CONTACT_RECORD_FLOATS)
    fail(BOREAS_ERROR_OUT_OF_MEMORY, "trees: " + std::to_string(rows) +
                                         " contact records (branches of touched trees times "
                                         "their colliders) pass one launch's 2^31 floats");
  pending_.rows = rows;
  // Buffers grow by doubling and are reused; a record buffer per ping-pong half, so the
  // last committed step's records stay readable while this one writes.
  auto fit = [&](cl::Buffer& buffer, size_t& capacity, size_t bytes, const char* what) {
    if (bytes <= capacity) return;
    capacity = std::max(bytes, 2 * capacity);
    buffer = runtime_.buffer(CL_MEM_READ_WRITE, capacity, what);
  };
  const int next = 1 - current_;
  fit(touches_buffer_, touches_capacity_, touches.size() * sizeof(int32_t), "tree touches");
  fit(colliders_buffer_, colliders_capacity_, gpu.size() * sizeof(BoreasGpuCollider),
      "tree colliders");
  fit(record_buffers_[next], record_capacity_[next],
      size_t(rows) * BOREAS_TREE_CONTACT_RECORD_FLOATS * sizeof(float), "tree contact records");
  runtime_.write(touches_buffer_, 0, touches.size() * sizeof(int32_t), touches.data());
  runtime_.write(colliders_buffer_, 0, gpu.size() * sizeof(BoreasGpuCollider), gpu.data());
  pending_.records = record_buffers_[next];
  // Their tiles: the branches the plain launch steps (the tree's level of detail), the
  // tile's object its touch.
  contact_tiles_.clear();
  for (size_t k = 0; k < pending_.touches.size(); ++k) {
    const Slot& slot = slots_[size_t(pending_.touches[k].slot)];
    TreeTileSource at = tile_source(slot);
    at.object = int32_t(k);
    add_tree_tiles(contact_tiles_, mode_, *slot.tree->model, at, slot.lod, slot.hold, 0,
                   int(runtime_.group_size()), nullptr, slot.derived);
  }
  contact_tiles_.flush(runtime_);
}

cl::Kernel& TreeBatch::contact_kernel(const std::string& defines) {
  return runtime_.kernel("tree_step.cl", "boreas_tree_step",
                         defines + "#define BOREAS_TREE_CONTACT 1\n#define BOREAS_W 1\n");
}

void TreeBatch::enqueue_contacts(cl::Kernel& k, const PlantWind& wind,
                                 const cl::Buffer& parent_state, int list, TreeStepEvents* events) {
  const size_t tiles = contact_tiles_.size(list);
  if (tiles == 0) return;
  const int next = 1 - current_;
  cl::Event event = launch(
      runtime_, k, Items(tiles * runtime_.group_size()).per_work_item(1), parent_state,
      state_[next], parents_, shape_, response_planes(), motion_[current_], motion_[next],
      state_[current_], motion_[current_], int(entries_.capacity), int(static_entries_.capacity),
      contact_tiles_.buffer(list), 0, 0.0f, *wind.waves, wind.wave_count, *wind.grid,
      wind.grid_layout, places_, breaks_, radius_, children_, contact_[current_], contact_[next], touches_buffer_,
      colliders_buffer_, pending_.records);
  if (events) events->branches.push_back(event);
}

void TreeBatch::add_contacts(std::vector<ContactSum>* sums) {
  if (committed_.rows == 0) return;
  // One pair per (pushed tree, collider), summed on the device (tree_contact_sums.cl): a
  // touched tree's thousands of branch records stay there, and a tree no collider pushed
  // (BOREAS_TREE_TOUCH_PUSHED) has nothing to add.
  std::vector<int32_t> pairs;
  std::vector<const Touch*> summed;
  for (size_t k = 0; k < committed_.touches.size(); ++k) {
    const Touch& t = committed_.touches[k];
    if (committed_.flags[k * BOREAS_TREE_TOUCH_INTS + BOREAS_TREE_TOUCH_PUSHED] == 0) continue;
    summed.push_back(&t);
    for (size_t j = 0; j < t.colliders.size(); ++j)
      pairs.insert(pairs.end(), {int32_t(t.record), t.entries, int32_t(t.colliders.size()),
                                 int32_t(j)});
  }
  const size_t count = pairs.size() / 4;
  if (count == 0) return;
  cl::Buffer pair_buffer = runtime_.buffer(CL_MEM_READ_ONLY, pairs.size() * sizeof(int32_t),
                                           "tree contact pairs");
  runtime_.write(pair_buffer, 0, pairs.size() * sizeof(int32_t), pairs.data());
  cl::Buffer out = runtime_.buffer(CL_MEM_WRITE_ONLY, count * 8 * sizeof(float), "tree contact sums");
  cl::Kernel& k = runtime_.kernel("tree_contact_sums.cl", "boreas_tree_contact_sums", "#define BOREAS_W 1\n");
  launch(runtime_, k, Items(count), committed_.records, pair_buffer, int(count), out);
  std::vector<float> got(count * 8);
  runtime_.read(out, 0, got.size() * sizeof(float), got.data());
  size_t p = 0;
  for (const Touch* t : summed)
    for (size_t j = 0; j < t->colliders.size(); ++j, ++p)
      (*sums)[size_t(t->colliders[j])].add(&got[8 * p]);
}

}  // namespace boreas::impl
