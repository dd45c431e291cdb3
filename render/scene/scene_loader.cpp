// boreas scenes: scene JSON to a validated Scene. The checks mirror the library's own
// (host/include/boreas/boreas.h), so a loaded scene always makes a valid world.
#include "scene/scene_loader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "scene/forest.h"
#include "scene/json_parse.h"
#include "scene/json_reader.h"
#include "scene/scene_error.h"
#include "scene/leaf_choice.h"
#include "scene/scene_seed.h"
#include "scene/sensor_loader.h"
#include "textures/leaf_kinds.h"

namespace boreas::embedded {
const std::vector<std::pair<const char*, const char*>>& scene_files();
}

namespace boreas::render {

namespace {

constexpr int kMaxWindObjects = 4096;  // primitives, gusts or obstacles each
constexpr char kDefaultSceneName[] = "scenes/default.json";
constexpr double kMinEyeToTarget = 1e-3;  // m: closer, the view direction is lost in rounding

bool is_zero(const float* v, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += double(v[i]) * v[i];
  return !(std::sqrt(sum) > 1e-12);
}

// "dir/gusty.json" -> "gusty": the name a scene gets when it does not give one.
std::string stem(const std::string& path) {
  size_t slash = path.find_last_of('/');
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  size_t dot = base.find('.');
  return dot == std::string::npos || dot == 0 ? base : base.substr(0, dot);
}

// One of a fixed set of names for an enum, fallback when absent.
template <typename Enum>
Enum read_choice(JsonObjectReader& r, const std::string& key, Enum fallback,
                 std::initializer_list<std::pair<const char*, Enum>> choices) {
  std::string names;
  for (const auto& choice : choices)
    names += (names.empty() ? "" : ", ") + std::string(choice.first);
  if (!r.has(key)) return fallback;
  std::string got = r.string(key, "");
  for (const auto& [name, value] : choices) {
    if (got == name) return value;
  }
  r.fail(key, "must be one of " + names + " (got \"" + got + "\")");
}

void read_grid(JsonObjectReader r, boreas_grid_def& g) {
  // The library's ranges (boreas.h), checked here to name the JSON path.
  r.numbers("origin", g.origin, 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE));
  g.cell_size = float(r.number("cell_size", g.cell_size, NumberRule::in(1e-3, 1e4)));
  r.integers("resolution", g.resolution, 3, NumberRule::in(2, BOREAS_GRID_MAX_RESOLUTION));
  double cells = double(g.resolution[0]) * g.resolution[1] * g.resolution[2];
  static_assert(BOREAS_GRID_MAX_CELLS == 1 << 26, "the message spells it 2^26");
  if (cells > double(BOREAS_GRID_MAX_CELLS)) {
    r.fail("resolution", "must have at most 2^26 = " + std::to_string(BOREAS_GRID_MAX_CELLS) +
                             " cells in all (got " + std::to_string(int64_t(cells)) + ")");
  }
  g.diffusion = float(r.number("diffusion", g.diffusion, NumberRule::in(0, 1e6)));
  g.decay_rate = float(r.number("decay_rate", g.decay_rate, NumberRule::in(0, 1e6)));
  g.response_time = float(r.number("response_time", g.response_time, NumberRule::in(1e-4, 1e6)));
  g.edge_fade = float(r.number("edge_fade", g.edge_fade, NumberRule::in(0, 1e6)));
  g.follow_focus = r.boolean("follow_focus", g.follow_focus != 0) ? 1 : 0;
  g.wind_sampling = read_choice(
      r, "wind_sampling", g.wind_sampling,
      {{"exact", BOREAS_WIND_SAMPLING_EXACT}, {"interpolated", BOREAS_WIND_SAMPLING_INTERPOLATED}});
  r.finish();
}

void read_world(JsonObjectReader r, Scene& scene) {
  scene.device = r.optional_string("device", std::nullopt);
  read_grid(r.object("grid"), scene.grid);
  r.finish();
}

boreas_wave read_wave(JsonObjectReader& r) {
  boreas_wave w = boreas_default_wave();
  r.numbers("direction", w.direction, 2);
  if (is_zero(w.direction, 2)) r.fail("direction", "must not be the zero vector");
  w.amplitude = float(r.number("amplitude", w.amplitude, NumberRule::in(0, BOREAS_WIND_MAX_SPEED)));
  w.wavelength = float(r.number("wavelength", w.wavelength, NumberRule::above_at_most(0, 1e7)));
  w.speed = float(r.number("speed", w.speed, NumberRule::within(BOREAS_WIND_MAX_SPEED)));
  w.sharpness = float(r.number("sharpness", w.sharpness, NumberRule::in(0, 64)));
  return w;
}

boreas_flow_primitive_def read_primitive(JsonObjectReader& r) {
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  static const std::pair<const char*, boreas_flow_type> kTypes[] = {
      {"uniform", BOREAS_FLOW_UNIFORM},
      {"source", BOREAS_FLOW_SOURCE},
      {"sink", BOREAS_FLOW_SINK},
      {"vortex", BOREAS_FLOW_VORTEX}};
  std::string type = r.string("type", "uniform");
  bool found = false;
  for (const auto& [name, value] : kTypes) {
    if (type == name) {
      p.type = value;
      found = true;
    }
  }
  if (!found) r.fail("type", "must be one of uniform, source, sink, vortex (got \"" + type + "\")");
  r.numbers("position", p.position, 3);
  r.numbers("direction", p.direction, 3);
  bool uses_direction = p.type == BOREAS_FLOW_UNIFORM || p.type == BOREAS_FLOW_VORTEX;
  if (uses_direction && is_zero(p.direction, 3)) {
    r.fail("direction", "must not be the zero vector");
  }
  p.strength = float(r.number("strength", p.strength, NumberRule::within(BOREAS_WIND_MAX_SPEED)));
  NumberRule radius_rule =
      p.type == BOREAS_FLOW_UNIFORM ? NumberRule::non_negative() : NumberRule::positive();
  if (p.type != BOREAS_FLOW_UNIFORM && !r.has("radius")) {
    r.fail("radius", "missing: a " + type + " needs a radius > 0 (m)");
  }
  p.radius = float(r.number("radius", p.radius, radius_rule));
  p.lifetime = float(r.number("lifetime", p.lifetime, NumberRule::non_negative()));
  return p;
}

boreas_gust_def read_gust(JsonObjectReader& r) {
  boreas_gust_def g = boreas_default_gust_def();
  r.numbers("direction", g.direction, 3);
  if (is_zero(g.direction, 3)) r.fail("direction", "must not be the zero vector");
  g.strength = float(r.number("strength", g.strength, NumberRule::within(BOREAS_WIND_MAX_SPEED)));
  g.delay = float(r.number("delay", g.delay, NumberRule::non_negative()));
  g.rise = float(r.number("rise", g.rise, NumberRule::non_negative()));
  g.hold = float(r.number("hold", g.hold, NumberRule::non_negative()));
  g.fall = float(r.number("fall", g.fall, NumberRule::non_negative()));
  r.numbers("center", g.center, 3);
  g.radius = float(r.number("radius", g.radius, NumberRule::non_negative()));
  return g;
}

SolidBox read_obstacle(JsonObjectReader& r) {
  SolidBox box;
  for (const char* key : {"min", "max"}) {
    if (!r.has(key)) r.fail(key, "missing: an obstacle needs both min and max (m)");
  }
  r.numbers("min", box.min, 3);
  r.numbers("max", box.max, 3);
  for (int i = 0; i < 3; ++i) {
    if (box.max[i] < box.min[i]) {
      std::ostringstream detail;
      detail << "must be >= min/" << i << " = " << box.min[i] << " (got " << box.max[i] << ")";
      throw SceneError(r.source(), r.path_of("max") + "/" + std::to_string(i), detail.str());
    }
  }
  return box;
}

void read_wind(JsonObjectReader r, Scene& scene) {
  r.objects("waves", BOREAS_WIND_MAX_WAVES,
            [&](JsonObjectReader& e) { scene.waves.push_back(read_wave(e)); });
  r.objects("primitives", kMaxWindObjects,
            [&](JsonObjectReader& e) { scene.primitives.push_back(read_primitive(e)); });
  r.objects("gusts", kMaxWindObjects,
            [&](JsonObjectReader& e) { scene.gusts.push_back(read_gust(e)); });
  r.objects("obstacles", kMaxWindObjects,
            [&](JsonObjectReader& e) { scene.obstacles.push_back(read_obstacle(e)); });
  r.finish();
}

bool ends_with_ci(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    char c = text[text.size() - suffix.size() + i];
    if (std::tolower(static_cast<unsigned char>(c)) != suffix[i]) return false;
  }
  return true;
}

