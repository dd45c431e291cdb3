// boreas scenes: builds the world a loaded scene describes, through the public API only,
// and moves the scene's LiDARs along their paths as the world steps (colliders move by the
// velocity in their def, the world's own way).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "boreas/boreas.hpp"
#include "scene/scene.h"

namespace boreas::render {

// The ids of what make_world added, each in the scene's order.
struct SceneIds {
  std::vector<boreas_tree_id> trees;
  std::vector<boreas_mesh_tree_id> mesh_trees;
  std::vector<boreas_meadow_id> meadows;
  std::vector<boreas_collider_id> colliders;
  std::vector<boreas_emitter_id> emitters;
  // One per scene sensor, in its order: the LiDAR's id, or the null id for a depth camera.
  std::vector<boreas_lidar_id> lidars;
};

// device overrides the scene's own request when set. Throws boreas::Error from the library;
// a tree or meadow the library rejects (a bad species file, an unreadable image) keeps its
// status, and its message, which names the file, is prefixed with the scene and the JSON
// path of the tree or meadow. ids, when given, receives the ids of what was added.
// cl_context_properties, when given, makes the world's OpenCL context share a GL context's
// objects (boreas_world_def; pairs ending in 0). focus, when given (x, y, z m), is set
// before anything is added (boreas_world_set_focus): trees whose level of detail from it
// derives their finest level settle as they are added, never holding it whole.
boreas::World make_world(const Scene& scene, const std::optional<std::string>& device,
                         SceneIds* ids = nullptr, const intptr_t* cl_context_properties = nullptr,
                         const float* focus = nullptr);

// Where a collider is at time t (s): center + velocity * t, each axis held within the
// library's +-BOREAS_WORLD_MAX_COORDINATE m.
void collider_position(const SceneCollider& collider, double t, float out[3]);
// Its pose at time t: that position, its orientation turned by angular_velocity * t (the
// world turns it by angular_velocity * dt each step, about a fixed world axis: the same).
boreas_pose collider_pose_at(const SceneCollider& collider, double t);

// Gives each of the scene's LiDARs that travel a path (ids are SceneIds::lidars) its pose
// at time t (s): call it before each step with the step's end, t = time + dt, the pose
// boreas_lidar_set_pose wants.
void move_lidars(boreas::World& world, const Scene& scene, const std::vector<boreas_lidar_id>& ids,
                 double t);

// `steps` world steps of dt, each after move_lidars for its end, as every view of `boreas
// run` makes a frame. Returns the steps' device times per stage, summed (boreas_step_stats;
// total: their wall time), and their breaks (branches_broken).
// (Colliders move themselves in the world's step: the scene's need no hand here.)
boreas_step_stats step_scene(boreas::World& world, const Scene& scene, int steps, float dt,
                             const std::vector<boreas_lidar_id>& lidars = {});

}  // namespace boreas::render
