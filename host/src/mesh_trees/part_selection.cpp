// boreas: a tree model's parts chosen by name (see part_selection.h).
#include "mesh_trees/part_selection.h"

#include <algorithm>
#include <sstream>

#include "errors.h"
#include "mesh_trees/model_import_internal.h"

namespace boreas::impl::model_import {

const char* part_name(Part part) { return part == Part::kTrunk ? "trunk" : "leaves"; }

NameSelector::NameSelector(const std::string& list) : text_(list) {
  std::istringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::string name = lowercase(trim(item));
    if (!name.empty()) names_.push_back(name);
  }
}

bool NameSelector::matches(std::string_view name) const {
  if (name.empty()) return false;
  std::string lower = lowercase(name);
  return std::any_of(names_.begin(), names_.end(),
                     [&](const std::string& n) { return lower.find(n) != std::string::npos; });
}

[[noreturn]] void fail_no_trunk(const std::string& path, const PartSelector& selector,
                                const TrunkSearch& search) {
  // Enough names to recognise the model's parts; a SpeedTree export can have thousands.
  constexpr size_t kMaxListed = 12;
  std::ostringstream m;
  m << about(path) << "no trunk triangles: ";
  if (selector.trunk().empty()) {
    m << "the trunk part's names are empty.";
  } else if (search.matched_runs == 0) {
    m << "no " << search.name_kinds << " name contains any of the trunk part's names "
      << quoted(selector.trunk().text()) << " (comma-separated, case-insensitive).";
  } else {
    m << "the " << search.matched_runs << " part(s) named by the trunk part's names "
      << quoted(selector.trunk().text()) << " have no triangles"
      << (search.skipped_note.empty() ? "." : ": " + search.skipped_note);
  }

  std::string example;
  bool any = false;
  for (const NameList* list : search.lists) {
    if (list->names.empty()) continue;
    m << (any ? "; " : " The file has ") << list->kind << " ";
    for (size_t i = 0; i < list->names.size() && i < kMaxListed; ++i) {
      m << (i ? ", " : "") << quoted(list->names[i]);
    }
    if (list->names.size() > kMaxListed) {
      m << " and " << list->names.size() - kMaxListed << " more";
    }
    any = true;
    for (const std::string& name : list->names) {
      if (example.empty() && !selector.leaves().matches(name)) example = name;
    }
  }
  if (any) {
    m << ". Set the trunk part to a comma-separated list of these names (or parts of them)";
    if (!example.empty()) m << ", e.g. " << quoted(example);
    m << ".";
  } else {
    m << " The file names no " << search.name_kinds
      << ": name the trunk in the modelling package and set the trunk part to that name.";
  }
  fail_argument(m.str());
}

}  // namespace boreas::impl::model_import
