// boreas: the grown models a world's trees share. Trees of the same species source and
// seed share one model (grown at scale 1; each tree's scale is applied where it is laid
// out), kept while a tree uses it; the models one call needs are grown on every core.
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

   private:
    friend class TreeTemplates;
    struct Grow {
      Species species;
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

}  // namespace boreas::impl
