// boreas render scene: a tree's leaf kind and its outline in the library.
#include "scene/leaf_choice.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "textures/leaf_kinds.h"

namespace boreas::render {

// leaf_kinds() is in the outlines' order (BOREAS_LEAF_OUTLINE_*), which the library's enum
// shifts by one.
std::string default_leaf_kind(const std::string& species) {
  const int outline = boreas_species_leaf_outline(species.c_str());
  return leaf_kind_names().at(size_t(outline - BOREAS_LEAF_BROADLEAF));
}

boreas_leaf_outline leaf_outline_of_kind(const std::string& kind) {
  const std::vector<std::string> names = leaf_kind_names();
  auto at = std::find(names.begin(), names.end(), kind);
  if (at == names.end()) throw std::invalid_argument("unknown leaf kind \"" + kind + "\"");
  return static_cast<boreas_leaf_outline>(BOREAS_LEAF_BROADLEAF + (at - names.begin()));
}

}  // namespace boreas::render
