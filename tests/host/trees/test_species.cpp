// boreas tests: Weber-Penn species — the parameter table, Arbaro XML and boreas JSON
// loading (every test file, the built-in presets, defaults), errors that name the file, the
// line and the parameter, and the shape ratios against their formulas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "errors.h"
#include "support/test_support.h"
#include "trees/species.h"

namespace boreas::test {
namespace {

namespace fs = std::filesystem;
using impl::Species;
using impl::SpeciesParam;

const fs::path kArbaroDir = fs::path(BOREAS_TEST_DATA_DIR) / "arbaro";
const std::vector<std::string> kBuiltins = {"black_tupelo", "ca_black_oak", "quaking_aspen",
                                            "weeping_willow"};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<fs::path> arbaro_files() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(kArbaroDir)) {
    if (e.path().extension() == ".xml") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The (name, value) pairs of a file's <param> lines, read with a regex rather than pugixml.
std::vector<std::pair<std::string, std::string>> params_in(const std::string& xml) {
  static const std::regex param(R"(<param name=['"]([^'"]+)['"] value=['"]([^'"]*)['"])");
  std::vector<std::pair<std::string, std::string>> out;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), param); it != std::sregex_iterator();
       ++it) {
    out.emplace_back((*it)[1], (*it)[2]);
  }
  return out;
}

void expect_xml_error(const std::string& text, std::initializer_list<std::string> pieces) {
  expect_error([&] { (void)impl::parse_arbaro_xml(text, "bad.xml"); },
               BOREAS_ERROR_INVALID_ARGUMENT, pieces);
}

void expect_json_error(const std::string& text, std::initializer_list<std::string> pieces) {
  expect_error([&] { (void)impl::parse_species_json(text, "bad.json"); },
               BOREAS_ERROR_INVALID_ARGUMENT, pieces);
}

// An Arbaro file: line 1 <?xml?>, 2 <arbaro>, 3 <species name='t'>, `body` from line 4 on
// (one entry a line), then </species> and </arbaro>.
std::string arbaro(const std::vector<std::string>& body) {
  std::string text = "<?xml version='1.0' ?>\n<arbaro>\n  <species name='t'>\n";
  for (const std::string& line : body) text += "    " + line + "\n";
  return text + "  </species>\n</arbaro>\n";
}

// A boreas JSON file: lines 1-4 open it ({, format, name, "params": {), `params` from line 5
// on (commas added), then the closing braces.
std::string species_json(const std::vector<std::string>& params) {
  std::string text =
      "{\n  \"format\": \"boreas-species-1\",\n  \"name\": \"t\",\n  \"params\": {\n";
  for (size_t i = 0; i < params.size(); ++i) {
    text += "    " + params[i] + (i + 1 < params.size() ? ",\n" : "\n");
  }
  return text + "  }\n}\n";
}

// Every table value of a and b is equal, and so are the names and leaf shapes.
void expect_same_species(const Species& a, const Species& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.leaf_shape, b.leaf_shape);
  for (const SpeciesParam& p : impl::species_params()) {
    EXPECT_EQ(impl::species_param_value(a, p), impl::species_param_value(b, p)) << p.name;
  }
}

// ---- The table ----

TEST(SpeciesTable, EveryParameterOnceWithOneHome) {
  const auto& table = impl::species_params();
  // + WoodModulus, WoodRupture, VogelExponent, VogelSpeed, LeafAreaIndex, Clumping: ours.
  EXPECT_EQ(table.size(), 28u + 6u + 16u * impl::kMaxTreeLevels);
  std::set<std::string> names;
  for (const SpeciesParam& p : table) {
    EXPECT_TRUE(names.insert(p.name).second) << p.name << " twice";
    int homes = (p.real != nullptr) + (p.whole != nullptr) + (p.per_level != nullptr);
    EXPECT_EQ(homes, p.name == "LeafShape" ? 0 : 1) << p.name;
    EXPECT_EQ(p.per_level != nullptr, p.level >= 0) << p.name;
    EXPECT_LE(p.min, p.default_value) << p.name;
    EXPECT_LE(p.default_value, p.max) << p.name;
    if (p.level >= 0) {
      EXPECT_LT(p.level, impl::kMaxTreeLevels);
      EXPECT_EQ(p.name[0], static_cast<char>('0' + p.level)) << p.name;
    }
    EXPECT_EQ(impl::find_species_param(p.name), &p);
  }
  EXPECT_EQ(impl::find_species_param("Nonsense"), nullptr);
  EXPECT_TRUE(impl::find_species_param("3CurveV") != nullptr);
  EXPECT_EQ(impl::find_species_param("4CurveV"), nullptr);
}

