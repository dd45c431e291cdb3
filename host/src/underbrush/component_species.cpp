// boreas: underbrush species files, checked field by field; the sections' physics.
#include "underbrush/component_species.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "errors.h"
#include "json_text.h"
#include "shared/underbrush_types.h"
#include "validation.h"

namespace boreas::embedded {
const std::vector<std::pair<const char*, const char*>>& underbrush_species_files();
}

namespace boreas::impl {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "boreas-underbrush-1";

// Reads one object's fields, refusing unknown keys, naming `file: path.key` in errors.
class Fields {
 public:
  Fields(const json& object, std::string source, std::string path)
      : object_(object), source_(std::move(source)), path_(std::move(path)) {
    if (!object_.is_object()) fail_here(path_, "must be an object");
  }

  [[noreturn]] void fail_here(const std::string& path, const std::string& what) const {
    fail(BOREAS_ERROR_INVALID_ARGUMENT, source_ + ": " + (path.empty() ? "the top level" : path) + " " + what);
  }
  std::string at(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  void allow_only(std::initializer_list<const char*> keys) const {
    for (const auto& [key, value] : object_.items()) {
      bool known = false;
      for (const char* k : keys) known = known || key == k;
      if (!known) fail_here(at(key), "is not a known key");
    }
  }
  bool has(const char* key) const { return object_.contains(key); }
  const json& get(const char* key) const {
    if (!object_.contains(key)) fail_here(at(key), "is missing");
    return object_.at(key);
  }

  double number(const char* key, double fallback, double lo, double hi) const {
    if (!has(key)) return fallback;
    return checked_number(object_.at(key), at(key), lo, hi);
  }
  int integer(const char* key, int fallback, int lo, int hi) const {
    if (!has(key)) return fallback;
    const json& v = object_.at(key);
    if (!v.is_number_integer()) fail_here(at(key), "must be an integer (got " + v.dump() + ")");
    long long i = v.get<long long>();
    if (i < lo || i > hi)
      fail_here(at(key), "must be in " + std::to_string(lo) + ".." + std::to_string(hi) + " (got " +
                             std::to_string(i) + ")");
    return static_cast<int>(i);
  }
  std::string text(const char* key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    const json& v = object_.at(key);
    if (!v.is_string()) fail_here(at(key), "must be a string (got " + v.dump() + ")");
    return v.get<std::string>();
  }
  // A pair [a, b] (or one number, for both).
  void pair(const char* key, double out[2], double lo, double hi) const {
    if (!has(key)) return;
    const json& v = object_.at(key);
    if (v.is_number()) {
      out[0] = out[1] = checked_number(v, at(key), lo, hi);
      return;
    }
    if (!v.is_array() || v.size() != 2) fail_here(at(key), "must be a number or a pair [a, b] (got " + v.dump() + ")");
    for (int i = 0; i < 2; ++i) out[i] = checked_number(v[i], at(key) + "[" + std::to_string(i) + "]", lo, hi);
  }
  void triple(const char* key, double out[kMaxNutrients], double lo, double hi) const {
    if (!has(key)) return;
    const json& v = object_.at(key);
    if (!v.is_array() || v.size() > kMaxNutrients)
      fail_here(at(key), "must be an array of at most " + std::to_string(kMaxNutrients) + " numbers (got " +
                             v.dump() + ")");
    for (size_t i = 0; i < v.size(); ++i)
      out[i] = checked_number(v[i], at(key) + "[" + std::to_string(i) + "]", lo, hi);
  }

 private:
  double checked_number(const json& v, const std::string& path, double lo, double hi) const {
    if (!v.is_number()) fail_here(path, "must be a number (got " + v.dump() + ")");
    double d = v.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi)
      fail_here(path, "must be in [" + num(lo) + ", " + num(hi) + "] (got " + num(d) + ")");
    return d;
  }

