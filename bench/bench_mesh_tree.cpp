// boreas benchmarks: the imported-tree rows (boreas_mesh_tree_branches, _trunk and _leaves
// through MeshTreeBatch, beside their native twin; compute_mesh_tree's preprocessing) on
// tube trees built here as an exporter would write them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_harness.h"
#include "mesh_trees/mesh_tree_batch.h"
#include "mesh_trees/noise_texture.h"
#include "mesh_trees/tree_model.h"
#include "mesh_trees/wind_weights.h"
#include "native_mesh_tree.h"
#include "shared/mesh_tree_types.h"

namespace boreas::bench {

namespace {

// ---- imported trees (boreas_mesh_tree_branches, boreas_mesh_tree_trunk and _leaves) ----

// A tree of tapered tubes as an exporter writes one (one connected run of triangles per
// branch, starting inside its parent, seam vertices duplicated), the idea of
// tests/host/mesh_trees/tube_trees.h scaled up: a stem, limbs on it, twigs on each limb,
// shoots on each twig, and quad leaves (4 vertices, 2 triangles) along every shoot.
struct MeshTreeShape {
  int limbs, twigs, shoots, leaves;  // limbs on the stem, twigs per limb, shoots per twig,
                                     // leaves per shoot
  int sides[4], rings[4];            // per level: stem, limb, twig, shoot
};

// A small game tree (~4.6 k trunk triangles, 480 leaves), and the seed's tree: 70,272
// trunk triangles (~70 k) and 12,000 leaves.
constexpr MeshTreeShape kMeshTreeShapes[] = {
    {4, 4, 3, 10, {16, 8, 6, 5}, {16, 8, 6, 5}},
    {12, 10, 4, 25, {32, 12, 8, 6}, {48, 20, 8, 8}},
};

// Steps both sides take from rest before the second twin check (the first is the first
// step, where every branch starts at the wind).
constexpr int kMeshCheckSteps = 30;
constexpr uint64_t kMeshTreeSeed = 1;

int mesh_tree_triangles(const MeshTreeShape& s) {
  const int tubes[4] = {1, s.limbs, s.limbs * s.twigs, s.limbs * s.twigs * s.shoots};
  int triangles = 0;
  for (int l = 0; l < 4; ++l) triangles += tubes[l] * 2 * s.sides[l] * s.rings[l];
  return triangles;
}

struct Vec3d {
  double x = 0.0, y = 0.0, z = 0.0;
};
Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3d operator*(double s, Vec3d a) { return {s * a.x, s * a.y, s * a.z}; }
Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3d normalized(Vec3d a) { return (1.0 / std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z)) * a; }

// A unit direction from azimuth (about +Y, from +X towards +Z) and elevation, radians.
Vec3d mesh_direction(double azimuth, double elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
          std::cos(elevation) * std::sin(azimuth)};
}

struct BenchTube {
  Vec3d base, dir{0.0, 1.0, 0.0}, a, b;  // dir unit; a, b: unit, normal to dir and each other
  double length = 1.0, r_base = 0.1, r_tip = 0.05;
  double azimuth = 0.0;
  Vec3d point(double u) const { return base + (u * length) * dir; }
  double radius(double u) const { return r_base + u * (r_tip - r_base); }
};

void push3(std::vector<float>& v, Vec3d p) {
  v.push_back(float(p.x));
  v.push_back(float(p.y));
  v.push_back(float(p.z));
}

// rings + 1 rings of sides + 1 vertices (the seam's first and last coincide), open ends.
BenchTube add_bench_tube(impl::MeshPart& part, Vec3d base, Vec3d dir, double length, double r_base,
                         double r_tip, double azimuth, int sides, int rings) {
  BenchTube t;
  t.base = base;
  t.dir = normalized(dir);
  t.length = length;
  t.r_base = r_base;
  t.r_tip = r_tip;
  t.azimuth = azimuth;
  const Vec3d ref = std::abs(t.dir.y) < 0.9 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0};
  t.a = normalized(cross(t.dir, ref));
  t.b = cross(t.dir, t.a);
  const uint32_t first = uint32_t(part.vertex_count());
  for (int i = 0; i <= rings; ++i) {
    const double u = double(i) / rings;
    for (int j = 0; j <= sides; ++j) {
      const double phi = 2.0 * M_PI * (j % sides) / sides;
      const Vec3d n = std::cos(phi) * t.a + std::sin(phi) * t.b;
      push3(part.positions, t.point(u) + t.radius(u) * n);
      push3(part.normals, n);
      part.uvs.push_back(float(j) / float(sides));
      part.uvs.push_back(float(u));
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const uint32_t v00 = first + uint32_t(i * (sides + 1) + j), v01 = v00 + 1;
      const uint32_t v10 = v00 + uint32_t(sides + 1), v11 = v10 + 1;
      part.indices.insert(part.indices.end(), {v00, v10, v11, v00, v11, v01});
    }
  return t;
}

