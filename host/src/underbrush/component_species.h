// boreas: underbrush species (Endo et al. sec. 3.1-3.2) — a plant as parts (blades,
// leaves, petals, stalks), each part a vector set: main-axis vectors section by section and
// left and right border vectors across them, with per-section mass, width and thickness.
// A part is fixed at its base to the ground or to a parent part.
//
// Species come as JSON (host/species/underbrush/*.json, embedded; or a user's file):
//   {"format": "boreas-underbrush-1", "name": "meadow_grass",
//    "tissue": {"density": 700, "young_modulus": 2e8, "break_stress": 3e7,
//               "drag_coefficient": 1.2, "tau": 0.3, "recovery_time": 30},
//    "ground": {"need": [0.3, 0, 0], "consumption": [0.02, 0, 0], "spacing": 0.05},
//    "parts": [{"name": "blade", "count": 6, "profile": "blade", "sections": 6,
//               "length": 0.3, "length_variation": 0.25, "width": [0.005, 0.001],
//               "thickness": [0.0005, 0.0002], "tilt": [5, 35],
//               "color": [0.36, 0.55, 0.2], "translucency": 0.6},
//              {"name": "petal", "parent": "stalk", "attach": 1.0, ...}]}
// Every error names the file and the JSON path of the value and what was wrong.
#pragma once

#include <string>
#include <vector>

#include "underbrush/terrain.h"

namespace boreas::impl {

enum class PartProfile { blade, leaf, petal, stalk };

struct PartDef {
  std::string name;
  int count = 1;             // per plant (ground parts) or per parent instance
  int parent = -1;           // index of an earlier part, -1: fixed to the ground
  double attach = 1.0;       // where on the parent, 0 base .. 1 tip (nearest joint)
  PartProfile profile = PartProfile::blade;
  int sections = 6;          // 1..BOREAS_UB_MAX_SECTIONS
  double length = 0.3;       // m
  double length_variation = 0.0;  // instances scale by 1 +- this, 0..0.5
  double width[2] = {0.005, 0.001};        // m: blade base, tip; leaf/petal: widest, -;
                                           // stalk: diameter, -
  double thickness[2] = {0.0005, 0.0002};  // m: base, tip
  double tilt[2] = {5.0, 30.0};            // degrees from the parent's axis (ground parts:
                                           // from the terrain normal), min..max
  // How it looks, for renderers (the physics ignores both): the upper side's color in
  // daylight (sRGB 0..1) and the share of light that passes through the tissue, per
  // channel of that color. Unset: a green leaf, or a white petal (default_look()).
  double color[3] = {-1.0, -1.0, -1.0};
  double translucency = -1.0;
};

// The color and translucency of a part whose file gives none: grass green for blades,
// leaves and stalks (stalks let less light through), white for petals.
void default_look(PartDef& part);

struct TissueDef {
  double density = 700.0;          // kg/m^3
  double young_modulus = 2.0e8;    // Pa
  double break_stress = 3.0e7;     // Pa: bending stress at which a section breaks
  double drag_coefficient = 1.2;
  double tau = 0.3;                // s: time constant of the dynamic constraint
  // s: a component flattened by a collider (or broken) rises again as exp(-t /
  // recovery_time). Trampled grass rises over hours in nature (about 1e4 s); the default
  // shows a track that fades over a scene.
  double recovery_time = 30.0;
};

struct ComponentSpecies {
  std::string name;
  std::string source;  // file it came from ("built-in NAME" for embedded ones)
  TissueDef tissue;
  double need[kMaxNutrients] = {0, 0, 0};
  double consumption[kMaxNutrients] = {0, 0, 0};
  double spacing = 0.05;  // m between plants
  std::vector<PartDef> parts;
  int components_per_plant() const;
};

// One section of a part as the rest-shape solver sees it (SI units).
struct SectionPhysics {
  double length = 0.0;      // m
  double mass = 0.0;        // kg
  double stiffness = 0.0;   // N m: kappa, the elastic moment at its base joint is kappa sin(alpha)
  double max_moment = 0.0;  // N m: it breaks beyond this
};

// The sections of a part, from base to tip, and the half width at every joint. The elastic
// constant of section j, stated: a rectangular blade section of width w, thickness t and
// length l (w, t at its middle) resists a bend alpha at its base joint like a beam element,
// kappa = E I / l with I = w t^3 / 12; seen at the center of mass X of the part above
// (arm r) this is the paper's k = kappa / r^2, so k depends on thickness, width and the
// position along the component as sec. 3.2 asks. It breaks when the bending stress at its
// surface reaches break_stress: max_moment = break_stress w t^2 / 6. Stalks are round-ish:
// w = t = the diameter.
std::vector<SectionPhysics> part_sections(const TissueDef& tissue, const PartDef& part);
std::vector<double> part_half_widths(const PartDef& part);  // sections + 1 values

// A built-in name (see builtin_underbrush_species) or a path to a .json species file.
ComponentSpecies load_component_species(const std::string& name_or_path);
ComponentSpecies parse_component_species(const std::string& text, const std::string& source);
const char* builtin_underbrush_species(int index);

}  // namespace boreas::impl