TEST(SpeciesTable, DefaultsMatchTheStructInitializers) {
  const Species s{};
  for (const SpeciesParam& p : impl::species_params()) {
    if (p.is_leaf_shape()) {
      EXPECT_EQ(s.leaf_shape, "0");
      EXPECT_EQ(p.default_value, 0.0);
    } else {
      EXPECT_EQ(impl::species_param_value(s, p), p.default_value) << p.name;
    }
  }
}

// ---- Arbaro XML ----

TEST(SpeciesXml, EveryArbaroFileImportsWithEveryValueStored) {
  std::vector<fs::path> files = arbaro_files();
  ASSERT_GE(files.size(), 13u);
  const Species defaults{};
  for (const fs::path& path : files) {
    SCOPED_TRACE(path.filename().string());
    Species s;
    ASSERT_NO_THROW(s = impl::load_species(path.string()));
    EXPECT_FALSE(s.name.empty());
    std::set<std::string> given;
    for (const auto& [name, value] : params_in(read_text(path))) {
      given.insert(name);
      const SpeciesParam* p = impl::find_species_param(name);
      ASSERT_NE(p, nullptr) << name;
      if (p->is_leaf_shape())
        EXPECT_EQ(s.leaf_shape, value);
      else
        EXPECT_EQ(impl::species_param_value(s, *p), std::stod(value)) << name;
    }
    // Omitted parameters keep the defaults; Clumping's follows the leaves (below).
    EXPECT_EQ(s.clumping, impl::species_default_clumping(s));
    for (const SpeciesParam& p : impl::species_params()) {
      if (given.count(p.name) == 0 && !p.is_leaf_shape() && p.name != "Clumping") {
        EXPECT_EQ(impl::species_param_value(s, p), impl::species_param_value(defaults, p))
            << p.name;
      }
    }
  }
}

TEST(SpeciesXml, ReadsNamesQuotesAndLeafShapes) {
  Species grass = impl::load_species((kArbaroDir / "shave-grass.xml").string());
  EXPECT_EQ(grass.name, "shave_grass");  // the attribute, not the file name
  Species wheat = impl::load_species((kArbaroDir / "wheat.xml").string());
  EXPECT_EQ(wheat.leaf_shape, "sphere");
  EXPECT_EQ(wheat.leaves, -1);
  EXPECT_EQ(impl::load_species((kArbaroDir / "palm.xml").string()).leaf_shape, "palm");
  Species aspen = impl::load_species((kArbaroDir / "quaking_aspen.xml").string());
  EXPECT_EQ(aspen.shape, 7);
  EXPECT_EQ(aspen.levels, 3);
  EXPECT_DOUBLE_EQ(aspen.scale, 13.0);
  EXPECT_DOUBLE_EQ(aspen.level[1].down_angle, 60.0);
  EXPECT_DOUBLE_EQ(aspen.level[1].down_angle_v, -50.0);
  EXPECT_DOUBLE_EQ(aspen.level[1].branches, 50.0);
  EXPECT_DOUBLE_EQ(aspen.level[3].rotate, 77.0);
  EXPECT_EQ(aspen.leaf_shape, "0");
}

TEST(SpeciesXml, OmittedParametersTakeDefaults) {
  Species s =
      impl::parse_arbaro_xml(arbaro({"<param name='Shape' value='5'/>", "<!-- a comment -->",
                                     "<param name=\"2Length\" value=\" 0.4 \"/>"}),
                             "min.xml");
  EXPECT_EQ(s.name, "t");
  EXPECT_EQ(s.shape, 5);
  EXPECT_DOUBLE_EQ(s.level[2].length, 0.4);
  Species expected{};
  expected.name = "t";
  expected.shape = 5;
  expected.level[2].length = 0.4;
  expect_same_species(s, expected);
}