// The bench tree of a shape, model space (m, Y up): a 14 m stem; limbs spread by the
// golden angle between 30 % and 90 % of its height, shorter towards the top; twigs and
// shoots alternating left and right along their parent; leaves 10 cm x 5 cm whose base
// sits on the shoot's surface, turned around it by the golden angle, pointing outwards and
// towards the shoot's tip.
impl::MeshModel bench_mesh_tree(const MeshTreeShape& s) {
  constexpr double kGolden = 2.39996322972865332;
  impl::MeshModel m;
  impl::MeshPart& trunk = m.trunk;
  impl::MeshPart& leaves = m.leaves;
  const BenchTube stem =
      add_bench_tube(trunk, {}, {0, 1, 0}, 14.0, 0.35, 0.1, 0.0, s.sides[0], s.rings[0]);
  for (int i = 0; i < s.limbs; ++i) {
    const double at = 0.3 + 0.6 * (i + 0.5) / s.limbs;
    const double azimuth = i * kGolden;
    const BenchTube limb =
        add_bench_tube(trunk, stem.point(at), mesh_direction(azimuth, 0.6), 5.5 - 4.0 * (at - 0.3),
                       0.12, 0.035, azimuth, s.sides[1], s.rings[1]);
    for (int j = 0; j < s.twigs; ++j) {
      const double side = j % 2 == 0 ? 1.0 : -1.0;
      const double twig_at = 0.2 + 0.75 * (j + 0.5) / s.twigs;
      const double twig_azimuth = limb.azimuth + 0.8 * side;
      const BenchTube twig =
          add_bench_tube(trunk, limb.point(twig_at), mesh_direction(twig_azimuth, 0.45), 1.8, 0.03,
                         0.012, twig_azimuth, s.sides[2], s.rings[2]);
      for (int k = 0; k < s.shoots; ++k) {
        const double shoot_side = k % 2 == 0 ? 1.0 : -1.0;
        const double shoot_at = 0.3 + 0.65 * (k + 0.5) / s.shoots;
        const double shoot_azimuth = twig.azimuth + 0.7 * shoot_side;
        const BenchTube shoot =
            add_bench_tube(trunk, twig.point(shoot_at), mesh_direction(shoot_azimuth, 0.3), 0.7,
                           0.011, 0.004, shoot_azimuth, s.sides[3], s.rings[3]);
        for (int q = 0; q < s.leaves; ++q) {
          const double u = 0.15 + 0.85 * (q + 0.5) / s.leaves;
          const double phi = q * kGolden;
          const Vec3d out = std::cos(phi) * shoot.a + std::sin(phi) * shoot.b;
          const Vec3d p = shoot.point(u) + shoot.radius(u) * out;
          const Vec3d along = normalized(out + 0.6 * shoot.dir);
          const Vec3d width = 0.025 * normalized(cross(along, out));
          const Vec3d normal = normalized(cross(width, along));
          const Vec3d corners[4] = {p - width, p + width, p + width + 0.1 * along,
                                    p - width + 0.1 * along};
          const uint32_t first = uint32_t(leaves.vertex_count());
          for (const Vec3d& c : corners) {
            push3(leaves.positions, c);
            push3(leaves.normals, normal);
            leaves.uvs.insert(leaves.uvs.end(), {0.0f, 0.0f});
          }
          leaves.indices.insert(leaves.indices.end(),
                                {first, first + 1, first + 2, first, first + 2, first + 3});
        }
      }
    }
  }
  return m;
}

}  // namespace

