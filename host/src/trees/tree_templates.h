// boreas: the grown models a world's trees share. Trees of the same species source and
// seed share one model (grown at scale 1; each tree's scale is applied where it is laid
// out), kept while a tree uses it, packed (without its leaves: TreeModel::Packed) once its
// trees are on the device; the models one call needs are grown on every core.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "errors.h"
#include "trees/species.h"
#include "trees/tree_model.h"
#include "trees/tree_params.h"

namespace boreas::impl {

class TreeTemplates {
 public:
  // The model a tree uses and its key among the templates.
  struct Found {
    std::shared_ptr<const TreeModel> model;  // null until grown
    std::string key;
  };

  // The templates one call needs: each tree's added in order (add reads its species and
  // throws for that tree), then grow() grows those no living tree has. Nothing is kept
  // until TreeTemplates::keep, so a failure anywhere changes nothing.
  class Request {
   public:
    explicit Request(const TreeTemplates& kept) : kept_(kept) {}
    // The template of tree `index` (its params checked already).
    void add(const TreeParams& params, int index);
    // Grows the missing templates on every core. A failure calls failed(first, error),
    // which must throw, with the first tree whose template failed (whatever the threads'
    // timing).
    void grow(const std::function<void(int, const Error&)>& failed);
    // After grow(): tree `index`'s template.
    const Found& of(int index) const { return *of_[size_t(index)]; }
    // Once the batches hold the grown models' blocks: each grown model replaced by its
    // packed form (of() then gives that), the whole ones let go.
    void pack();
    // Models this request grew.
    size_t grown() const { return grows_.size(); }

   private:
    friend class TreeTemplates;
    struct Grow {
      std::shared_ptr<const Species> species;
      uint64_t seed = 0;
      int first = 0;  // the first tree that needs it, for the error's name
      std::shared_ptr<const TreeModel> model;
    };
    struct Needed {
      Found found;
      int grow = -1;  // its entry in grows_, or -1 when a living tree has it
    };
    const TreeTemplates& kept_;
    std::vector<Grow> grows_;
    // Species parsed once per source (distinct seeds of one species share it).
    std::unordered_map<std::string, std::shared_ptr<const Species>> species_;
    std::unordered_map<std::string, Needed> needed_;  // by species name and seed (stable)
    std::vector<const Found*> of_;                    // by tree index, into needed_
  };

  // Keeps the request's templates (once its trees are in the world).
  void keep(const Request& request);
  // Lets a removed tree's template go when no other tree uses it.
  void release(const std::shared_ptr<const TreeModel>& model, const std::string& key);
  size_t size() const { return models_.size(); }

 private:
  // Grown models by species source key and seed, kept while a tree uses them.
  std::unordered_map<std::string, std::weak_ptr<const TreeModel>> models_;
};

// The model without its branches and leaves (TreeModel::Packed), for a model grown from
// species and seed at scale 1 whose leaves all share one size; any other (a model built
// by hand, or an already packed one) comes back as it is.
std::shared_ptr<const TreeModel> pack_model(const std::shared_ptr<const TreeModel>& model,
                                            const std::shared_ptr<const Species>& species,
                                            uint64_t seed);
// The model with its branches and leaves: itself, or a packed one grown again (the same
// bits: growing is a pure function of species and seed; about 10 ms an aspen).
std::shared_ptr<const TreeModel> whole_model(const std::shared_ptr<const TreeModel>& model);

}  // namespace boreas::impl
