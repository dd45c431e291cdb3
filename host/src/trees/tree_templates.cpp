// boreas: finding, growing and keeping the trees' shared models.
#include "trees/tree_templates.h"

#include <algorithm>
#include <climits>

#include "parallel_for.h"

namespace boreas::impl {

void TreeTemplates::Request::add(const TreeParams& params, int index) {
  const std::string local = params.species + "\n" + std::to_string(params.seed);
  auto it = needed_.find(local);
  if (it == needed_.end()) {
    const SpeciesSource source = read_species_source(params.species);
    std::shared_ptr<const Species>& species = species_[source.key];
    Needed n;
    n.found.key = source.key + "\n" + std::to_string(params.seed);
    if (auto known = kept_.models_.find(n.found.key); known != kept_.models_.end())
      n.found.model = known->second.lock();
    if (!n.found.model) {
      n.grow = int(grows_.size());
      if (!species) species = std::make_shared<const Species>(parse_species_source(source));
      grows_.push_back({species, params.seed, index, nullptr, nullptr});
    }
    it = needed_.emplace(local, std::move(n)).first;
    if (it->second.grow >= 0) grows_[size_t(it->second.grow)].found = &it->second.found;
  }
  if (of_.size() <= size_t(index)) of_.resize(size_t(index) + 1, nullptr);
  of_[size_t(index)] = &it->second;
}

namespace {

// What a whole model holds beyond its packed form: its branches and leaves.
size_t whole_model_bytes(const TreeModel& m) {
  return m.branches.capacity() * sizeof(BranchModel) + m.leaves.capacity() * sizeof(LeafModel);
}

}  // namespace

void TreeTemplates::Request::grow(size_t begin, size_t end,
                                  const std::function<void(int, const Error&)>& failed) {
  // Each template is a pure function of species and seed, grown at scale 1.
  try {
    parallel_for(end - begin, [&](size_t k) {
      Grow& g = grows_[begin + k];
      g.model = std::make_shared<const TreeModel>(grow_tree(*g.species, g.seed, 1.0));
    });
  } catch (const Error& e) {
    int first = INT32_MAX;
    for (size_t g = begin; g < end; ++g)
      if (!grows_[g].model) first = std::min(first, grows_[g].first);
    failed(first, e);
    throw;  // failed() must throw; this is the fallback
  }
  for (size_t g = begin; g < end; ++g) {
    grows_[g].found->model = grows_[g].model;
    whole_bytes_ += whole_model_bytes(*grows_[g].model);
  }
}

void TreeTemplates::Request::pack(size_t begin, size_t end) {
  for (size_t k = begin; k < end; ++k) {
    Grow& g = grows_[k];
    whole_bytes_ -= whole_model_bytes(*g.model);
    g.found->model = pack_model(g.model, g.species, g.seed);
    g.model.reset();
  }
}

void TreeTemplates::keep(const Request& request) {
  for (const auto& [local, n] : request.needed_) models_[n.found.key] = n.found.model;
}

void TreeTemplates::release(const std::shared_ptr<const TreeModel>& model, const std::string& key) {
  if (model.use_count() == 1) models_.erase(key);
}

std::shared_ptr<const TreeModel> pack_model(const std::shared_ptr<const TreeModel>& model,
                                            const std::shared_ptr<const Species>& species,
                                            uint64_t seed) {
  if (model->packed) return model;
  const LeafModel first = model->leaves.empty() ? LeafModel{} : model->leaves.front();
  for (const LeafModel& l : model->leaves)
    if (l.length != first.length || l.width != first.width) return model;
  auto packed = std::make_shared<TreeModel::Packed>();
  packed->branches.reserve(model->branches.size());
  for (const BranchModel& b : model->branches)
    packed->branches.push_back({b.parent, float(b.v), b.radius, b.length});
  packed->leaf_count = int32_t(model->leaves.size());
  packed->leaf_length = first.length;
  packed->leaf_width = first.width;
  packed->species = species;
  packed->seed = seed;
  // Every field of TreeModel but the branches and leaves, in its order (a field added
  // there is added here).
  auto out = std::make_shared<TreeModel>();
  out->species = model->species;
  out->wood_modulus = model->wood_modulus;
  out->wood_rupture = model->wood_rupture;
  out->vogel_exponent = model->vogel_exponent;
  out->vogel_speed = model->vogel_speed;
  out->leaf_area_index = model->leaf_area_index;
  out->clumping = model->clumping;
  out->crown_area = model->crown_area;
  out->levels = model->levels;
  out->level_begin = model->level_begin;
  out->tier_begin = model->tier_begin;
  out->tier_level = model->tier_level;
  out->packed = std::move(packed);
  return out;
}

std::shared_ptr<const TreeModel> whole_model(const std::shared_ptr<const TreeModel>& model) {
  if (!model->packed) return model;
  return std::make_shared<const TreeModel>(
      grow_tree(*model->packed->species, model->packed->seed, 1.0));
}

}  // namespace boreas::impl
