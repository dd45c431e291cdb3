// boreas command: the scene's part of the run summary (scene_stats.h).
#include "cli/scene_stats.h"

#include <algorithm>

#include "scene/scene_world.h"

namespace boreas::render {

TreeStats tree_stats(const SceneTree& tree, const TreePose& rest, int leaves) {
  return tree_stats(tree, int(rest.branches.size()), leaves < 0 ? int(rest.leaves.size()) : leaves);
}

TreeStats tree_stats(const SceneTree& tree, int branches, int leaves) {
  TreeStats s;
  s.species = tree.species;
  std::copy(tree.def.position, tree.def.position + 3, s.position);
  s.branches = branches;
  s.leaves = leaves;
  return s;
}

void add_mesh_tree_stats(const boreas::World& world, const Scene& scene,
                         const std::vector<boreas_mesh_tree_id>& ids, RunSummary& summary) {
  for (size_t i = 0; i < ids.size(); ++i) {
    MeshTreeStats s;
    s.model = scene.mesh_trees[i].model;
    std::copy(scene.mesh_trees[i].def.position, scene.mesh_trees[i].def.position + 3, s.position);
    s.info = world.mesh_tree_get_info(ids[i]);
    summary.mesh_trees.push_back(s);
  }
}

void add_meadow_stats(const Scene& scene, const FrameMeadows& meadows, RunSummary& summary) {
  for (size_t i = 0; i < meadows.ids.size(); ++i) {
    const boreas_meadow_def& def = scene.meadows[i].def;
    MeadowStats s;
    s.species = meadows.species[i];
    std::copy(def.center, def.center + 3, s.center);
    std::copy(def.size, def.size + 2, s.size);
    s.density = def.density;
    s.components = meadows.counts[i];
    summary.meadows.push_back(s);
  }
}

void add_collider_stats(const Scene& scene, RunSummary& summary) {
  for (const SceneCollider& collider : scene.colliders) {
    ColliderStats c;
    const boreas_collider_def& d = collider.def;
    c.shape = d.shape == BOREAS_COLLIDER_BOX ? "box"
              : d.shape == BOREAS_COLLIDER_CAPSULE ? "capsule"
                                                   : "sphere";
    c.radius = d.shape == BOREAS_COLLIDER_BOX ? 0.0f : d.radius;
    if (d.shape == BOREAS_COLLIDER_CAPSULE) c.half_height = d.half_height;
    if (d.shape == BOREAS_COLLIDER_BOX) std::copy(d.half_extents, d.half_extents + 3, c.half_extents);
    std::copy(collider.def.pose.position, collider.def.pose.position + 3, c.start);
    std::copy(collider.def.velocity, collider.def.velocity + 3, c.velocity);
    collider_position(collider, summary.sim_time, c.end);
    summary.colliders.push_back(c);
  }
}

}  // namespace boreas::render