const impl::MeshModel& bench_mesh_model(int shape) {
  static std::map<int, impl::MeshModel> models;
  auto it = models.find(shape);
  if (it == models.end()) it = models.emplace(shape, bench_mesh_tree(kMeshTreeShapes[shape])).first;
  return it->second;
}

namespace {

// The tree as a world places it: default parameters (boreas_default_mesh_tree_def), at
// the grid's middle on the ground, preprocessed with compute_mesh_tree and its noise.
std::shared_ptr<impl::MeshTreeInstance> bench_mesh_instance(int shape) {
  auto tree = std::make_shared<impl::MeshTreeInstance>();
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = "bench tube tree";
  def.seed = kMeshTreeSeed;
  tree->params = impl::checked_mesh_tree_def(def);
  tree->model = bench_mesh_model(shape);
  tree->data = impl::compute_mesh_tree(tree->model, kMeshTreeSeed);
  tree->drag = impl::mesh_tree_drag(tree->model);
  tree->noise =
      impl::make_noise_texture(BOREAS_MESH_TREE_NOISE_SIZE, double(def.noise_beta), kMeshTreeSeed);
  tree->key = 1;
  return tree;
}

// Compulsory traffic per vertex, bytes read + written: a trunk vertex reads its rest
// position and 4 weights (28) and its branch (4) and writes its position (12); a leaf
// vertex reads its rest position, normal and tip distance (28) and its leaf (4), writes
// position and normal (24), and shares its leaf's row (10 floats: petiole, axis and
// weights; and its branch: 44 B) with the leaf's other 3 vertices. Branch rows, tree rows
// and the noise textures (512 KiB per tree) are left out, as cached.
constexpr double kBytesPerTrunkVertex = 44.0;
constexpr double kBytesPerLeafVertex = 56.0 + 44.0 / 4.0;

// Everything the mesh-tree rows of one shape share: made by the first of them. The CL
// side is a MeshTreeBatch holding the tree, stepped with each kernel's event kept; it is
// checked once against the native twin.
struct MeshTreeFixture : Fixture {
  TreeWindScene wind;  // the trees' wind: the scene's four waves over a calm grid
  std::shared_ptr<impl::MeshTreeInstance> tree;
  NativeMeshTrees native;
  double native_time = 0.0;
  int64_t vertices = 0;  // trunk + leaf vertices
  double bytes_per_vertex = 0.0;
  // CL
  bool cl_made = false;
  std::string cl_error;
  double twin_difference = 0.0;
  std::unique_ptr<impl::MeshTreeBatch> batch;
  cl::Buffer waves, grid;
  double cl_time = 0.0;
};

MeshTreeFixture& mesh_tree_fixture(int shape) {
  return fixture<MeshTreeFixture>("meshwind/" + std::to_string(shape), [&] {
    auto f = std::make_unique<MeshTreeFixture>();
    f->tree = bench_mesh_instance(shape);
    f->native = native_mesh_layout({f->tree.get()});
    const double nv = f->native.nv, nlv = f->native.nlv;
    f->vertices = int64_t(f->native.nv) + f->native.nlv;
    f->bytes_per_vertex = (kBytesPerTrunkVertex * nv + kBytesPerLeafVertex * nlv) / (nv + nlv);
    return f;
  });
}

// One CL step of kStepSeconds from the current state, committed at once (commit only
// moves the batch's host-side index); the caller finishes the queue before the next step,
// as the batch's per-step upload requires.
impl::MeshTreeStepEvents mesh_tree_launch(MeshTreeFixture& f) {
  f.cl_time += kStepSeconds;
  impl::MeshTreeStepEvents e;
  f.batch->enqueue_step(kStepSeconds, f.cl_time, f.wind.cl(f.waves, f.grid), &e);
  f.batch->commit();
  return e;
}

// The CL result of the last step as the native twin holds it: trunk positions, then leaf
// positions and normals, then the branches' wind (planar) and the tree's roll.
std::vector<float> mesh_tree_cl_result(MeshTreeFixture& f) {
  impl::MeshTreeBatch& batch = *f.batch;
  const uint64_t key = f.tree->key;
  std::vector<float> r;
  for (const boreas_vertex& v : batch.trunk_vertices(key))
    r.insert(r.end(), v.position, v.position + 3);
  for (const boreas_vertex& v : batch.leaf_vertices(key)) {
    r.insert(r.end(), v.position, v.position + 3);
    r.insert(r.end(), v.normal, v.normal + 3);
  }
  const std::vector<float> wind = batch.branch_wind(key);
  const size_t nb = wind.size() / 3;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = 0; b < nb; ++b) r.push_back(wind[3 * b + a]);
  const std::vector<float> roll = batch.noise_roll(key);
  r.insert(r.end(), roll.begin(), roll.end());
  return r;
}