  const json& object_;
  std::string source_;
  std::string path_;
};

PartProfile parse_profile(const Fields& f, const std::string& name) {
  if (name == "blade") return PartProfile::blade;
  if (name == "leaf") return PartProfile::leaf;
  if (name == "petal") return PartProfile::petal;
  if (name == "stalk") return PartProfile::stalk;
  f.fail_here(f.at("profile"), "must be \"blade\", \"leaf\", \"petal\" or \"stalk\" (got \"" + name + "\")");
}

PartDef parse_part(const json& j, const std::string& source, const std::string& path,
                   const std::vector<PartDef>& earlier) {
  Fields f(j, source, path);
  f.allow_only({"name", "count", "parent", "attach", "profile", "sections", "length",
                "length_variation", "width", "thickness", "tilt", "color", "translucency"});
  PartDef p;
  p.name = f.text("name", "");
  if (p.name.empty()) f.fail_here(f.at("name"), "must be a non-empty string");
  for (const PartDef& e : earlier)
    if (e.name == p.name) f.fail_here(f.at("name"), "repeats the name \"" + p.name + "\"");
  p.count = f.integer("count", 1, 1, 64);
  std::string parent = f.text("parent", "");
  if (!parent.empty()) {
    for (size_t i = 0; i < earlier.size(); ++i)
      if (earlier[i].name == parent) p.parent = static_cast<int>(i);
    if (p.parent < 0) f.fail_here(f.at("parent"), "names no earlier part (got \"" + parent + "\")");
  }
  p.attach = f.number("attach", 1.0, 0.0, 1.0);
  p.profile = parse_profile(f, f.text("profile", "blade"));
  p.sections = f.integer("sections", 6, 1, BOREAS_UB_MAX_SECTIONS);
  p.length = f.number("length", 0.3, 1e-3, 10.0);
  p.length_variation = f.number("length_variation", 0.0, 0.0, 0.5);
  f.pair("width", p.width, 1e-5, 1.0);
  f.pair("thickness", p.thickness, 1e-6, 0.1);
  f.pair("tilt", p.tilt, 0.0, 180.0);
  if (p.tilt[0] > p.tilt[1])
    f.fail_here(f.at("tilt"), "must be [min, max] with min <= max (got [" + num(p.tilt[0]) + ", " + num(p.tilt[1]) + "])");
  if (f.has("color")) {
    const json& c = f.get("color");
    if (!c.is_array() || c.size() != 3)
      f.fail_here(f.at("color"), "must be [r, g, b], sRGB 0..1 (got " + c.dump() + ")");
    f.triple("color", p.color, 0.0, 1.0);
  }
  p.translucency = f.number("translucency", -1.0, 0.0, 1.0);
  default_look(p);
  return p;
}

}  // namespace

void default_look(PartDef& part) {
  const bool petal = part.profile == PartProfile::petal;
  if (part.color[0] < 0.0) {
    const double green[3] = {0.36, 0.55, 0.20}, white[3] = {0.95, 0.95, 0.92};
    for (int i = 0; i < 3; ++i) part.color[i] = petal ? white[i] : green[i];
  }
  if (part.translucency < 0.0)
    part.translucency = part.profile == PartProfile::stalk ? 0.3 : (petal ? 0.4 : 0.6);
}

int ComponentSpecies::components_per_plant() const {
  std::vector<int> instances(parts.size(), 0);
  int total = 0;
  for (size_t i = 0; i < parts.size(); ++i) {
    int parents = parts[i].parent < 0 ? 1 : instances[parts[i].parent];
    instances[i] = parents * parts[i].count;
    total += instances[i];
  }
  return total;
}

ComponentSpecies parse_component_species(const std::string& text, const std::string& source) {
  json root;
  if (const auto bad = parse_json_text(text, &root)) {
    const std::string at = source + ":";
    switch (bad->kind) {
      case JsonTextError::Kind::kNulByte:
        fail_argument(at + std::to_string(json_line_at(text, bad->offset)) +
                      ": not valid JSON: " + bad->reason);
      case JsonTextError::Kind::kSyntax:
        // nlohmann's whole message, and the line of the character it stopped at.
        fail_argument(at + std::to_string(json_line_at(text, bad->offset)) +
                      ": not valid JSON: " + bad->what);
      case JsonTextError::Kind::kNumberOverflow:
        fail_argument(source + ": not valid JSON: " + bad->what);
    }
  }
  Fields top(root, source, "");
  top.allow_only({"format", "name", "source", "tissue", "ground", "parts"});
  if (top.text("format", "") != kFormat)
    top.fail_here("format", std::string("must be \"") + kFormat + "\" (got " +
                                (root.contains("format") ? root["format"].dump() : std::string("nothing")) + ")");
  ComponentSpecies s;
  s.source = source;
  s.name = top.text("name", "");
  if (s.name.empty()) top.fail_here("name", "must be a non-empty string");
  if (top.has("tissue")) {
    Fields t(root["tissue"], source, "tissue");
    t.allow_only({"density", "young_modulus", "break_stress", "drag_coefficient", "tau",
                  "recovery_time"});
    s.tissue.density = t.number("density", s.tissue.density, 1.0, 1e5);
    s.tissue.young_modulus = t.number("young_modulus", s.tissue.young_modulus, 1e3, 1e12);
    s.tissue.break_stress = t.number("break_stress", s.tissue.break_stress, 1.0, 1e11);
    s.tissue.drag_coefficient = t.number("drag_coefficient", s.tissue.drag_coefficient, 0.0, 10.0);
    s.tissue.tau = t.number("tau", s.tissue.tau, 1e-3, 100.0);
    s.tissue.recovery_time = t.number("recovery_time", s.tissue.recovery_time, 1e-2, 1e7);
  }
  if (top.has("ground")) {
    Fields g(root["ground"], source, "ground");
    g.allow_only({"need", "consumption", "spacing"});
    g.triple("need", s.need, 0.0, 1.0);
    g.triple("consumption", s.consumption, 0.0, 1e3);
    s.spacing = g.number("spacing", s.spacing, 1e-3, 100.0);
  }
  const json& parts = top.get("parts");
  if (!parts.is_array() || parts.empty()) top.fail_here("parts", "must be a non-empty array");
  for (size_t i = 0; i < parts.size(); ++i)
    s.parts.push_back(parse_part(parts[i], source, "parts[" + std::to_string(i) + "]", s.parts));
  if (s.components_per_plant() > BOREAS_PLANT_MAX_COMPONENTS)
    top.fail_here("parts", "make " + std::to_string(s.components_per_plant()) +
                               " components per plant; at most " +
                               std::to_string(BOREAS_PLANT_MAX_COMPONENTS));
  return s;
}

