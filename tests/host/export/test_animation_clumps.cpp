// boreas tests: meadows as clumps in boreas_world_export_animation (meadow_clumps > 0), read
// back with tinygltf and played as a viewer plays them. A clump at its own cell plays as a
// second world of the same inputs has that cell's components after k frames, less the
// loop's drift (k / (keys - 1) of the move from key 0 to the last, the stated bound), within
// the tolerance; every cell of the meadow with components gets one clump at its center and
// ground height, and their components add up to the meadow's; bad fields are named.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"
#include "host/export/gltf_replay.h"

namespace {

using Points = std::vector<std::array<double, 3>>;

// A 3 x 2 m meadow on rolling ground (0.4 m relief) in a steady 12 m/s wind, or (swaying)
// in the default scene's three waves (render/scenes/default.json), cells of 1 m.
struct ClumpScene {
  boreas::World world;
  boreas_meadow_id meadow{};
  boreas_meadow_def def = boreas_default_meadow_def();
  explicit ClumpScene(bool swaying = false) : world(make_def()) {
    boreas_wave wave = boreas_default_wave();
    wave.direction[0] = 1.0f;
    wave.direction[1] = 0.0f;
    wave.amplitude = 12.0f;
    wave.sharpness = 0.0f;
    if (!swaying) {
      world.wind_set_waves({wave});
    } else {
      // direction, amplitude, wavelength, speed, sharpness
      const float waves[3][6] = {{1, 0.3f, 3, 40, 6, 2}, {0.6f, 1, 1.5f, 23, 4, 3}, {1, -0.8f, 1, 13, 3, 1}};
      std::vector<boreas_wave> set;
      for (const auto& w : waves) {
        boreas_wave x = boreas_default_wave();
        x.direction[0] = w[0], x.direction[1] = w[1];
        x.amplitude = w[2], x.wavelength = w[3], x.speed = w[4], x.sharpness = w[5];
        set.push_back(x);
      }
      world.wind_set_waves(set);
    }
    def.center[0] = 2.0f;
    def.size[0] = 3.0f;
    def.size[1] = 2.0f;
    def.density = 60.0f;
    def.terrain_relief = 0.4f;
    EXPECT_EQ(boreas_world_add_meadow(world.handle(), &def, &meadow), BOREAS_OK) << boreas_last_error();
  }
  static boreas_world_def make_def() {
    boreas_world_def d = boreas_default_world_def();
    d.grid.origin[0] = d.grid.origin[2] = -16.0f;
    d.grid.cell_size = 2.0f;
    d.grid.resolution[0] = d.grid.resolution[2] = 16;
    d.grid.resolution[1] = 8;
    return d;
  }
  std::vector<boreas_component> components() {
    int n = 0;
    EXPECT_EQ(boreas_meadow_get_components(world.handle(), meadow, nullptr, 0, &n), BOREAS_OK);
    std::vector<boreas_component> c(static_cast<size_t>(n));
    EXPECT_EQ(boreas_meadow_get_components(world.handle(), meadow, c.data(), n, &n), BOREAS_OK);
    return c;
  }
  // The cell (column + columns row) of each component, cells of `size` (dividing 3 and 2 m):
  // its root's base.
  std::vector<int> cells(double size = 1.0) {
    const std::vector<boreas_component> c = components();
    const int columns = int(std::lround(3.0 / size)), rows = int(std::lround(2.0 / size));
    std::vector<int> out;
    for (const boreas_component& x : c) {
      const boreas_component* root = &x;
      while (root->parent >= 0) root = &c[size_t(root->parent)];
      const int col = std::clamp(int(std::floor((root->base[0] - (def.center[0] - 1.5)) / size)), 0, columns - 1);
      const int row = std::clamp(int(std::floor((root->base[2] - (def.center[2] - 1.0)) / size)), 0, rows - 1);
      out.push_back(col + columns * row);
    }
    return out;
  }
  // The strip vertices of the components in `cell`, in the meadow's order.
  Points cell_vertices(int cell) {
    const std::vector<int> of = cells();
    int count = 0;
    EXPECT_EQ(boreas_meadow_get_vertices(world.handle(), meadow, nullptr, nullptr, 0, &count, nullptr), BOREAS_OK);
    std::vector<boreas_meadow_vertex> v(static_cast<size_t>(count));
    std::vector<int32_t> strips(static_cast<size_t>(count) / BOREAS_MEADOW_VERTEX_STRIDE);
    EXPECT_EQ(boreas_meadow_get_vertices(world.handle(), meadow, nullptr, v.data(), count, &count, strips.data()),
              BOREAS_OK);
    Points out;
    for (size_t c = 0; c < strips.size(); ++c)
      if (cell < 0 || of[c] == cell)
        for (int32_t i = 0; i < strips[c]; ++i) {
          const float* x = v[c * BOREAS_MEADOW_VERTEX_STRIDE + size_t(i)].position;
          out.push_back({x[0], x[1], x[2]});
        }
    return out;
  }
  tinygltf::Model exported(int clumps, int frames, float size = 1.0f, float warmup = 0.0f,
                           float frame_time = 1.0f / 24.0f, int steps_per_frame = 2) {
    const std::string path = (std::filesystem::temp_directory_path() / "boreas_animation_clumps.glb").string();
    boreas_animation_def d = boreas_default_animation_def();
    d.frames = frames;
    d.frame_time = frame_time;
    d.steps_per_frame = steps_per_frame;
    d.meadows = &meadow;
    d.meadow_count = 1;
    d.meadow_clumps = clumps;
    d.clump_size = size;
    d.warmup = warmup;
    EXPECT_EQ(boreas_world_export_animation(world.handle(), &d, nullptr, 0, path.c_str()), BOREAS_OK)
        << boreas_last_error();
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, path)) << err;
    std::filesystem::remove(path);
    return m;
  }
};

