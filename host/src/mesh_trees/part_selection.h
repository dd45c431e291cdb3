// boreas: which part of a tree model (trunk, leaves or neither) a run of triangles goes to,
// by its names, and the error that helps the user name the trunk when none matched.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "mesh_trees/tree_model.h"

namespace boreas::impl::model_import {

enum class Part { kNone, kTrunk, kLeaves };

const char* part_name(Part part);

// One part's comma-separated names, matched case-insensitively as substrings.
class NameSelector {
 public:
  explicit NameSelector(const std::string& list);
  bool matches(std::string_view name) const;
  bool empty() const { return names_.empty(); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
  std::vector<std::string> names_;
};

class PartSelector {
 public:
  explicit PartSelector(const ModelPartSelection& selection)
      : trunk_(selection.trunk), leaves_(selection.leaves) {}

  // names: a run's names, most specific first; the first one that either part matches
  // decides. A name that matches both goes to the leaves: exporters name leaf cards after
  // what they hang on ("branch_leaves", "twig_leaf"), while trunk geometry rarely carries a
  // leaf word.
  Part classify(std::initializer_list<std::string_view> names) const {
    for (std::string_view name : names) {
      if (leaves_.matches(name)) return Part::kLeaves;
      if (trunk_.matches(name)) return Part::kTrunk;
    }
    return Part::kNone;
  }
  const NameSelector& trunk() const { return trunk_; }
  const NameSelector& leaves() const { return leaves_; }

 private:
  NameSelector trunk_;
  NameSelector leaves_;
};

// The distinct names of one kind in a file, in order of first appearance, for the error that
// asks the user to pick the trunk by name.
struct NameList {
  std::string kind;  // plural, as the message says it: "objects/groups", "materials"
  std::vector<std::string> names;
  std::unordered_set<std::string> seen;

  explicit NameList(std::string k) : kind(std::move(k)) {}
  void add(const std::string& name) {
    if (!name.empty() && seen.insert(name).second) names.push_back(name);
  }
};

// Why the trunk came out empty, as the readers saw it.
struct TrunkSearch {
  std::string name_kinds;    // what the names are matched against: "object/group or material"
  size_t matched_runs = 0;   // runs whose names chose the trunk
  std::string skipped_note;  // why matched runs gave no triangles, if the reader knows
  std::vector<const NameList*> lists;
};

// Throws Error (INVALID_ARGUMENT) saying why the trunk came out empty and which names the
// file has that the trunk part could be set to.
[[noreturn]] void fail_no_trunk(const std::string& path, const PartSelector& selector,
                                const TrunkSearch& search);

}  // namespace boreas::impl::model_import
