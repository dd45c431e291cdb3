// boreas benchmarks: the underbrush rows (boreas_underbrush_step, boreas_underbrush_vertices)
// on meadows of grass tufts, each kernel beside its native twin.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "bench_harness.h"
#include "colliders/collider.h"
#include "native_underbrush.h"
#include "runtime/kernel_defines.h"
#include "runtime/launch.h"
#include "shared/underbrush_types.h"
#include "underbrush/meadow.h"
#include "underbrush/underbrush_batch.h"

namespace boreas::bench {

namespace {

// ---- underbrush (boreas_underbrush_step, boreas_underbrush_vertices) ----

// Compulsory traffic per item; the part records and table cells (a few KiB that every
// component shares) and the wind's grid gathers are left out.
// Step: in, state 40 (X, V, broken, base), frame 16 (base, follow) and the parent's rest X
// 12, index 12 (link, packed axis, side and scale); out, state 40.
constexpr double kBytesPerComponentStep = 120.0;
constexpr int kUnderbrushStrip = 2 * BOREAS_UB_JOINTS;  // vertices per component
// out: position, normal, uv; plus the component's share of what its strip reads (X 12,
// broken 4, base 12, packed axis, side and scale 8, link 4) and writes (its count, 4) over
// its 18 vertices.
constexpr double kBytesPerUnderbrushVertex = 32.0 + 44.0 / kUnderbrushStrip;

// Components per meadow: every size for the step, the smallest and largest for the strips.
constexpr int kUnderbrushSizes[] = {1 << 16, 1 << 18, 1 << 20};
constexpr int kUnderbrushVertexSizes[] = {1 << 16, 1 << 20};
// CL steps from rest before the twin check, so that it sees bent, moving blades.
constexpr int kUnderbrushCheckSteps = 30;
// Where the strips are seen from: 1.7 m above the meadow's middle (default LOD distances).
constexpr float kUnderbrushCamera[3] = {0.0f, 1.7f, 0.0f};

// Everything the underbrush rows of one meadow size share; made by the first of them, kept
// for the others. The CL side is made by the first CL row: the planes of a batch holding
// this one meadow (UnderbrushBatch lays out a lone meadow as the meadow's own planes), the
// kernels launched as UnderbrushBatch launches them, but each launch alone, so that its
// event times the kernel. (UnderbrushBatch::enqueue_step returns no event, and it writes
// the collider and impulse buffers with blocking writes, so markers around it would time
// the host too.) One step through a real UnderbrushBatch checks the set-up.
struct UnderbrushFixture : Fixture {
  TreeWindScene wind;  // the trees' wind: the scene's four waves over a calm grid
  std::vector<BoreasGpuCollider> colliders = scene_colliders();
  std::shared_ptr<impl::MeadowInstance> meadow;
  std::vector<BoreasGpuPart> parts;  // decay written for kStepSeconds
  std::array<float, 3> lod{};
  // native
  std::vector<float> native_state[2];
  int native_current = 0;
  std::vector<float> native_vertices;
  std::vector<int32_t> native_counts;
  // CL
  bool cl_made = false, vertices_checked = false;
  std::string step_defines, step_error, vertices_error;
  cl::Buffer waves, grid, state[2], frame, index, part_buffer, tables, collider_buffer,
      tile_colliders, impulse_buffer, vertices, counts, draws, phases;
  impl::TileLists tiles{1};
  int cl_current = 0;

