// boreas: a Weber-Penn species — the parameters of Weber & Penn (1995) as Arbaro names them,
// with their defaults and valid ranges, loaded from boreas's own JSON presets or from
// Arbaro's species XML.
//
// Every parameter has one row in the table of species.cpp (name, level, default, range):
// the loaders, the checks and the error messages all read that table, so a parameter is
// added in one place.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace boreas::impl {

// The branching levels a tree can have: 0 (trunk) to 3. Leaves grow on the last level.
inline constexpr int kMaxTreeLevels = 4;

// Per level n, the Arbaro parameters named "n<Name>" (angles in degrees). The initializers
// are the defaults every level shares; default_levels() sets those Arbaro gives per level.
struct SpeciesLevel {
  double down_angle = 0.0;     // nDownAngle: angle between the child and its parent's axis
  double down_angle_v = 0.0;   // nDownAngleV (negative: varies along the parent)
  double rotate = 0.0;         // nRotate: turn around the parent from one child to the next
  double rotate_v = 0.0;       // nRotateV
  double branches = 0.0;       // nBranches: children per stem (on the trunk: total; 0: trunks)
  double branch_dist = 0.0;    // nBranchDist (Arbaro: 0 whorled .. 1 evenly spread; on
                               // level 0 how far apart trunks stand, m: 0..1)
  double length = 1.0;         // nLength: length relative to the parent (level 0: of the tree)
  double length_v = 0.0;       // nLengthV
  double taper = 1.0;          // nTaper: 0..1 cone to cylinder, 1..2 rounded tip, 2..3 periodic
  double seg_splits = 0.0;     // nSegSplits: clones per segment (the trunk's first: 0BaseSplits)
  double split_angle = 0.0;    // nSplitAngle: how far clones turn from the stem
  double split_angle_v = 0.0;  // nSplitAngleV
  double curve_res = 3.0;      // nCurveRes: segments of the stem (walked, then one Bezier each
                               // run between splits)
  double curve = 0.0;          // nCurve: total curvature of the stem, degrees
  double curve_back = 0.0;     // nCurveBack: curvature of the second half
  double curve_v = 0.0;        // nCurveV: random curvature, degrees
};

// Arbaro's per-level defaults for omitted parameters: nLength 1, 0.5, 0.5, 0.5; nBranches 1,
// 10, 5, 5; nDownAngle 0, 30, 30, 30; nRotate 0, 120, 120, 120; nBranchDist 0, 1, 1, 1;
// nCurveRes 3, 3, 1, 1.
std::array<SpeciesLevel, kMaxTreeLevels> default_levels();

