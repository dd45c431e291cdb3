// boreas: a BlobTree model packed for the polygonizer's kernels — the grid it is sampled on,
// its primitives and cuts as float planes (cl/shared/blobtree_types.h), and the spatial
// bins that let each grid point evaluate only the primitives that reach it.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "blobtree/blobtree_model.h"

namespace boreas::impl {

// Grid points at origin + cell * (x, y, z); every count a multiple of BOREAS_BT_BIN.
struct BlobGrid {
  glm::dvec3 origin{0.0};
  double cell = 1.0;  // m
  int nx = 0, ny = 0, nz = 0;

  int64_t points() const { return int64_t(nx) * ny * nz; }
  int bins_x() const { return nx / 8; }
  int bins_y() const { return ny / 8; }
  int bins_z() const { return nz / 8; }
  glm::dvec3 point(int x, int y, int z) const { return origin + cell * glm::dvec3(x, y, z); }
};

// The grid over the model's bounds with `resolution` points along its longest side (at
// least one empty cell all round, so the surface closes inside the grid); with cubic, the
// same count along every side (the bounds centred in a cube). Throws std::invalid_argument
// for a resolution outside 16..1024 or a model with nothing in it.
BlobGrid blob_grid(const BlobModel& model, int resolution, bool cubic = false);

// Positions in the planes are relative to `origin` (the grid's): the kernels then work
// with small floats wherever the tree stands (a tree 100 km out would otherwise lose
// centimetres, and its mesh would gain zero-area triangles).
struct BlobPlanes {
  glm::dvec3 origin{0.0};
  int n = 1;  // primitives' stride (at least 1)
  int count = 0;
  std::vector<float> prims;   // BOREAS_BT_FLOATS planes
  std::vector<int32_t> ints;  // BOREAS_BT_INTS planes
  int nc = 1;                 // cuts' stride
  int cut_count = 0;
  std::vector<float> cuts;  // BOREAS_BT_CUT_FLOATS planes
};

BlobPlanes blob_planes(const BlobModel& model, const glm::dvec3& origin);

// Bin (bx, by, bz) covers the grid positions [8 b, 8 (b + 1)] cells on each axis, so any
// point of the grid's box belongs to the bin of floor(coordinate / 8 cells). Its list,
// items[first[bin] .. first[bin + 1]), holds every primitive whose reach (blob_reach, with
// a margin for float rounding) meets the bin's box, ascending.
struct BlobBins {
  int bx = 0, by = 0, bz = 0;
  std::vector<int32_t> first;  // bins + 1
  std::vector<int32_t> items;
};

BlobBins blob_bins(const BlobModel& model, const BlobGrid& grid);

}  // namespace boreas::impl