// A species without a Clumping gets one from what it bears: the tamarack (a conical crown
// of narrow needle tufts) a conifer's 0.6, every broadleaf in Arbaro's files 0.8, the
// desert bush too (a conical crown, but round leaves). A Clumping given is kept.
TEST(SpeciesClumping, NeedlesAndBroadLeavesWithoutOneGetTheirOwn) {
  for (const fs::path& path : arbaro_files()) {
    SCOPED_TRACE(path.filename().string());
    const Species s = impl::load_species(path.string());
    const bool needles = path.stem() == "tamarack";
    EXPECT_EQ(impl::species_is_needle_leaved(s), needles);
    EXPECT_EQ(s.clumping, needles ? 0.6 : 0.8);
  }
  const Species conifer = impl::parse_arbaro_xml(
      arbaro({"<param name='Shape' value='0'/>", "<param name='LeafScaleX' value='0.3'/>"}),
      "conifer.xml");
  EXPECT_EQ(conifer.clumping, 0.6);
  const Species given = impl::parse_species_json(
      species_json({"\"Shape\": 0", "\"LeafScaleX\": 0.3", "\"Clumping\": 0.9"}), "given.json");
  EXPECT_EQ(given.clumping, 0.9);
  const Species round = impl::parse_species_json(
      species_json({"\"Shape\": 0", "\"LeafScaleX\": 0.5"}), "round.json");
  EXPECT_EQ(round.clumping, 0.8) << "twice as long as wide is not yet a needle";
  for (const std::string& name : impl::builtin_species_names())
    EXPECT_FALSE(impl::species_is_needle_leaved(impl::load_species(name))) << name;
}

TEST(SpeciesXml, MalformedXmlNamesTheLine) {
  // Line 5 opens <param> without closing it; the parser finds out at </species>, line 7.
  expect_xml_error(arbaro({"<param name='Shape' value='7'/>", "<param name='Levels' value='3'>",
                           "<param name='Scale' value='5'/>"}),
                   {"bad.xml:7:", "malformed XML"});
  expect_xml_error("<?xml version='1.0' ?>\n<arbaro>\n  <species name='t'\n",
                   {"bad.xml:", "malformed XML"});
}

TEST(SpeciesXml, UnknownParameterNamesFileLineAndName) {
  std::string text = arbaro({"<param name='Shape' value='7'/>", "<param name='Bogus' value='1'/>"});
  expect_xml_error(text, {"bad.xml:5:", "parameter 'Bogus'", "unknown parameter"});
  // The same with Windows line ends.
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expect_xml_error(crlf, {"bad.xml:5:", "parameter 'Bogus'"});
}

TEST(SpeciesXml, NonNumberNamesFileLineAndName) {
  expect_xml_error(
      arbaro({"<param name='Shape' value='7'/>", "<param name='Levels' value='3'/>",
              "<param name='1DownAngle' value='6O'/>"}),
      {"bad.xml:6:", "parameter '1DownAngle'", "'6O' is not a number", "valid range [-180, 180]"});
  expect_xml_error(arbaro({"<param name='Scale' value=''/>"}),
                   {"bad.xml:4:", "parameter 'Scale'", "is not a number"});
  expect_xml_error(arbaro({"<param name='Scale' value='nan'/>"}),
                   {"bad.xml:4:", "parameter 'Scale'", "is not a number"});
  expect_xml_error(arbaro({"<param name='LeafShape' value='2 discs'/>"}),
                   {"bad.xml:4:", "parameter 'LeafShape'", "not a number or a leaf shape name"});
}

TEST(SpeciesXml, OutOfRangeNamesFileLineNameAndRange) {
  expect_xml_error(
      arbaro({"<param name='Shape' value='9'/>"}),
      {"bad.xml:4:", "parameter 'Shape'", "value 9 is out of range", "(valid range [0, 8])"});
  expect_xml_error(
      arbaro({"<param name='Shape' value='1'/>", "<param name='2Taper' value='-0.5'/>"}),
      {"bad.xml:5:", "parameter '2Taper'", "valid range [0, 3]"});
  expect_xml_error(arbaro({"<param name='Levels' value='2.5'/>"}),
                   {"bad.xml:4:", "parameter 'Levels'", "not a whole number"});
}