// Instances by name "meadow0_clumpK_cellC": cell -> (clump, node).
std::map<int, std::pair<int, const tinygltf::Node*>> instances(const tinygltf::Model& m) {
  std::map<int, std::pair<int, const tinygltf::Node*>> out;
  for (const tinygltf::Node& n : m.nodes) {
    int k = -1, c = -1;
    if (std::sscanf(n.name.c_str(), "meadow0_clump%d_cell%d", &k, &c) == 2) {
      EXPECT_EQ(out.count(c), 0u) << "one instance a cell";
      out[c] = {k, &n};
    }
  }
  return out;
}

double farthest(const Points& a, const Points& b) {
  EXPECT_EQ(a.size(), b.size());
  double most = 0.0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    most = std::max(most, std::hypot(a[i][0] - b[i][0], a[i][1] - b[i][1], a[i][2] - b[i][2]));
  return most;
}

// From rest in a steady wind the loop holds the meadow's first bend (a seam of several
// frames' motion); after a warm-up (the def's: the base still taken at rest), its sway
// about the bent pose. Each clump's loop is the window of `frames` keys among the first 3 frames - 2 whose last key
// is nearest its first: found here in boreas's steps of a twin world (the earliest of the
// least seams) and checked against what the file plays. Returns the seam the loop closes
// (the drift from the window's first key to its last) and the most a vertex moves in one
// frame in that window, both as boreas stepped them.
struct Seam {
  double drift = 0, frame = 0;
};
// The keys: 12 at 24 a second, 2 steps a key; or the default scene's, 20 at 6 a second,
// 4 steps a key (render/scenes/default.json).
struct Keys {
  int frames = 12, steps = 2;
  float frame_time = 1.0f / 24.0f;
};
Seam loops_as_stepped(float warmup, bool swaying = false, Keys t = {}) {
  ClumpScene scene(swaying), twin(swaying);
  const int frames = t.frames, keys = 3 * frames - 2;
  const float dt = t.frame_time / float(t.steps);
  const int warmup_steps = int(std::lround(warmup / dt));
  for (int s = 0; s < warmup_steps; ++s) twin.world.step(dt);
  const Points rest = scene.cell_vertices(-1);
  const tinygltf::Model m = scene.exported(2, frames, 1.0f, warmup, t.frame_time, t.steps);
  EXPECT_NEAR(scene.world.get_time(), double(warmup_steps + t.steps * (keys - 1)) * dt, 1e-4)
      << "the warm-up and the keys the loops are sought in stepped";
  const auto placed = instances(m);
  std::map<int, std::vector<Points>> stepped;  // cell -> its strips at each key
  for (int k = 0; k < keys; ++k) {
    if (k > 0)
      for (int s = 0; s < t.steps; ++s) twin.world.step(dt);
    for (const auto& [cell, at] : placed) stepped[cell].push_back(twin.cell_vertices(cell));
  }
  // Each clump's own cell: the instance whose first key is one of that cell's keys (the
  // window's first), found in the earliest window of the least seam.
  std::map<int, std::pair<int, int>> own;  // clump -> its cell, its window's first key
  for (const auto& [cell, at] : placed) {
    const Points first = played(m, *at.second, 0);
    const std::vector<Points>& s = stepped[cell];
    if (first.size() != s[0].size()) continue;
    int start = 0;
    for (int w = 1; w + frames <= keys; ++w)
      if (farthest(s[size_t(w + frames - 1)], s[size_t(w)]) < farthest(s[size_t(start + frames - 1)], s[size_t(start)]))
        start = w;
    if (farthest(first, s[size_t(start)]) < 2e-3) own[at.first] = {cell, start};
  }
  EXPECT_EQ(own.size(), 2u) << "both clumps at their own cells, each playing its least seam's window";
  double off = 0, departed = 0, moved = 0, bent = 0;
  Seam seam;
  for (const auto& [clump, found] : own) {
    const auto [cell, start] = found;
    const std::vector<Points> s(stepped[cell].begin() + start, stepped[cell].begin() + start + frames);
    for (int k = 0; k < frames; ++k) {
      const Points p = played(m, *placed.at(cell).second, size_t(k));
      Points looped = s[size_t(k)];
      for (size_t v = 0; v < looped.size(); ++v)
        for (size_t a = 0; a < 3; ++a)
          looped[v][a] -= double(k) / (frames - 1) * (s[frames - 1][v][a] - s[0][v][a]);
      off = std::max(off, farthest(p, looped));
      departed = std::max(departed, farthest(p, s[size_t(k)]));
      moved = std::max(moved, farthest(s[0], s[size_t(k)]));
      if (k > 0) seam.frame = std::max(seam.frame, farthest(s[size_t(k - 1)], s[size_t(k)]));
    }
    seam.drift = std::max(seam.drift, farthest(s[0], s[frames - 1]));
    EXPECT_LE(farthest(played(m, *placed.at(cell).second, frames - 1), played(m, *placed.at(cell).second, 0)), 1e-5)
        << "the last key is the first";
    std::printf("clump %d: its loop from key %d\n", clump, start);
  }
  bent = farthest(rest, twin.cell_vertices(-1));  // how far the meadow stands from its rest (the base)
  std::printf("%s, after %d warm-up steps: bent %.4f m from rest; clumps moved up to %.4f m; drift first to last key "
              "%.4f m, a frame's motion up to %.4f m; played within %.5f m of the loop, %.4f m of boreas's steps\n",
              swaying ? "swaying" : "steady", warmup_steps, bent, moved, seam.drift, seam.frame, off, departed);
  EXPECT_GT(warmup_steps ? bent : moved, 0.01) << "the wind moved the clumps";
  EXPECT_LE(off, 1e-3 + 1e-5) << "the loop within the tolerance";
  EXPECT_LE(departed, seam.drift + 1e-3 + 1e-5) << "boreas's steps within the drift (the stated bound)";
  return seam;
}