// A file named in the scene: relative paths are found from the scene file's folder.
std::string resolve_path(const std::string& path_text, const std::string& base_dir) {
  std::filesystem::path path(path_text);
  if (path.is_relative() && !base_dir.empty()) path = std::filesystem::path(base_dir) / path;
  return path.lexically_normal().string();
}

std::vector<std::string> builtin_species() {
  std::vector<std::string> names;
  for (int i = 0; const char* name = boreas_builtin_species(i); ++i) names.emplace_back(name);
  return names;
}

std::string species_list() {
  std::string list;
  for (const std::string& name : builtin_species()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

// A tree species as a scene names it: a built-in name or a species file (resolved).
std::string read_tree_species(JsonObjectReader& r, const std::string& base_dir) {
  if (!r.has("species")) {
    r.fail("species", "missing: a tree needs a species: a built-in name (" + species_list() +
                          ") or a species file (.xml from Arbaro, or .json)");
  }
  std::string species = r.string("species", "");
  // The library's rule: a name ending in .xml or .json is a file, anything else a preset.
  if (ends_with_ci(species, ".xml") || ends_with_ci(species, ".json"))
    return resolve_path(species, base_dir);
  std::vector<std::string> names = builtin_species();
  if (std::find(names.begin(), names.end(), species) == names.end()) {
    std::string hint = did_you_mean(species, names);
    r.fail("species", "unknown species \"" + species + "\"" +
                          (hint.empty() ? "; the built-in species are " + species_list() : hint) +
                          " (a species file must end in .xml or .json)");
  }
  return species;
}

// The animation and level-of-detail settings a tree and a forest share.
void read_tree_settings(JsonObjectReader& r, boreas_tree_def& def) {
  // The library's ranges (boreas.h).
  def.mode = read_choice(r, "mode", def.mode,
                         {{"lagged", BOREAS_TREE_LAGGED}, {"exact", BOREAS_TREE_EXACT}});
  def.response =
      read_choice(r, "response", def.response,
                  {{"quasi_static", BOREAS_TREE_QUASI_STATIC}, {"damped", BOREAS_TREE_DAMPED}});
  def.load = read_choice(r, "load", def.load,
                         {{"drag", BOREAS_TREE_LOAD_DRAG}, {"linear", BOREAS_TREE_LOAD_LINEAR}});
  def.bend_exponent =
      float(r.number("bend_exponent", def.bend_exponent, NumberRule::in(0.1, 10.0)));
  r.numbers("lod_distances", def.lod_distances, 3, NumberRule::in(0, 1e9));
  for (int i = 1; i < 3; ++i) {
    if (def.lod_distances[i] < def.lod_distances[i - 1]) {
      std::ostringstream detail;
      detail << "must be >= lod_distances/" << i - 1 << " = " << def.lod_distances[i - 1]
             << " (got " << def.lod_distances[i] << ")";
      throw SceneError(r.source(), r.path_of("lod_distances") + "/" + std::to_string(i),
                       detail.str());
    }
  }
}

SceneTree read_tree(JsonObjectReader& r, const std::string& base_dir) {
  SceneTree tree;
  tree.def.species = nullptr;
  tree.species = read_tree_species(r, base_dir);
  tree.leaf_kind = default_leaf_kind(tree.species);
  if (r.has("leaf")) {
    tree.leaf_kind = r.string("leaf", tree.leaf_kind);
    const std::vector<std::string> kinds = leaf_kind_names();
    if (std::find(kinds.begin(), kinds.end(), tree.leaf_kind) == kinds.end()) {
      std::string list;
      for (const std::string& k : kinds) list += (list.empty() ? "" : ", ") + k;
      r.fail("leaf", "unknown leaf kind \"" + tree.leaf_kind + "\"" +
                         did_you_mean(tree.leaf_kind, kinds) + " (the kinds are " + list + ")");
    }
  }
  r.numbers("position", tree.def.position, 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE));
  tree.def.rotation = float(r.number("rotation", tree.def.rotation, NumberRule::within(1e4)));
  tree.def.scale = float(r.number("scale", tree.def.scale, NumberRule::above_at_most(0, 1000)));
  tree.def.seed = r.unsigned_integer("seed", tree.def.seed);
  read_tree_settings(r, tree.def);
  return tree;
}

SceneForest read_forest(JsonObjectReader& r, const std::string& base_dir, int max_trees) {
  SceneForest forest;
  int entries = r.objects("species", 64, [&](JsonObjectReader& e) {
    std::string species = read_tree_species(e, base_dir);
    float weight = float(e.number("weight", 1.0, NumberRule::above_at_most(0, 1e9)));
    forest.species.emplace_back(species, weight);
  });
  if (entries == 0)
    r.fail("species", "must list at least one species ({\"species\": \"quaking_aspen\"}, ...)");
  if (!r.has("count"))
    r.fail("count",
           "missing: how many trees the forest has (1.." + std::to_string(max_trees) + ")");
  forest.count = r.integer("count", 0, NumberRule::in(1, max_trees));
  r.numbers("center", forest.center, 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE));
  r.numbers("size", forest.size, 2, NumberRule::in(0.01, 1e6));
  forest.templates = r.integer("templates", forest.templates, NumberRule::in(1, 1000000));
  forest.seed = r.unsigned_integer("seed", forest.seed);
  r.numbers("scale", forest.scale, 2, NumberRule::above_at_most(0, 1000));
  if (forest.scale[1] < forest.scale[0]) {
    std::ostringstream detail;
    detail << "must be >= scale/0 = " << forest.scale[0] << " (got " << forest.scale[1] << ")";
    throw SceneError(r.source(), r.path_of("scale") + "/1", detail.str());
  }
  read_tree_settings(r, forest.def);
  return forest;
}

