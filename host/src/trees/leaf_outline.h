// boreas: which leaf outline (cl/shared/leaf_outline.h) a tree's leaves have: the one its
// def names, or the one named after its species; one rule for the rays and the renderer.
#pragma once

#include <string>

#include "boreas/boreas.h"

namespace boreas::impl {

// The outline kind, 0..BOREAS_LEAF_OUTLINE_COUNT - 1, named after a built-in species
// (matched on a species file's stem too: ".../weeping_willow.xml"); broadleaf for any other.
int species_leaf_outline(const std::string& species);

// The kind of a tree of this species whose def asks for `outline` (checked: an error
// names tree_def.leaf_outline).
int resolved_leaf_outline(int outline, const std::string& species);

}  // namespace boreas::impl