TEST(AnimationClumps, AClumpLoopsAsBoreasSteppedItFromRest) {
  const Seam seam = loops_as_stepped(0.0f);
  EXPECT_GT(seam.drift, 2 * seam.frame) << "from rest the loop undoes the first bend: its seam is frames' motion";
}

// The command's default warm-up (render/cli/animation_command.h) in the default scene's
// waves and keys: the seam the loop closes is no more than what one frame of boreas's
// motion moves a vertex.
TEST(AnimationClumps, AfterTheWarmUpTheLoopsSeamIsWithinAFramesMotion) {
  const Seam seam = loops_as_stepped(2.0f, true, {20, 4, 1.0f / 6.0f});
  EXPECT_LE(seam.drift, seam.frame) << "the loop closes within a frame's motion";
}

TEST(AnimationClumps, InstancesCoverTheMeadowWithItsDensity) {
  ClumpScene scene;
  const double size = 0.25;  // 12 x 8 cells
  const int columns = 12;
  const std::vector<int> of = scene.cells(size);
  std::map<int, int> in_cell;
  std::map<int, double> ground;  // mean y of the cell's ground-fixed bases
  std::map<int, int> roots;
  const std::vector<boreas_component> c = scene.components();
  for (size_t i = 0; i < c.size(); ++i) {
    ++in_cell[of[i]];
    if (c[i].parent < 0) {
      ground[of[i]] += c[i].base[1];
      ++roots[of[i]];
    }
  }
  const tinygltf::Model m = scene.exported(3, 3, float(size));
  const auto placed = instances(m);
  EXPECT_EQ(placed.size(), roots.size()) << "a clump on every cell with plants";
  std::map<int, int> first;  // clump -> the cell of its first instance: the others are placed from it
  size_t vertices = 0;
  for (const auto& [cell, at] : placed) {
    ASSERT_TRUE(roots.count(cell)) << cell;
    const auto& mesh = m.meshes[size_t(at.second->mesh)];
    vertices += m.accessors[size_t(mesh.primitives[0].attributes.at("POSITION"))].count;
    if (!first.count(at.first)) {
      first[at.first] = cell;
      continue;
    }
    // Translation differences between two instances of one clump: the cells' centers and grounds.
    const int a = cell, fc = first[at.first];
    const tinygltf::Node& f = *placed.at(fc).second;
    const double dx = size * ((a % columns) - (fc % columns)), dz = size * ((a / columns) - (fc / columns));
    const double dy = ground[a] / roots[a] - ground[fc] / roots[fc];
    EXPECT_NEAR(at.second->matrix[12] - f.matrix[12], dx, 1e-4) << "cell " << a;
    EXPECT_NEAR(at.second->matrix[14] - f.matrix[14], dz, 1e-4) << "cell " << a;
    EXPECT_NEAR(at.second->matrix[13] - f.matrix[13], dy, 1e-4) << "cell " << a << ": its ground";
  }
  const size_t all = scene.cell_vertices(-1).size();
  std::printf("%zu instances of 3 clumps: %zu strip vertices for the meadow's %zu\n", placed.size(), vertices, all);
  // 3 clumps for 16 cells of very different counts: a share's clump is the cell nearest its
  // mean, not the mean (measured: 78 %; the default scene's meadows, 4 clumps each: 1.85 M
  // strip vertices of about 1.9 M).
  EXPECT_NEAR(double(vertices), double(all), 0.25 * double(all)) << "the meadow's density, near enough";
  // As many clumps as cells (1 m: 6 cells at most): every cell its own, the meadow's vertices exactly.
  const tinygltf::Model every = scene.exported(BOREAS_ANIMATION_MAX_CLUMPS, 3);
  size_t exact = 0;
  for (const auto& [cell, at] : instances(every))
    exact += every.accessors[size_t(every.meshes[size_t(at.second->mesh)].primitives[0].attributes.at("POSITION"))].count;
  EXPECT_EQ(exact, all);
}

