// boreas benchmarks: print_carry_detach (boreas_bench --boreas_carry_detach), how far the
// levels of detail let a branch's base drift off its parent's curve, in the forest of
// BM_ForestStep/mixed/1000, as a Markdown table: what carrying branches every 4th or 8th
// step costs the eye (trees/tree_tiles.h), beside the one-step lag of the lagged step.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "bench_forest.h"
#include "benchmarks.h"
#include "trees/tree_model.h"
#include "trees/tree_tiles.h"

namespace boreas::bench {

namespace {

struct Vec {
  double x, y, z;
};

Vec point(const float (&p)[3]) { return {p[0], p[1], p[2]}; }
double distance(Vec a, Vec b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }

// The branch's curve at u (a cubic Bezier over its control points), in double.
Vec bezier(const boreas_branch& b, double u) {
  const double w = 1.0 - u;
  const double c[4] = {w * w * w, 3.0 * u * w * w, 3.0 * u * u * w, u * u * u};
  Vec r{0.0, 0.0, 0.0};
  for (int k = 0; k < 4; ++k) {
    r.x += c[k] * b.control_points[k][0];
    r.y += c[k] * b.control_points[k][1];
    r.z += c[k] * b.control_points[k][2];
  }
  return r;
}

// Largest and root-mean-square drift of one group of branches, in m and in pixels.
struct Drift {
  int64_t samples = 0;
  double max_m = 0.0, sum2_m = 0.0, max_px = 0.0, sum2_px = 0.0;
  void add(double m, double px) {
    ++samples;
    max_m = std::max(max_m, m);
    sum2_m += m * m;
    max_px = std::max(max_px, m / px);
    sum2_px += (m / px) * (m / px);
  }
};

// The levels a tree of `levels` levels steps at a level of detail (the rest are carried).
int stepped_levels(int levels, int lod) {
  impl::TreeModel m;
  m.levels = levels;
  return impl::stepped_levels(m, static_cast<impl::TreeLod>(lod));
}

}  // namespace

int print_carry_detach(int steps) {
  try {
    constexpr int kTrees = 1000;
    constexpr int kPerBand = 6;
    const std::vector<const char*> mixed{"quaking_aspen", "black_tupelo", "ca_black_oak"};
    WorldHandle w{make_forest_world(std::sqrt(float(kTrees)) * kTreeSpacing)};
    const std::vector<boreas_tree_def> defs = forest_defs(kTrees, 20, mixed);
    std::vector<boreas_tree_id> ids(defs.size());
    check(boreas_world_add_trees(w.world, defs.data(), kTrees, ids.data()));
    const Vec eye{0.0, 1.8, 0.0};
    const float focus[3] = {0.0f, 1.8f, 0.0f};
    check(boreas_world_set_focus(w.world, focus, 1));
    // Trees by level of detail from their bases' distances (the defaults of
    // boreas_tree_def), kPerBand of each spread through the band.
    const boreas_tree_def d = boreas_default_tree_def();
    std::vector<std::vector<int>> bands(3);
    for (int i = 0; i < kTrees; ++i) {
      const double r = distance(eye, {defs[size_t(i)].position[0], defs[size_t(i)].position[1],
                                      defs[size_t(i)].position[2]});
      const int lod = r < d.lod_distances[0]   ? 0
                      : r < d.lod_distances[1] ? 1
                      : r < d.lod_distances[2] ? 2
                                               : 3;
      if (lod < 3) bands[size_t(lod)].push_back(i);
    }
    for (int s = 0; s < 200; ++s) check(boreas_world_step(w.world, kForestDt));
    // [lod][carried]
    Drift drift[3][2];
    int trees[3] = {};
    std::vector<boreas_branch> branches;
    for (int s = 0; s < steps; ++s) {
      check(boreas_world_step(w.world, kForestDt));
      for (int lod = 0; lod < 3; ++lod) {
        const std::vector<int>& band = bands[size_t(lod)];
        const int take = std::min<int>(kPerBand, int(band.size()));
        trees[lod] = take;
        for (int t = 0; t < take; ++t) {
          const boreas_tree_id id = ids[size_t(band[size_t(t) * band.size() / size_t(take)])];
          int count = 0;
          check(boreas_tree_get_branches(w.world, id, nullptr, 0, &count));
          branches.resize(size_t(count));
          check(boreas_tree_get_branches(w.world, id, branches.data(), count, &count));
          int levels = 0;
          for (const boreas_branch& b : branches) levels = std::max(levels, b.level + 1);
          const int stepped = stepped_levels(levels, lod);
          for (const boreas_branch& b : branches) {
            if (b.parent < 0) continue;
            const Vec base = point(b.control_points[0]);
            const Vec on_parent = bezier(branches[size_t(b.parent)], double(b.parent_v));
            // One pixel at the branch's distance: a 1080-row view 60 degrees high.
            const double px = 2.0 * distance(eye, base) * std::tan(0.5236) / 1080.0;
            drift[lod][b.level >= stepped ? 1 : 0].add(distance(base, on_parent), px);
          }
        }
      }
    }
    std::printf("| level of detail | trees | branches | how updated | largest drift | RMS drift | "
                "largest, pixels | RMS, pixels |\n|---|---|---|---|---|---|---|---|\n");
    const char* names[3] = {"full", "reduced", "far"};
    for (int lod = 0; lod < 3; ++lod)
      for (int carried = 0; carried < 2; ++carried) {
        const Drift& g = drift[lod][carried];
        if (g.samples == 0) continue;
        const double n = double(g.samples);
        const std::string how =
            carried ? "carried every " +
                          std::to_string(impl::carry_rate(static_cast<impl::TreeLod>(lod))) +
                          " steps"
                    : "stepped (lagged: on the parent's last pose)";
        std::printf("| %s | %d | %lld a step | %s | %.2f cm | %.2f cm | %.2f | %.3f |\n",
                    names[lod], trees[lod], static_cast<long long>(g.samples / steps), how.c_str(),
                    100.0 * g.max_m, 100.0 * std::sqrt(g.sum2_m / n), g.max_px,
                    std::sqrt(g.sum2_px / n));
      }
    std::printf("\n%d steps of 1/60 s after 200 of warm-up; drift: the distance from a branch's "
                "base to the point of its parent's curve it belongs at; pixels of a 1080-row, "
                "60-degree view from the focus.\n", steps);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "boreas_carry_detach: %s\n", e.what());
    return 1;
  }
}

}  // namespace boreas::bench