TEST(SpeciesXml, LevelsAboveFourAreRefusedWithAReason) {
  expect_xml_error(arbaro({"<param name='Levels' value='5'/>"}),
                   {"bad.xml:4:", "parameter 'Levels'", "valid range [1, 4]", "levels 0-3"});
  expect_xml_error(
      arbaro({"<param name='Shape' value='1'/>", "<param name='4DownAngle' value='30'/>"}),
      {"bad.xml:5:", "parameter '4DownAngle'", "level 4 is not supported"});
}

TEST(SpeciesXml, DuplicateNamesBothLines) {
  expect_xml_error(arbaro({"<param name='Shape' value='7'/>", "<param name='Levels' value='3'/>",
                           "<param name='Shape' value='7'/>"}),
                   {"bad.xml:6:", "parameter 'Shape'", "given twice (first on line 4)"});
}

TEST(SpeciesXml, StructureErrorsNameTheLine) {
  expect_xml_error("<?xml version='1.0' ?>\n<tree>\n  <species name='t'/>\n</tree>\n",
                   {"bad.xml:2:", "root element is <tree>", "expected <arbaro>"});
  expect_xml_error(arbaro({"<param name='Shape'/>"}),
                   {"bad.xml:4:", "parameter 'Shape'", "no value attribute"});
  expect_xml_error(arbaro({"<param value='3'/>"}), {"bad.xml:4:", "no name attribute"});
  expect_xml_error(arbaro({"<leaf name='Shape' value='3'/>"}), {"bad.xml:4:", "<leaf>"});
  expect_xml_error("<arbaro>\n<species name='a'/>\n<species name='b'/>\n</arbaro>\n",
                   {"bad.xml:3:", "second <species> (first on line 2)"});
  expect_xml_error("<arbaro>\n  <species>\n  </species>\n</arbaro>\n",
                   {"bad.xml:2:", "<species> has no name"});
  expect_xml_error("<arbaro>\n</arbaro>\n", {"bad.xml:1:", "no <species>"});
  expect_xml_error("<arbaro><species name='a'/></arbaro>\n<x/>\n",
                   {"bad.xml:2:", "second root element <x>"});
  expect_xml_error(arbaro({"<param name='Shape' value='1'/>", "stray"}),
                   {"bad.xml:5:", "unexpected text in <species>"});
}

// ---- boreas JSON ----

TEST(SpeciesJson, BuiltinPresetsEqualTheirArbaroTwins) {
  EXPECT_EQ(impl::builtin_species_names(), kBuiltins);
  for (const std::string& name : kBuiltins) {
    SCOPED_TRACE(name);
    Species preset = impl::load_species(name);
    Species twin = impl::load_species((kArbaroDir / (name + ".xml")).string());
    EXPECT_EQ(preset.name, name);
    // WoodModulus, WoodRupture, Vogel's and the crown light's are boreas's own: the
    // presets give their species' wood and crown, Arbaro's files none.
    EXPECT_NE(preset.wood_modulus, Species{}.wood_modulus);
    EXPECT_NE(preset.wood_rupture, Species{}.wood_rupture);
    twin.wood_modulus = preset.wood_modulus;
    twin.wood_rupture = preset.wood_rupture;
    twin.vogel_exponent = preset.vogel_exponent;
    twin.vogel_speed = preset.vogel_speed;
    twin.leaf_area_index = preset.leaf_area_index;
    twin.clumping = preset.clumping;
    expect_same_species(preset, twin);
    // And the preset gives every parameter its twin gives, not just the same result.
    std::string json_text = read_text(fs::path(BOREAS_TEST_DATA_DIR) / ".." / ".." / "host" /
                                      "species" / (name + ".json"));
    for (const auto& [param, value] : params_in(read_text(kArbaroDir / (name + ".xml")))) {
      EXPECT_NE(json_text.find("\"" + param + "\":"), std::string::npos) << param;
    }
  }
}

