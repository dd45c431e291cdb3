// boreas: a meadow in the animated glTF as a few representative clumps
// (boreas_animation_def.meadow_clumps). The meadow's rectangle is tiled by square cells; its
// cells with plants, ranked by their count, fall in n equal shares, each with one clump (the
// share's cell nearest its mean count, then species counts: its components, stepped by boreas in the
// meadow's wind like the rest) instanced on every cell of the share, at the cell's ground
// height and a phase of its own. The clumps' keys are made a loop (close_loops) so an
// instance can start anywhere in it.
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
  // After the last key: the drift between the first and last key taken out linearly, so
  // the last key is the first (vertex v at key k moves by -k / (keys - 1) of its drift).
  void close_loops();

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

// The cell (column + columns * row) of each component: its root's base on the meadow's
// grid of cells of about `size` (columns, rows: the grid's). For tests as well.
std::vector<int> component_cells(const std::vector<boreas_component>& components,
                                 const std::array<double, 3>& origin, double center_x,
                                 double center_z, double size_x, double size_z, double size,
                                 int* columns, int* rows);

}  // namespace boreas::impl
