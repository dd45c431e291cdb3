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
    Needed n;
    n.found.key = source.key + "\n" + std::to_string(params.seed);
    if (auto known = kept_.models_.find(n.found.key); known != kept_.models_.end())
      n.found.model = known->second.lock();
    if (!n.found.model) {
      n.grow = int(grows_.size());
      grows_.push_back({parse_species_source(source), params.seed, index, nullptr});
    }
    it = needed_.emplace(local, std::move(n)).first;
  }
  if (of_.size() <= size_t(index)) of_.resize(size_t(index) + 1, nullptr);
  of_[size_t(index)] = &it->second.found;
}

void TreeTemplates::Request::grow(const std::function<void(int, const Error&)>& failed) {
  // Each template is a pure function of species and seed, grown at scale 1.
  try {
    parallel_for(grows_.size(), [&](size_t g) {
      grows_[g].model =
          std::make_shared<const TreeModel>(grow_tree(grows_[g].species, grows_[g].seed, 1.0));
    });
  } catch (const Error& e) {
    int first = INT32_MAX;
    for (const Grow& g : grows_)
      if (!g.model) first = std::min(first, g.first);
    failed(first, e);
    throw;  // failed() must throw; this is the fallback
  }
  for (auto& [local, n] : needed_)
    if (n.grow >= 0) n.found.model = grows_[size_t(n.grow)].model;
}

void TreeTemplates::keep(const Request& request) {
  for (const auto& [local, n] : request.needed_) models_[n.found.key] = n.found.model;
}

void TreeTemplates::release(const std::shared_ptr<const TreeModel>& model, const std::string& key) {
  if (model.use_count() == 1) models_.erase(key);
}

}  // namespace boreas::impl
