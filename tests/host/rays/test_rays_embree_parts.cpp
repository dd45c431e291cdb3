// boreas tests: boreas_world_cast_rays against Embree part for part on every kind of
// surface a ray can hit (issue 37, "Reference"): generated trees (branch, leaf), an
// imported tree (its trunk's and leaves' triangle indices), a BlobTree (its mesh's
// triangle), a meadow's components (the component) over ground with relief (the
// triangle of its height grid, built here from the meadow's own height field) and a solid
// box of the wind grid (its index). Rays are aimed at each kind's own surfaces, so every
// kind is hit often; a ray agrees when kind, object, part and distance (1 mm) agree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
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

void ok(boreas_status s) { ASSERT_EQ(s, BOREAS_OK) << boreas_last_error(); }


// Triangles of one surface kind, for rays to be aimed at (3 floats a vertex).
struct Targets {
  const char* name;
  std::vector<float> positions;
  std::vector<uint32_t> indices;
};

// The box [lo, hi]: its 8 corners (corner c at hi along axis k where bit k of c is set),
// two triangles a face.
Targets box_of(const float lo[3], const float hi[3]) {
  Targets out{"solid box", {}, {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                                2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3}};
  for (int c = 0; c < 8; ++c)
    out.positions.insert(out.positions.end(),
                         {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]});
  return out;
}

