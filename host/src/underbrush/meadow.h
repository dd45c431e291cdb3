// boreas: a meadow — its checked definition, its species' parts with their precomputed
// tables, and its components planted at rest: either placed whole (host copies of the
// device planes of cl/shared/underbrush_types.h, stride = the meadow's component count,
// until the upload: drop_uploaded), or, as plant_meadow leaves it, still as plantings,
// which the batch places a bounded piece at a time as it uploads them (place_piece), so
// adding a meadow costs its device planes and one piece more, not its planes twice.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "boreas/boreas.h"
// The host's float path uses the polynomial math the CPU kernels use.
#ifndef BOREAS_FAST_MATH
#define BOREAS_FAST_MATH 1
#endif
#include "shared/tree_math.h"
#include "shared/underbrush_types.h"
#include "underbrush/component_species.h"
#include "underbrush/distribution.h"
#include "underbrush/shape_table.h"
#include "underbrush/terrain.h"
#include "wind/air.h"

namespace boreas::impl {

constexpr double kColliderPushG = 40.0;  // a collider's full push, in g (see step kernel)

// boreas_default_meadow_def(), made once.
inline const boreas_meadow_def& meadow_defaults() {
  static const boreas_meadow_def defaults = boreas_default_meadow_def();
  return defaults;
}

struct MeadowParams {
  std::vector<ComponentSpecies> species;
  std::vector<double> weights;
  GroundRect rect;
  // A meadow made by hand (tests, benchmarks) takes the public def's defaults
  // (boreas_default_meadow_def, the one place they are defined; boreas.h documents them).
  double density = meadow_defaults().density;  // components per m^2
  uint64_t seed = meadow_defaults().seed;
  // The caller's maps, from the def until planting (empty: procedural; a planted meadow's
  // are empty, its grids hold them).
  GroundPixels terrain, nutrients;
  double relief = meadow_defaults().terrain_relief;  // m
  int seed_points = meadow_defaults().seed_points;
  ShapeTableSizes sizes;
  std::array<float, 3> lod{meadow_defaults().lod_distances[0], meadow_defaults().lod_distances[1],
                           meadow_defaults().lod_distances[2]};  // m
};

// Checks every field (naming it), loads the species. Throws Error.
MeadowParams checked_meadow_def(const boreas_meadow_def& def);

struct MeadowPart {
  int species = 0, part = 0;
  PartDef def;
  PartTables tables;
  BoreasGpuPart gpu{};  // table offsets relative to this meadow's `tables`
};

struct Meadow {
  MeadowParams params;
  // m: where the meadow's local coordinates are 0 in the world (the def's center). Every
  // position of its planes (frame, state) is relative to it, so that a meadow far from 0
  // keeps the float precision it has at 0 (README "Far from the origin"); readers add it
  // back, in double. An exact float.
  std::array<double, 3> origin{};
  std::vector<MeadowPart> parts;
  std::vector<float> tables;        // every part's tables, one after the other
  int count = 0;                    // components
  // Plantings not yet placed (plant_meadow's meadows, until the upload): their components
  // are [0, count) in this order, components_of(planting) each. Empty where the planes
  // below are placed whole (meadow_from_plantings).
  std::vector<Planting> plantings;
  // The component planes, until the upload (drop_uploaded): a world's batch holds them on
  // the device, and its readers read them there (UnderbrushBatch::read_meadow_frame).
  std::vector<float> frame;         // BOREAS_UB_FRAME_PLANES x count
  std::vector<int32_t> index;       // BOREAS_UB_INDEX_PLANES x count (meadow-local)
  // BOREAS_UB_STATE_PLANES x count: X at rest, V = 0.
  std::vector<float> rest_state;
  std::vector<int32_t> species_of;  // per component (parts[its part].species)
  std::vector<int32_t> plant_of;    // per component: which planting
  Terrain terrain;                  // the ground it grows on (rays see it); empty for a
                                    // meadow planted by hand
};

// Components [first, first + count) of a meadow, placed at rest: the component planes of
// Meadow at stride count, their parent indices the meadow's (a planting's components are
// one piece's, so every parent is in its piece).
struct MeadowPiece {
  int first = 0, count = 0;
  std::vector<float> frame;         // BOREAS_UB_FRAME_PLANES x count
  std::vector<int32_t> index;       // BOREAS_UB_INDEX_PLANES x count (meadow-local)
  std::vector<float> rest_state;    // BOREAS_UB_STATE_PLANES x count
  std::vector<int32_t> species_of;  // per component
  std::vector<int32_t> plant_of;    // per component
};

// How many components a planting of the meadow grows.
int components_of(const Meadow& m, const Planting& planting);

// Places m.plantings[planting_first, planting_end) at rest into `piece` (reusing its
// storage), whose first component is `first` (the components of the plantings before).
// The same bits as meadow_from_plantings gives those components.
void place_piece(const Meadow& m, size_t planting_first, size_t planting_end, int first,
                 MeadowPiece* piece);

// Lets go of the component planes (72 bytes a component besides the rest state's 44) and
// of the plantings once a batch holds the meadow: the upload and the batch's tiles, made
// in the add, read them; the getter and the rays read the device's copies.
inline void drop_uploaded(Meadow& m) {
  std::vector<Planting>().swap(m.plantings);
  std::vector<float>().swap(m.rest_state);
  std::vector<float>().swap(m.frame);
  std::vector<int32_t>().swap(m.index);
  std::vector<int32_t>().swap(m.species_of);
  std::vector<int32_t>().swap(m.plant_of);
}

// Places every planting's components and brings them to rest under gravity (breaking those
// too heavy to hold themselves). Plantings name species by index into params.species, and
// stand at their positions relative to `origin` (the meadow's, m).
Meadow meadow_from_plantings(MeadowParams params, const std::vector<Planting>& plantings,
                             const std::function<void(double)>& progress = {},
                             std::array<double, 3> origin = {});

// Orders plantings along a Z-order curve over the ground, so that plants near in the list
// are near on the ground (the step's tiles then each cover a small patch).
void sort_plantings_by_place(std::vector<Planting>& plantings, const GroundRect& rect);

// Plants the meadow: terrain, nutrients, distribution (ordered by place), kept as its
// plantings, whose components (placed and brought to rest under gravity, breaking those
// too heavy to hold themselves) the batch places piece by piece (place_piece). All of it
// in the meadow's local coordinates (origin: the rectangle's center), so the same def
// planted anywhere gives the same components to the bit; the terrain it keeps is moved
// back to the world's coordinates (the rays read it).
Meadow plant_meadow(MeadowParams params, const std::function<void(double)>& progress = {});

// Host float path of the kernels' table reads (the same header math), for rest placement
// and tests: the equilibrium X of component c under load a (m/s^2, gravity included), and
// the joint k of the shape for center of mass x.
BoreasV3 meadow_equilibrium(const Meadow& m, int c, BoreasV3 base, BoreasV3 load, int broken);
BoreasV3 meadow_shape_joint(const Meadow& m, int c, BoreasV3 base, BoreasV3 x, int broken, int k);

}  // namespace boreas::impl
