// boreas tests and benchmarks: the ray forest (ray_forest.h) through the public C API.
#include "ray_forest.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace boreas::reference {

namespace {

void check(boreas_status status, const char* call) {
  if (status != BOREAS_OK)
    throw std::runtime_error(std::string("ray forest: ") + call + ": " + boreas_last_error());
}

// A world whose grid covers the stand, with a strong main wave and a cross wave, so that
// branches and leaves move visibly between steps.
boreas_world make_world(float half_extent, float wind) {
  boreas_world_def def = boreas_default_world_def();
  def.grid.cell_size = 4.0f;
  const int cells = std::clamp(int(std::ceil(2.0f * half_extent / def.grid.cell_size)) + 2, 4, 64);
  def.grid.resolution[0] = def.grid.resolution[2] = cells;
  def.grid.resolution[1] = 8;
  def.grid.origin[0] = def.grid.origin[2] = -0.5f * float(cells) * def.grid.cell_size;
  def.grid.origin[1] = 0.0f;
  boreas_wave waves[2] = {boreas_default_wave(), boreas_default_wave()};
  waves[0].direction[0] = 1.0f;
  waves[0].amplitude = wind;
  waves[0].wavelength = 40.0f;
  waves[0].speed = 6.0f;
  waves[1].direction[0] = 0.3f;
  waves[1].direction[2] = 1.0f;
  waves[1].amplitude = 0.4f * wind;
  waves[1].wavelength = 11.0f;
  waves[1].speed = 4.0f;
  def.waves = waves;
  def.wave_count = 2;
  boreas_world world = nullptr;
  check(boreas_world_create(&def, &world), "boreas_world_create");
  return world;
}

float bezier(const float p[4][3], float t, int k) {
  const float s = 1.0f - t;
  return s * s * s * p[0][k] + 3.0f * s * s * t * p[1][k] + 3.0f * s * t * t * p[2][k] +
         t * t * t * p[3][k];
}

// A ray from `origin` at `target`, to 1.5 times its distance.
boreas_ray aimed(const float origin[3], const float target[3]) {
  boreas_ray r{};
  float length = 0.0f;
  for (int k = 0; k < 3; ++k) {
    r.origin[k] = origin[k];
    r.direction[k] = target[k] - origin[k];
    length += r.direction[k] * r.direction[k];
  }
  r.max_distance = 1.5f * std::sqrt(length);
  return r;
}

}  // namespace

std::unique_ptr<RayForest> make_ray_forest(const RayForestDef& def) {
  auto f = std::make_unique<RayForest>();
  const int side = std::max(1, int(std::ceil(std::sqrt(double(def.trees)))));
  f->half_extent = 0.5f * float(side) * def.spacing;
  f->world = make_world(f->half_extent + 8.0f, def.wind);
  const float first = -0.5f * float(side - 1) * def.spacing;
  for (int i = 0; i < def.trees; ++i) {
    boreas_tree_def d = boreas_default_tree_def();
    const size_t species = size_t(i) % def.species.size();
    d.species = def.species[species].c_str();
    d.seed = uint64_t(1 + (i / int(def.species.size())) % std::max(1, def.templates));
    d.position[0] = first + float(i % side) * def.spacing;
    d.position[2] = first + float(i / side) * def.spacing;
    d.rotation = std::fmod(2.39996f * float(i), 6.2831853f);  // the golden angle
    d.scale = def.scale * (0.85f + 0.3f * float((i * 7919) % 101) / 100.0f);
    f->tree_defs.push_back(d);
  }
  f->trees.resize(f->tree_defs.size());
  if (!f->tree_defs.empty())
    check(boreas_world_add_trees(f->world, f->tree_defs.data(), int(f->tree_defs.size()),
                                 f->trees.data()),
          "boreas_world_add_trees");
  if (def.components > 0) {
    f->meadow_def = boreas_default_meadow_def();
    f->meadow_def.size[0] = f->meadow_def.size[1] = 2.0f * f->half_extent;
    f->meadow_def.density = float(double(def.components) / (4.0 * double(f->half_extent) *
                                                            double(f->half_extent)));
    f->meadow_def.terrain_relief = 0.0f;  // flat ground at y = 0
    check(boreas_world_add_meadow(f->world, &f->meadow_def, &f->meadow), "boreas_world_add_meadow");
  }
  for (size_t m = 0; m < def.mesh_tree_models.size(); ++m) {
    boreas_mesh_tree_def d = boreas_default_mesh_tree_def();
    d.model = def.mesh_tree_models[m].c_str();
    d.position[0] = f->half_extent + 3.0f;
    d.position[2] = -f->half_extent + 4.0f * float(m);
    d.cache = 0;
    boreas_mesh_tree_id id{};
    check(boreas_world_add_mesh_tree(f->world, &d, &id), "boreas_world_add_mesh_tree");
    f->mesh_trees.push_back(id);
  }
  std::vector<boreas_branch> branches;
  for (boreas_tree_id t : f->trees) {
    int n = 0;
    check(boreas_tree_get_branches(f->world, t, nullptr, 0, &n), "boreas_tree_get_branches");
    branches.resize(size_t(n));
    check(boreas_tree_get_branches(f->world, t, branches.data(), n, &n), "boreas_tree_get_branches");
    for (const boreas_branch& b : branches)
      for (int c = 0; c < 4; ++c) f->top = std::max(f->top, b.control_points[c][1]);
  }
  return f;
}

