// Underbrush species files: the built-ins load, and bad definitions get errors that name
// the file, the JSON path and what was wrong, and change nothing.
#include <gtest/gtest.h>

#include <fstream>

#include "errors.h"
#include "support/test_support.h"
#include "underbrush/component_species.h"

namespace boreas::impl {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_component_species(text, "bad.json");
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT);
    return e.what();
  }
  ADD_FAILURE() << "no error for: " << text;
  return "";
}

const char* kMinimal = R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "blade"}]})";

TEST(ComponentSpecies, BuiltinsLoadWithTheirParts) {
  int count = 0;
  for (int i = 0; builtin_underbrush_species(i); ++i, ++count) {
    ComponentSpecies s = load_component_species(builtin_underbrush_species(i));
    EXPECT_EQ(s.name, builtin_underbrush_species(i));
    EXPECT_FALSE(s.parts.empty());
    for (const PartDef& p : s.parts) {
      std::vector<SectionPhysics> sec = part_sections(s.tissue, p);
      ASSERT_EQ(int(sec.size()), p.sections);
      for (const SectionPhysics& x : sec) {
        EXPECT_GT(x.mass, 0.0);
        EXPECT_GT(x.stiffness, 0.0);
        EXPECT_GT(x.max_moment, 0.0);
      }
    }
  }
  EXPECT_EQ(count, 4);
  ComponentSpecies daisy = load_component_species("daisy");
  EXPECT_EQ(daisy.components_per_plant(),
            4 + 1 + 14 + 6);  // leaves, stalk; rays and disc on the stalk
  EXPECT_EQ(daisy.parts[2].parent, 1);
}

TEST(ComponentSpecies, StiffnessFollowsTheStatedBeamFormula) {
  ComponentSpecies s = parse_component_species(
      R"({"format": "boreas-underbrush-1", "name": "x", "tissue": {"young_modulus": 1e9, "density": 500,
          "break_stress": 1e7},
          "parts": [{"name": "b", "sections": 2, "length": 0.2, "width": [0.004, 0.002], "thickness": [0.001, 0.0005]}]})",
      "t.json");
  std::vector<SectionPhysics> sec = part_sections(s.tissue, s.parts[0]);
  // Section 0: width and thickness at its middle (s = 1/4).
  double w = 0.004 - 0.002 * 0.25, t = 0.001 - 0.0005 * 0.25, l = 0.1;
  EXPECT_NEAR(sec[0].stiffness, 1e9 * w * t * t * t / (12 * l), 1e-15);
  EXPECT_NEAR(sec[0].mass, 500 * w * t * l, 1e-15);
  EXPECT_NEAR(sec[0].max_moment, 1e7 * w * t * t / 6, 1e-15);
  // Thinner toward the tip: much less stiff (t^3).
  EXPECT_LT(sec[1].stiffness, 0.5 * sec[0].stiffness);
}