SceneMeshTree read_mesh_tree(JsonObjectReader& r, const std::string& base_dir) {
  SceneMeshTree tree;
  if (!r.has("model"))
    r.fail("model", "missing: an imported tree needs a model file (.obj, .gltf or .glb)");
  tree.model = resolve_path(r.string("model", ""), base_dir);
  tree.trunk_part = r.optional_string("trunk", std::nullopt);
  tree.leaves_part = r.optional_string("leaves", std::nullopt);
  boreas_mesh_tree_def& d = tree.def;
  r.numbers("position", d.position, 3, NumberRule::within(1e6));
  d.yaw =
      float(r.number("yaw_deg", 0.0, NumberRule::within(3600.0)) * 3.14159265358979323846 / 180.0);
  // The library's ranges (boreas.h).
  d.scale = float(r.number("scale", d.scale, NumberRule::in(1e-4, 1e4)));
  d.seed = r.unsigned_integer("seed", d.seed);
  d.noise_beta = float(r.number("noise_beta", d.noise_beta, NumberRule::in(0.0, 4.0)));
  d.bend_exponent = float(r.number("bend_exponent", d.bend_exponent, NumberRule::in(0.25, 4.0)));
  d.leaf_flutter = float(r.number("leaf_flutter", d.leaf_flutter, NumberRule::in(0.0, 1e3)));
  d.leaf_turn = float(r.number("leaf_turn", d.leaf_turn, NumberRule::in(0.0, 1.0)));
  d.flutter_wavelength =
      float(r.number("flutter_wavelength", d.flutter_wavelength, NumberRule::in(1e-3, 1e5)));
  d.cache = r.boolean("cache", d.cache != 0) ? 1 : 0;
  int level = 0;
  r.objects("levels", 4, [&](JsonObjectReader& e) {
    boreas_mesh_level_def& l = d.levels[level++];
    l.bend = float(e.number("bend", l.bend, NumberRule::in(0.0, 1e3)));
    l.sway = float(e.number("sway", l.sway, NumberRule::in(0.0, 1e3)));
    l.frequency = float(e.number("frequency", l.frequency, NumberRule::in(0.001, 50.0)));
    l.response_time = float(e.number("response_time", l.response_time, NumberRule::in(0.0, 60.0)));
  });
  return tree;
}