  int n() const { return meadow->meadow.count; }
  NativeMeadowPlanes planes() const {
    const impl::Meadow& m = meadow->meadow;
    NativeMeadowPlanes p;
    p.frame = m.frame.data();
    p.index = m.index.data();
    p.parts = parts.data();
    p.tables = m.tables.data();
    p.n = m.count;
    return p;
  }
  impl::PlantWind cl_wind() const { return wind.cl(waves, grid); }
};

UnderbrushFixture& underbrush_fixture(int components) {
  return fixture<UnderbrushFixture>("underbrush/" + std::to_string(components), [&] {
    auto f = std::make_unique<UnderbrushFixture>();
    f->meadow = std::make_shared<impl::MeadowInstance>();
    f->meadow->key = 1;
    f->meadow->meadow = scene_meadow(components);
    const impl::Meadow& m = f->meadow->meadow;
    // As UnderbrushBatch::upload_parts writes them for a step of kStepSeconds.
    for (const impl::MeadowPart& part : m.parts) {
      BoreasGpuPart g = part.gpu;
      g.recovery_loss = float(-std::expm1(-kStepSeconds / double(g.recovery_time)));
      f->parts.push_back(g);
    }
    f->lod = m.params.lod;
    f->native_state[0] = f->native_state[1] = m.rest_state;
    f->native_vertices.assign(size_t(m.count) * kUnderbrushStrip * 8, 0.0f);
    f->native_counts.assign(size_t(m.count), 0);
    return f;
  });
}

// One native step of the whole meadow from the current state.
void underbrush_step_native_once(UnderbrushFixture& f) {
  const int next = 1 - f.native_current;
  native_underbrush_step(f.planes(), f.native_state[f.native_current].data(),
                         f.native_state[next].data(), float(kStepSeconds), float(impl::kGravity),
                         f.wind.native(), f.colliders.data(), int(f.colliders.size()), nullptr, 0);
  f.native_current = next;
}

// Enqueues one CL step from state[cl_current], as UnderbrushBatch::enqueue_step sets it up
// (no impulses), and returns the kernel's event; the caller flips cl_current. width 0:
// the device's SIMD width, as the batch launches it; else the kernel built at that width
// (1: the scalar form of before issue 22).
cl::Event underbrush_step_launch(impl::Runtime& rt, UnderbrushFixture& f, int width = 0) {
  const std::string width_define = impl::width_define(width);
  cl::Kernel& k =
      rt.kernel("underbrush_step.cl", "boreas_underbrush_step", f.step_defines + width_define);
  // A tile of group_size() components per group, as the batch launches it.
  const impl::Items items = impl::Items(f.tiles.size(0) * rt.group_size())
                                .per_work_item(size_t(width ? width : rt.simd_width()));
  return impl::launch(rt, k, items, f.state[f.cl_current], f.state[1 - f.cl_current], f.frame,
                      f.index, f.part_buffer, f.tables, f.n(), float(kStepSeconds),
                      float(impl::kGravity), f.waves, int(f.wind.device.padded.size()), f.phases,
                      f.grid,
                      f.wind.g, f.collider_buffer, f.tile_colliders,
                      f.impulse_buffer, 0, f.tiles.buffer(0), 0);
}

std::vector<float> read_floats(impl::Runtime& rt, const cl::Buffer& b, size_t count) {
  std::vector<float> out(count);
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, count * sizeof(float), out.data()));
  return out;
}

