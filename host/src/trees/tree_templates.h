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
    // The missing templates, in the order of the first tree that needs each: grow(),
    // grow_index() and pack() count them so. An add grows them a piece at a time (each
    // grown piece's trees added and its models packed before the next is grown), so that
    // the whole models it holds at once stay bounded whatever the count
    // (World::add_trees).
    size_t grows() const { return grows_.size(); }
    // Grows templates [begin, end) on every core. A failure calls failed(first, error),
    // which must throw, with the first tree whose template failed (whatever the threads'
    // timing).
    void grow(size_t begin, size_t end, const std::function<void(int, const Error&)>& failed);
    // The bytes the grown models not yet packed hold (their branches and leaves).
    size_t whole_bytes() const { return whole_bytes_; }
    // The template tree `index` grows (-1: a living tree has it).
    int grow_index(int index) const { return of_[size_t(index)]->grow; }
    // After its template is grown: tree `index`'s template.
    const Found& of(int index) const { return of_[size_t(index)]->found; }
    // Once the batches hold templates [begin, end)'s blocks: each replaced by its packed
    // form (of() then gives that), the whole ones let go.
    void pack(size_t begin, size_t end);
    // Models this request grew.
    size_t grown() const { return grows_.size(); }

   private:
    friend class TreeTemplates;
    struct Grow {
      std::shared_ptr<const Species> species;
      uint64_t seed = 0;
      int first = 0;  // the first tree that needs it, for the error's name
      std::shared_ptr<const TreeModel> model;
      Found* found = nullptr;  // its entry in needed_ (stable: a node of the map)
    };
    struct Needed {
      Found found;
      int grow = -1;  // its entry in grows_, or -1 when a living tree has it
    };
    const TreeTemplates& kept_;
    std::vector<Grow> grows_;
    size_t whole_bytes_ = 0;
    // Species parsed once per source (distinct seeds of one species share it).
    std::unordered_map<std::string, std::shared_ptr<const Species>> species_;
    std::unordered_map<std::string, Needed> needed_;  // by species name and seed (stable)
    std::vector<const Needed*> of_;                   // by tree index, into needed_
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
