// boreas: colliders against the imported trees of a batch (cl/shared/mesh_tree_contact.h
// says the model): which trees a step's colliders bend, the launch over those alone, and
// the sums they push the colliders back with.
//
// A tree joins the launch when a collider's swept bounds meet its reach (mesh_tree_reach),
// and stays while its bends spring back (mesh_tree_settle_time after the last meeting);
// then its bends are zeroed, one step per half of the state, and it leaves. With no tree
// in the launch the vertex kernels are the variant that reads no bends: a world whose
// colliders touch no tree pays for them a box test per tree and collider.
#include <algorithm>
#include <string>

#include "errors.h"
#include "mesh_trees/mesh_tree_batch.h"
#include "runtime/launch.h"
#include "shared/mesh_tree_contact_types.h"

namespace boreas::impl {

namespace {

// Steps a settled tree spends zeroing its bends: one per half of the double buffer.
constexpr int kClearingSteps = 2;

template <typename T>
void stage(Runtime& runtime, cl::Buffer& buffer, const std::vector<T>& data, const char* what) {
  const size_t bytes = std::max<size_t>(data.size(), 1) * sizeof(T);
  if (buffer() == nullptr || buffer.getInfo<CL_MEM_SIZE>() < bytes)
    buffer = runtime.buffer(CL_MEM_READ_WRITE, std::max<size_t>(bytes, 256), what);
  if (!data.empty()) runtime.upload_async(buffer, data);
}

}  // namespace

bool MeshTreeBatch::enqueue_contacts(double dt, double time, const StepColliders& colliders,
                                     const cl::Buffer& state, int next) {
  ContactStaging& s = contact_staging_;
  s.active.clear();
  s.pairs.clear();
  s.colliders = colliders.gpu;
  pending_keys_.clear();
  // In slot order, so the launch and the sums' order follow from the calls alone.
  for (const MeshTreeInstance* tree : slot_trees_) {
    if (tree == nullptr) continue;
    const Placed& at = placed(tree->key);
    const std::vector<int> met =
        colliders.empty() ? std::vector<int>() : colliders.touching(at.reach, 0.0);
    auto was = contact_keys_.find(tree->key);
    if (met.empty() && was == contact_keys_.end()) continue;
    InContact now = met.empty() ? was->second : InContact{time, 0};
    if (met.empty() && now.clearing == 0 && time - now.last_met > at.settle)
      now.clearing = kClearingSteps;
    const int32_t clear = now.clearing > 0 ? 1 : 0;
    s.active.insert(s.active.end(),
                    {int32_t(at.first_branch), int32_t(tree->data.branches.size()),
                     int32_t(s.pairs.size()), int32_t(met.size()), clear});
    s.pairs.insert(s.pairs.end(), met.begin(), met.end());
    if (clear) --now.clearing;
    if (!clear || now.clearing > 0) pending_keys_[tree->key] = now;
  }
  pair_collider_[next] = s.pairs;
  if (s.active.empty()) return false;
  if (s.colliders.empty()) s.colliders.push_back(silent_collider());
  stage(runtime_, active_, s.active, "imported trees: contacts");
  stage(runtime_, pairs_, s.pairs, "imported trees: contacts");
  stage(runtime_, colliders_, s.colliders, "imported trees: colliders");
  const size_t pair_bytes = std::max<size_t>(s.pairs.size(), 1) * BOREAS_MESH_TREE_PAIR_FLOATS;
  if (pair_out_[next]() == nullptr ||
      pair_out_[next].getInfo<CL_MEM_SIZE>() < pair_bytes * sizeof(float))
    pair_out_[next] = runtime_.buffer(CL_MEM_READ_WRITE,
                                      std::max<size_t>(pair_bytes, 64) * sizeof(float),
                                      "imported trees: contact sums");
  const int trees = int(s.active.size() / BOREAS_MESH_TREE_ACTIVE_INTS);
  cl::Kernel& k = runtime_.kernel("mesh_tree_contact.cl", "boreas_mesh_tree_contact");
  launch(runtime_, k, Items(size_t(trees)), contact_table_, branch_table_, links_,
         int(branches_.capacity), state, tree_table_, int(slots_.capacity), noise_,
         bend_[1 - next], bend_[next], active_, trees, pairs_, colliders_, pair_out_[next],
         float(dt));
  return true;
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
    ContactSum& sum = (*sums)[size_t(pairs[q])];
    const float* f = &out[q * BOREAS_MESH_TREE_PAIR_FLOATS];
    for (size_t a = 0; a < 3; ++a) {
      sum.force[a] += double(f[a]);
      sum.torque[a] += double(f[3 + a]);
    }
    sum.contacts += int64_t(f[6]);
  }
}

}  // namespace boreas::impl