std::vector<float> ground_positions(const RayForest& forest) {
  const float h = 0.5f * forest.meadow_def.size[0], y = forest.meadow_def.center[1];
  const float cx = forest.meadow_def.center[0], cz = forest.meadow_def.center[2];
  return {cx - h, y, cz - h, cx + h, y, cz - h, cx - h, y, cz + h, cx + h, y, cz + h};
}

void add_to_embree(const RayForest& forest, EmbreeWorld* embree, bool flat_ground) {
  for (size_t t = 0; t < forest.trees.size(); ++t)
    // The outline the tree's leaves wear: its species' (public kinds count from 1).
    embree->add_tree(forest.world, forest.trees[t], forest.tree_defs[t].levels,
                     int(boreas_species_leaf_outline(forest.tree_defs[t].species)) - 1);
  if (!boreas_meadow_id_is_null(forest.meadow)) embree->add_meadow(forest.world, forest.meadow);
  if (!boreas_meadow_id_is_null(forest.meadow) && flat_ground) {
    const boreas_object_id ground{forest.meadow.index, forest.meadow.generation,
                                  forest.meadow.tag};
    embree->add_triangles(BOREAS_HIT_GROUND, ground, ground_positions(forest),
                          {0, 1, 2, 1, 3, 2});
  }
  for (boreas_mesh_tree_id m : forest.mesh_trees) embree->add_mesh_tree(forest.world, m);
}

std::vector<boreas_ray> forest_rays(const RayForest& forest, int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float reach = forest.half_extent + 4.0f;
  auto origin = [&](float* o) {
    o[0] = (2.0f * unit(rng) - 1.0f) * reach;
    o[1] = 0.2f + unit(rng) * std::max(1.0f, 1.2f * forest.top);
    o[2] = (2.0f * unit(rng) - 1.0f) * reach;
  };
  // Every tree's leaves and branches as of the last step, read once.
  std::vector<std::vector<boreas_leaf>> leaves(forest.trees.size());
  std::vector<std::vector<boreas_branch>> branches(forest.trees.size());
  for (size_t t = 0; t < forest.trees.size(); ++t) {
    int n = 0;
    check(boreas_tree_get_leaves(forest.world, forest.trees[t], nullptr, 0, &n),
          "boreas_tree_get_leaves");
    leaves[t].resize(size_t(n));
    check(boreas_tree_get_leaves(forest.world, forest.trees[t], leaves[t].data(), n, &n),
          "boreas_tree_get_leaves");
    check(boreas_tree_get_branches(forest.world, forest.trees[t], nullptr, 0, &n),
          "boreas_tree_get_branches");
    branches[t].resize(size_t(n));
    check(boreas_tree_get_branches(forest.world, forest.trees[t], branches[t].data(), n, &n),
          "boreas_tree_get_branches");
  }
  std::normal_distribution<float> gauss;
  std::vector<boreas_ray> rays;
  rays.reserve(size_t(count));
  for (int i = 0; i < count; ++i) {
    float o[3];
    origin(o);
    const int mode = forest.trees.empty() ? 0 : i % 3;
    if (mode == 0) {
      boreas_ray r{};
      for (int k = 0; k < 3; ++k) {
        r.origin[k] = o[k];
        r.direction[k] = gauss(rng);
      }
      if (r.direction[0] == 0.0f && r.direction[1] == 0.0f && r.direction[2] == 0.0f)
        r.direction[1] = -1.0f;
      r.max_distance = INFINITY;
      rays.push_back(r);
      continue;
    }
    const size_t tree = size_t(rng() % forest.trees.size());
    float target[3];
    if (mode == 1 && !leaves[tree].empty()) {
      // The middle of the blade: across u = 0.5, halfway from its base to its tip.
      leaf_quad_corner(leaves[tree][size_t(rng() % leaves[tree].size())], 0.5f,
                       0.5f * (kLeafBaseV + kLeafTipV), target);
    } else {
      const boreas_branch& b = branches[tree][size_t(rng() % branches[tree].size())];
      const float t = unit(rng);
      for (int k = 0; k < 3; ++k) target[k] = bezier(b.control_points, t, k);
    }
    rays.push_back(aimed(o, target));
  }
  return rays;
}

}  // namespace boreas::reference
