// boreas: a meadow in the animated glTF as a few representative clumps
// (boreas_animation_def.meadow_clumps). The meadow's rectangle is tiled by square cells; its
// cells with plants, ranked by their count, fall in n equal shares, each with one clump (the
// share's cell nearest its mean count, then species counts: its components, stepped by boreas in the
// meadow's wind like the rest) instanced on every cell of the share, at the cell's ground
// height and a phase of its own. The clumps' keys are made a loop (close_loops) so an
// instance can start anywhere in it; the loop is sought among later keys too (the world is
// stepped past the animation's last key for them, MorphGather::loop_search_keys).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "boreas/boreas.h"
#include "boreas_gltf/animation_gltf.h"

namespace boreas::impl {

class World;

struct ClumpParams {
  int clumps = 0;      // per meadow; 0: none (the meadows exact)
  double size = 1.0;   // m: the cells' side, as near as divides the meadow's rectangle
  int frames = 1;      // keys: the phases are 0..frames - 2
};

class MeadowClumps {
 public:
  // Adds the clumps' bases and meshes (with their instances) to *a, without keys yet.
  MeadowClumps(World& world, boreas_meadow_id id, size_t index, const ClumpParams& p,
               gltf::ForestAnimation* a);
  // Appends every clump's vertices as the world has them now.
  void key();
  // After the last key, each clump's loop: the window of `frames` keys (of the keys taken,
  // frames or more) whose last key is nearest its first (loop_start), the drift between
  // them taken out linearly so the last key is the first (vertex v at the window's key k
  // moves by -k / (frames - 1) of its drift).
  void close_loops(size_t frames);

 private:
  struct Clump {
    size_t copy;                       // index in a_->morphed
    std::vector<uint32_t> components;  // the cell's, in the meadow's order
  };
  World& world_;
  boreas_meadow_id id_;
  gltf::ForestAnimation* a_;
  std::vector<Clump> clumps_;
};

// The first key of the window of `frames` keys whose last key is nearest its first (the
// farthest vertex's distance; the earliest of equals): in a sway, a window about a turn
// of the clump's motion, so the seam its loop closes is the least the keys offer.
size_t loop_start(const std::vector<std::vector<float>>& keys, size_t frames);

// The cell (column + columns * row) of each component: its root's base on the meadow's
// grid of cells of about `size` (columns, rows: the grid's). For tests as well.
std::vector<int> component_cells(const std::vector<boreas_component>& components,
                                 const std::array<double, 3>& origin, double center_x,
                                 double center_z, double size_x, double size_z, double size,
                                 int* columns, int* rows);

}  // namespace boreas::impl