struct Species {
  std::string name;
  std::string file;              // its file, for errors ("quaking_aspen.json" if built in)
  int shape = 0;                 // Shape 0-8 (see shape_ratio)
  int levels = 3;                // Levels: stem levels, 1..4 (0..levels-1), leaves on the last
  double scale = 10.0;           // Scale, m: the tree's size
  double scale_v = 0.0;          // ScaleV, m
  double base_size = 0.25;       // BaseSize: fraction of the trunk without branches
  double ratio = 0.05;           // Ratio: trunk radius / trunk length
  double ratio_power = 1.0;      // RatioPower: child radius = parent's * (L/L_parent)^this
  double flare = 0.5;            // Flare: trunk base widening
  int lobes = 0;                 // Lobes: trunk cross-section lobes
  double lobe_depth = 0.0;       // LobeDepth
  double smooth = 0.5;           // Smooth (mesh quality hint)
  int leaves = 0;                // Leaves per last-level stem (negative: Arbaro's fans, |n|)
  std::string leaf_shape = "0";  // LeafShape: a number or a name (disc, palm, sphere, ...)
  double leaf_scale = 0.2;       // LeafScale, m
  double leaf_scale_x = 0.5;     // LeafScaleX: width / length
  double leaf_quality = 1.0;     // LeafQuality: multiplies the leaf count
  double leaf_stem_len = 0.5;    // LeafStemLen: petiole length / leaf length
  int leaf_distrib = 4;          // LeafDistrib: shape index for the leaf density along stems
  double leaf_bend = 0.3;        // LeafBend: how much leaves turn toward light and up
  double attraction_up = 0.0;    // AttractionUp: levels >= 2 bend upward
  double prune_ratio = 0.0;      // PruneRatio and the envelope (shape 8)
  double prune_power_low = 0.5;
  double prune_power_high = 0.5;
  double prune_width = 0.5;
  double prune_width_peak = 0.5;
  double trunk_scale = 1.0;    // 0Scale
  double trunk_scale_v = 0.0;  // 0ScaleV: Arbaro's bark jitter per mesh vertex; not grown
  int base_splits = 0;         // 0BaseSplits: clones at the end of the trunk's first segment
  // Not Weber-Penn's: boreas's own, for the wind's load (trees/wind_load.h). Young's modulus
  // of the green wood, GPa (the Wood Handbook's green-wood values: 5-10 for most
  // hardwoods); Arbaro files leave it at the default.
  double wood_modulus = 7.0;  // WoodModulus
  // The green wood's modulus of rupture, MPa: a branch breaks where its bending stress
  // passes it (trees/wind_load.h). Wood Handbook green-wood values: 30-60 for most woods.
  double wood_rupture = 40.0;  // WoodRupture
  // Vogel's reconfiguration of the leafy crown: above VogelSpeed (m/s) the drag grows as
  // U^(2 + VogelExponent) instead of U^2 (trees/wind_load.h); -0.7..-1 for leafy crowns.
  double vogel_exponent = -0.8;  // VogelExponent
  double vogel_speed = 8.0;      // VogelSpeed, m/s
  // The crown's light (trees/leaf_occlusion.h): the leaf area index over the crown's
  // projection the light sees (Weber-Penn leaves are a visual stand-in, and a crown carries
  // several times a real one's area), and the clumping index. The defaults are a
  // broadleaf's, boreas's choices, not measurements: 4 lies within one standard deviation of
  // the global mean of measured canopies (4.5 +- 2.5, Asner, Scurlock and Hicke 2003); 0.8 is
  // a working value no checked source gives for a species. A file without Clumping gets
  // species_default_clumping's (0.6 for needles) instead (host/species/README.md).
  double leaf_area_index = 4.0;  // LeafAreaIndex, m^2 of leaf (one side) per m^2 of ground
  double clumping = 0.8;         // Clumping, (0, 1]: 1 leaves at random
  std::array<SpeciesLevel, kMaxTreeLevels> level = default_levels();
};

// Whether a species bears needles: a conical crown (Weber and Penn's Shape 0, their
// conifers' form) with leaves more than twice as long as wide (LeafScaleX < 0.5). Arbaro
// names no needle leaf shape, so the crown and the blade's proportions are what a file says.
bool species_is_needle_leaved(const Species& s);

// The clumping index a species gets where its file gives none: 0.6 for needles, 0.8 for
// broad leaves (host/species/README.md, Clumping).
double species_default_clumping(const Species& s);

// How errors name a species: "species 'quaking_aspen' (quaking_aspen.json)".
std::string species_label(const Species& s);

// A parameter's value as errors quote it: "60", "0.015", "1e-06".
std::string param_text(double value);

// Weber-Penn's shape ratio (data README): Shape 0-8 at r in [0, 1]. Shape 8 uses the
// species' prune envelope.
double shape_ratio(const Species& s, int shape, double r);

// Arbaro's species XML: <arbaro><species name=".."><param name=".." value=".."/>...
// Omitted parameters keep the defaults above. Errors (Error, INVALID_ARGUMENT; IO for an
// unreadable file) name the file, the line and the parameter: "species.xml:12: parameter
// '1DownAngle': value 'abc' is not a number".
Species parse_arbaro_xml(const std::string& text, const std::string& file_name);

