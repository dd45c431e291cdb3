// boreas: a tree's leaf outline, from its def or its species.
#include "trees/leaf_outline.h"

#include <filesystem>

#include "errors.h"
#include "shared/leaf_outline.h"

namespace boreas::impl {

// The public enum is the device's kinds shifted by one, so 0 can mean "by species".
static_assert(BOREAS_LEAF_BROADLEAF - 1 == BOREAS_LEAF_OUTLINE_BROADLEAF);
static_assert(BOREAS_LEAF_ASPEN - 1 == BOREAS_LEAF_OUTLINE_ASPEN);
static_assert(BOREAS_LEAF_OAK - 1 == BOREAS_LEAF_OUTLINE_OAK);
static_assert(BOREAS_LEAF_WILLOW - 1 == BOREAS_LEAF_OUTLINE_WILLOW);
static_assert(BOREAS_LEAF_TUPELO - 1 == BOREAS_LEAF_OUTLINE_TUPELO);
static_assert(BOREAS_LEAF_TUPELO == BOREAS_LEAF_OUTLINE_COUNT);

int species_leaf_outline(const std::string& species) {
  const std::string stem = std::filesystem::path(species).stem().string();
  if (stem == "quaking_aspen") return BOREAS_LEAF_OUTLINE_ASPEN;
  if (stem == "ca_black_oak") return BOREAS_LEAF_OUTLINE_OAK;
  if (stem == "weeping_willow") return BOREAS_LEAF_OUTLINE_WILLOW;
  if (stem == "black_tupelo") return BOREAS_LEAF_OUTLINE_TUPELO;
  return BOREAS_LEAF_OUTLINE_BROADLEAF;
}

int resolved_leaf_outline(int outline, const std::string& species) {
  if (outline < BOREAS_LEAF_OUTLINE_SPECIES || outline > BOREAS_LEAF_TUPELO)
    fail_argument("tree_def.leaf_outline must be BOREAS_LEAF_OUTLINE_SPECIES (0) or a kind 1.." +
                  std::to_string(BOREAS_LEAF_TUPELO) + " (got " + std::to_string(outline) + ")");
  if (outline == BOREAS_LEAF_OUTLINE_SPECIES) return species_leaf_outline(species);
  return outline - 1;
}

}  // namespace boreas::impl
