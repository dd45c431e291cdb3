// boreas_tree_def.leaf_outline: by species (the default) it resolves to the kind named after
// a built-in species, an explicit kind is kept (shifted to cl/shared/leaf_outline.h's
// numbering), and a value out of range is refused naming the field.
#include <gtest/gtest.h>

#include "boreas/boreas.h"
#include "shared/leaf_outline.h"
#include "support/expect_error.h"
#include "trees/tree_params.h"

namespace boreas {
namespace {

using test::expect_error;

int outline_of(const char* species, boreas_leaf_outline outline) {
  boreas_tree_def t = boreas_default_tree_def();
  t.species = species;
  t.leaf_outline = outline;
  return impl::checked_tree_def(t).leaf_outline;
}

TEST(TreeLeafOutline, DefaultResolvesBySpecies) {
  EXPECT_EQ(boreas_default_tree_def().leaf_outline, BOREAS_LEAF_OUTLINE_SPECIES);
  EXPECT_EQ(outline_of("quaking_aspen", BOREAS_LEAF_OUTLINE_SPECIES), BOREAS_LEAF_OUTLINE_ASPEN);
  EXPECT_EQ(outline_of("ca_black_oak", BOREAS_LEAF_OUTLINE_SPECIES), BOREAS_LEAF_OUTLINE_OAK);
  EXPECT_EQ(outline_of("weeping_willow", BOREAS_LEAF_OUTLINE_SPECIES), BOREAS_LEAF_OUTLINE_WILLOW);
  EXPECT_EQ(outline_of("black_tupelo", BOREAS_LEAF_OUTLINE_SPECIES), BOREAS_LEAF_OUTLINE_TUPELO);
  EXPECT_EQ(outline_of("some/dir/black_tupelo.json", BOREAS_LEAF_OUTLINE_SPECIES),
            BOREAS_LEAF_OUTLINE_TUPELO);
  EXPECT_EQ(outline_of("my_maple.xml", BOREAS_LEAF_OUTLINE_SPECIES), BOREAS_LEAF_OUTLINE_BROADLEAF);
  EXPECT_EQ(boreas_species_leaf_outline("ca_black_oak"), BOREAS_LEAF_OAK);
  EXPECT_EQ(boreas_species_leaf_outline(nullptr), BOREAS_LEAF_BROADLEAF);
}

TEST(TreeLeafOutline, ExplicitKindIsKept) {
  EXPECT_EQ(outline_of("quaking_aspen", BOREAS_LEAF_OAK), BOREAS_LEAF_OUTLINE_OAK);
  EXPECT_EQ(outline_of("ca_black_oak", BOREAS_LEAF_BROADLEAF), BOREAS_LEAF_OUTLINE_BROADLEAF);
  EXPECT_EQ(outline_of("ca_black_oak", BOREAS_LEAF_TUPELO), BOREAS_LEAF_OUTLINE_TUPELO);
}

TEST(TreeLeafOutline, OutOfRangeIsRefusedNamingTheField) {
  for (int bad : {-1, BOREAS_LEAF_TUPELO + 1, 1000}) {
    boreas_tree_def t = boreas_default_tree_def();
    t.leaf_outline = static_cast<boreas_leaf_outline>(bad);
    expect_error([&] { impl::checked_tree_def(t); }, BOREAS_ERROR_INVALID_ARGUMENT,
                 {"tree_def.leaf_outline"});
  }
}

}  // namespace
}  // namespace boreas
