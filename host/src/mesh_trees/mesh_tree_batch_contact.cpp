// boreas: colliders against the imported trees of a batch (cl/shared/mesh_tree_contact.h
// says the model): which trees a step's colliders bend, the launch over those alone, and
// the sums they push the colliders back with.
//
// A tree joins the launch when a collider's swept bounds meet its reach (mesh_tree_reach),
// and stays while its bends spring back: once a step's launch finds it touching nothing
// and at rest (BOREAS_MESH_TREE_QUIET_*; read back at the next step, after the queue has
// finished), its bends are zeroed, one step per half of the state, and it leaves. The bends are
// added to the vertices of the trees in the launch alone, run by run of the batch's
// layout: a world whose colliders touch no tree pays for them a box test per tree and
// collider.
#include <algorithm>
#include <string>
#include <unordered_set>
#include <utility>

#include "errors.h"
#include "mesh_trees/mesh_tree_batch.h"
#include "runtime/launch.h"
#include "shared/mesh_tree_contact_types.h"

namespace boreas::impl {

namespace {

// Steps a settled tree spends zeroing its bends: one per half of the double buffer.
constexpr int kClearingSteps = 2;

// A buffer of at least `bytes` (kept when it is big enough).
void ensure_size(Runtime& runtime, cl::Buffer& buffer, size_t bytes, const char* what) {
  if (buffer() == nullptr || buffer.getInfo<CL_MEM_SIZE>() < bytes)
    buffer = runtime.buffer(CL_MEM_READ_WRITE, std::max<size_t>(bytes, 256), what);
}

template <typename T>
void stage(Runtime& runtime, cl::Buffer& buffer, const std::vector<T>& data, const char* what) {
  ensure_size(runtime, buffer, std::max<size_t>(data.size(), 1) * sizeof(T), what);
  if (!data.empty()) runtime.upload_async(buffer, data);
}

}  // namespace

std::unordered_set<uint64_t> MeshTreeBatch::quiet_trees() {
  // The last kept step's launch wrote a flag per tree; its queue has finished.
  const std::vector<uint64_t>& keys = bent_keys_[current_];
  std::unordered_set<uint64_t> quiet;
  if (keys.empty()) return quiet;
  std::vector<int32_t> flags(keys.size());
  runtime_.read(quiet_[current_], 0, flags.size() * sizeof(int32_t), flags.data());
  for (size_t i = 0; i < keys.size(); ++i)
    if (flags[i] != 0) quiet.insert(keys[i]);
  return quiet;
}

bool MeshTreeBatch::enqueue_contacts(double dt, const StepColliders& colliders,
                                     const cl::Buffer& state, int next) {
  ContactStaging& s = contact_staging_;
  s.active.clear();
  s.pairs.clear();
  s.colliders.clear();
  pending_keys_.clear();
  std::vector<uint64_t>& keys = bent_keys_[next];
  keys.clear();
  const std::unordered_set<uint64_t> quiet = quiet_trees();
  // In slot order, so the launch and the sums' order follow from the calls alone.
  for (const MeshTreeInstance* tree : slot_trees_) {
    if (tree == nullptr) continue;
    const Placed& at = placed(tree->key);
    const std::vector<int> met =
        colliders.empty() ? std::vector<int>() : colliders.touching(at.reach, 0.0);
    auto was = contact_keys_.find(tree->key);
    if (met.empty() && was == contact_keys_.end()) continue;
    int clearing = met.empty() ? was->second : 0;
    if (met.empty() && clearing == 0 && quiet.count(tree->key)) clearing = kClearingSteps;
    const int32_t clear = clearing > 0 ? 1 : 0;
    s.active.insert(s.active.end(), {int32_t(at.first_branch), int32_t(tree->data.branches.size()),
                                     int32_t(s.pairs.size()), int32_t(met.size()), clear});
    s.pairs.insert(s.pairs.end(), met.begin(), met.end());
    // Pair q's collider record, relative to the tree's position (its contact points' origin).
    const std::array<float, 3>& p = tree->params.position;
    for (int c : met) s.colliders.push_back(colliders.relative(c, {p[0], p[1], p[2]}));
    keys.push_back(tree->key);
    if (clear) --clearing;
    if (!clear || clearing > 0) pending_keys_[tree->key] = clearing;
  }
  pair_collider_[next] = s.pairs;
  if (s.active.empty()) return false;
  if (s.colliders.empty()) s.colliders.push_back(silent_collider());
  stage(runtime_, active_, s.active, "imported trees: contacts");
  stage(runtime_, colliders_, s.colliders, "imported trees: colliders");
  const size_t pair_floats = std::max<size_t>(s.pairs.size(), 1) * BOREAS_MESH_TREE_PAIR_FLOATS;
  ensure_size(runtime_, pair_out_[next], pair_floats * sizeof(float), "imported trees: contacts");
  ensure_size(runtime_, quiet_[next], keys.size() * sizeof(int32_t), "imported trees: contacts");
  const int trees = int(keys.size());
  cl::Kernel& k = runtime_.kernel("mesh_tree_contact.cl", "boreas_mesh_tree_contact");
  launch(runtime_, k, Items(size_t(trees)), contact_table_, branch_table_, links_,
         int(branches_.capacity), state, tree_table_, int(slots_.capacity), noise_, bend_[1 - next],
         bend_[next], active_, trees, colliders_, pair_out_[next], quiet_[next], float(dt));
  return true;
}

namespace {

// Runs [first, first + count) sorted and merged where one ends where the next begins.
std::vector<std::pair<int64_t, int64_t>> merged(std::vector<std::pair<int64_t, int64_t>> runs) {
  std::sort(runs.begin(), runs.end());
  std::vector<std::pair<int64_t, int64_t>> out;
  for (const auto& r : runs) {
    if (r.second == 0) continue;
    if (!out.empty() && out.back().first + out.back().second == r.first)
      out.back().second += r.second;
    else
      out.push_back(r);
  }
  return out;
}

}  // namespace

void MeshTreeBatch::enqueue_bends(const cl::Buffer& bend) {
  std::vector<std::pair<int64_t, int64_t>> trunk, leaves;
  for (uint64_t key : bent_keys_[1 - current_]) {
    const Placed& at = placed(key);
    trunk.push_back({at.first_trunk, int64_t(at.tree->model.trunk.vertex_count())});
    leaves.push_back({at.first_leaf_vertex, int64_t(at.tree->model.leaves.vertex_count())});
  }
  const int nb = int(branches_.capacity);
  cl::Kernel& kt = runtime_.kernel("mesh_tree_contact.cl", "boreas_mesh_tree_bend_trunk");
  for (const auto& [first, count] : merged(trunk))
    launch(runtime_, kt, Items(size_t(count)), trunk_table_, trunk_branch_, int(trunk_.capacity),
           int(first), int(count), links_, nb, bend, trunk_out_);
  cl::Kernel& kl = runtime_.kernel("mesh_tree_contact.cl", "boreas_mesh_tree_bend_leaves");
  for (const auto& [first, count] : merged(leaves))
    launch(runtime_, kl, Items(size_t(count)), vertex_leaf_, int(first), int(count), leaf_table_,
           leaf_branch_, int(leaves_.capacity), links_, nb, bend, leaf_out_);
}

void MeshTreeBatch::commit_contacts() { contact_keys_ = std::move(pending_keys_); }

void MeshTreeBatch::add_contacts(std::vector<ContactSum>* sums) {
  const std::vector<int32_t>& pairs = pair_collider_[current_];
  if (pairs.empty()) return;
  std::vector<float> out(pairs.size() * BOREAS_MESH_TREE_PAIR_FLOATS);
  runtime_.read(pair_out_[current_], 0, out.size() * sizeof(float), out.data());
  for (size_t q = 0; q < pairs.size(); ++q) {
    if (size_t(pairs[q]) >= sums->size())
      fail(BOREAS_ERROR_INTERNAL, "imported trees: a contact names collider " +
                                      std::to_string(pairs[q]) + " of " +
                                      std::to_string(sums->size()));
    (*sums)[size_t(pairs[q])].add(&out[q * BOREAS_MESH_TREE_PAIR_FLOATS]);
  }
}

}  // namespace boreas::impl
