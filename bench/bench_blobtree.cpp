// boreas benchmarks: the BlobTree rows (the boreas_blobtree_field kernel beside its native
// twin; the whole of polygonize_blobtree, binned and naive) on a generated tree.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_harness.h"
#include "blobtree/blobtree_bins.h"
#include "blobtree/blobtree_instance.h"
#include "blobtree/polygonizer.h"
#include "native_blobtree.h"
#include "runtime/launch.h"
#include "shared/blobtree_types.h"

namespace boreas::bench {

namespace {

// ---- BlobTree trees (boreas_blobtree_field; polygonize_blobtree: field, count, emit,
// attributes) ----

// Cubic grids (blob_grid(model, resolution, cubic)): 128^3 and 256^3 points.
constexpr int kBlobResolutions[] = {128, 256};
// Compulsory traffic per grid point of the field stage: the point's F written. The
// primitives and bin lists (a few hundred KiB) stay in cache.
constexpr double kBytesPerFieldPoint = 4.0;
// How far the native twin may be from the device's field, field units (F is 0 .. ~1):
// both are float with the same polynomials and differ only by rounding order (fma
// contraction in the CL compiler).
constexpr double kBlobAgreement = 1e-5;
// The same where the device computes the field with its builtins (GPUs, or
// BOREAS_FAST_MATH=0; cl/shared/fast_math.h) while the native twin keeps the polynomials:
// the bent primitives' boreas_atan2 is then the builtin atan2 (a few ulp), and OpenCL
// allows a device's float divide and sqrt to be 2.5 and 3 ulp off (the twin's C++ rounds
// them correctly). Each term is within a few ulp of the twin's, but a point's F sums tens
// of primitives' terms of up to ~1 each, so the differences add up: measured 2.6e-5 to
// 3.7e-5 field units on NVIDIA GPUs, over kBlobAgreement. 1e-4 admits them with room and
// is still tight enough to catch a wrong field: the iso-value is 0.5, a missed or
// misplaced primitive changes F by 1e-2 or more near it, and 1e-4 moves the surface by
// 1e-4 / |grad F| (|grad F| = 1.72 / R on a primitive's own surface: under 1e-4 R, far
// inside a grid cell).
constexpr double kBlobBuiltinAgreement = 1e-4;

// The CL-vs-native tolerance for the runtime's device: kBlobAgreement where it uses the
// polynomial fast math the native twin uses, kBlobBuiltinAgreement where it uses builtins.
double blob_agreement(const impl::Runtime& rt) {
  return rt.device().uses_fast_math() ? kBlobAgreement : kBlobBuiltinAgreement;
}

// The grid the naive rows warm PoCL up on (it compiles each kernel at its first launch):
// the smallest blob_grid takes, so that the warm-up costs no full naive pass.
constexpr int kBlobWarmUpResolution = 16;

// The tree of the BlobTree rows: quaking aspen seed 1 (bench_tree_models()[0]: 3 levels,
// ~1224 branches), at the origin.
const impl::TreeModel& blob_bench_tree() { return bench_tree_models()[0]; }

// Which branches a row's model has: those make_blobtree keeps (min_radius automatic, half
// a grid cell: the product's case, but on this tree that leaves the trunk alone at 128^3
// and the trunk with its ~10 thickest limbs at 256^3), or every branch (the whole tree's
// ~5900 primitives, the thinnest thickened to 0.9 cells as the product does; the load of
// a tree polygonized whole).
enum class BlobBranches { kAutomatic, kEvery };

// Everything the BlobTree rows of one resolution and model share, made by the first of
// them: the model and grid of blobtree_setup (what make_blobtree polygonizes) from
// boreas_default_blobtree_def() with this resolution, cubic, min_radius automatic (half a
// grid cell) or below every branch; the planes and bins the kernels read; the native twin's field,
// checked once against boreas_bt_field per point and against the device's field; on the
// device, the binned mesh and the buffers of the field kernel's timed launch.
struct BlobTreeFixture : Fixture {
  impl::BlobModel model;
  impl::BlobGrid grid;
  double min_radius = 0.0;  // m
  impl::BlobPlanes planes;
  impl::BlobBins bins;
  double bins_seconds = 0.0;  // blob_planes + blob_bins, best of 3 (host; polygonize_blobtree
                              // runs both)
  std::vector<float> native_field;
  std::string native_error;         // the SIMD twin is not boreas_bt_field
  double per_point_difference = 0;  // SIMD twin vs boreas_bt_field per point
  // CL
  bool cl_made = false;
  std::string cl_error;
  double twin_difference = 0.0;  // native twin vs sample_blobtree_field
  impl::BlobMesh mesh;           // polygonize_blobtree, binned
  impl::BlobScratch scratch;     // the field grid kept between calls, as a world keeps it
  cl::Buffer prims, ints, cuts, bin_first, bin_items, field;
  double binned_seconds = 0.0;  // per polygonize_blobtree in the binned row (0: not run)
};

BlobTreeFixture& blobtree_fixture(int resolution, BlobBranches branches) {
  const std::string key = "blobtree/" + std::to_string(resolution) +
                          (branches == BlobBranches::kEvery ? "/every" : "/automatic");
  return fixture<BlobTreeFixture>(key, [&] {
    auto f = std::make_unique<BlobTreeFixture>();
    boreas_blobtree_def def = boreas_default_blobtree_def();
    def.resolution = resolution;
    def.cubic = 1;
    impl::BlobTreeParams params = impl::checked_blobtree_def(def);
    // Every branch: a radius below any branch's (0 would mean the automatic half cell).
    if (branches == BlobBranches::kEvery) params.options.min_radius = 1e-6;
    impl::BlobSetup setup = impl::blobtree_setup(blob_bench_tree(), glm::dvec3(0.0), params);
    f->model = std::move(setup.model);
    f->grid = setup.grid;
    f->min_radius = setup.min_radius;
    f->bins_seconds = 1e30;
    for (int i = 0; i < 3; ++i) {
      Clock::time_point start = Clock::now();
      f->planes = impl::blob_planes(f->model, f->grid.origin);
      f->bins = impl::blob_bins(f->model, f->grid);
      f->bins_seconds =
          std::min(f->bins_seconds, std::chrono::duration<double>(Clock::now() - start).count());
    }

    f->native_field.assign(size_t(f->grid.points()), 0.0f);
    native_blobtree_field(f->planes, f->bins, f->grid, f->native_field.data());
    std::vector<float> per_point(f->native_field.size());
    native_blobtree_field_per_point(f->planes, f->bins, f->grid, per_point.data());
    f->per_point_difference = max_difference(f->native_field, per_point);
    if (f->per_point_difference > kBlobAgreement) {
      f->native_error =
          "the native twin (bench/native_blobtree.cpp) differs from "
          "boreas_bt_field by up to " +
          std::to_string(f->per_point_difference) +
          ": follow cl/shared/blobtree_field.h's walk there";
    }
    return f;
  });
}

// The counters every BlobTree row reports (triangles and vertices once the device made
// the mesh).
void blob_counters(benchmark::State& state, const BlobTreeFixture& f) {
  state.counters["points"] = double(f.grid.points());
  state.counters["primitives"] = double(f.model.primitives.size());
  state.counters["bin_items"] = double(f.bins.items.size());
  state.counters["min_radius_mm"] = 1e3 * f.min_radius;
  if (f.cl_made) {
    state.counters["triangles"] = double(f.mesh.triangle_count());
    state.counters["vertices"] = double(f.mesh.vertex_count());
  }
}

// The field kernel's launch as polygonize_blobtree's stage 1 makes it (its arguments and
// range), in one launch over the whole grid instead of slabs.
// make_blobtree_cl checks that it computes what sample_blobtree_field does.
cl::Event blobtree_field_launch(impl::Runtime& rt, BlobTreeFixture& f) {
  cl::Kernel& k = rt.kernel("blobtree_field.cl", "boreas_blobtree_field");
  const int z0 = 0;  // the whole grid
  return impl::launch(rt, k, impl::blobtree_field_items(f.grid, rt.simd_width(), size_t(f.grid.nz)),
                      f.prims, f.ints, f.planes.n, f.bin_first, f.bin_items, f.bins.bx, f.bins.by,
                      f.cuts, f.planes.cut_count, float(f.grid.cell), f.grid.nx, f.grid.ny, z0,
                      f.field);
}

// The device side, once: the binned mesh (which also has PoCL compile the binned path's
// kernels), the product's field (sample_blobtree_field) compared with the native twin's,
// and the timed launch's buffers, its result checked identical to the product's.
void make_blobtree_cl(impl::Runtime& rt, BlobTreeFixture& f) {
  if (f.cl_made) return;
  impl::PolygonizeOptions first;
  first.scratch = &f.scratch;
  f.mesh = impl::polygonize_blobtree(rt, f.model, f.grid, first);
  const std::vector<float> device = impl::sample_blobtree_field(rt, f.model, f.grid);
  f.twin_difference = max_difference(f.native_field, device);
  f.prims =
      upload(rt, CL_MEM_READ_ONLY, f.planes.prims.data(), f.planes.prims.size() * sizeof(float));
  f.ints =
      upload(rt, CL_MEM_READ_ONLY, f.planes.ints.data(), f.planes.ints.size() * sizeof(int32_t));
  f.cuts = upload(rt, CL_MEM_READ_ONLY, f.planes.cuts.data(), f.planes.cuts.size() * sizeof(float));
  f.bin_first =
      upload(rt, CL_MEM_READ_ONLY, f.bins.first.data(), f.bins.first.size() * sizeof(int32_t));
  f.bin_items = rt.buffer(CL_MEM_READ_ONLY, f.bins.items.size() * sizeof(int32_t));
  rt.upload(f.bin_items, f.bins.items);
  f.field = rt.buffer(CL_MEM_READ_WRITE, size_t(f.grid.points()) * sizeof(float));
  blobtree_field_launch(rt, f);
  std::vector<float> launched(device.size());
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(f.field, CL_TRUE, 0, launched.size() * sizeof(float),
                                               launched.data()));
  f.cl_made = true;
  std::printf(
      "blobtree %dx%dx%d: %zu primitives (min_radius %.3g m), %zu bin items, %zu triangles; "
      "native twin vs device field max |difference| %.3g, vs boreas_bt_field per point %.3g\n",
      f.grid.nx, f.grid.ny, f.grid.nz, f.model.primitives.size(), f.min_radius, f.bins.items.size(),
      f.mesh.triangle_count(), f.twin_difference, f.per_point_difference);
  if (const double d = max_difference(launched, device); d != 0.0) {
    f.cl_error = "the bench's field launch differs from sample_blobtree_field by up to " +
                 std::to_string(d) + ": follow polygonizer.cpp's run_field";
  } else {
    f.cl_error = disagreement("fields", f.twin_difference, "(field units)", blob_agreement(rt));
  }
}

void blobtree_field_native(benchmark::State& state, int resolution, BlobBranches branches) {
  BlobTreeFixture& f = blobtree_fixture(resolution, branches);
  if (skipped_for(state, f.native_error)) return;
  time_native(state, "BM_BlobTreeField", f.grid.points(), kBytesPerFieldPoint,
              [&] { native_blobtree_field(f.planes, f.bins, f.grid, f.native_field.data()); });
  blob_counters(state, f);
}

void blobtree_field_cl(benchmark::State& state, int resolution, BlobBranches branches) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  BlobTreeFixture& f = blobtree_fixture(resolution, branches);
  make_blobtree_cl(*rt, f);
  if (skipped_for(state, f.cl_error)) return;
  auto launch = [&] { return blobtree_field_launch(*rt, f); };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_BlobTreeField", f.grid.points(), kBytesPerFieldPoint, launch);
  blob_counters(state, f);
  state.counters["vs_native_max_diff"] = f.twin_difference;
}

