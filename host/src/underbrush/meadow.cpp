// boreas: checking a meadow's definition and planting it at rest.
#include "underbrush/meadow.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "shared/underbrush_math.h"
#include "trees/tree_random.h"
#include "underbrush/frame_pack.h"
#include "underbrush/distribution.h"
#include "validation.h"

namespace boreas::impl {

namespace {

BoreasV3 v3(double x, double y, double z) { return boreas_v3(float(x), float(y), float(z)); }

// Unit vector at `tilt` radians from `axis`, turned `azimuth` radians around it.
void tilt_from(const double axis[3], double tilt, double azimuth, double out[3], double side[3]) {
  // Two unit vectors perpendicular to axis.
  double ref[3] = {std::fabs(axis[1]) < 0.9 ? 0.0 : 1.0, std::fabs(axis[1]) < 0.9 ? 1.0 : 0.0, 0.0};
  double e1[3] = {ref[1] * axis[2] - ref[2] * axis[1], ref[2] * axis[0] - ref[0] * axis[2],
                  ref[0] * axis[1] - ref[1] * axis[0]};
  double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (double& e : e1) e /= l1;
  double e2[3] = {axis[1] * e1[2] - axis[2] * e1[1], axis[2] * e1[0] - axis[0] * e1[2],
                  axis[0] * e1[1] - axis[1] * e1[0]};
  double c = std::cos(azimuth), s = std::sin(azimuth);
  double dir[3];  // the horizontal-ish direction it leans toward
  for (int a = 0; a < 3; ++a) dir[a] = c * e1[a] + s * e2[a];
  for (int a = 0; a < 3; ++a) out[a] = std::cos(tilt) * axis[a] + std::sin(tilt) * dir[a];
  // Side: the lean direction made perpendicular to the new axis, so an upright component
  // bends the way it leans (sec. 3.2: gravity alone cannot choose for an upright one).
  for (int a = 0; a < 3; ++a) side[a] = -std::sin(tilt) * axis[a] + std::cos(tilt) * dir[a];
}

// The straight part's compliance to a small load across it, m per m/s^2: how far its
// center of mass moves per unit load, read from its forward table at the first tabulated
// norm (the slope the kernel's equilibrium follows there).
double transverse_compliance(const PartTables& t) {
  const float a1 = float(table_norm(t, 1.0));
  BoreasUbPlane plane{0.0f, a1, boreas_v3(1.0f, 0.0f, 0.0f)};
  BoreasV3 x0 = boreas_ub_equilibrium(t.forward.data(), 0, t.sizes.angles, t.sizes.norms,
                                      float(t.sizes.a_ref), float(t.q_max), boreas_v3(0.0f, 0.0f, 0.0f),
                                      boreas_v3(0.0f, 1.0f, 0.0f), plane, 0.5f * BOREAS_UB_PI, a1, 1.0f);
  return double(x0.x) / double(a1);
}

BoreasGpuPart part_record(const ComponentSpecies& sp, const PartDef& def, const PartTables& t,
                          int offset) {
  std::vector<SectionPhysics> sec = part_sections(sp.tissue, def);
  std::vector<double> half = part_half_widths(def);
  double mass = 0.0, area = 0.0;
  for (size_t j = 0; j < sec.size(); ++j) {
    mass += sec[j].mass;
    area += (half[j] + half[j + 1]) * sec[j].length;
  }
  BoreasGpuPart g{};
  g.inv_mass = float(1.0 / mass);
  g.drag_area = float(0.5 * kAirDensity * sp.tissue.drag_coefficient * area);
  g.tau = float(sp.tissue.tau);
  g.air_coupling = float(transverse_compliance(t) / (sp.tissue.tau * sp.tissue.tau));
  g.recovery_time = float(sp.tissue.recovery_time);
  g.reach = float(t.reach);
  g.collider_push = float(kColliderPushG * kGravity);
  g.a_ref = float(t.sizes.a_ref);
  g.q_max = float(t.q_max);
  g.rho_min = float(t.rho_min);
  g.sections = def.sections;
  g.angles = t.sizes.angles;
  g.norms = t.sizes.norms;
  g.psi_count = t.sizes.psi_count;
  g.rho_count = t.sizes.rho_count;
  g.forward_size = t.forward_size;
  g.inverse_size = t.inverse_size;
  g.forward = offset;
  offset += static_cast<int>(t.forward.size());
  g.inverse = offset;
  offset += static_cast<int>(t.inverse.size());
  g.breaking = offset;
  offset += static_cast<int>(t.breaking.size());
  g.widths = offset;
  return g;
}

struct Frame {
  double base[3], axis[3], side[3];
  double scale = 1.0, follow = 0.0;
  int part = 0, parent = -1;
};

}  // namespace

MeadowParams checked_meadow_def(const boreas_meadow_def& def) {
  MeadowParams p;
  for (int a = 0; a < 3; ++a)
    check_range(def.center[a], -BOREAS_WORLD_MAX_COORDINATE, BOREAS_WORLD_MAX_COORDINATE,
                "meadow_def.center[" + std::to_string(a) + "]");
  for (int a = 0; a < 2; ++a)
    check_range(def.size[a], 0.01, 1e5, "meadow_def.size[" + std::to_string(a) + "]");
  check_range(def.density, 0.0, BOREAS_MEADOW_MAX_DENSITY, "meadow_def.density");
  check_range(def.terrain_relief, 0.0, 1e4, "meadow_def.terrain_relief");
  check_count(def.seed_points, 1, BOREAS_MEADOW_MAX_SEED_POINTS, "meadow_def.seed_points");
  check_count(def.shape_angles, 3, 181, "meadow_def.shape_angles");
  check_count(def.shape_norms, 3, 256, "meadow_def.shape_norms");
  for (int a = 0; a < 3; ++a) {
    check_range(def.lod_distances[a], 0.0, 1e7,
                "meadow_def.lod_distances[" + std::to_string(a) + "]");
    if (a > 0 && def.lod_distances[a] < def.lod_distances[a - 1])
      fail_argument("meadow_def.lod_distances[" + std::to_string(a) +
                    "] must not be below lod_distances[" + std::to_string(a - 1) + "] (got " +
                    std::to_string(def.lod_distances[a]) + " after " +
                    std::to_string(def.lod_distances[a - 1]) + ")");
  }
  double area = double(def.size[0]) * def.size[1];
  if (area * def.density > double(BOREAS_MEADOW_MAX_COMPONENTS))
    fail_argument("meadow_def: density * area = " + std::to_string(area * def.density) +
                  " components; at most " + std::to_string(BOREAS_MEADOW_MAX_COMPONENTS) +
                  " per meadow");
  check_count(def.species_count, 0, BOREAS_MEADOW_MAX_SPECIES, "meadow_def.species_count");
  if (def.species_count > 0 && !def.species)
    fail_argument("meadow_def.species is NULL with species_count > 0");
  if (def.species_count == 0) {
    const char* names[] = {"meadow_grass", "clover", "daisy"};
    const double weights[] = {6.0, 2.0, 1.0};
    for (int i = 0; i < 3; ++i) {
      p.species.push_back(load_component_species(names[i]));
      p.weights.push_back(weights[i]);
    }
  } else {
    for (int i = 0; i < def.species_count; ++i) {
      std::string where = "meadow_def.species[" + std::to_string(i) + "]";
      if (!def.species[i].species || !*def.species[i].species)
        fail_argument(where + ".species is NULL or empty");
      check_range(def.species[i].weight, 1e-9, 1e9, where + ".weight");
      p.species.push_back(load_component_species(def.species[i].species));
      p.weights.push_back(def.species[i].weight);
    }
  }
  p.rect.center_x = def.center[0];
  p.rect.center_y = def.center[1];
  p.rect.center_z = def.center[2];
  p.rect.size_x = def.size[0];
  p.rect.size_z = def.size[1];
  p.density = def.density;
  p.seed = def.seed;
  p.terrain = checked_ground_pixels(def.terrain, "meadow_def.terrain");
  p.nutrients = checked_ground_pixels(def.nutrients, "meadow_def.nutrients");
  p.relief = def.terrain_relief;
  p.seed_points = def.seed_points;
  p.sizes.angles = def.shape_angles;
  p.sizes.norms = def.shape_norms;
  for (int a = 0; a < 3; ++a) p.lod[a] = def.lod_distances[a];
  return p;
}

namespace {

// meadow_equilibrium and meadow_shape_joint for a component of part `part` whose packed
// words decode to f (placement decodes a component once for several of these).
BoreasV3 equilibrium_of(const Meadow& m, int part, const UnpackedFrame& f, BoreasV3 base,
                        BoreasV3 load, int broken) {
  const BoreasGpuPart& g = m.parts[size_t(part)].gpu;
  BoreasUbPlane plane = boreas_ub_plane(load, f.axis, f.side);
  float theta = boreas_ub_angle(plane.par, plane.perp);
  return boreas_ub_equilibrium(m.tables.data(), g.forward + broken * g.forward_size, g.angles,
                               g.norms, g.a_ref, g.q_max, base, f.axis, plane, theta,
                               boreas_v3_length(load), f.scale);
}

BoreasV3 shape_joint_of(const Meadow& m, int part, const UnpackedFrame& f, BoreasV3 base,
                        BoreasV3 x, int broken, int k) {
  const BoreasGpuPart& g = m.parts[size_t(part)].gpu;
  const BoreasV3 e_u = f.axis;
  const float scale = f.scale;
  BoreasUbPlane plane = boreas_ub_plane(boreas_v3_sub(x, base), e_u, f.side);
  BoreasUbCell psi, rho;
  boreas_ub_shape_cell(plane.par, plane.perp, g.reach * scale, g.psi_count, g.rho_count, g.rho_min,
                       &psi, &rho);
  float u, v;
  boreas_ub_shape_joint(m.tables.data(), g.inverse + broken * g.inverse_size, g.rho_count, psi, rho,
                        k, &u, &v);
  return boreas_v3_lin3(base, 1.0f, e_u, u * scale, plane.e_v, v * scale);
}

// The same for component c of index planes at stride n.
BoreasV3 equilibrium_in(const Meadow& m, const int32_t* index, int n, int c, BoreasV3 base,
                        BoreasV3 load, int broken) {
  return equilibrium_of(m, part_of(index, n, c), unpack_frame(index, n, c), base, load, broken);
}
BoreasV3 shape_joint_in(const Meadow& m, const int32_t* index, int n, int c, BoreasV3 base,
                        BoreasV3 x, int broken, int k) {
  return shape_joint_of(m, part_of(index, n, c), unpack_frame(index, n, c), base, x, broken, k);
}

}  // namespace

BoreasV3 meadow_equilibrium(const Meadow& m, int c, BoreasV3 base, BoreasV3 load, int broken) {
  return equilibrium_in(m, m.index.data(), m.count, c, base, load, broken);
}

BoreasV3 meadow_shape_joint(const Meadow& m, int c, BoreasV3 base, BoreasV3 x, int broken, int k) {
  return shape_joint_in(m, m.index.data(), m.count, c, base, x, broken, k);
}

namespace {

// Parts and their tables (the precomputation of sec. 3.1); part_index[species][part].
void build_parts(Meadow& m, const MeadowParams& params,
                 std::vector<std::vector<int>>* part_index_out) {
  std::vector<std::vector<int>>& part_index = *part_index_out;
  part_index.assign(params.species.size(), {});
  // Parts and their tables (the precomputation of sec. 3.1).
  for (size_t s = 0; s < params.species.size(); ++s) {
    const ComponentSpecies& sp = params.species[s];
    for (size_t p = 0; p < sp.parts.size(); ++p) {
      MeadowPart mp;
      mp.species = static_cast<int>(s);
      mp.part = static_cast<int>(p);
      mp.def = sp.parts[p];
      mp.tables = build_part_tables(part_sections(sp.tissue, mp.def), part_half_widths(mp.def),
                                    params.sizes);
      mp.gpu = part_record(sp, mp.def, mp.tables, static_cast<int>(m.tables.size()));
      for (const std::vector<float>* t :
           {&mp.tables.forward, &mp.tables.inverse, &mp.tables.breaking, &mp.tables.widths})
        m.tables.insert(m.tables.end(), t->begin(), t->end());
      part_index[s].push_back(static_cast<int>(m.parts.size()));
      m.parts.push_back(std::move(mp));
    }
  }
}

// Room for components [first, first + count) of a meadow, zero.
void size_piece(MeadowPiece* piece, int first, int count) {
  const size_t n = size_t(count);
  piece->first = first;
  piece->count = count;
  piece->frame.assign(size_t(BOREAS_UB_FRAME_PLANES) * n, 0.0f);
  piece->index.assign(size_t(BOREAS_UB_INDEX_PLANES) * n, 0);
  piece->rest_state.assign(size_t(BOREAS_UB_STATE_PLANES) * n, 0.0f);
  piece->species_of.assign(n, 0);
  piece->plant_of.assign(n, 0);
}

// The frame of the k-th component of a part (global_part) on `parent` (-1: on the ground):
// scale, tilt and turn drawn from rng in a fixed order; a ground part's start within a
// quarter spacing of the planting, another's at its parent's joint at rest.
Frame component_frame(const Meadow& m, const MeadowPiece& piece, const Planting& pl,
                      const ComponentSpecies& sp, const PartDef& def, int global_part, int parent,
                      int k, TreeRandom& rng) {
  const int n = piece.count;
  Frame f;
  f.part = global_part;
  f.parent = parent;
  f.scale = 1.0 + def.length_variation * rng.uniform_pm1();
  double tilt = (def.tilt[0] + (def.tilt[1] - def.tilt[0]) * rng.uniform01()) * M_PI / 180.0;
  double azimuth =
      2.0 * M_PI * (def.count > 1 ? (k + 0.3 * rng.uniform_pm1()) / def.count : rng.uniform01());
  double from[3];
  if (parent < 0) {
    // A tuft: the components of a ground part start within a quarter spacing.
    double jitter = 0.25 * sp.spacing;
    f.base[0] = pl.position[0] + jitter * rng.uniform_pm1();
    f.base[1] = pl.position[1];
    f.base[2] = pl.position[2] + jitter * rng.uniform_pm1();
    for (int a = 0; a < 3; ++a) from[a] = pl.normal[a];
  } else {
    const int lp = parent - piece.first;  // the parent in the piece's planes
    const float* frame = piece.frame.data();
    const int32_t* index = piece.index.data();
    const int ppart = part_of(index, n, lp);
    const UnpackedFrame pf = unpack_frame(index, n, lp);
    const MeadowPart& pp = m.parts[size_t(ppart)];
    int joint = static_cast<int>(std::lround(def.attach * pp.def.sections));
    BoreasV3 pbase = boreas_tree_load3(frame, n, BOREAS_UB_FRAME_BASE, lp);
    BoreasV3 px = boreas_tree_load3(piece.rest_state.data(), n, BOREAS_UB_STATE_X, lp);
    int pbroken = int(piece.rest_state[size_t(BOREAS_UB_STATE_BROKEN * n + lp)]);
    BoreasV3 at = shape_joint_of(m, ppart, pf, pbase, px, pbroken, joint);
    BoreasV3 below = joint > 0 ? shape_joint_of(m, ppart, pf, pbase, px, pbroken, joint - 1)
                               : boreas_v3_sub(at, pf.axis);
    BoreasV3 t = boreas_v3_normalize(boreas_v3_sub(at, below));
    from[0] = t.x, from[1] = t.y, from[2] = t.z;
    f.base[0] = at.x, f.base[1] = at.y, f.base[2] = at.z;
    double arm = boreas_v3_length(boreas_v3_sub(px, pbase));
    f.follow = arm > 0.0 ? boreas_v3_length(boreas_v3_sub(at, pbase)) / arm : 0.0;
  }
  tilt_from(from, tilt, azimuth, f.axis, f.side);
  return f;
}

// The packed words of a component (frame_pack.h) at i in the piece's planes (c: the
// meadow's index). What they hold fits by the limits a meadow's species are checked
// against (component_species.cpp), so nothing is refused here, mid-add: planting keeps a
// plant's components together and a part's parent before it, so the parent is at most
// BOREAS_PLANT_MAX_COMPONENTS - 1 back; every part makes a component a plant at least,
// so a meadow has at most BOREAS_MEADOW_MAX_SPECIES x BOREAS_PLANT_MAX_COMPONENTS parts;
// a scale is 1 +- length_variation (at most 0.5), within a half's normal range.
static_assert(BOREAS_PLANT_MAX_COMPONENTS - 1 <= BOREAS_UB_LINK_PART_MASK, "parent offset");
static_assert(BOREAS_MEADOW_MAX_SPECIES * BOREAS_PLANT_MAX_COMPONENTS <= BOREAS_UB_LINK_PART_MASK + 1,
              "parts of a meadow");
static_assert(BOREAS_UB_SCALE_MIN <= 0.5 && 1.5 <= BOREAS_UB_SCALE_MAX, "scale");
void write_packed(MeadowPiece& piece, size_t i, const Frame& f, int c) {
  const size_t n = size_t(piece.count);
  const int32_t axis = pack_axis(f.axis);
  piece.index[size_t(BOREAS_UB_INDEX_LINK) * n + i] =
      pack_link(f.part, f.parent < 0 ? 0 : c - f.parent, "meadow component");
  piece.index[size_t(BOREAS_UB_INDEX_AXIS) * n + i] = axis;
  piece.index[size_t(BOREAS_UB_INDEX_TURN) * n + i] =
      pack_turn(axis, f.side, f.scale, "meadow component");
}

// Component c of plant `plant` (planted as pl): its frame written, then brought to rest
// under gravity (c: the meadow's index, in the piece's planes at c - piece.first).
void place_component(const Meadow& m, MeadowPiece& piece, int c, const Frame& f,
                     const Planting& pl, int plant, BoreasV3 gravity) {
  const size_t n = size_t(piece.count), i = size_t(c - piece.first);
  float* frame = piece.frame.data();
  for (int a = 0; a < 3; ++a) frame[size_t(BOREAS_UB_FRAME_BASE + a) * n + i] = float(f.base[a]);
  frame[size_t(BOREAS_UB_FRAME_FOLLOW) * n + i] = float(f.follow);
  write_packed(piece, i, f, c);
  piece.species_of[i] = pl.kind;
  piece.plant_of[i] = plant;

  // From here on the packed axis, side and scale, as every later reader sees them.
  const BoreasGpuPart& g = m.parts[size_t(f.part)].gpu;
  const UnpackedFrame u = unpack_frame(piece.index.data(), piece.count, int(i));
  BoreasUbPlane plane = boreas_ub_plane(gravity, u.axis, u.side);
  float theta = boreas_ub_angle(plane.par, plane.perp);
  int broken = static_cast<int>(
      boreas_ub_broken(m.tables.data(), g.breaking, g.angles, theta,
                       boreas_ub_break_norm(boreas_v3_length(gravity), u.scale), 0.0f));
  piece.rest_state[size_t(BOREAS_UB_STATE_BROKEN) * n + i] = float(broken);
  BoreasV3 base = v3(f.base[0], f.base[1], f.base[2]);
  BoreasV3 x = equilibrium_of(m, f.part, u, base, gravity, broken);
  boreas_tree_store3(frame, int(n), BOREAS_UB_FRAME_REST, int(i), x);
  boreas_tree_store3(piece.rest_state.data(), int(n), BOREAS_UB_STATE_X, int(i), x);
  boreas_tree_store3(piece.rest_state.data(), int(n), BOREAS_UB_STATE_BASE, int(i), base);
}

// The parts' global indices, per species and part: part_index[species][part].
std::vector<std::vector<int>> part_indices(const Meadow& m) {
  std::vector<std::vector<int>> part_index(m.params.species.size());
  for (size_t p = 0; p < m.parts.size(); ++p)
    part_index[size_t(m.parts[p].species)].push_back(int(p));
  return part_index;
}

// Plantings [planting_first, planting_end) placed into `piece` (sized for them), their
// first component at piece->first: components in part order, each brought to rest as
// it is placed (children need their parent's rest shape).
void place_plantings(const Meadow& m, const std::vector<Planting>& plantings,
                     size_t planting_first, size_t planting_end, MeadowPiece* piece,
                     const std::function<void(double)>& progress) {
  const std::vector<std::vector<int>> part_index = part_indices(m);
  const BoreasV3 gravity = boreas_v3(0.0f, float(-kGravity), 0.0f);
  int c = piece->first;
  std::vector<std::vector<int>> instances;  // per part of the plant: its components
  for (size_t pi = planting_first; pi < planting_end; ++pi) {
    const Planting& pl = plantings[pi];
    const ComponentSpecies& sp = m.params.species[size_t(pl.kind)];
    TreeRandom rng(m.params.seed, pl.seed, 0x75ULL);
    instances.assign(sp.parts.size(), {});
    for (size_t p = 0; p < sp.parts.size(); ++p) {
      const PartDef& def = sp.parts[p];
      int global_part = part_index[size_t(pl.kind)][p];
      std::vector<int> parents = def.parent < 0 ? std::vector<int>{-1} : instances[size_t(def.parent)];
      for (int parent : parents) {
        for (int k = 0; k < def.count; ++k) {
          const Frame f = component_frame(m, *piece, pl, sp, def, global_part, parent, k, rng);
          place_component(m, *piece, c, f, pl, static_cast<int>(pi), gravity);
          instances[p].push_back(c);
          ++c;
        }
      }
    }
    if (progress && (pi & 65535) == 0) progress(double(pi) / double(plantings.size()));
  }
}

}  // namespace

int components_of(const Meadow& m, const Planting& planting) {
  return m.params.species[size_t(planting.kind)].components_per_plant();
}

void place_piece(const Meadow& m, size_t planting_first, size_t planting_end, int first,
                 MeadowPiece* piece) {
  int64_t count = 0;
  for (size_t pi = planting_first; pi < planting_end; ++pi)
    count += components_of(m, m.plantings[pi]);
  size_piece(piece, first, int(count));
  place_plantings(m, m.plantings, planting_first, planting_end, piece, {});
}

Meadow meadow_from_plantings(MeadowParams params, const std::vector<Planting>& plantings,
                             const std::function<void(double)>& progress,
                             std::array<double, 3> origin) {
  Meadow m;
  m.origin = origin;
  std::vector<std::vector<int>> part_index;
  build_parts(m, params, &part_index);
  m.params = std::move(params);
  int64_t total = 0;
  for (const Planting& pl : plantings) total += components_of(m, pl);
  m.count = static_cast<int>(total);
  // Placed whole: one piece of every component, its planes the meadow's.
  MeadowPiece piece;
  size_piece(&piece, 0, m.count);
  place_plantings(m, plantings, 0, plantings.size(), &piece, progress);
  m.frame = std::move(piece.frame);
  m.index = std::move(piece.index);
  m.rest_state = std::move(piece.rest_state);
  m.species_of = std::move(piece.species_of);
  m.plant_of = std::move(piece.plant_of);
  if (progress) progress(1.0);
  return m;
}

void sort_plantings_by_place(std::vector<Planting>& plantings, const GroundRect& rect) {
  // Z-order (Morton) of 0.5 m cells: neighbours on the ground end up near in the list, at
  // every scale, so a run of 64 components (a tile of the step's launches) covers a small
  // patch and takes one level of detail (underbrush_batch.h). Stable: equal cells keep the
  // distribution's order, so the result is as deterministic as it is.
  constexpr double kCell = 0.5;
  const double x0 = rect.center_x - 0.5 * rect.size_x, z0 = rect.center_z - 0.5 * rect.size_z;
  auto spread = [](uint64_t v) {  // the low 32 bits of v to the even bits
    v &= 0xffffffffull;
    v = (v | (v << 16)) & 0x0000ffff0000ffffull;
    v = (v | (v << 8)) & 0x00ff00ff00ff00ffull;
    v = (v | (v << 4)) & 0x0f0f0f0f0f0f0f0full;
    v = (v | (v << 2)) & 0x3333333333333333ull;
    v = (v | (v << 1)) & 0x5555555555555555ull;
    return v;
  };
  auto key = [&](const Planting& p) {
    const double cx = std::clamp((p.position[0] - x0) / kCell, 0.0, 4.0e9);
    const double cz = std::clamp((p.position[2] - z0) / kCell, 0.0, 4.0e9);
    return spread(uint64_t(cx)) | (spread(uint64_t(cz)) << 1);
  };
  std::vector<std::pair<uint64_t, size_t>> order(plantings.size());
  for (size_t i = 0; i < plantings.size(); ++i) order[i] = {key(plantings[i]), i};
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Planting> sorted;
  sorted.reserve(plantings.size());
  for (const auto& [k, i] : order) sorted.push_back(plantings[i]);
  plantings = std::move(sorted);
}

Meadow plant_meadow(MeadowParams params, const std::function<void(double)>& progress) {
  // Planted about the rectangle's center: every position below is local.
  const GroundRect world_rect = params.rect;
  params.rect.center_x = params.rect.center_y = params.rect.center_z = 0.0;
  // The ground and where the plants grow.
  Terrain terrain = params.terrain.empty()
                        ? procedural_terrain(params.rect, params.relief, params.seed)
                        : pixel_terrain(params.rect, params.relief, params.terrain);
  NutrientMaps nutrients;
  if (params.nutrients.empty()) {
    // Procedural ground is a meadow's: fertile everywhere (0.35..1), so a small meadow is
    // never bare, with patches where the needier species thrive.
    nutrients = procedural_nutrients(params.rect, params.seed);
    for (int c = 0; c < nutrients.channels; ++c)
      for (float& v : nutrients.values[c]) v = 0.35f + 0.65f * v;
  } else {
    nutrients = pixel_nutrients(params.rect, params.nutrients);
  }
  // The caller's pixels are now the terrain's and nutrients' grids: the planted meadow,
  // which keeps its params for its whole life, does not keep a second copy of them.
  params.terrain = GroundPixels{};
  params.nutrients = GroundPixels{};
  std::vector<PlantNeeds> kinds;
  double weight_sum = 0.0, components_per_plant = 0.0;
  for (size_t s = 0; s < params.species.size(); ++s) {
    const ComponentSpecies& sp = params.species[s];
    PlantNeeds k;
    k.weight = params.weights[s];
    for (int c = 0; c < kMaxNutrients; ++c) {
      k.need[c] = sp.need[c];
      k.consumption[c] = sp.consumption[c];
    }
    k.spacing = sp.spacing;
    kinds.push_back(k);
    weight_sum += k.weight;
    components_per_plant += k.weight * sp.components_per_plant();
  }
  components_per_plant /= weight_sum;
  DistributionParams dp;
  double area = params.rect.size_x * params.rect.size_z;
  dp.target_count =
      static_cast<int64_t>(std::llround(params.density * area / components_per_plant));
  dp.seed_points = params.seed_points;
  dp.seed = params.seed;
  if (progress) dp.progress = [&](double f) { progress(f); };
  std::vector<Planting> plantings =
      dp.target_count > 0 ? distribute(terrain, nutrients, kinds, dp) : std::vector<Planting>{};
  sort_plantings_by_place(plantings, params.rect);

  // The components stay plantings: the batch places them a piece at a time as it uploads
  // them (place_piece; underbrush_batch.cpp).
  params.rect = world_rect;
  Meadow meadow;
  meadow.origin = {world_rect.center_x, world_rect.center_y, world_rect.center_z};
  std::vector<std::vector<int>> part_index;
  build_parts(meadow, params, &part_index);
  meadow.params = std::move(params);
  int64_t total = 0;
  for (const Planting& pl : plantings) total += components_of(meadow, pl);
  meadow.count = static_cast<int>(total);
  meadow.plantings = std::move(plantings);
  if (progress) progress(1.0);
  // The ground back in the world's coordinates, for the rays.
  terrain.grid.origin_x += world_rect.center_x;
  terrain.grid.origin_z += world_rect.center_z;
  for (float& h : terrain.height) h = float(double(h) + world_rect.center_y);
  meadow.terrain = std::move(terrain);
  return meadow;
}

}  // namespace boreas::impl