std::vector<std::string> builtin_underbrush_species() {
  std::vector<std::string> names;
  for (int i = 0; const char* name = boreas_builtin_underbrush_species(i); ++i) {
    names.emplace_back(name);
  }
  return names;
}

std::string underbrush_species_list() {
  std::string list;
  for (const std::string& name : builtin_underbrush_species()) {
    list += (list.empty() ? "" : ", ") + name;
  }
  return list;
}

SceneMeadowSpecies read_meadow_species(JsonObjectReader& r, const std::string& base_dir) {
  SceneMeadowSpecies entry;
  if (!r.has("species")) {
    r.fail("species", "missing: a species mix entry needs a species: a built-in name (" +
                          underbrush_species_list() + ") or a species file (.json)");
  }
  std::string species = r.string("species", "");
  // As for trees: a name ending in .json is a file, anything else a built-in species.
  if (ends_with_ci(species, ".json")) {
    entry.species = resolve_path(species, base_dir);
  } else {
    std::vector<std::string> names = builtin_underbrush_species();
    if (std::find(names.begin(), names.end(), species) == names.end()) {
      std::string hint = did_you_mean(species, names);
      r.fail("species",
             "unknown underbrush species \"" + species + "\"" +
                 (hint.empty() ? "; the built-in species are " + underbrush_species_list() : hint) +
                 " (a species file must end in .json)");
    }
    entry.species = species;
  }
  // The library's range (boreas_meadow_species.weight).
  entry.weight = float(r.number("weight", entry.weight, NumberRule::above_at_most(0, 1e9)));
  if (!(entry.weight >= 1e-9f)) r.fail("weight", "must be at least 1e-9");
  return entry;
}

