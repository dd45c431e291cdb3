// boreas: the C API of a tree's skin (trees/tree_skin.h): the joints, and the bindings of
// the mesh's vertices and the leaves, from the tree's public branch and leaf lists.
#include <vector>

#include "api/c_api_guard.h"
#include "boreas/boreas.h"
#include "export/animation_export.h"
#include "trees/tree_skin.h"

namespace {

using boreas::api::copy_out;
using boreas::api::guarded;
using boreas::api::world_of;

boreas::impl::LevelGrids level_grids(const boreas::impl::TreeParams& params) {
  boreas::impl::LevelGrids grids{};
  for (size_t l = 0; l < grids.size(); ++l)
    grids[l] = {params.levels[l].rings, params.levels[l].sides};
  return grids;
}

}  // namespace

boreas_skin_def boreas_default_skin_def(void) {
  boreas_skin_def d{};
  d.max_level = 3;
  d.segments = 4;
  return d;
}

boreas_status boreas_tree_get_joints(boreas_world world, boreas_tree_id tree,
                                     const boreas_skin_def* def, boreas_joint* out, int capacity,
                                     int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    const boreas::impl::SkinParams p = boreas::impl::checked_skin_def(def);
    copy_out(boreas::impl::skin_joints(w.tree_branches(tree), p), out, capacity, count);
  });
}

boreas_status boreas_tree_get_skin_weights(boreas_world world, boreas_tree_id tree,
                                           const boreas_skin_def* def, boreas_skin_weight* out,
                                           int capacity, int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    const boreas::impl::SkinParams p = boreas::impl::checked_skin_def(def);
    const boreas::impl::LevelGrids grids = level_grids(w.tree(tree).params);
    const std::vector<float> caps = boreas::impl::skin_tip_caps(w.tree(tree).model);
    copy_out(boreas::impl::skin_vertex_weights(w.tree_branches(tree), caps, grids, p), out,
             capacity, count);
  });
}

boreas_status boreas_tree_get_leaf_skin_weights(boreas_world world, boreas_tree_id tree,
                                                const boreas_skin_def* def,
                                                boreas_skin_weight* out, int capacity,
                                                int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    const boreas::impl::SkinParams p = boreas::impl::checked_skin_def(def);
    copy_out(boreas::impl::skin_leaf_weights(w.tree_branches(tree), w.tree_leaves(tree), p), out,
             capacity, count);
  });
}

boreas_animation_def boreas_default_animation_def(void) {
  boreas_animation_def d{};
  d.frames = 48;
  d.frame_time = 1.0f / 24.0f;
  d.steps_per_frame = 1;
  d.skin = boreas_default_skin_def();
  d.skin.max_level = 1;
  d.skin.segments = 2;
  d.leaves = 1;
  d.morph_tolerance = 1e-3f;
  d.meadow_clumps = 0;
  d.clump_size = 1.0f;
  d.warmup = 0.0f;
  return d;
}

boreas_status boreas_world_export_animation(boreas_world world, const boreas_animation_def* def,
                                            const boreas_tree_id* trees, int tree_count,
                                            const char* path) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    const boreas::impl::AnimationParams p = boreas::impl::checked_animation_def(def);
    if (tree_count < 0 || (tree_count > 0 && !trees))
      boreas::impl::fail_argument("trees is NULL or tree_count " + std::to_string(tree_count) +
                                  " is negative");
    if (!path) boreas::impl::fail_argument("path is NULL");
    boreas::impl::export_animation(w, p, std::vector<boreas_tree_id>(trees, trees + tree_count),
                                   path);
  });
}
