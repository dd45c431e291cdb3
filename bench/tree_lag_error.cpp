// boreas benchmarks: print_tree_lag_error (boreas_bench --boreas_lag_error), the tip error
// of the lagged tree step against the exact one on the bench trees, as a Markdown table.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "bench_harness.h"
#include "benchmarks.h"
#include "shared/tree_types.h"
#include "trees/species.h"
#include "trees/tree_batch.h"
#include "trees/tree_model.h"

namespace boreas::bench {

namespace {

// The scene's waves at time t, as a world's device copy would hold them: steady (the
// phases of t = 0), or gusty: crests moving downwind at 6 m/s and every amplitude swelling
// and dropping with two incommensurate gust periods (3.1 s and 1.3 s), between 0.2x and
// 1.8x.
std::vector<BoreasGpuWave> lag_error_waves(double t, bool gusty) {
  std::vector<BoreasGpuWave> waves = scene_waves();
  if (!gusty) return waves;
  const double kPi = 3.14159265358979324;
  const double gust =
      1.0 + 0.5 * std::sin(2.0 * kPi * t / 3.1) + 0.3 * std::sin(2.0 * kPi * t / 1.3 + 1.0);
  for (BoreasGpuWave& w : waves) {
    double phase = double(w.phase_cycles) - 6.0 * t * double(w.cycles_per_meter);
    w.phase_cycles = float(phase - std::floor(phase));
    w.amplitude = float(double(w.amplitude) * gust);
  }
  return waves;
}

}  // namespace

int print_tree_lag_error(int steps) {
  ClState& cl = cl_state();
  if (!cl.runtime) {
    std::fprintf(stderr, "no OpenCL device: %s\n", cl.error.c_str());
    return 1;
  }
  impl::Runtime& rt = *cl.runtime;
  const TreeWindScene scene;
  cl::Buffer grid =
      upload(rt, CL_MEM_READ_ONLY, scene.cells.data(), scene.cells.size() * sizeof(float));
  std::printf(
      "| wind | response | steps | max tip error | RMS tip error | max tip error, last second | "
      "RMS tip error, last second | max tip error (m) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  double mean_height = 0.0;
  int branch_total = 0;
  for (boreas_tree_response response : {BOREAS_TREE_QUASI_STATIC, BOREAS_TREE_DAMPED}) {
    for (bool gusty : {false, true}) {
      // One of each bench tree, side by side, in a lagged and an exact batch.
      const auto trees = bench_trees(0, scene.def, response);
      auto lagged = leafless_batch(rt, BOREAS_TREE_LAGGED, trees);
      auto exact = leafless_batch(rt, BOREAS_TREE_EXACT, trees);
      // Both batches hold the trees packed from entry 0 (one add each): n entries.
      int n = 0;
      for (const auto& t : trees) n += 1 + int(t->model->branches.size());
      // Each branch's tree, and each tree's height at rest (highest control point above
      // its base).
      std::vector<int> tree_of(size_t(n), -1);
      std::vector<double> height(trees.size(), 0.0);
      const std::vector<float> rest = exact->read_state_prefix(n);
      for (size_t k = 0; k < trees.size(); ++k) {
        const impl::TreeModel& m = *trees[k]->model;
        for (int b = 0; b < int(m.branches.size()); ++b) {
          const int i = exact->branch_index(trees[k]->key, b);
          tree_of[size_t(i)] = int(k);
          for (int c = 0; c < 4; ++c)
            height[k] = std::max(
                height[k], double(rest[size_t(3 * c + 1) * n + i]));  // relative to the base
        }
      }
      mean_height = 0.0;
      for (double h : height) mean_height += h / double(height.size());
      branch_total = exact->branch_count();
      DeviceWaves device = device_waves(scene.waves);
      cl::Buffer waves = upload(rt, CL_MEM_READ_WRITE, device.padded.data(),
                                device.padded.size() * sizeof(BoreasGpuWave));
      impl::PlantWind in;
      in.waves = &waves;
      in.wave_count = int(device.padded.size());
      in.wave_slots = device.slots;
      in.grid = &grid;
      in.grid_layout = scene.g;
      in.host_waves = &device.padded;
      const int last_second = std::max(steps - int(std::lround(1.0 / kStepSeconds)), 0);
      double max_rel = 0.0, sum_sq = 0.0, max_abs = 0.0, late_max = 0.0, late_sum_sq = 0.0;
      int64_t count = 0, late_count = 0;
      for (int s = 1; s <= steps; ++s) {
        DeviceWaves now = device_waves(lag_error_waves(s * kStepSeconds, gusty));
        BOREAS_CL_CHECK(rt.queue().enqueueWriteBuffer(
            waves, CL_TRUE, 0, now.padded.size() * sizeof(BoreasGpuWave), now.padded.data()));
        lagged->enqueue_step(kStepSeconds, in, impl::StepColliders{});
        exact->enqueue_step(kStepSeconds, in, impl::StepColliders{});
        BOREAS_CL_CHECK(rt.queue().finish());
        lagged->commit();
        exact->commit();
        const std::vector<float> a = lagged->read_state_prefix(n), b = exact->read_state_prefix(n);
        for (int i = 0; i < n; ++i) {
          if (tree_of[size_t(i)] < 0) continue;  // a root
          double d2 = 0.0;
          for (int c = 0; c < 3; ++c) {
            const size_t k = size_t(BOREAS_TREE_STATE_P3 + c) * n + i;
            d2 += double(a[k] - b[k]) * double(a[k] - b[k]);
          }
          const double h = height[size_t(tree_of[size_t(i)])];
          const double rel = std::sqrt(d2) / h;
          max_rel = std::max(max_rel, rel);
          max_abs = std::max(max_abs, std::sqrt(d2));
          sum_sq += rel * rel;
          ++count;
          if (s > last_second) {
            late_max = std::max(late_max, rel);
            late_sum_sq += rel * rel;
            ++late_count;
          }
        }
      }
      std::printf(
          "| %s | %s | %d | %.3g %% | %.3g %% | %.3g %% | %.3g %% | %.3g |\n",
          gusty ? "gusty" : "steady", response == BOREAS_TREE_DAMPED ? "damped" : "quasi-static",
          steps, 100.0 * max_rel, 100.0 * std::sqrt(sum_sq / double(std::max<int64_t>(count, 1))),
          100.0 * late_max,
          100.0 * std::sqrt(late_sum_sq / double(std::max<int64_t>(late_count, 1))), max_abs);
      std::fflush(stdout);
    }
  }
  std::printf(
      "\n%d trees (%d branches), mean height %.3g m; errors are |P3 lagged - P3 exact| "
      "over every branch and step, relative to the branch's tree height.\n",
      int(bench_tree_models().size()), branch_total, mean_height);
  return 0;
}

}  // namespace boreas::bench