std::vector<float> mesh_tree_native_result(const NativeMeshTrees& t) {
  std::vector<float> r = t.trunk_out;
  r.insert(r.end(), t.leaf_out.begin(), t.leaf_out.end());
  r.insert(r.end(), t.state[t.current].begin(), t.state[t.current].end());
  r.insert(r.end(), t.roll[t.current].begin(), t.roll[t.current].end());
  return r;
}

// The CL side, checked against the native twin's after the first step (every branch
// starts at the wind) and after kMeshCheckSteps more (low-passed wind, rolled noise). The
// largest difference is kept for the row's counter.
void make_mesh_tree_cl(impl::Runtime& rt, MeshTreeFixture& f) {
  if (f.cl_made) return;
  f.cl_made = true;
  f.waves = upload(rt, CL_MEM_READ_ONLY, f.wind.device.padded.data(),
                   f.wind.device.padded.size() * sizeof(BoreasGpuWave));
  f.grid = upload(rt, CL_MEM_READ_ONLY, f.wind.cells.data(), f.wind.cells.size() * sizeof(float));
  f.batch = std::make_unique<impl::MeshTreeBatch>(rt);
  f.batch->add(f.tree, 0.0);
  f.cl_time = 0.0;

  NativeMeshTrees twin = native_mesh_layout({f.tree.get()});
  double time = 0.0;
  for (int s = 0; s <= kMeshCheckSteps; ++s) {
    time += kStepSeconds;
    native_mesh_step(twin, kStepSeconds, time, f.wind.native());
    mesh_tree_launch(f);
    BOREAS_CL_CHECK(rt.queue().finish());
    if (s == 0 || s == kMeshCheckSteps)
      f.twin_difference = std::max(
          f.twin_difference, max_difference(mesh_tree_cl_result(f), mesh_tree_native_result(twin)));
  }
  // How far the twin's vertices moved from rest, so that the differences above can be
  // read against it (a check of vertices that hardly move would prove little).
  double moved = 0.0;
  for (int i = 0; i < twin.nv; ++i)
    for (int a = 0; a < 3; ++a)
      moved = std::max(
          moved,
          double(std::fabs(twin.trunk_out[size_t(3 * i + a)] -
                           twin.trunk[size_t(BOREAS_MESH_TREE_TRUNK_REST + a) * twin.nv + i])));
  for (int i = 0; i < twin.nlv; ++i)
    for (int a = 0; a < 3; ++a)
      moved = std::max(
          moved,
          double(std::fabs(
              twin.leaf_out[size_t(6 * i + a)] -
              twin.leaf_vertices[size_t(BOREAS_MESH_TREE_LEAF_VERTEX_REST + a) * twin.nlv + i])));
  std::printf(
      "mesh tree %d+%d vertices: CL (MeshTreeBatch) vs native twin (steps 1 and %d), max "
      "|difference| %.3g (m, unit or m/s); vertices moved up to %.3g m per axis\n",
      twin.nv, twin.nlv, kMeshCheckSteps + 1, f.twin_difference, moved);
  f.cl_error = disagreement("mesh-tree steps", f.twin_difference, "(m, unit or m/s)");
}