// The CL side, checked: one step against a real UnderbrushBatch's from rest, then, after
// kUnderbrushCheckSteps more, one step against the native twin's from the same state.
void make_underbrush_cl(impl::Runtime& rt, UnderbrushFixture& f) {
  if (f.cl_made) return;
  f.cl_made = true;
  const impl::Meadow& m = f.meadow->meadow;
  const size_t state_floats = size_t(BOREAS_UB_STATE_PLANES) * m.count;
  f.waves = upload(rt, CL_MEM_READ_ONLY, f.wind.device.padded.data(),
                   f.wind.device.padded.size() * sizeof(BoreasGpuWave));
  f.grid = upload(rt, CL_MEM_READ_ONLY, f.wind.cells.data(), f.wind.cells.size() * sizeof(float));
  for (cl::Buffer& s : f.state)
    s = upload(rt, CL_MEM_READ_WRITE, m.rest_state.data(), state_floats * sizeof(float));
  f.frame = upload(rt, CL_MEM_READ_ONLY, m.frame.data(), m.frame.size() * sizeof(float));
  f.index = upload(rt, CL_MEM_READ_ONLY, m.index.data(), m.index.size() * sizeof(int32_t));
  f.part_buffer =
      upload(rt, CL_MEM_READ_ONLY, f.parts.data(), f.parts.size() * sizeof(BoreasGpuPart));
  f.tables = upload(rt, CL_MEM_READ_ONLY, m.tables.data(), m.tables.size() * sizeof(float));
  // The colliders, every tile reading them all (UnderbrushBatch gives a tile its near ones
  // only; the others push with exactly 0), and one silent impulse.
  const BoreasGpuImpulse silent{1e18f, 1e18f, 1e18f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  f.collider_buffer = upload(rt, CL_MEM_READ_ONLY, f.colliders.data(),
                             f.colliders.size() * sizeof(BoreasGpuCollider));
  f.impulse_buffer = upload(rt, CL_MEM_READ_ONLY, &silent, sizeof silent);
  const int width = int(rt.group_size());
  const int tile_count = (m.count + width - 1) / width;
  std::vector<int32_t> per_tile;
  for (int t = 0; t < tile_count; ++t) per_tile.insert(per_tile.end(), {0, int(f.colliders.size())});
  f.tile_colliders =
      upload(rt, CL_MEM_READ_ONLY, per_tile.data(), per_tile.size() * sizeof(int32_t));
  // The whole meadow in tiles, its own planes from 0 (its part and parent indices as they
  // are: part base and root 0).
  // One tile at a time, as UnderbrushBatch adds them: the tile's STATIC is the meadow's part
  // base (0 here), not an item's entry, so it must not count up along a range.
  // The meadow's origin (0: planted from world positions) in the tiles, and its row of wave
  // phases there (cl/shared/underbrush_types.h).
  impl::TileLists::Shared at_origin;
  at_origin.value = at_origin.scale = at_origin.scale_root = 0.0f;
  for (int first = 0; first < m.count; first += width)
    f.tiles.add(0, first, std::min(width, m.count - first), width, at_origin);
  std::vector<float> phases(std::max<size_t>(f.wind.device.padded.size(), 1), 0.0f);
  f.cl_wind().phases_at(m.origin[0], m.origin[2], phases.data());
  f.phases = upload(rt, CL_MEM_READ_ONLY, phases.data(), phases.size() * sizeof(float));
  f.tiles.flush(rt);
  f.step_defines = f.cl_wind().defines() + impl::slot_define("BOREAS_UB_COLLIDERS", 1) +
                   impl::slot_define("BOREAS_UB_RATE", 1) +
                   impl::slot_define("BOREAS_IMPULSE_SLOTS", 0);

  std::string layout;
  {
    impl::UnderbrushBatch batch(rt);
    batch.add(f.meadow);
    batch.enqueue_step(kStepSeconds, f.cl_wind(), scene_step_colliders(), {});
    BOREAS_CL_CHECK(rt.queue().finish());
    batch.commit();
    const std::vector<float> want = batch.read_meadow_state(f.meadow->key);
    underbrush_step_launch(rt, f);
    f.cl_current = 1 - f.cl_current;
    const std::vector<float> got = read_floats(rt, f.state[f.cl_current], state_floats);
    layout = disagreement("steps (bench set-up vs UnderbrushBatch)", max_difference(got, want),
                          "m or m/s");
  }
  for (int s = 0; s < kUnderbrushCheckSteps; ++s) {
    underbrush_step_launch(rt, f);
    f.cl_current = 1 - f.cl_current;
  }
  const std::vector<float> before = read_floats(rt, f.state[f.cl_current], state_floats);
  underbrush_step_launch(rt, f);
  f.cl_current = 1 - f.cl_current;
  const std::vector<float> got = read_floats(rt, f.state[f.cl_current], state_floats);
  std::vector<float> want(state_floats);
  native_underbrush_step(f.planes(), before.data(), want.data(), float(kStepSeconds),
                         float(impl::kGravity), f.wind.native(), f.colliders.data(),
                         int(f.colliders.size()), nullptr, 0);
  const double diff = max_difference(got, want);
  std::printf("underbrush %d: CL step vs native twin, max |difference| %.3g (m, m/s)\n", f.n(),
              diff);
  f.step_error = !layout.empty() ? layout : disagreement("underbrush steps", diff, "m or m/s");
}

// width as for underbrush_step_launch (0: the device's).
void underbrush_step_cl(benchmark::State& state, int components, int width = 0) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  UnderbrushFixture& f = underbrush_fixture(components);
  make_underbrush_cl(*rt, f);
  if (skipped_for(state, f.step_error)) return;
  auto launch = [&] {
    cl::Event e = underbrush_step_launch(*rt, f, width);
    f.cl_current = 1 - f.cl_current;
    return e;
  };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_UnderbrushStep", components, kBytesPerComponentStep, launch);
}

void underbrush_step_native(benchmark::State& state, int components) {
  UnderbrushFixture& f = underbrush_fixture(components);
  auto run = [&] { underbrush_step_native_once(f); };
  run();
  time_native(state, "BM_UnderbrushStep", components, kBytesPerComponentStep, run);
}

