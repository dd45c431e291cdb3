// boreas tests: Embree 3, the reference ray tracer, against boreas_world_cast_rays on a windy
// forest's current triangles (issue 37, "Reference and speed"), and the reference itself
// (tests/reference/embree_world.h) against analytic hits, the parts it was aimed at, and
// a scene built afresh after a step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "api/c_api_guard.h"
#include "embree_world.h"
#include "mesh_trees/tube_trees.h"
#include "ray_forest.h"
#include "rays/embree_ground.h"
#include "support/temp_dir.h"

namespace boreas::reference {
namespace {

constexpr float kDt = 1.0f / 60.0f;

void step(boreas_world world, int steps) {
  for (int s = 0; s < steps; ++s) ASSERT_EQ(boreas_world_step(world, kDt), BOREAS_OK)
      << boreas_last_error();
}

boreas_ray ray(float ox, float oy, float oz, float dx, float dy, float dz,
               float max_distance = INFINITY) {
  return boreas_ray{{ox, oy, oz}, {dx, dy, dz}, max_distance};
}

bool same_object(const boreas_hit& a, const boreas_hit& b) {
  return a.kind == b.kind && a.object.index == b.object.index &&
         a.object.generation == b.object.generation && a.object.tag == b.object.tag;
}

// ---- the reference itself ----------------------------------------------------------------

TEST(EmbreeReference, SquareGivesTheAnalyticHit) {
  EmbreeWorld embree;
  // A 2 m square at y = 1 over x, z in [-1, 1], its two triangles labelled 7 and 9.
  const boreas_object_id object{3, 1, 42};
  embree.add_triangles(BOREAS_HIT_SOLID_BOX, object, {-1, 1, -1, 1, 1, -1, -1, 1, 1, 1, 1, 1},
                       {0, 1, 2, 1, 3, 2}, {7, 9});
  embree.commit();
  const boreas_ray rays[] = {
      ray(-0.5f, 5.0f, -0.3f, 0, -10, 0),       // down onto the first triangle; not unit
      ray(0.6f, -2.0f, 0.7f, 0, 1, 0),          // up onto the second, from below
      ray(-2.5f, 5.0f, 0.0f, 3, -4, 0),         // slanted: 4 m down over 5 m, to (0.5, 1, 0)
      ray(2.0f, 5.0f, 0.0f, 0, -1, 0),          // beside the square
      ray(-0.5f, 5.0f, -0.3f, 0, -1, 0, 3.9f),  // short of it
  };
  boreas_hit hits[5];
  embree.cast(rays, 5, hits);
  EXPECT_EQ(hits[0].kind, BOREAS_HIT_SOLID_BOX);
  EXPECT_NEAR(hits[0].distance, 4.0f, 1e-6f);
  EXPECT_NEAR(hits[0].point[0], -0.5f, 1e-6f);
  EXPECT_NEAR(hits[0].point[1], 1.0f, 1e-6f);
  EXPECT_EQ(hits[0].part, 7);
  EXPECT_EQ(hits[0].object.tag, 42u);
  EXPECT_FLOAT_EQ(hits[0].normal[1], 1.0f);  // faces the ray, which comes from above
  EXPECT_EQ(hits[1].part, 9);
  EXPECT_NEAR(hits[1].distance, 3.0f, 1e-6f);
  EXPECT_FLOAT_EQ(hits[1].normal[1], -1.0f);  // the same triangle seen from below
  EXPECT_NEAR(hits[2].distance, 5.0f, 1e-5f);
  EXPECT_NEAR(hits[2].point[0], 0.5f, 1e-5f);
  EXPECT_EQ(hits[2].part, 9);  // past the diagonal x + z = 0
  for (int i : {3, 4}) {
    EXPECT_EQ(hits[i].kind, BOREAS_HIT_NONE) << i;
    EXPECT_TRUE(std::isinf(hits[i].distance)) << i;
    EXPECT_EQ(hits[i].part, -1) << i;
    EXPECT_EQ(hits[i].object.tag, 0u) << i;
  }
  const EmbreeHit one = embree.cast_one(rays[2]);
  EXPECT_NEAR(one.cos_incidence, 0.8f, 1e-6f);  // |(3, -4, 0) / 5 . (0, 1, 0)|
  // (0.5, 1, 0): 0.5 / sqrt(2) m from the diagonal, 0.5 m from the edge x = 1.
  EXPECT_NEAR(one.edge_distance, 0.5f / std::sqrt(2.0f), 1e-5f);
}

// A small windy stand of two species, stepped.
std::unique_ptr<RayForest> small_forest(RayForestDef* def) {
  def->trees = 2;
  def->species = {"quaking_aspen", "black_tupelo"};
  def->templates = 1;
  def->scale = 0.5f;
  auto forest = make_ray_forest(*def);
  step(forest->world, 5);
  return forest;
}

std::vector<boreas_leaf> leaves_of(boreas_world world, boreas_tree_id tree) {
  int n = 0;
  EXPECT_EQ(boreas_tree_get_leaves(world, tree, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_leaf> leaves(static_cast<size_t>(n));
  EXPECT_EQ(boreas_tree_get_leaves(world, tree, leaves.data(), n, &n), BOREAS_OK);
  return leaves;
}

std::vector<boreas_branch> branches_of(boreas_world world, boreas_tree_id tree) {
  int n = 0;
  EXPECT_EQ(boreas_tree_get_branches(world, tree, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_branch> branches(static_cast<size_t>(n));
  EXPECT_EQ(boreas_tree_get_branches(world, tree, branches.data(), n, &n), BOREAS_OK);
  return branches;
}

// A ray kLeafGap above the blade point (u, v) of a leaf, straight down onto it. The leaves'
// quads are wider than their blades and cross their neighbours' in a dense crown: at 1 mm
// about 5 % of an aspen's rays meet a neighbour first, at 0.1 mm under 1 %.
constexpr float kLeafGap = 1e-4f;
boreas_ray onto_leaf(const boreas_leaf& leaf, float u, float v) {
  float p[3];
  leaf_quad_corner(leaf, u, v, p);
  const float* n = leaf.normal;
  return ray(p[0] + kLeafGap * n[0], p[1] + kLeafGap * n[1], p[2] + kLeafGap * n[2], -n[0], -n[1],
             -n[2]);
}

TEST(EmbreeReference, RaysOntoALeafOrABranchNameIt) {
  RayForestDef def;
  auto forest = small_forest(&def);
  EmbreeWorld embree;
  add_to_embree(*forest, &embree);
  embree.commit();
  for (size_t t = 0; t < forest->trees.size(); ++t) {
    // Every leaf's blade, from just above it.
    const std::vector<boreas_leaf> leaves = leaves_of(forest->world, forest->trees[t]);
    std::vector<boreas_ray> rays;
    for (const boreas_leaf& leaf : leaves) rays.push_back(onto_leaf(leaf, 0.5f, 0.5f));
    std::vector<boreas_hit> hits(rays.size());
    embree.cast(rays.data(), int(rays.size()), hits.data());
    int named = 0;
    for (size_t i = 0; i < hits.size(); ++i)
      if (hits[i].kind == BOREAS_HIT_LEAF && hits[i].part == int(i) &&
          hits[i].object.index == forest->trees[t].index &&
          std::fabs(hits[i].distance - kLeafGap) < 5e-6f)
        ++named;
    EXPECT_GE(named, 0.99 * double(leaves.size())) << "tree " << t << ": " << leaves.size()
                                                   << " leaves";
    // The trunk and the first level: from the middle of the curve, inside the branch, across
    // it, the branch's own wall comes first (seen from inside), nearer than its base radius
    // (the radius tapers), or the wall of a child whose base is inside it there.
    const std::vector<boreas_branch> branches = branches_of(forest->world, forest->trees[t]);
    rays.clear();
    std::vector<int> aimed_at;
    for (size_t b = 0; b < branches.size(); ++b) {
      const boreas_branch& br = branches[b];
      if (br.level > 1) continue;
      float mid[3], tangent[3];
      for (int k = 0; k < 3; ++k) {
        const float(*p)[3] = br.control_points;
        mid[k] = 0.125f * (p[0][k] + 3.0f * p[1][k] + 3.0f * p[2][k] + p[3][k]);
        tangent[k] = p[3][k] + p[2][k] - p[1][k] - p[0][k];
      }
      // Across the curve: the tangent crossed with the horizontal axis least along it.
      const float axis[3] = {std::fabs(tangent[0]) < std::fabs(tangent[2]) ? 1.0f : 0.0f, 0.0f,
                             std::fabs(tangent[0]) < std::fabs(tangent[2]) ? 0.0f : 1.0f};
      const float across[3] = {tangent[1] * axis[2] - tangent[2] * axis[1],
                         tangent[2] * axis[0] - tangent[0] * axis[2],
                         tangent[0] * axis[1] - tangent[1] * axis[0]};
      rays.push_back(ray(mid[0], mid[1], mid[2], across[0], across[1], across[2],
                         2.0f * br.radius));
      aimed_at.push_back(int(b));
    }
    hits.resize(rays.size());
    embree.cast(rays.data(), int(rays.size()), hits.data());
    int on_branch = 0;
    for (size_t i = 0; i < hits.size(); ++i) {
      const boreas_hit& h = hits[i];
      on_branch += h.kind == BOREAS_HIT_BRANCH && h.object.index == forest->trees[t].index &&
                   (h.part == aimed_at[i] || branches[size_t(h.part)].parent == aimed_at[i]) &&
                   h.distance <= branches[size_t(aimed_at[i])].radius;
    }
    EXPECT_GE(on_branch, 0.95 * double(rays.size())) << "tree " << t << ": " << rays.size()
                                                    << " branches of levels 0 and 1";
  }
}

TEST(EmbreeReference, MeadowStripsNameTheirComponent) {
  RayForestDef def;
  def.trees = 0;
  def.components = 2000;
  auto forest = make_ray_forest(def);
  step(forest->world, 5);
  EmbreeWorld embree;
  add_to_embree(*forest, &embree);
  embree.commit();
  int vertex_count = 0;
  ASSERT_EQ(boreas_meadow_get_vertices(forest->world, forest->meadow, nullptr, nullptr, 0,
                                       &vertex_count, nullptr),
            BOREAS_OK);
  std::vector<boreas_meadow_vertex> v(static_cast<size_t>(vertex_count));
  std::vector<int32_t> counts(size_t(vertex_count / BOREAS_MEADOW_VERTEX_STRIDE));
  ASSERT_EQ(boreas_meadow_get_vertices(forest->world, forest->meadow, nullptr, v.data(),
                                       vertex_count, &vertex_count, counts.data()),
            BOREAS_OK);
  // A ray 0.1 mm off the middle of each component's first quad, along its normal.
  std::vector<boreas_ray> rays;
  for (size_t c = 0; c < counts.size(); ++c) {
    ASSERT_GE(counts[c], 4) << "component " << c;
    const boreas_meadow_vertex* q = &v[c * BOREAS_MEADOW_VERTEX_STRIDE];
    float mid[3];
    for (int k = 0; k < 3; ++k)
      mid[k] = 0.25f * (q[0].position[k] + q[1].position[k] + q[2].position[k] + q[3].position[k]);
    const float* n = q[0].normal;
    rays.push_back(ray(mid[0] + 1e-4f * n[0], mid[1] + 1e-4f * n[1], mid[2] + 1e-4f * n[2], -n[0],
                       -n[1], -n[2], 1e-2f));
  }
  std::vector<boreas_hit> hits(rays.size());
  embree.cast(rays.data(), int(rays.size()), hits.data());
  int named = 0;
  for (size_t c = 0; c < hits.size(); ++c)
    named += hits[c].kind == BOREAS_HIT_UNDERBRUSH && hits[c].part == int(c);
  EXPECT_GE(named, 0.99 * double(hits.size()));
}

TEST(EmbreeReference, LeafOutlineFilterDropsHitsOutsideIt) {
  RayForestDef def;
  auto forest = small_forest(&def);
  EmbreeWorld embree;
  add_to_embree(*forest, &embree);
  // An outline that keeps only the right half of every blade (u > 0.5).
  embree.set_leaf_outline([](int32_t, float u, float) { return u > 0.5f; });
  embree.commit();
  const std::vector<boreas_leaf> leaves = leaves_of(forest->world, forest->trees[0]);
  std::vector<boreas_ray> rays;
  for (const boreas_leaf& leaf : leaves) {
    rays.push_back(onto_leaf(leaf, 0.25f, 0.3f));  // on the left half
    rays.push_back(onto_leaf(leaf, 0.75f, 0.8f));  // on the right half, the second triangle
  }
  std::vector<boreas_hit> hits(rays.size());
  embree.cast(rays.data(), int(rays.size()), hits.data());
  int left = 0, right = 0;
  for (size_t i = 0; i < leaves.size(); ++i) {
    const boreas_hit& l = hits[2 * i];
    left += l.kind == BOREAS_HIT_LEAF && l.part == int(i) && l.object.index == forest->trees[0].index;
    const boreas_hit& r = hits[2 * i + 1];
    right += r.kind == BOREAS_HIT_LEAF && r.part == int(i) && r.object.index == forest->trees[0].index;
    const EmbreeHit one = embree.cast_one(rays[2 * i + 1]);
    if (one.hit.part == int(i) && one.hit.kind == BOREAS_HIT_LEAF) {
      EXPECT_NEAR(one.leaf_uv[0], 0.75f, 1e-3f) << "leaf " << i;
      EXPECT_NEAR(one.leaf_uv[1], 0.8f, 1e-3f) << "leaf " << i;
    }
  }
  EXPECT_EQ(left, 0);
  EXPECT_GE(right, 0.99 * double(leaves.size()));
}

// After steps, refitting or rebuilding gives what a scene built afresh from the same state
// gives, and the hits have moved with the wind.
TEST(EmbreeReference, RefitAndRebuildFollowTheStep) {
  RayForestDef def;
  def.components = 3000;
  auto forest = small_forest(&def);
  EmbreeWorld refit(EmbreeOptions{EmbreeUpdate::kRefit});
  EmbreeWorld rebuild(EmbreeOptions{EmbreeUpdate::kRebuild});
  add_to_embree(*forest, &refit);
  add_to_embree(*forest, &rebuild);
  refit.commit();
  rebuild.commit();
  const std::vector<boreas_ray> rays = forest_rays(*forest, 20000, 7);
  std::vector<boreas_hit> before(rays.size()), after_refit(rays.size()),
      after_rebuild(rays.size()), fresh_hits(rays.size());
  rebuild.cast(rays.data(), int(rays.size()), before.data());
  step(forest->world, 30);
  refit.update(forest->world);
  rebuild.update(forest->world);
  EmbreeWorld fresh;
  add_to_embree(*forest, &fresh);
  fresh.commit();
  refit.cast(rays.data(), int(rays.size()), after_refit.data());
  rebuild.cast(rays.data(), int(rays.size()), after_rebuild.data());
  fresh.cast(rays.data(), int(rays.size()), fresh_hits.data());
  // The same hit as a fresh scene's, part for part; where two surfaces lie at the same
  // distance (a leaf against a twig, a shared edge) a hierarchy's order may pick either:
  // then the distance alone must agree (Embree's SIMD paths differ between CPUs).
  int moved = 0, hit = 0, ties = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    for (const boreas_hit* h : {&after_refit[i], &after_rebuild[i]}) {
      ASSERT_EQ(h->kind == BOREAS_HIT_NONE, fresh_hits[i].kind == BOREAS_HIT_NONE) << "ray " << i;
      if (h->kind == BOREAS_HIT_NONE) continue;
      ASSERT_NEAR(h->distance, fresh_hits[i].distance, 1e-5f) << "ray " << i;
      ties += !(same_object(*h, fresh_hits[i]) && h->part == fresh_hits[i].part);
    }
    hit += fresh_hits[i].kind != BOREAS_HIT_NONE;
    moved += !same_object(before[i], fresh_hits[i]) ||
             std::fabs(before[i].distance - fresh_hits[i].distance) > 1e-3f;
  }
  EXPECT_LE(ties, int(rays.size()) / 1000);
  EXPECT_GT(hit, int(rays.size()) / 2);
  EXPECT_GT(moved, int(rays.size()) / 20) << "half a second of wind moved few hits";
}

// ---- boreas against the reference --------------------------------------------------------

// Why a ray's two answers differ, from the reference's view of it (the first that fits).
enum class Cause { kGrazing, kLeafOutline, kLeafMargin, kEdge, kTie, kOther };
constexpr int kCauses = 6;
const char* const kCauseNames[] = {"grazing (|cos| < 0.01, or < 0.1 within 2 mm)",
                                   "near a leaf quad's border",
                                   "on a leaf outline's margin (< 10 um)",
                                   "near a triangle edge (< 0.1 mm)",
                                   "two surfaces within 1 mm (tie)", "other"};

// How far (m, across the blade) the ray's crossing of a leaf's plane lies from the leaf's
// outline (cl/shared/leaf_outline.h, in double but for the outline's own float math): a
// ray through a margin within rounding may be inside for one tracer and outside for the
// other. Infinity when the crossing is off the quad or the ray parallel to the leaf.
double outline_margin(const boreas_leaf& leaf, const boreas_ray& r, int outline) {
  const float *a = leaf.axis, *n = leaf.normal;
  double len = 0.0, denom = 0.0, towards = 0.0;
  for (int k = 0; k < 3; ++k) len += double(r.direction[k]) * r.direction[k];
  len = std::sqrt(len);
  for (int k = 0; k < 3; ++k) {
    denom += r.direction[k] / len * n[k];
    towards += (double(leaf.position[k]) - r.origin[k]) * n[k];
  }
  if (denom == 0.0) return INFINITY;
  const double t = towards / denom;
  const double across[3] = {double(a[1]) * n[2] - double(a[2]) * n[1],
                            double(a[2]) * n[0] - double(a[0]) * n[2],
                            double(a[0]) * n[1] - double(a[1]) * n[0]};
  double along = 0.0, side = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double rel = r.origin[k] + r.direction[k] / len * t - leaf.position[k];
    along += rel * a[k];
    side += rel * across[k];
  }
  float u = 0.0f, v = 0.0f;
  boreas_leaf_uv(float(along), float(side), leaf.length, leaf.width, &u, &v);
  if (u < 0.0f || u > 1.0f || v < 0.0f || v > 1.0f) return INFINITY;
  const BoreasLeafOutline* o = &boreas_leaf_outlines[outline];
  const float ax = std::fabs(u - 0.5f);
  const float start = boreas_leaf_blade_start_v(o, ax);
  const float h = boreas_leaf_half_width(o, (v - start) / (BOREAS_LEAF_BLADE_TIP_V - start));
  return std::fabs(double(ax) - double(h)) * leaf.width / (2.0 * BOREAS_LEAF_BLADE_HALF_WIDTH);
}

// The forest's trees' leaves and outline kinds, to judge rays at a leaf's margin.
struct ForestLeaves {
  std::vector<std::vector<boreas_leaf>> leaves;
  std::vector<int> outline;
  const RayForest* forest;
  explicit ForestLeaves(const RayForest& f) : forest(&f) {
    for (size_t t = 0; t < f.trees.size(); ++t) {
      leaves.push_back(leaves_of(f.world, f.trees[t]));
      outline.push_back(int(boreas_species_leaf_outline(f.tree_defs[t].species)) - 1);
    }
  }
  // The margin distance of the ray at the leaf a hit names (infinity for another kind).
  double margin(const boreas_hit& h, const boreas_ray& r) const {
    if (h.kind != BOREAS_HIT_LEAF) return INFINITY;
    for (size_t t = 0; t < forest->trees.size(); ++t)
      if (forest->trees[t].index == h.object.index)
        return outline_margin(leaves[t][size_t(h.part)], r, outline[t]);
    return INFINITY;
  }
};

double cos_of(const float normal[3], const boreas_ray& r) {
  const double len = std::sqrt(double(r.direction[0]) * r.direction[0] +
                               double(r.direction[1]) * r.direction[1] +
                               double(r.direction[2]) * r.direction[2]);
  return std::fabs((normal[0] * r.direction[0] + normal[1] * r.direction[1] +
                    normal[2] * r.direction[2]) / len);
}

// A triangle met at a small |cos| c from far away has a float distance that cancels in
// Moller and Trumbore's formula (terms of |origin - vertex| |edge| for a result of t det,
// det shrinking with c): measured 1.4 mm off at c = 0.05 from 16 m on the device (0.13 mm
// in the host's float), enough to put the next triangle of a branch's ring first.
Cause cause_of(const boreas_hit& mine, const EmbreeHit& ref, const boreas_ray& r,
               const ForestLeaves& leaves) {
  const double cos_mine = mine.kind != BOREAS_HIT_NONE ? cos_of(mine.normal, r) : 1.0;
  const double cos_ref = ref.hit.kind != BOREAS_HIT_NONE ? double(ref.cos_incidence) : 1.0;
  const double cos_min = std::min(cos_mine, cos_ref);
  const bool both = mine.kind != BOREAS_HIT_NONE && ref.hit.kind != BOREAS_HIT_NONE;
  if (cos_min < 0.01 ||
      (cos_min < 0.1 && both && std::fabs(mine.distance - ref.hit.distance) <= 2e-3f))
    return Cause::kGrazing;
  const float border = std::fmin(std::fmin(ref.leaf_uv[0], 1.0f - ref.leaf_uv[0]),
                                 std::fmin(ref.leaf_uv[1], 1.0f - ref.leaf_uv[1]));
  if (ref.hit.kind == BOREAS_HIT_LEAF && border < 0.01f) return Cause::kLeafOutline;
  if (std::min(leaves.margin(mine, r), leaves.margin(ref.hit, r)) < 1e-5)
    return Cause::kLeafMargin;
  if (mine.kind == BOREAS_HIT_LEAF && ref.hit.kind != BOREAS_HIT_LEAF) return Cause::kLeafOutline;
  if (ref.hit.kind != BOREAS_HIT_NONE && ref.edge_distance < 1e-4f) return Cause::kEdge;
  if (both && std::fabs(mine.distance - ref.hit.distance) <= 1e-3f) return Cause::kTie;
  return Cause::kOther;
}

TEST(RaysEmbree, AgreeOnAWindyForest) {
  test::TempDir dir;
  RayForestDef def;
  def.trees = 6;  // aspen, tupelo, oak, twice each, two seeds
  def.components = 20000;
  def.mesh_tree_models = {test::write_tube_tree_obj(dir.path())};
  auto forest = make_ray_forest(def);
  step(forest->world, 10);
  const std::vector<boreas_ray> rays = forest_rays(*forest, 100000, 37);
  std::vector<boreas_hit> mine(rays.size());
  ASSERT_EQ(boreas_world_cast_rays(forest->world, rays.data(), int(rays.size()), mine.data()),
            BOREAS_OK)
      << boreas_last_error();
  // The ground as boreas's height grid, so that ground hits compare their triangle too.
  EmbreeWorld embree;
  add_to_embree(*forest, &embree, /*flat_ground=*/false);
  add_ground_grid(forest->world, forest->meadow, &embree);
  embree.commit();
  int64_t agree = 0, both_hit = 0, ref_hits = 0;
  int64_t by_cause[kCauses] = {};
  const ForestLeaves leaves(*forest);
  std::vector<std::string> others;  // each disagreement, with its cause
  for (size_t i = 0; i < rays.size(); ++i) {
    const EmbreeHit ref = embree.cast_one(rays[i]);
    ref_hits += ref.hit.kind != BOREAS_HIT_NONE;
    const bool hit = mine[i].kind != BOREAS_HIT_NONE && ref.hit.kind != BOREAS_HIT_NONE;
    both_hit += hit;
    if (same_object(mine[i], ref.hit) && mine[i].part == ref.hit.part &&
        (!hit || std::fabs(mine[i].distance - ref.hit.distance) <= 1e-3f)) {
      ++agree;
      continue;
    }
    const Cause c = cause_of(mine[i], ref, rays[i], leaves);
    ++by_cause[int(c)];
    if (others.size() < 20) {
      char line[300];
      std::snprintf(line, sizeof line,
                    "ray %zu (%s): boreas kind %d part %d at %.5f m, Embree kind %d part %d at "
                    "%.5f m, |cos| %.3f, %.1e m from an edge",
                    i, kCauseNames[int(c)], mine[i].kind, mine[i].part, double(mine[i].distance),
                    ref.hit.kind, ref.hit.part, double(ref.hit.distance),
                    double(ref.cos_incidence), double(ref.edge_distance));
      others.push_back(line);
    }
  }
  const double n = double(rays.size());
  std::printf("Rays vs Embree: %zu rays, %lld hit in Embree, %lld hit in both, %.4f %% agree "
              "(same kind, object and part, distance within 1 mm)\n",
              rays.size(), (long long)ref_hits, (long long)both_hit, 100.0 * double(agree) / n);
  for (int c = 0; c < kCauses; ++c)
    std::printf("  %-44s %lld\n", kCauseNames[c], (long long)by_cause[c]);
  for (const std::string& o : others) std::printf("  %s\n", o.c_str());
  EXPECT_GT(double(ref_hits), 0.5 * n) << "the rays were meant to hit mostly";
  EXPECT_GE(double(agree), 0.999 * n);
  // Every disagreement is one of the rounding cases above (README, "Checked against
  // Embree"): a ray of no known cause is a difference in what the two see.
  EXPECT_EQ(by_cause[int(Cause::kOther)], 0);
}

}  // namespace
}  // namespace boreas::reference