// An image file, or null for the procedural one; returns "" for null or absent.
std::string read_image_path(JsonObjectReader& r, const std::string& key,
                            const std::string& base_dir) {
  std::optional<std::string> path = r.optional_string(key, std::nullopt);
  if (!path) return "";
  if (path->empty()) r.fail(key, "must be a file name, or null for the procedural one");
  return resolve_path(*path, base_dir);
}

SceneMeadow read_meadow(JsonObjectReader& r, const std::string& base_dir) {
  SceneMeadow meadow;
  boreas_meadow_def& d = meadow.def;
  // The library's ranges (boreas.h, boreas_meadow_def), checked here to name the JSON path.
  int entries = r.objects("species", BOREAS_MEADOW_MAX_SPECIES, [&](JsonObjectReader& e) {
    meadow.species.push_back(read_meadow_species(e, base_dir));
  });
  if (r.has("species") && entries == 0) {
    r.fail("species", "must list at least one species; leave it out for the default mix (" +
                          default_meadow_mix()[0] + ", " + default_meadow_mix()[1] + ", " +
                          default_meadow_mix()[2] + ")");
  }
  r.numbers("center", d.center, 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE));
  r.numbers("size", d.size, 2, NumberRule::in(0.01, 1e5));
  d.density = float(r.number("density", d.density, NumberRule::in(0, BOREAS_MEADOW_MAX_DENSITY)));
  double components = double(d.size[0]) * d.size[1] * d.density;
  static_assert(BOREAS_MEADOW_MAX_COMPONENTS == 1 << 24, "the message spells it 2^24");
  if (components > double(BOREAS_MEADOW_MAX_COMPONENTS)) {
    std::ostringstream detail;
    detail << "gives size[0] * size[1] * density = " << components << " components; at most "
           << double(BOREAS_MEADOW_MAX_COMPONENTS)
           << " (2^24) per meadow: lower the density or split the meadow";
    r.fail("density", detail.str());
  }
  d.seed = r.unsigned_integer("seed", d.seed);
  meadow.terrain_image = read_image_path(r, "terrain_image", base_dir);
  d.terrain_relief = float(r.number("terrain_relief", d.terrain_relief, NumberRule::in(0, 1e4)));
  meadow.nutrient_image = read_image_path(r, "nutrient_image", base_dir);
  d.seed_points =
      r.integer("seed_points", d.seed_points, NumberRule::in(1, BOREAS_MEADOW_MAX_SEED_POINTS));
  d.shape_angles = r.integer("shape_angles", d.shape_angles, NumberRule::in(3, 181));
  d.shape_norms = r.integer("shape_norms", d.shape_norms, NumberRule::in(3, 256));
  r.numbers("lod_distances", d.lod_distances, 3, NumberRule::in(0, 1e7));
  for (int i = 1; i < 3; ++i) {
    if (d.lod_distances[i] < d.lod_distances[i - 1]) {
      std::ostringstream detail;
      detail << "must be >= lod_distances/" << i - 1 << " = " << d.lod_distances[i - 1] << " (got "
             << d.lod_distances[i] << ")";
      throw SceneError(r.source(), r.path_of("lod_distances") + "/" + std::to_string(i),
                       detail.str());
    }
  }
  d.species = nullptr;
  d.species_count = 0;
  d.terrain = boreas_image{0, 0, 0, nullptr};
  d.nutrients = boreas_image{0, 0, 0, nullptr};
  return meadow;
}