void mesh_tree_cl(benchmark::State& state, int shape) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  MeshTreeFixture& f = mesh_tree_fixture(shape);
  make_mesh_tree_cl(*rt, f);
  if (skipped_for(state, f.cl_error)) return;
  // Warm-up: PoCL compiles each work-group function at its first launch. Finished after
  // each step, as the tree planes' staging must outlive their upload.
  for (int i = 0; i < 3; ++i) {
    mesh_tree_launch(f);
    BOREAS_CL_CHECK(rt->queue().finish());
  }
  // Device time per kernel, summed over the timed iterations: each iteration's events are
  // read at the start of the next (time_cl_span has finished the queue by then).
  double branches = 0.0, trunk = 0.0, leaves = 0.0;
  impl::MeshTreeStepEvents last;
  bool pending = false;
  auto take = [&] {
    if (!pending) return;
    branches += event_seconds(last.branches);
    trunk += event_seconds(last.trunk);
    leaves += event_seconds(last.leaves);
    pending = false;
  };
  time_cl_span(state, *rt, "BM_MeshTree", f.vertices, f.bytes_per_vertex,
               std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape])), [&] {
                 take();
                 last = mesh_tree_launch(f);
                 pending = true;
                 ClSpan span;
                 span.first = last.branches;
                 span.last = last.leaves;
                 return span;
               });
  take();
  const double steps = double(std::max<int64_t>(state.iterations(), 1));
  state.counters["branches_us"] = 1e6 * branches / steps;
  state.counters["trunk_us"] = 1e6 * trunk / steps;
  state.counters["leaves_us"] = 1e6 * leaves / steps;
  state.counters["vs_native_max_diff"] = f.twin_difference;
}

void mesh_tree_native(benchmark::State& state, int shape) {
  MeshTreeFixture& f = mesh_tree_fixture(shape);
  const NativeTreeWind wind = f.wind.native();
  double passes[3] = {0.0, 0.0, 0.0};  // wall time per pass, as the CL row's per kernel
  auto run = [&] {
    f.native_time += kStepSeconds;
    native_mesh_step(f.native, kStepSeconds, f.native_time, wind, passes);
  };
  run();
  passes[0] = passes[1] = passes[2] = 0.0;
  time_native(state, "BM_MeshTree", f.vertices, f.bytes_per_vertex, run,
              std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape])));
  const double steps = double(std::max<int64_t>(state.iterations(), 1));
  state.counters["branches_us"] = 1e6 * passes[0] / steps;
  state.counters["trunk_us"] = 1e6 * passes[1] / steps;
  state.counters["leaves_us"] = 1e6 * passes[2] / steps;
}

// The one-time preprocessing of an imported tree (compute_mesh_tree: hierarchy, weights,
// phases, motion vectors, leaf assignment), one thread, on the already built mesh; the
// noise texture (make_noise_texture, the other per-tree cost) as a counter.
void mesh_tree_preprocess(benchmark::State& state, int shape) {
  const impl::MeshModel& model = bench_mesh_model(shape);
  const int64_t vertices = int64_t(model.trunk.vertex_count() + model.leaves.vertex_count());
  Clock::time_point start = Clock::now();
  for (auto _ : state) {
    impl::MeshTreeData data = impl::compute_mesh_tree(model, kMeshTreeSeed);
    benchmark::DoNotOptimize(data.branches.data());
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  report(state, "BM_MeshTreePreprocess", "native", vertices, 0.0, wall, wall,
         std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape])));
  Clock::time_point noise_start = Clock::now();
  impl::NoiseTexture noise =
      impl::make_noise_texture(BOREAS_MESH_TREE_NOISE_SIZE, 2.0, kMeshTreeSeed);
  benchmark::DoNotOptimize(noise.texels.data());
  state.counters["noise_ms"] =
      1e3 * std::chrono::duration<double>(Clock::now() - noise_start).count();
  const impl::MeshTreeData data = impl::compute_mesh_tree(model, kMeshTreeSeed);
  state.counters["branches"] = double(data.branches.size());
  state.counters["leaves"] = double(data.leaf_length.size());
  state.counters["levels"] = double(data.levels);
  state.counters["orphans"] = double(data.orphans);
}

}  // namespace

void register_mesh_tree_benchmarks() {
  for (int shape = 0; shape < int(std::size(kMeshTreeShapes)); ++shape) {
    const std::string triangles = std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape]));
    add("BM_MeshTree/native/" + triangles, [=](auto& s) { mesh_tree_native(s, shape); });
    add("BM_MeshTree/cl/" + triangles, [=](auto& s) { mesh_tree_cl(s, shape); });
  }
  for (int shape = 0; shape < int(std::size(kMeshTreeShapes)); ++shape) {
    const std::string triangles = std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape]));
    add("BM_MeshTreePreprocess/native/" + triangles,
        [=](auto& s) { mesh_tree_preprocess(s, shape); });
  }
}

}  // namespace boreas::bench