const char* builtin_underbrush_species(int index) {
  const auto& files = embedded::underbrush_species_files();
  if (index < 0 || index >= static_cast<int>(files.size())) return nullptr;
  static std::vector<std::string> names = [&] {
    std::vector<std::string> out;
    for (const auto& [file, text] : files) {
      std::string n = file;
      out.push_back(n.substr(0, n.rfind('.')));
    }
    return out;
  }();
  return names[static_cast<size_t>(index)].c_str();
}

ComponentSpecies load_component_species(const std::string& name_or_path) {
  for (const auto& [file, text] : embedded::underbrush_species_files()) {
    std::string n = file;
    if (n.substr(0, n.rfind('.')) == name_or_path) return parse_component_species(text, "built-in " + name_or_path);
  }
  std::ifstream in(name_or_path, std::ios::binary);
  if (!in) {
    std::string names;
    for (int i = 0; builtin_underbrush_species(i); ++i) names += std::string(i ? ", " : "") + builtin_underbrush_species(i);
    fail(BOREAS_ERROR_IO, "underbrush species '" + name_or_path + "' is neither a built-in species (" + names +
                              ") nor a readable file");
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_component_species(buffer.str(), name_or_path);
}

std::vector<double> part_half_widths(const PartDef& part) {
  std::vector<double> w(static_cast<size_t>(part.sections) + 1);
  for (int k = 0; k <= part.sections; ++k) {
    double s = double(k) / part.sections;
    switch (part.profile) {
      case PartProfile::blade: w[k] = 0.5 * (part.width[0] + (part.width[1] - part.width[0]) * s); break;
      // A leaf is widest past its middle and narrows to a short stalk and a point; a petal
      // is rounder. Neither reaches zero width, so every section has mass and stiffness.
      case PartProfile::leaf: w[k] = 0.5 * part.width[0] * (0.12 + 0.88 * std::sin(M_PI * std::pow(s, 0.8))); break;
      case PartProfile::petal: w[k] = 0.5 * part.width[0] * (0.25 + 0.75 * std::sin(M_PI * std::sqrt(s))); break;
      case PartProfile::stalk: w[k] = 0.5 * part.width[0]; break;
    }
  }
  return w;
}

std::vector<SectionPhysics> part_sections(const TissueDef& tissue, const PartDef& part) {
  std::vector<double> half = part_half_widths(part);
  std::vector<SectionPhysics> out(static_cast<size_t>(part.sections));
  double l = part.length / part.sections;
  for (int j = 0; j < part.sections; ++j) {
    double s = (j + 0.5) / part.sections;
    double w = half[j] + half[j + 1];  // the full width at the middle of the section
    double t = part.thickness[0] + (part.thickness[1] - part.thickness[0]) * s;
    if (part.profile == PartProfile::stalk) t = w;  // round: diameter both ways
    SectionPhysics& p = out[static_cast<size_t>(j)];
    p.length = l;
    p.mass = tissue.density * w * t * l;
    p.stiffness = tissue.young_modulus * w * t * t * t / (12.0 * l);
    p.max_moment = tissue.break_stress * w * t * t / 6.0;
  }
  return out;
}

}  // namespace boreas::impl