SceneCollider read_collider(JsonObjectReader& r) {
  SceneCollider collider;
  boreas_collider_def& d = collider.def;
  // The library's ranges (boreas_collider_def).
  d.shape = read_choice(r, "shape", d.shape,
                        {{"sphere", BOREAS_COLLIDER_SPHERE},
                         {"capsule", BOREAS_COLLIDER_CAPSULE},
                         {"box", BOREAS_COLLIDER_BOX}});
  r.numbers("center", d.pose.position, 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE));
  read_unit_quaternion(r, "orientation", d.pose.orientation);
  d.radius = float(r.number("radius", d.radius, NumberRule::in(1e-3, 1e3)));
  d.half_height = float(r.number("half_height", d.half_height, NumberRule::in(0, 1e3)));
  r.numbers("half_extents", d.half_extents, 3, NumberRule::in(1e-3, 1e3));
  r.numbers("velocity", d.velocity, 3, NumberRule::within(BOREAS_COLLIDER_MAX_SPEED));
  r.numbers("angular_velocity", d.angular_velocity, 3,
            NumberRule::within(BOREAS_COLLIDER_MAX_SPIN));
  return collider;
}

boreas_emitter_def read_emitter(JsonObjectReader& r) {
  boreas_emitter_def e = boreas_default_emitter_def();
  // The library's ranges (boreas_emitter_def).
  r.numbers("center", e.center, 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE));
  e.area_radius = float(r.number("area_radius", e.area_radius, NumberRule::in(0, 1e5)));
  e.event_radius = float(r.number("event_radius", e.event_radius, NumberRule::in(1e-4, 1e3)));
  r.numbers("impulse", e.impulse, 3, NumberRule::within(1e3));
  e.rate = float(r.number("rate", e.rate, NumberRule::in(0, 1e6)));
  e.lifetime = float(r.number("lifetime", e.lifetime, NumberRule::in(0, 1e9)));
  e.seed = r.unsigned_integer("seed", e.seed);
  return e;
}