TEST(SpeciesJson, OmittedParametersTakeDefaultsAndLeafShapeMayBeAName) {
  Species s = impl::parse_species_json(
      species_json({"\"Shape\": 2", "\"1DownAngle\": -30.5", "\"LeafShape\": \"disc2\""}),
      "min.json");
  Species expected{};
  expected.name = "t";
  expected.shape = 2;
  expected.level[1].down_angle = -30.5;
  expected.leaf_shape = "disc2";
  expect_same_species(s, expected);
  EXPECT_EQ(impl::parse_species_json(species_json({"\"LeafShape\": 3"}), "x.json").leaf_shape, "3");
}

TEST(SpeciesJson, SyntaxErrorNamesTheLine) {
  // The comma after line 5 is missing: nlohmann stops at the key on line 6.
  expect_json_error(species_json({"\"Shape\": 7\n    \"Levels\": 3"}),
                    {"bad.json:6:", "malformed JSON"});
  expect_json_error("{\n  \"format\": \"boreas-species-1\",\n  \"name\": \"t\",\n", {"bad.json:"});
}

// Found by fuzz_species_json (tests/fuzz): a number past a double's range made nlohmann
// throw out_of_range, which escaped the parser as no boreas error at all.
// Found by fuzz_species_json: nlohmann stops at a NUL byte as at the end of the input, so
// "{}" followed by a NUL and anything read as an empty object, and the key scan that
// follows the parse met the rest and threw from nlohmann.
TEST(SpeciesJson, ANulByteIsRefusedWithItsLine) {
  expect_json_error(std::string("{}\n\0\": \"x\"", 10), {"bad.json:2:", "NUL byte"});
  std::string text = species_json({"\"Shape\": 7"});
  text.insert(text.find("Shape") - 1, 1, '\0');
  expect_json_error(text, {"bad.json:5:", "NUL byte"});
}

TEST(SpeciesJson, NumberPastADoublesRangeNamesItsLine) {
  expect_json_error(species_json({"\"Shape\": 7", "\"Levels\": 1e400"}),
                    {"bad.json:6:", "malformed JSON", "number overflow", "1e400"});
}

TEST(SpeciesJson, ParameterErrorsNameFileLineAndName) {
  expect_json_error(species_json({"\"Shape\": 7", "\"Bogus\": 1"}),
                    {"bad.json:6:", "parameter 'Bogus'", "unknown parameter"});
  expect_json_error(species_json({"\"Shape\": 7", "\"Levels\": 3", "\"1DownAngle\": \"60\""}),
                    {"bad.json:7:", "parameter '1DownAngle'", "is a string, expected a number"});
  expect_json_error(species_json({"\"Shape\": 9"}),
                    {"bad.json:5:", "parameter 'Shape'", "out of range", "(valid range [0, 8])"});
  expect_json_error(species_json({"\"0CurveRes\": 2.5"}),
                    {"bad.json:5:", "parameter '0CurveRes'", "not a whole number"});
  expect_json_error(species_json({"\"Shape\": 7", "\"Levels\": 3", "\"Shape\": 4"}),
                    {"bad.json:7:", "parameter 'Shape'", "given twice (first on line 5)"});
  expect_json_error(species_json({"\"Levels\": 6"}),
                    {"bad.json:5:", "parameter 'Levels'", "valid range [1, 4]", "levels 0-3"});
}

TEST(SpeciesJson, KeyLinesIgnoreLookalikesInsideStrings) {
  // The source text mentions "Shape": 99 in escaped quotes; only the real key counts.
  std::string text =
      "{\n  \"format\": \"boreas-species-1\",\n  \"name\": \"t\",\n"
      "  \"source\": \"not \\\"Shape\\\": 99\",\n  \"params\": {\n    \"Levels\": 3,\n"
      "    \"Shape\": 99\n  }\n}\n";
  expect_json_error(text, {"bad.json:7:", "parameter 'Shape'", "value 99"});
}