// Where polygonize_blobtree's time goes, ms, best of 3 untimed calls with a progress
// callback: the polygonizer finishes the queue before each report (every field slab, the
// counts, the triangles, the end), so the stages' wall times can be told apart: field
// (with the upload, blob_bins and the field buffer), count (with the counts read back and
// scanned), emit, attributes (with the mesh read back).
void blobtree_stage_counters(benchmark::State& state, impl::Runtime& rt, BlobTreeFixture& f) {
  const char* const stages[] = {"field", "count", "triangles", "done"};
  const char* const counters[] = {"field_ms", "count_ms", "emit_ms", "attributes_ms"};
  double best[4] = {1e30, 1e30, 1e30, 1e30};
  for (int call = 0; call < 3; ++call) {
    double at[4] = {0.0, 0.0, 0.0, 0.0};  // when each stage's last report came, s
    Clock::time_point start = Clock::now();
    impl::PolygonizeOptions options;
    options.scratch = &f.scratch;
    options.progress = [&](double, const char* stage) {
      for (int i = 0; i < 4; ++i)
        if (std::string(stage) == stages[i])
          at[i] = std::chrono::duration<double>(Clock::now() - start).count();
    };
    impl::polygonize_blobtree(rt, f.model, f.grid, options);
    for (int i = 0; i < 4; ++i) best[i] = std::min(best[i], at[i] - (i > 0 ? at[i - 1] : 0.0));
  }
  for (int i = 0; i < 4; ++i) state.counters[counters[i]] = 1e3 * best[i];
}