// Enqueues the strips of the current CL state, as UnderbrushBatch::enqueue_vertices.
cl::Event underbrush_vertices_launch(impl::Runtime& rt, UnderbrushFixture& f) {
  cl::Kernel& k = rt.kernel("underbrush_vertices.cl", "boreas_underbrush_vertices");
  // The whole meadow as a list of one (shared/underbrush_types.h): from component 0, its
  // part indices from record 0, into slots from 0.
  if (!f.draws()) {
    const BoreasUbDraw draw{0,
                            0,
                            f.n(),
                            0,
                            0,
                            {f.lod[0], f.lod[1], f.lod[2]},
                            {kUnderbrushCamera[0], kUnderbrushCamera[1], kUnderbrushCamera[2]},
                            {0.0f, 0.0f, 0.0f}};
    f.draws = rt.buffer(CL_MEM_READ_ONLY, sizeof(draw), "meadow draw table");
    rt.write(f.draws, 0, sizeof(draw), &draw);
  }
  return impl::launch(rt, k, impl::Items(size_t(f.n())), f.state[f.cl_current], f.index,
                      f.part_buffer, f.tables, f.n(), f.draws, 1, f.n(), f.vertices, f.counts);
}

void underbrush_vertices_cl(benchmark::State& state, int components) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  UnderbrushFixture& f = underbrush_fixture(components);
  make_underbrush_cl(*rt, f);
  if (skipped_for(state, f.step_error)) return;
  const int64_t vertices = int64_t(f.n()) * kUnderbrushStrip;
  if (!f.vertices_checked) {
    // Against the native twin on the same (CL) state; the native row's buffers hold the
    // twin's result, overwritten by its next run.
    f.vertices_checked = true;
    f.vertices = rt->buffer(CL_MEM_READ_WRITE, size_t(vertices) * 8 * sizeof(float));
    f.counts = rt->buffer(CL_MEM_READ_WRITE, size_t(f.n()) * sizeof(int32_t));
    underbrush_vertices_launch(*rt, f);
    std::vector<int32_t> got_counts(size_t(f.n()));
    BOREAS_CL_CHECK(rt->queue().enqueueReadBuffer(
        f.counts, CL_TRUE, 0, got_counts.size() * sizeof(int32_t), got_counts.data()));
    const std::vector<float> got = read_floats(*rt, f.vertices, size_t(vertices) * 8);
    const std::vector<float> planes =
        read_floats(*rt, f.state[f.cl_current], size_t(BOREAS_UB_STATE_PLANES) * f.n());
    native_underbrush_vertices(f.planes(), planes.data(), kUnderbrushCamera, f.lod.data(),
                               f.native_vertices.data(), f.native_counts.data());
    const double diff = max_difference(got, f.native_vertices);
    std::printf("underbrush %d: CL strips vs native twin, max |difference| %.3g (m or unit)\n",
                f.n(), diff);
    f.vertices_error = got_counts != f.native_counts
                           ? std::string("CL and native strip vertex counts differ")
                           : disagreement("strips", diff, "(m or unit)");
  }
  if (skipped_for(state, f.vertices_error)) return;
  auto launch = [&] { return underbrush_vertices_launch(*rt, f); };
  warm_up(*rt, launch);
  time_cl_span(state, *rt, "BM_UnderbrushVertices", vertices, kBytesPerUnderbrushVertex,
               std::to_string(components), [&] {
                 ClSpan span;
                 span.first = span.last = launch();
                 return span;
               });
}

void underbrush_vertices_native(benchmark::State& state, int components) {
  UnderbrushFixture& f = underbrush_fixture(components);
  const float* planes = f.native_state[f.native_current].data();
  auto run = [&] {
    native_underbrush_vertices(f.planes(), planes, kUnderbrushCamera, f.lod.data(),
                               f.native_vertices.data(), f.native_counts.data());
  };
  run();
  time_native(state, "BM_UnderbrushVertices", int64_t(f.n()) * kUnderbrushStrip,
              kBytesPerUnderbrushVertex, run, std::to_string(components));
}


// ---- the step with moving colliders, through UnderbrushBatch (its broadphase included) ----

// Balls of 0.3 m (walkers, boulders rolling) spread over the meadow (fixed seed), each
// driving at 2 m/s in its own direction: the step's cost with `count` of them, all of the
// batch's launches (device span) and the host's share (wall).
struct UnderbrushCollidersFixture : Fixture {
  TreeWindScene wind;
  cl::Buffer waves, grid;
  std::unique_ptr<impl::UnderbrushBatch> batch;
  std::vector<impl::Collider> colliders;
};