void read_run(JsonObjectReader r, Scene& scene) {
  RunSettings& run = scene.run;
  run.frames = r.integer("frames", run.frames, NumberRule::in(1, kMaxFrames));
  run.steps_per_frame =
      r.integer("steps_per_frame", run.steps_per_frame, NumberRule::in(1, kMaxStepsPerFrame));
  run.dt = float(r.number("dt", run.dt, NumberRule::above_at_most(0, BOREAS_STEP_MAX_SECONDS)));
  // The world steps in float: a dt that rounds to 0 there would only fail mid-run.
  if (!(run.dt > 0.0f)) r.fail("dt", "must be at least 1e-38 s, the smallest float step");
  // Unless given, the slice lies 2 m above the grid's floor (or halfway up a shallower grid).
  float floor_y = scene.grid.origin[1];
  float grid_height = scene.grid.cell_size * float(scene.grid.resolution[1]);
  run.slice_height = floor_y + std::min(2.0f, 0.5f * grid_height);
  run.slice_height = float(r.number("slice_height", run.slice_height, NumberRule::any()));
  std::string height_rule = check_slice_height(scene.grid, run.slice_height);
  if (!height_rule.empty()) {
    std::ostringstream detail;
    detail << "must be " << height_rule << " m, the grid's vertical extent (got "
           << run.slice_height << ")";
    r.fail("slice_height", detail.str());
  }
  int size[2] = {run.image_width, run.image_height};
  r.integers("image_size", size, 2, NumberRule::in(kMinImageSide, kMaxImageSide));
  run.image_width = size[0];
  run.image_height = size[1];
  run.color_max = float(r.number_or_null("color_max", run.color_max, NumberRule::positive()));
  run.view = read_choice(
      r, "view", run.view,
      {{"scene", ViewMode::scene}, {"slice", ViewMode::slice}, {"trails", ViewMode::trails},
       {"lidar", ViewMode::lidar}});
  r.finish();
}

// The 3D view's camera and sky; the ranges are SceneView's (scene.h).
void read_view(JsonObjectReader r, SceneView& view) {
  // null or absent leaves a position unset: the command then frames the scene's content.
  std::array<float, 3> p{};
  if (r.numbers_or_null("eye", p.data(), 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE)))
    view.eye = p;
  if (r.numbers_or_null("target", p.data(), 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE)))
    view.target = p;
  if (r.numbers_or_null("eye_end", p.data(), 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE))) {
    if (!view.eye) r.fail("eye_end", "needs eye: the camera walks from eye to eye_end");
    view.eye_end = p;
  }
  if (view.eye && view.target) {
    const std::array<float, 3>& e = *view.eye;
    const std::array<float, 3>& t = *view.target;
    double distance = std::hypot(double(t[0]) - e[0], double(t[1]) - e[1], double(t[2]) - e[2]);
    if (distance < kMinEyeToTarget) {
      std::ostringstream detail;
      detail << "must be at least " << kMinEyeToTarget
             << " m from eye, or the camera looks nowhere (got " << distance << " m)";
      r.fail("target", detail.str());
    }
  }
  view.fov_deg = float(r.number("fov_deg", view.fov_deg, NumberRule::in(5, 150)));
  view.sun_elevation_deg =
      float(r.number("sun_elevation_deg", view.sun_elevation_deg, NumberRule::in(-90, 90)));
  view.sun_azimuth_deg = float(r.number("sun_azimuth_deg", view.sun_azimuth_deg));
  view.turbidity = float(r.number("turbidity", view.turbidity, NumberRule::in(1.7, 10)));
  view.exposure = float(r.number("exposure", view.exposure, NumberRule::above_at_most(0, 1000)));
  view.shadows = r.boolean("shadows", view.shadows);
  view.msaa = r.integer("msaa", view.msaa, NumberRule::in(1, 16));
  view.thinning = r.boolean("thinning", view.thinning);
  view.bloom = float(r.number("bloom", view.bloom, NumberRule::in(0.0, 1.0)));
  view.light_shafts =
      float(r.number("light_shafts", view.light_shafts, NumberRule::in(0.0, 100.0)));
  view.impostor_distance =
      float(r.number("impostor_distance", view.impostor_distance, NumberRule::in(0.0, 1e5)));
  r.finish();
}

}  // namespace