// The whole of polygonize_blobtree, as make_blobtree calls it in a world (upload, bins,
// the five stages, the mesh read back; the field grid's buffer kept from the previous
// call), wall time: it keeps no events, so there is no kernel time.
void blobtree_polygonize_cl(benchmark::State& state, int resolution, BlobBranches branches,
                            bool naive) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  BlobTreeFixture& f = blobtree_fixture(resolution, branches);
  make_blobtree_cl(*rt, f);
  if (skipped_for(state, f.cl_error)) return;
  impl::PolygonizeOptions options;
  options.naive = naive;
  options.scratch = &f.scratch;
  if (naive) {
    // The binned path is warm (make_blobtree_cl); the naive field kernel is not.
    impl::polygonize_blobtree(*rt, f.model, impl::blob_grid(f.model, kBlobWarmUpResolution, true),
                              options);
  }
  impl::BlobMesh mesh;
  Clock::time_point start = Clock::now();
  for (auto _ : state) {
    mesh = impl::polygonize_blobtree(*rt, f.model, f.grid, options);
    benchmark::DoNotOptimize(mesh.indices.data());
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  report(state, "BM_BlobTreePolygonize", "cl", f.grid.points(), 0.0, wall, 0.0);
  state.counters.erase("kernel_items/s");  // no kernel time: "-" in results-table.py
  state.counters.erase("kernel_bytes/s");
  blob_counters(state, f);
  state.counters["bins_ms"] = 1e3 * f.bins_seconds;
  const double per_call = wall / double(std::max<int64_t>(state.iterations(), 1));
  if (!naive) {
    f.binned_seconds = per_call;
    blobtree_stage_counters(state, *rt, f);
    return;
  }
  // Naive and binned evaluate the same terms in the same order, so the meshes are equal.
  double diff = -1.0;  // -1: the vertex or triangle counts differ
  if (mesh.positions.size() == f.mesh.positions.size() && mesh.indices == f.mesh.indices)
    diff = max_difference(mesh.positions, f.mesh.positions);
  state.counters["vs_binned_max_diff"] = diff;
  state.counters["binned_speedup"] = f.binned_seconds > 0 ? per_call / f.binned_seconds : 0.0;
}

}  // namespace

