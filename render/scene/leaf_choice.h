// boreas render scene: which leaf kind (render/textures/leaf_kinds.h) a scene's tree wears,
// and the library's leaf outline that goes with it, so the picture and the rays agree.
#pragma once

#include <string>

#include "boreas/boreas.h"

namespace boreas::render {

// The kind a tree of this species wears when its scene does not choose one: the library's
// rule (boreas_species_leaf_outline), named as leaf_kind_names() names it.
std::string default_leaf_kind(const std::string& species);

// The tree def's leaf_outline for a kind of leaf_kind_names() (throws std::invalid_argument
// for a name that is not one).
boreas_leaf_outline leaf_outline_of_kind(const std::string& kind);

}  // namespace boreas::render