TEST(SpeciesJson, TopLevelErrors) {
  expect_json_error(
      "{\n  \"format\": \"boreas-species-1\",\n  \"name\": \"t\",\n  \"colour\": 1,\n"
      "  \"params\": {}\n}\n",
      {"bad.json:4:", "unknown key 'colour'"});
  expect_json_error("{\n  \"format\": \"arbaro\",\n  \"name\": \"t\",\n  \"params\": {}\n}\n",
                    {"bad.json:2:", "format", "boreas-species-1"});
  expect_json_error("{\n  \"name\": \"t\",\n  \"params\": {}\n}\n", {"bad.json:1:", "format"});
  expect_json_error(
      "{\n  \"format\": \"boreas-species-1\",\n  \"name\": \"t\",\n"
      "  \"name\": \"u\",\n  \"params\": {}\n}\n",
      {"bad.json:4:", "key 'name' given twice"});
  expect_json_error(
      "{\n  \"format\": \"boreas-species-1\",\n  \"name\": \"t\",\n  \"params\": 3\n}\n",
      {"bad.json:4:", "params"});
  expect_json_error("[1, 2]", {"bad.json:1:", "expected a JSON object"});
}

// ---- load_species ----

TEST(SpeciesLoad, FilesByExtensionAndErrorsNameThePath) {
  TempDir dir;
  fs::path good = dir.path() / "mine.json";
  std::ofstream(good) << species_json({"\"Shape\": 1"});
  EXPECT_EQ(impl::load_species(good.string()).shape, 1);

  fs::path bad = dir.path() / "broken.json";
  std::ofstream(bad) << species_json({"\"Shape\": 1", "\"Ratio\": -1"});
  expect_error([&] { (void)impl::load_species(bad.string()); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {bad.string() + ":6:", "parameter 'Ratio'"});
}

TEST(SpeciesLoad, MissingFileIsAnIoError) {
  expect_error([] { (void)impl::load_species("/nonexistent/dir/oak.xml"); }, BOREAS_ERROR_IO,
               {"/nonexistent/dir/oak.xml"});
  expect_error([] { (void)impl::load_species("/nonexistent/dir/oak.json"); }, BOREAS_ERROR_IO,
               {"oak.json"});
  TempDir dir;
  expect_error([&] { (void)impl::load_species((dir.path() / "sub.xml").string()); },
               BOREAS_ERROR_IO, {"sub.xml"});
}

TEST(SpeciesLoad, UnknownNameListsTheBuiltins) {
  expect_error([] { (void)impl::load_species("baobab"); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"'baobab'", "black_tupelo, ca_black_oak, quaking_aspen, weeping_willow"});
}

// ---- Shape ratios ----

TEST(SpeciesShapeRatio, EveryShapeFollowsItsFormula) {
  constexpr double kPi = 3.14159265358979323846;
  Species s{};
  s.prune_width_peak = 0.3;
  s.prune_power_low = 0.5;
  s.prune_power_high = 2.0;
  // The data README's formulas, written out again here.
  std::vector<std::function<double(double)>> formula = {
      [](double r) { return r; },  // conical, as Arbaro (species.cpp says why)
      [&](double r) { return 0.2 + 0.8 * std::sin(kPi * r); },
      [&](double r) { return 0.2 + 0.8 * std::sin(kPi * r / 2); },
      [](double) { return 1.0; },
      [](double r) { return 0.5 + 0.5 * r; },
      [](double r) { return r <= 0.7 ? r / 0.7 : (1 - r) / 0.3; },
      [](double r) { return 1 - 0.8 * r; },
      [](double r) { return r <= 0.7 ? 0.5 + 0.5 * r / 0.7 : 0.5 + 0.5 * (1 - r) / 0.3; },
      [](double r) { return r < 0.7 ? std::pow(r / 0.7, 2.0) : std::pow((1 - r) / 0.7, 0.5); },
  };
  for (int shape = 0; shape <= 8; ++shape) {
    for (double r : {0.0, 0.1, 0.3, 0.5, 0.7, 0.85, 1.0}) {
      EXPECT_NEAR(impl::shape_ratio(s, shape, r), formula[shape](r), 1e-12)
          << "shape " << shape << " r " << r;
    }
  }
  // A few values by hand.
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 0, 0.0), 0.0);  // Arbaro's cone, not the paper's 0.2 + 0.8r
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 1, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 2, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 5, 0.7), 1.0);
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 6, 1.0), 0.2);
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 7, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 8, 0.35), 0.25);  // (0.35 / 0.7)^2 below the peak
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 8, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(impl::shape_ratio(s, 8, 1.5), 0.0);  // outside the envelope
  expect_error([&] { (void)impl::shape_ratio(s, 9, 0.5); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"shape 9"});
}

}  // namespace
}  // namespace boreas::test