void register_blobtree_benchmarks() {
  // Variants: binned and naive (every primitive at every point) on the model make_blobtree
  // builds; all_branches: binned on every branch (naive there would take minutes). A
  // naive iteration at 256^3 takes 10-20 s, so Google Benchmark runs one.
  for (int resolution : kBlobResolutions) {
    const std::string points = std::to_string(int64_t(resolution) * resolution * resolution);
    for (BlobBranches branches : {BlobBranches::kAutomatic, BlobBranches::kEvery}) {
      const std::string variant = branches == BlobBranches::kEvery ? "/all_branches" : "/binned";
      add("BM_BlobTreeField/native/" + points + variant,
          [=](auto& s) { blobtree_field_native(s, resolution, branches); });
      add("BM_BlobTreeField/cl/" + points + variant,
          [=](auto& s) { blobtree_field_cl(s, resolution, branches); });
      add("BM_BlobTreePolygonize/cl/" + points + variant,
          [=](auto& s) { blobtree_polygonize_cl(s, resolution, branches, false); });
      if (branches == BlobBranches::kAutomatic) {
        add("BM_BlobTreePolygonize/cl/" + points + "/naive",
            [=](auto& s) { blobtree_polygonize_cl(s, resolution, branches, true); });
      }
    }
  }
}

}  // namespace boreas::bench
