// boreas benchmarks: print_tree_wind_point (boreas_bench --boreas_wind_point), where a trunk
// should sample the wind: cl/tree_step.cl takes the drag on the wind at the branch's tip,
// drag |u| u R, as the load of the whole crown it carries. Here, in a world with the
// default wave (sharpness 2, 20 m) and gusts through its grid (whole-grid ones every 4 s
// and a local one 8 m across), the crown's load is summed leaf by leaf, sum |u_i| u_i over
// its leaves (the drag where it acts; Vogel's factor left out, it scales all three alike),
// and set against N |u| u at the trunk's tip, at the leaves' centroid (the center of the
// load), and averaged over four points along the trunk's curve (t = 1/4 .. 1). Printed: the time-mean and RMS of the difference in the load's along-wind part
// (what bends the trunk, in a quasi-static step in proportion), relative to the mean load.
// The wind comes from boreas_wind_sample (the device's float), the sums are in double.
#include <cmath>
#include <cstdio>
#include <vector>

#include "benchmarks.h"
#include "boreas/boreas.h"

namespace boreas::bench {

namespace {

struct Load {
  double x = 0.0, z = 0.0;
};

Load drag_of(const float* u, double weight) {
  const double s = std::sqrt(double(u[0]) * u[0] + double(u[1]) * u[1] + double(u[2]) * u[2]);
  return {weight * s * u[0], weight * s * u[2]};
}

bool ok(boreas_status s, const char* what) {
  if (s == BOREAS_OK) return true;
  std::fprintf(stderr, "%s: %s\n", what, boreas_last_error());
  return false;
}

}  // namespace

int print_tree_wind_point(int steps) {
  std::printf("| species | height m | leaves | load at tip: mean, RMS | at load center: mean, RMS | "
              "along the trunk: mean, RMS |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const char* species : {"quaking_aspen", "ca_black_oak", "black_tupelo"}) {
    boreas_world_def def = boreas_default_world_def();
    boreas_wave wave = boreas_default_wave();
    def.waves = &wave;
    def.wave_count = 1;
    boreas_world world = nullptr;
    if (!ok(boreas_world_create(&def, &world), "world")) return 1;
    for (int k = 0; k < steps / 120 + 1; ++k) {  // a whole-grid gust every 4 s
      boreas_gust_def g = boreas_default_gust_def();
      g.delay = 4.0f * float(k);
      if (!ok(boreas_wind_add_gust(world, &g, nullptr), "gust")) return 1;
      g.radius = 4.0f;  // and a local one, 8 m across, beside the crown
      g.center[0] = 3.0f;
      g.center[1] = 8.0f;
      g.delay += 2.0f;
      g.strength = 6.0f;
      if (!ok(boreas_wind_add_gust(world, &g, nullptr), "gust")) return 1;
    }
    boreas_tree_def t = boreas_default_tree_def();
    t.species = species;
    boreas_tree_id tree;
    if (!ok(boreas_world_add_tree(world, &t, &tree), species)) return 1;
    int branch_count = 0, leaf_count = 0;
    boreas_tree_get_branches(world, tree, nullptr, 0, &branch_count);
    std::vector<boreas_branch> branches(static_cast<size_t>(branch_count));
    std::vector<boreas_leaf> leaves;
    std::vector<float> points, winds;
    double sum_tip = 0.0, sum2_tip = 0.0, sum_center = 0.0, sum2_center = 0.0, sum_load = 0.0;
    double sum_along = 0.0, sum2_along = 0.0;
    double height = 0.0;
    for (int s = 0; s < steps; ++s) {
      if (!ok(boreas_world_step(world, 1.0f / 30.0f), "step")) return 1;
      boreas_tree_get_branches(world, tree, branches.data(), branch_count, &branch_count);
      boreas_tree_get_leaves(world, tree, nullptr, 0, &leaf_count);
      leaves.resize(size_t(leaf_count));
      boreas_tree_get_leaves(world, tree, leaves.data(), leaf_count, &leaf_count);
      // Points: the leaves, then the tip, then the leaves' centroid, then four along the trunk.
      points.assign(size_t(3 * (leaf_count + 6)), 0.0f);
      double c[3] = {0.0, 0.0, 0.0};
      for (int i = 0; i < leaf_count; ++i)
        for (int a = 0; a < 3; ++a) {
          points[size_t(3 * i + a)] = leaves[size_t(i)].position[a];
          c[a] += leaves[size_t(i)].position[a] / leaf_count;
        }
      for (int a = 0; a < 3; ++a) {
        points[size_t(3 * leaf_count + a)] = branches[0].control_points[3][a];
        points[size_t(3 * leaf_count + 3 + a)] = float(c[a]);
        for (int q = 1; q <= 4; ++q) {  // the trunk's Bezier curve at t = q / 4
          const double t1 = q / 4.0, t0 = 1.0 - t1;
          const float(*p)[3] = branches[0].control_points;
          points[size_t(3 * (leaf_count + 1 + q) + a)] =
              float(t0 * t0 * t0 * p[0][a] + 3.0 * t0 * t0 * t1 * p[1][a] + 3.0 * t0 * t1 * t1 * p[2][a] +
                    t1 * t1 * t1 * p[3][a]);
        }
      }
      height = branches[0].control_points[3][1] - branches[0].control_points[0][1];
      winds.resize(points.size());
      if (!ok(boreas_wind_sample(world, points.data(), leaf_count + 6, winds.data()), "sample")) return 1;
      Load crown;
      for (int i = 0; i < leaf_count; ++i) {
        const Load l = drag_of(&winds[size_t(3 * i)], 1.0);
        crown.x += l.x;
        crown.z += l.z;
      }
      const Load tip = drag_of(&winds[size_t(3 * leaf_count)], leaf_count);
      const Load center = drag_of(&winds[size_t(3 * leaf_count + 3)], leaf_count);
      Load along;
      for (int q = 1; q <= 4; ++q) along.x += drag_of(&winds[size_t(3 * (leaf_count + 1 + q))], leaf_count / 4.0).x;
      // Along the mean wind (+x): what bends the trunk downwind.
      sum_load += crown.x;
      sum_tip += tip.x - crown.x;
      sum2_tip += (tip.x - crown.x) * (tip.x - crown.x);
      sum_center += center.x - crown.x;
      sum2_center += (center.x - crown.x) * (center.x - crown.x);
      sum_along += along.x - crown.x;
      sum2_along += (along.x - crown.x) * (along.x - crown.x);
    }
    const double mean = sum_load / steps;
    std::printf("| %s | %.1f | %d | %+.1f %%, %.1f %% | %+.1f %%, %.1f %% | %+.1f %%, %.1f %% |\n", species,
                height, leaf_count, 100.0 * sum_tip / steps / mean, 100.0 * std::sqrt(sum2_tip / steps) / mean,
                100.0 * sum_center / steps / mean, 100.0 * std::sqrt(sum2_center / steps) / mean,
                100.0 * sum_along / steps / mean, 100.0 * std::sqrt(sum2_along / steps) / mean);
    boreas_world_destroy(world);
  }
  return 0;
}

}  // namespace boreas::bench