// boreas's own format (host/species/*.json): {"name": "..", "format": "boreas-species-1",
// "params": {"Shape": 7, "1DownAngle": 60, ...}} with Arbaro's parameter names, so one
// table checks both. Errors name the file, line and parameter as above.
Species parse_species_json(const std::string& text, const std::string& file_name);

// The built-in presets embedded in the library (quaking_aspen, black_tupelo,
// weeping_willow, ca_black_oak, ...), in name order.
std::vector<std::string> builtin_species_names();

// A built-in name, or a path to a .xml (Arbaro) or .json (boreas) file.
Species load_species(const std::string& name_or_path);

// A species' text before parsing, and what identifies it: the built-in's name, or a
// file's path and a hash of its bytes. Trees whose sources have the same key and the same
// seed grow the same model, so a world grows it once (World's templates).
struct SpeciesSource {
  std::string key;
  std::string text;
  std::string file_name;  // for error messages
  bool xml = false;       // Arbaro XML, else boreas JSON
};
SpeciesSource read_species_source(const std::string& name_or_path);
Species parse_species_source(const SpeciesSource& source);

// ---- The parameter table and what the two loaders share (species.cpp) ----

// One row of the table: an Arbaro parameter, its default, its valid range and where it is
// stored. Per-level parameters have one row per level ("0Length" .. "3Length").
struct SpeciesParam {
  std::string name;            // Arbaro's name: "Shape", "1DownAngle"
  int level = -1;              // index into Species::level, -1 for a field of Species itself
  double default_value = 0.0;  // equals the initializer above (a test checks)
  double min = 0.0;            // valid range, inclusive
  double max = 0.0;
  bool integer = false;        // the value must be a whole number
  const char* note = nullptr;  // why boreas's range is narrower than Arbaro's, if it is
  // Where the value lives: exactly one is set, or none for LeafShape (a number or a name,
  // kept as text in Species::leaf_shape).
  double Species::*real = nullptr;
  int Species::*whole = nullptr;
  double SpeciesLevel::*per_level = nullptr;

  bool is_leaf_shape() const { return !real && !whole && !per_level; }
};

// Every row, general parameters first, then levels 0 to 3.
const std::vector<SpeciesParam>& species_params();

// The row of an Arbaro name, nullptr if there is none.
const SpeciesParam* find_species_param(const std::string& name);

// The value of a numeric parameter in s (LeafShape, which is text, gives 0).
double species_param_value(const Species& s, const SpeciesParam& p);

// A number as Arbaro writes it, the whole text ("60", " -1.5e1 "), finite; false otherwise.
bool parse_species_number(const std::string& text, double* value);

// What both loaders do once they have a parameter's name, value and line: check it against
// its row and store it, or throw Error "<file>:<line>: parameter '<name>': <what>". The
// species starts from the table's defaults.
class SpeciesBuilder {
 public:
  explicit SpeciesBuilder(std::string file_name);

  // The row of `name`; an unknown name, or a level above 3, fails.
  const SpeciesParam& find(const std::string& name, int line) const;
  // A number: whole where the row says so, within range, given once.
  void set_number(const SpeciesParam& p, double value, int line);
  // Text: a number, or for LeafShape also a shape name ("disc", "palm", "disc2").
  void set_text(const SpeciesParam& p, const std::string& text, int line);
  void set_name(const std::string& name) { species_.name = name; }

  [[noreturn]] void fail_at(int line, const std::string& what) const;
  [[noreturn]] void fail_param(int line, const std::string& name, const std::string& what) const;

  // The species as given, with what the file left out filled in from what it is
  // (species_default_clumping).
  Species finish() const;

 private:
  void mark_given(const SpeciesParam& p, int line);

  std::string file_;
  Species species_;
  std::vector<int> given_line_;  // per row: the line it was given on, 0 if not yet
};

}  // namespace boreas::impl
