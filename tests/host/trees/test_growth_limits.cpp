// boreas tests: the growth limits (GrowthLimits, trees/tree_model.h). A species asking for
// more branches, leaves or stem segments than one tree may have is refused before it is
// grown, naming its file, the parameter to lower and the limit; every real species grows far
// below them.
#include <gtest/gtest.h>

#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>

#include "errors.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace boreas::impl {
namespace {

// A species file's text with the given params ({"Levels": 3, ...} without the braces).
std::string species_json(const std::string& params) {
  return R"({"format": "boreas-species-1", "name": "greedy", "params": {)" + params + "}}";
}

// Grows the species (parsed as the file "dir/greedy.json") and expects a refusal whose
// message holds every one of `parts`.
void expect_refused(const std::string& params, std::initializer_list<std::string> parts,
                    const GrowthLimits& limits = {}) {
  const Species s = parse_species_json(species_json(params), "dir/greedy.json");
  try {
    (void)grow_tree(s, 1, 1.0, limits);
    ADD_FAILURE() << "grew: " << params;
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT);
    const std::string what = e.what();
    for (const std::string& part : {std::string("'greedy'"), std::string("dir/greedy.json")})
      EXPECT_NE(what.find(part), std::string::npos) << what;
    for (const std::string& part : parts) EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

TEST(GrowthLimits, TooManyBranchesNamesTheLevelsBranches) {
  // 1 + 10,000 + about 7.5 million: the count is refused before level 2 grows.
  expect_refused(R"("Levels": 3, "1Branches": 10000, "2Branches": 1000)",
                 {"1048575 branches", "at level 2", "2Branches (1000)"});
}

TEST(GrowthLimits, TooManyLeavesNamesLeaves) {
  // 1,000 stems with 10,000 leaves each: 10 million, more than 2^22.
  expect_refused(R"("Levels": 2, "1Branches": 1000, "Leaves": 10000, "LeafDistrib": 3)",
                 {"4194304 leaves", "Leaves (10000)", "LeafQuality (1)"});
}

// Arbaro (Params.prepare) refuses nSegSplits > 0 with nSplitAngle 0: the clones would grow
// inside their stem. Named by level and both parameters, on every level that grows.
TEST(GrowthLimits, SplitsWithoutASplitAngleAreRefused) {
  expect_refused(R"("Levels": 3, "1SegSplits": 0.2)", {"1SegSplits is 0.2", "1SplitAngle is 0"});
  expect_refused(R"("Levels": 1, "0SegSplits": 1, "0SplitAngle": 0)",
                 {"0SegSplits is 1", "0SplitAngle is 0"});
  // A level the species does not grow is not checked (Arbaro checks levels below Levels).
  const Species s =
      parse_species_json(species_json(R"("Levels": 2, "2SegSplits": 0.5)"), "dir/greedy.json");
  EXPECT_NO_THROW((void)grow_tree(s, 1));
}

TEST(GrowthLimits, TooManySplitsNamesSegSplits) {
  // Ten clones at every segment, seven splits deep: 11^7 pieces of one trunk.
  expect_refused(R"("Levels": 1, "0CurveRes": 10, "0SegSplits": 10, "0SplitAngle": 20)",
                 {"1048575 branches", "splitting at level 0", "0SegSplits (10)"});
}

TEST(GrowthLimits, TooManySegmentsNamesTheLevelsCurveRes) {
  // Within the branch limit but 1,000 segments a stem: the walk stops at the limit. A
  // small limit keeps the test fast; the check is the one the default limit runs.
  GrowthLimits limits;
  limits.segments = 100000;
  expect_refused(R"("Levels": 3, "1Branches": 30, "2Branches": 30, "2CurveRes": 1000)",
                 {"100000 stem segments", "at level 2, 1000 per stem", "2CurveRes"}, limits);
}

TEST(GrowthLimits, ManyTrunksCountAgainstTheSegments) {
  GrowthLimits limits;
  limits.segments = 100000;
  expect_refused(R"("Levels": 1, "0Branches": 10000, "0CurveRes": 1000)",
                 {"100000 stem segments", "at level 0", "0CurveRes"}, limits);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// An eighth of every default limit is still more than every real species grows (the
// margins host/species/README.md states).
TEST(GrowthLimits, EveryRealSpeciesGrowsFarBelowTheLimits) {
  GrowthLimits eighth;
  eighth.branches /= 8;
  eighth.leaves /= 8;
  eighth.segments /= 8;
  for (const std::string& name : builtin_species_names()) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW((void)grow_tree(load_species(name), 1, 1.0, eighth));
  }
  for (const char* name :
       {"barley", "black_tupelo", "ca_black_oak", "desert_bush", "eastern_cottonwood", "fanpalm",
        "palm", "quaking_aspen", "rush", "shave-grass", "tamarack", "weeping_willow", "wheat"}) {
    SCOPED_TRACE(name);
    const std::string file = std::string(BOREAS_TEST_DATA_DIR) + "/arbaro/" + name + ".xml";
    EXPECT_NO_THROW((void)grow_tree(parse_arbaro_xml(read_text(file), file), 1, 1.0, eighth));
  }
}

}  // namespace
}  // namespace boreas::impl
