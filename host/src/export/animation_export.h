// boreas: boreas_world_export_animation — the world's trees stepped for a number of frames
// and written as one animated glTF file (host/gltf/animation_gltf.cpp writes it): each tree
// a skin (trees/tree_skin.h) over its template's mesh, one mesh per template.
#pragma once

#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::impl {

class World;

struct AnimationParams {
  int frames = 48;
  double frame_time = 1.0 / 24.0;
  int steps_per_frame = 1;
  boreas_skin_def skin{};
  bool leaves = true;
  std::vector<boreas_meadow_id> meadows;
  std::vector<boreas_mesh_tree_id> mesh_trees;
  double morph_tolerance = 1e-3;  // m
  int meadow_clumps = 0;          // per meadow; 0: exact
  double clump_size = 1.0;        // m
  int warmup_steps = 0;           // steps of frame_time / steps_per_frame before key 0
};

// The def checked (NULL: the defaults); errors name the field and its range.
AnimationParams checked_animation_def(const boreas_animation_def* def);

// Checks every id, takes the bind pose, steps the world warmup_steps and then
// (frames - 1) * steps_per_frame times, keying, and writes path.
void export_animation(World& world, const AnimationParams& p, const std::vector<boreas_tree_id>& trees,
                      const std::string& path);

}  // namespace boreas::impl