std::vector<impl::Collider> moving_balls(int count, double half_side) {
  std::vector<impl::Collider> out;
  uint64_t s = 12345;
  auto uniform = [&] {  // a fixed LCG: the same balls on every machine
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(s >> 11) / double(1ULL << 53);
  };
  for (int i = 0; i < count; ++i) {
    impl::Collider c;
    c.def = boreas_default_collider_def();
    c.def.radius = 0.3f;
    c.def.pose.position[0] = float((2.0 * uniform() - 1.0) * half_side);
    c.def.pose.position[1] = 0.25f;
    c.def.pose.position[2] = float((2.0 * uniform() - 1.0) * half_side);
    const double a = 2.0 * M_PI * uniform();
    c.def.velocity[0] = float(2.0 * std::cos(a));
    c.def.velocity[2] = float(2.0 * std::sin(a));
    out.push_back(c);
  }
  return out;
}

impl::StepColliders step_colliders_of(const std::vector<impl::Collider>& colliders) {
  impl::StepColliders sc;
  sc.dt = kStepSeconds;
  for (const impl::Collider& c : colliders) {
    sc.add(c);
  }
  return sc;
}

void underbrush_colliders_cl(benchmark::State& state, int count, int components) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  // One fixture is held at a time (bench_fixture.h): this one makes its own meadow.
  auto& f = fixture<UnderbrushCollidersFixture>(
      "underbrush_colliders/" + std::to_string(count) + "/" + std::to_string(components), [&] {
        auto out = std::make_unique<UnderbrushCollidersFixture>();
        out->waves = upload(*rt, CL_MEM_READ_ONLY, out->wind.device.padded.data(),
                            out->wind.device.padded.size() * sizeof(BoreasGpuWave));
        out->grid = upload(*rt, CL_MEM_READ_ONLY, out->wind.cells.data(),
                           out->wind.cells.size() * sizeof(float));
        out->batch = std::make_unique<impl::UnderbrushBatch>(*rt);
        auto meadow = std::make_shared<impl::MeadowInstance>();
        meadow->key = 1;
        meadow->meadow = scene_meadow(components);
        out->batch->add(meadow);
        // The lattice's half side, less a metre so the balls start inside.
        const double side = std::ceil(std::sqrt(double(components) / 7.0)) * kMeadowSpacing;
        out->colliders = moving_balls(count, 0.5 * side - 1.0);
        return out;
      });
  const impl::PlantWind wind = f.wind.cl(f.waves, f.grid);
  auto launch = [&] {
    std::vector<cl::Event> events;
    const impl::StepColliders sc = step_colliders_of(f.colliders);
    f.batch->enqueue_step(kStepSeconds, wind, sc, {}, &events);
    BOREAS_CL_CHECK(rt->queue().finish());
    f.batch->commit();
    for (impl::Collider& c : f.colliders) c.advance(kStepSeconds);
    ClSpan span;
    span.first = events.front();
    span.last = events.back();
    return span;
  };
  for (int i = 0; i < 3; ++i) launch();
  time_cl_span(state, *rt, "BM_UnderbrushColliders", components, kBytesPerComponentStep,
               std::to_string(count) + "/" + std::to_string(components), launch);
}

}  // namespace

void register_underbrush_benchmarks() {
  for (int n : kUnderbrushSizes) {
    const std::string components = std::to_string(n);
    add("BM_UnderbrushStep/native/" + components, [=](auto& s) { underbrush_step_native(s, n); });
    add("BM_UnderbrushStep/cl/" + components, [=](auto& s) { underbrush_step_cl(s, n); });
    add("BM_UnderbrushStep/cl_w1/" + components, [=](auto& s) { underbrush_step_cl(s, n, 1); });
    if (std::find(std::begin(kUnderbrushVertexSizes), std::end(kUnderbrushVertexSizes), n) !=
        std::end(kUnderbrushVertexSizes)) {
      add("BM_UnderbrushVertices/native/" + components,
          [=](auto& s) { underbrush_vertices_native(s, n); });
      add("BM_UnderbrushVertices/cl/" + components, [=](auto& s) { underbrush_vertices_cl(s, n); });
    }
  }
  for (int n : {1 << 18, 1 << 20})
    for (int count : {0, 10, 100})
      add("BM_UnderbrushColliders/cl/" + std::to_string(count) + "/" + std::to_string(n),
          [=](auto& s) { underbrush_colliders_cl(s, count, n); });
}

}  // namespace boreas::bench
