// boreas benchmarks: a forest's records in one call (boreas_world_enqueue_tree_records)
// over forest sizes, through the C API as an engine makes it each frame: aspens from 20
// templates on an 8 m grid, the eye at one corner looking across it (a 60-degree view,
// 1280 x 720 pixels' leaf thinning, impostors past 150 m). The time is one call finished
// (clFinish), at most six launches per stepping mode whatever the size
// (trees/tree_batch_view.cpp lists them; tests/host/trees/test_view_costs.cpp counts them).
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_harness.h"
#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"

namespace boreas::bench {

namespace {

void check(boreas_status s) {
  if (s != BOREAS_OK) throw std::runtime_error(boreas_last_error());
}

struct RecordsScene {
  boreas_world world = nullptr;
  boreas_cl_objects cl{};
  boreas_tree_view_def view{};
  cl_mem m[5] = {};
  ~RecordsScene() {
    for (cl_mem x : m)
      if (x) clReleaseMemObject(x);
    if (world) boreas_world_destroy(world);
  }
};

void tree_records(benchmark::State& state, int trees, bool settled) {
  RecordsScene s;
  boreas_world_def def = boreas_default_world_def();
  check(boreas_world_create(&def, &s.world));
  check(boreas_world_get_cl(s.world, &s.cl));
  const int side = int(std::ceil(std::sqrt(double(trees))));
  std::vector<boreas_tree_def> defs(size_t(trees), boreas_default_tree_def());
  for (int i = 0; i < trees; ++i) {
    defs[size_t(i)].position[0] = 8.0f * float(i % side);
    defs[size_t(i)].position[2] = -8.0f * float(i / side);
    defs[size_t(i)].seed = uint64_t(1 + i % 20);
    defs[size_t(i)].rotation = 0.7f * float(i);
  }
  check(boreas_world_add_trees(s.world, defs.data(), trees, nullptr));
  boreas_tree_view_def& v = s.view;
  v = boreas_default_tree_view_def();
  v.eye[0] = -10.0f, v.eye[1] = 10.0f, v.eye[2] = 10.0f;
  if (settled) {
    // The simulation's levels of detail from the eye, past the settle time: the finest
    // levels of the trees past 30 m are derived (read through boreas_tree_pose), unless
    // the environment has BOREAS_TREE_DERIVATION=0 (carried: the A/B of deriving's cost).
    check(boreas_world_set_focus(s.world, v.eye, 1));
    for (int k = 0; k < 200; ++k) check(boreas_world_step(s.world, 1.0f / 60.0f));
  } else {
    check(boreas_world_step(s.world, 1.0f / 60.0f));
  }
  // Looking along (1, 0, -1): four planes 30 degrees either side of it.
  const float half = 0.5236f, d[3] = {0.7071f, 0.0f, -0.7071f};
  const float right[3] = {0.7071f, 0.0f, 0.7071f}, up[3] = {0.0f, 1.0f, 0.0f};
  const float c = std::cos(half), sn = std::sin(half);
  const float* sides[2] = {right, up};
  for (int p = 0; p < 4; ++p) {
    const float* a = sides[p / 2];
    const float sign = p % 2 ? -1.0f : 1.0f;
    float n[3];
    for (int k = 0; k < 3; ++k) n[k] = c * sign * a[k] + sn * d[k];
    for (int k = 0; k < 3; ++k) v.planes[p][k] = n[k];
    v.planes[p][3] = -(n[0] * v.eye[0] + n[1] * v.eye[1] + n[2] * v.eye[2]);
  }
  v.pixel_angle = 1.0472f / 720.0f;
  v.impostor_distance = 150.0f;
  // Buffers as large as the view needs: one call with empty ones says how large.
  const size_t record_bytes[4] = {BOREAS_BRANCH_RECORD_FLOATS * 4, BOREAS_LEAF_RECORD_FLOATS * 4,
                                  BOREAS_TREE_IMPOSTOR_RECORD_FLOATS * 4, BOREAS_TREE_RANGE_RECORD_INTS * 4};
  std::vector<uint32_t> indirect(BOREAS_TREE_INDIRECT_UINTS, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < 5; ++k) {
      if (s.m[k]) clReleaseMemObject(s.m[k]);
      const size_t bytes = k == 4 ? BOREAS_TREE_INDIRECT_UINTS * 4
                                  : std::max<size_t>(4, pass == 0 ? 4 : record_bytes[k] * indirect[size_t(16 + k)]);
      cl_int err = CL_SUCCESS;
      s.m[k] = clCreateBuffer(s.cl.context, CL_MEM_READ_WRITE, bytes, nullptr, &err);
      if (err != CL_SUCCESS) throw std::runtime_error("clCreateBuffer failed");
    }
    const boreas_tree_record_buffers b{s.m[0], s.m[1], s.m[2], s.m[3], s.m[4]};
    check(boreas_world_enqueue_tree_records(s.world, &s.view, &b));
    clEnqueueReadBuffer(s.cl.queue, s.m[4], CL_TRUE, 0, indirect.size() * 4, indirect.data(), 0, nullptr, nullptr);
  }
  const boreas_tree_record_buffers b{s.m[0], s.m[1], s.m[2], s.m[3], s.m[4]};
  for (auto _ : state) {
    check(boreas_world_enqueue_tree_records(s.world, &s.view, &b));
    clFinish(s.cl.queue);
  }
  state.counters["trees"] = double(trees);
  state.counters["drawn"] = double(indirect[BOREAS_TREE_INDIRECT_RANGES_WRITTEN]);
  state.counters["impostors"] = double(indirect[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1]);
  state.counters["branches"] = double(indirect[BOREAS_TREE_INDIRECT_BRANCH_COMMAND + 1]);
  state.counters["leaves"] = double(indirect[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1]);
}

}  // namespace

void register_tree_records_benchmarks() {
  for (int n : {100, 1000, 3000, 10000})
    add("BM_TreeRecords/cl/" + std::to_string(n), [=](auto& s) { tree_records(s, n, false); },
        benchmark::kMillisecond);
  // The same view of a forest whose levels of detail have settled (derived branches).
  add("BM_TreeRecords/cl/1000/settled", [=](auto& s) { tree_records(s, 1000, true); },
      benchmark::kMillisecond);
}

}  // namespace boreas::bench