TEST(ComponentSpecies, BadDefinitionsNameFileAndPath) {
  EXPECT_NE(error_of("{\"format\": ").find("bad.json:1: not valid JSON"), std::string::npos);
  // A raw newline in a string is the error, and it ends line 1: named as line 1, not 2.
  EXPECT_NE(error_of("{\"format\": \"a\nb\"}").find("bad.json:1: not valid JSON"),
            std::string::npos)
      << error_of("{\"format\": \"a\nb\"}");
  // A NUL byte would end nlohmann's input there (what follows, unread): refused.
  EXPECT_NE(error_of(std::string("{}\n\0garbage", 11)).find("bad.json:2: not valid JSON: a NUL byte"),
            std::string::npos);
  // Found by fuzz_underbrush_species (tests/fuzz): a number past a double's range escaped
  // the parser as nlohmann's out_of_range.
  EXPECT_NE(error_of("{\"format\": 1e400}").find("bad.json: not valid JSON: "), std::string::npos)
      << error_of("{\"format\": 1e400}");
  EXPECT_NE(error_of(R"({"name": "x", "parts": []})").find("format"), std::string::npos);
  std::string e = error_of(
      R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "blade", "sections": 12}]})");
  EXPECT_NE(e.find("bad.json: parts[0].sections must be in 1..8 (got 12)"), std::string::npos) << e;
  e = error_of(R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "blade", "length": -1}]})");
  EXPECT_NE(e.find("parts[0].length"), std::string::npos) << e;
  e = error_of(R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "blade", "width": "wide"}]})");
  EXPECT_NE(e.find("parts[0].width must be a number or a pair"), std::string::npos) << e;
  e = error_of(R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "a", "parent": "b"}]})");
  EXPECT_NE(e.find("parts[0].parent names no earlier part"), std::string::npos) << e;
  e = error_of(R"({"format": "boreas-underbrush-1", "name": "x", "tissue": {"tau": 0}, "parts": [{"name": "a"}]})");
  EXPECT_NE(e.find("tissue.tau must be in"), std::string::npos) << e;
  e = error_of(R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "a", "colour": 1}]})");
  EXPECT_NE(e.find("parts[0].colour is not a known key"), std::string::npos) << e;
  e = error_of(R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "a", "tilt": [40, 10]}]})");
  EXPECT_NE(e.find("parts[0].tilt must be [min, max]"), std::string::npos) << e;
  e = error_of(R"({"format": "boreas-underbrush-1", "name": "x", "ground": {"need": [0.5, 2]}, "parts": [{"name": "a"}]})");
  EXPECT_NE(e.find("ground.need[1]"), std::string::npos) << e;
  e = error_of(R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "a", "count": 64},
               {"name": "b", "parent": "a", "count": 64}]})");
  EXPECT_NE(e.find("components per plant"), std::string::npos) << e;
  e = error_of(
      R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "a", "color": [1, 0.5]}]})");
  EXPECT_NE(e.find("parts[0].color must be [r, g, b], sRGB 0..1"), std::string::npos) << e;
  e = error_of(
      R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "a", "color": [1, 0.5, 1.5]}]})");
  EXPECT_NE(e.find("parts[0].color[2] must be in [0, 1] (got 1.5)"), std::string::npos) << e;
  e = error_of(
      R"({"format": "boreas-underbrush-1", "name": "x", "parts": [{"name": "a", "translucency": -0.1}]})");
  EXPECT_NE(e.find("parts[0].translucency must be in [0, 1]"), std::string::npos) << e;
  EXPECT_NO_THROW(parse_component_species(kMinimal, "ok.json"));
}

TEST(ComponentSpecies, LookComesFromTheFileElseFromTheProfile) {
  ComponentSpecies s = parse_component_species(
      R"({"format": "boreas-underbrush-1", "name": "x", "parts": [
          {"name": "blade"},
          {"name": "stalk", "profile": "stalk"},
          {"name": "petal", "parent": "stalk", "profile": "petal"},
          {"name": "disc", "parent": "stalk", "profile": "petal", "color": [0.9, 0.7, 0.1], "translucency": 0}]})",
      "look.json");
  ASSERT_EQ(s.parts.size(), 4u);
  EXPECT_GT(s.parts[0].color[1], s.parts[0].color[0]);          // green
  EXPECT_GT(s.parts[0].translucency, s.parts[1].translucency);  // a stalk lets less through
  EXPECT_GT(s.parts[2].color[2], 0.9);                          // petals white
  EXPECT_DOUBLE_EQ(s.parts[3].color[0], 0.9);
  EXPECT_DOUBLE_EQ(s.parts[3].color[1], 0.7);
  EXPECT_DOUBLE_EQ(s.parts[3].color[2], 0.1);
  EXPECT_DOUBLE_EQ(s.parts[3].translucency, 0.0);
}

TEST(ComponentSpecies, MissingFileIsAnIoErrorListingTheBuiltins) {
  try {
    load_component_species("/nonexistent/grass.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_IO);
    EXPECT_NE(std::string(e.what()).find("meadow_grass"), std::string::npos);
  }
}

TEST(ComponentSpecies, LoadsAUsersFile) {
  test::TempDir dir;
  std::string path = dir.str() + "/mine.json";
  std::ofstream(path) << kMinimal;
  ComponentSpecies s = load_component_species(path);
  EXPECT_EQ(s.source, path);
  EXPECT_EQ(s.parts.size(), 1u);
}

}  // namespace
}  // namespace boreas::impl