Targets mesh_part(boreas_world w, boreas_mesh_tree_id t, boreas_mesh_part part, const char* name) {
  Targets out{name, {}, {}};
  int n = 0;
  EXPECT_EQ(boreas_mesh_tree_get_vertices(w, t, part, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_vertex> v(static_cast<size_t>(n));
  EXPECT_EQ(boreas_mesh_tree_get_vertices(w, t, part, v.data(), n, &n), BOREAS_OK);
  for (const boreas_vertex& x : v) out.positions.insert(out.positions.end(), x.position, x.position + 3);
  EXPECT_EQ(boreas_mesh_tree_get_indices(w, t, part, nullptr, 0, &n), BOREAS_OK);
  out.indices.resize(size_t(n));
  EXPECT_EQ(boreas_mesh_tree_get_indices(w, t, part, out.indices.data(), n, &n), BOREAS_OK);
  return out;
}

Targets blob_mesh(boreas_world w, boreas_blobtree_id b) {
  Targets out{"BlobTree", {}, {}};
  int nv = 0, ni = 0;
  EXPECT_EQ(boreas_blobtree_get_mesh(w, b, nullptr, 0, &nv, nullptr, 0, &ni), BOREAS_OK);
  std::vector<boreas_vertex> v(static_cast<size_t>(nv));
  out.indices.resize(size_t(ni));
  EXPECT_EQ(boreas_blobtree_get_mesh(w, b, v.data(), nv, &nv, out.indices.data(), ni, &ni),
            BOREAS_OK);
  for (const boreas_vertex& x : v) out.positions.insert(out.positions.end(), x.position, x.position + 3);
  return out;
}

Targets meadow_strips(boreas_world w, boreas_meadow_id m) {
  Targets out{"underbrush", {}, {}};
  int n = 0;
  EXPECT_EQ(boreas_meadow_get_vertices(w, m, nullptr, nullptr, 0, &n, nullptr), BOREAS_OK);
  std::vector<boreas_meadow_vertex> v(static_cast<size_t>(n));
  std::vector<int32_t> counts(size_t(n / BOREAS_MEADOW_VERTEX_STRIDE));
  EXPECT_EQ(boreas_meadow_get_vertices(w, m, nullptr, v.data(), n, &n, counts.data()), BOREAS_OK);
  for (const boreas_meadow_vertex& x : v)
    out.positions.insert(out.positions.end(), x.position, x.position + 3);
  for (size_t c = 0; c < counts.size(); ++c)
    for (int k = 0; k + 2 < counts[c]; ++k) {
      const uint32_t first = uint32_t(c * BOREAS_MEADOW_VERTEX_STRIDE + size_t(k));
      out.indices.insert(out.indices.end(), {first, first + 1, first + 2});
    }
  return out;
}

// `count` rays from random points up to 6 m away at random points of random triangles.
void aim_at(const Targets& t, int count, std::mt19937_64& rng, std::vector<boreas_ray>* rays) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss;
  const size_t triangles = t.indices.size() / 3;
  ASSERT_GT(triangles, 0u) << t.name;
  for (int i = 0; i < count; ++i) {
    const uint32_t* tri = &t.indices[3 * size_t(rng() % triangles)];
    float a = unit(rng), b = unit(rng);
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    boreas_ray r{};
    float len = 0.0f, off[3];
    for (int k = 0; k < 3; ++k) len += (off[k] = gauss(rng)) * off[k];
    len = std::sqrt(len);
    const float reach = 0.5f + 5.5f * unit(rng);
    for (int k = 0; k < 3; ++k) {
      const float p = t.positions[3 * tri[0] + k] +
                      a * (t.positions[3 * tri[1] + k] - t.positions[3 * tri[0] + k]) +
                      b * (t.positions[3 * tri[2] + k] - t.positions[3 * tri[0] + k]);
      r.origin[k] = p + reach * off[k] / len;
      r.direction[k] = p - r.origin[k];
    }
    r.max_distance = 2.0f * reach;
    rays->push_back(r);
  }
}

// |cos| between a hit's normal and its ray.
double facing_cos(const boreas_hit& h, const boreas_ray& r) {
  double dn = 0.0, dd = 0.0;
  for (int k = 0; k < 3; ++k) {
    dn += double(h.normal[k]) * r.direction[k];
    dd += double(r.direction[k]) * r.direction[k];
  }
  return std::fabs(dn) / std::sqrt(dd);
}

bool same_part(const boreas_hit& a, const boreas_hit& b) {
  return a.kind == b.kind && a.object.index == b.object.index &&
         a.object.generation == b.object.generation && a.object.tag == b.object.tag &&
         a.part == b.part;
}

TEST(RaysEmbree, EveryKindsPartsAgreeWithTheReference) {
  test::TempDir dir;
  RayForestDef def;
  def.trees = 2;
  def.species = {"quaking_aspen", "black_tupelo"};
  def.templates = 1;
  def.scale = 0.5f;
  def.mesh_tree_models = {test::write_tube_tree_obj(dir.path())};
  auto forest = make_ray_forest(def);
  boreas_world w = forest->world;
  // A meadow over rolling ground, a BlobTree of a tree added for it (and removed: the
  // BlobTree keeps its mesh) and a solid box, each beside the stand.
  boreas_meadow_def m = boreas_default_meadow_def();
  m.size[0] = m.size[1] = 2.0f * forest->half_extent;
  m.density = 40.0f;
  m.terrain_relief = 1.5f;
  boreas_meadow_id meadow{};
  ok(boreas_world_add_meadow(w, &m, &meadow));
  boreas_tree_def t = boreas_default_tree_def();
  t.species = "quaking_aspen";
  t.scale = 0.4f;
  t.position[0] = -forest->half_extent - 4.0f;
  boreas_tree_id for_blob{};
  ok(boreas_world_add_tree(w, &t, &for_blob));
  boreas_blobtree_def bd = boreas_default_blobtree_def();
  bd.resolution = 64;
  boreas_blobtree_id blob{};
  ok(boreas_world_add_blobtree(w, for_blob, &bd, nullptr, nullptr, &blob));
  ok(boreas_world_remove_tree(w, for_blob));
  const float lo[3] = {-2.0f, 0.0f, forest->half_extent + 1.0f};
  const float hi[3] = {2.0f, 2.5f, forest->half_extent + 2.0f};
  ok(boreas_wind_add_solid_box(w, lo, hi));
  for (int s = 0; s < 10; ++s) ok(boreas_world_step(w, 1.0f / 60.0f));

  EmbreeWorld embree;
  add_to_embree(*forest, &embree);  // the trees and the imported tree
  embree.add_meadow(w, meadow);
  add_ground_grid(w, meadow, &embree);
  embree.add_blobtree(w, blob);
  const Targets box = box_of(lo, hi);
  // A solid box's object is null and its part its index among the boxes (the first: 0).
  embree.add_triangles(BOREAS_HIT_SOLID_BOX, {0, 0, 0}, box.positions, box.indices,
                       std::vector<int32_t>(box.indices.size() / 3, 0));
  embree.commit();

  // Rays at every kind: the stand's leaves and branches, then each other surface.
  std::vector<boreas_ray> rays = forest_rays(*forest, 6000, 3);
  std::mt19937_64 rng(37);
  const boreas_mesh_tree_id mesh = forest->mesh_trees[0];
  aim_at(mesh_part(w, mesh, BOREAS_MESH_TRUNK, "mesh trunk"), 3000, rng, &rays);
  aim_at(mesh_part(w, mesh, BOREAS_MESH_LEAVES, "mesh leaves"), 3000, rng, &rays);
  aim_at(blob_mesh(w, blob), 3000, rng, &rays);
  aim_at(meadow_strips(w, meadow), 3000, rng, &rays);
  aim_at(box, 1000, rng, &rays);
  // The ground: from above, at random points of the meadow.
  std::uniform_real_distribution<float> across(-forest->half_extent, forest->half_extent);
  for (int i = 0; i < 3000; ++i)
    rays.push_back({{across(rng), 6.0f, across(rng)}, {0.3f * (i % 3 - 1), -1.0f, 0.2f}, INFINITY});

  // A ray from inside a solid box sees nothing of it (boreas.h: a sensor inside a wall),
  // where Embree's triangles would show the wall's inner face: such rays are left out.
  std::vector<boreas_ray> outside;
  for (const boreas_ray& r : rays) {
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside = inside && r.origin[k] > lo[k] && r.origin[k] < hi[k];
    if (!inside) outside.push_back(r);
  }
  rays.swap(outside);
  std::vector<boreas_hit> mine(rays.size()), ref(rays.size());
  ok(boreas_world_cast_rays(w, rays.data(), int(rays.size()), mine.data()));
  embree.cast(rays.data(), int(rays.size()), ref.data());
  int agree[9] = {}, seen[9] = {}, unexplained = 0;
  std::vector<std::string> report;
  for (size_t i = 0; i < rays.size(); ++i) {
    ++seen[ref[i].kind];
    const bool hit = ref[i].kind != BOREAS_HIT_NONE;
    if (same_part(mine[i], ref[i]) &&
        (!hit || std::fabs(mine[i].distance - ref[i].distance) <= 1e-3f)) {
      ++agree[ref[i].kind];
      continue;
    }
    // A disagreement must be a ray at an edge or grazing a surface, where rounding decides.
    const EmbreeHit one = embree.cast_one(rays[i]);
    const double cos_mine = mine[i].kind == BOREAS_HIT_NONE ? 1.0 : facing_cos(mine[i], rays[i]);
    const bool rounding = (hit && (one.cos_incidence < 0.05f || one.edge_distance < 1e-5f)) ||
                          cos_mine < 0.05;
    unexplained += !rounding;
    if (report.size() < 12) {
      char line[240];
      std::snprintf(line, sizeof line,
                    "ray %zu: boreas kind %d part %d at %.5f m, Embree kind %d part %d at %.5f m "
                    "(|cos| %.3f, %.1e m from an edge)",
                    i, mine[i].kind, mine[i].part, double(mine[i].distance), ref[i].kind,
                    ref[i].part, double(ref[i].distance), double(one.cos_incidence),
                    double(one.edge_distance));
      report.push_back(line);
    }
  }
  const char* const names[9] = {"none", "branch", "leaf", "mesh trunk", "mesh leaf",
                                "underbrush", "BlobTree", "ground", "solid box"};
  for (int k = 0; k < 9; ++k)
    std::printf("  %-11s %6d rays (Embree's kind), %6d agree part for part\n", names[k], seen[k],
                agree[k]);
  for (const std::string& r : report) std::printf("  %s\n", r.c_str());
  EXPECT_EQ(unexplained, 0) << "disagreements neither at an edge nor grazing";
  for (int k = BOREAS_HIT_BRANCH; k <= BOREAS_HIT_SOLID_BOX; ++k) {
    EXPECT_GT(seen[k], 100) << names[k] << ": the rays were aimed to hit it";
    EXPECT_GE(double(agree[k]), 0.995 * double(seen[k])) << names[k];
  }
}

}  // namespace
}  // namespace boreas::reference