std::string check_slice_height(const boreas_grid_def& grid, double height) {
  double lo = grid.origin[1];
  double hi = lo + double(grid.cell_size) * grid.resolution[1];
  if (std::isfinite(height) && height >= lo && height <= hi) return "";
  std::ostringstream rule;
  rule << "in [" << lo << ", " << hi << "]";
  return rule.str();
}

Scene load_scene_text(const std::string& text, const std::string& source,
                      const std::string& base_dir, const SceneLimits& limits,
                      std::optional<uint64_t> run_seed) {
  nlohmann::json root = parse_scene_json(text, source);
  JsonObjectReader r(root, "", source);
  Scene scene;
  scene.source = source;
  scene.name = r.string("name", stem(source));
  scene.description = r.string("description", "");
  // world before run: the slice height is checked against the grid.
  read_world(r.object("world"), scene);
  read_wind(r.object("wind"), scene);
  const int max_trees = std::min(limits.trees, kMaxTrees);
  r.objects("trees", max_trees,
            [&](JsonObjectReader& e) { scene.trees.push_back(read_tree(e, base_dir)); });
  // Forests after the single trees: their trees follow in the world's order.
  r.objects("forests", max_trees, [&](JsonObjectReader& e) {
    SceneForest forest = read_forest(e, base_dir, max_trees);
    if (run_seed) forest.seed = mix_seed(*run_seed, forest.seed);
    const size_t total = scene.trees.size() + size_t(forest.count);
    if (total > size_t(max_trees)) {
      e.fail("count", "makes the scene's trees " + std::to_string(total) + ", more than the " +
                          std::to_string(max_trees) +
                          " a scene may hold, its trees and its forests' together");
    }
    std::vector<SceneTree> planted = plant_forest(forest);
    scene.trees.insert(scene.trees.end(), std::make_move_iterator(planted.begin()),
                       std::make_move_iterator(planted.end()));
  });
  r.objects("mesh_trees", kMaxMeshTrees,
            [&](JsonObjectReader& e) { scene.mesh_trees.push_back(read_mesh_tree(e, base_dir)); });
  r.objects("meadows", kMaxMeadows,
            [&](JsonObjectReader& e) { scene.meadows.push_back(read_meadow(e, base_dir)); });
  r.objects("colliders", kMaxColliders,
            [&](JsonObjectReader& e) { scene.colliders.push_back(read_collider(e)); });
  r.objects("emitters", kMaxEmitters,
            [&](JsonObjectReader& e) { scene.emitters.push_back(read_emitter(e)); });
  r.objects("sensors", kMaxSensors, [&](JsonObjectReader& e) {
    scene.sensors.push_back(read_sensor(e, int(scene.sensors.size()), scene.sensors));
  });
  read_run(r.object("run"), scene);
  read_view(r.object("view"), scene.view);
  r.finish();
  if (run_seed) apply_run_seed(scene, *run_seed);
  return scene;
}

Scene load_scene_file(const std::string& path, std::optional<uint64_t> run_seed) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, "", std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(path, "", std::string("cannot read: ") + std::strerror(errno));
  return load_scene_text(text.str(), path, std::filesystem::path(path).parent_path().string(), {},
                         run_seed);
}

const std::string& default_scene_text() {
  static const std::string text = [] {
    for (const auto& [name, contents] : boreas::embedded::scene_files()) {
      if (std::string(name) == kDefaultSceneName) return std::string(contents);
    }
    return std::string();
  }();
  return text;
}

Scene load_default_scene(std::optional<uint64_t> run_seed) {
  return load_scene_text(default_scene_text(), "default.json (built in)", "", {}, run_seed);
}

}  // namespace boreas::render