TEST(AnimationClumps, BadFieldsAreNamed) {
  ClumpScene scene;
  const std::string path = (std::filesystem::temp_directory_path() / "boreas_animation_clumps_bad.glb").string();
  auto refused = [&](int clumps, float size, const char* named) {
    boreas_animation_def d = boreas_default_animation_def();
    d.frames = 2;
    d.meadows = &scene.meadow;
    d.meadow_count = 1;
    d.meadow_clumps = clumps;
    d.clump_size = size;
    EXPECT_EQ(boreas_world_export_animation(scene.world.handle(), &d, nullptr, 0, path.c_str()),
              BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(boreas_last_error()).find(named), std::string::npos) << boreas_last_error();
  };
  refused(-1, 1.0f, "meadow_clumps");
  refused(BOREAS_ANIMATION_MAX_CLUMPS + 1, 1.0f, "meadow_clumps");
  refused(2, 0.05f, "clump_size");
  refused(2, NAN, "clump_size");
  auto warm = [&](float warmup) {
    boreas_animation_def d = boreas_default_animation_def();
    d.frames = 2;
    d.warmup = warmup;
    EXPECT_EQ(boreas_world_export_animation(scene.world.handle(), &d, nullptr, 0, path.c_str()),
              BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(boreas_last_error()).find("warmup"), std::string::npos) << boreas_last_error();
  };
  warm(-1.0f);
  warm(NAN);
  warm(BOREAS_ANIMATION_MAX_WARMUP_SECONDS * 2.0f);
  EXPECT_EQ(scene.world.get_time(), 0.0) << "nothing stepped";
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
