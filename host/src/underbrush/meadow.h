// boreas: a meadow — its checked definition, its species' parts with their precomputed
// tables, and its components planted at rest (host copies of the device planes of
// cl/shared/underbrush_types.h, stride = the meadow's component count, until the upload:
// drop_uploaded).
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

// Lets go of the component planes once a batch holds the meadow (72 bytes a component
// besides the rest state's 44): the upload and the batch's tiles, made in the add, read
// them; the getter and the rays read the device's copies.
inline void drop_uploaded(Meadow& m) {
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

// Plants the meadow: terrain, nutrients, distribution (ordered by place), then every plant's
// components placed and brought to rest under gravity (breaking those too heavy to hold
// themselves). All of it in the meadow's local coordinates (origin: the rectangle's
// center), so the same def planted anywhere gives the same components to the bit; the
// terrain it keeps is moved back to the world's coordinates (the rays read it).
Meadow plant_meadow(MeadowParams params, const std::function<void(double)>& progress = {});

// Host float path of the kernels' table reads (the same header math), for rest placement
// and tests: the equilibrium X of component c under load a (m/s^2, gravity included), and
// the joint k of the shape for center of mass x.
BoreasV3 meadow_equilibrium(const Meadow& m, int c, BoreasV3 base, BoreasV3 load, int broken);
BoreasV3 meadow_shape_joint(const Meadow& m, int c, BoreasV3 base, BoreasV3 x, int broken, int k);

}  // namespace boreas::impl
