// boreas: polygonizing a BlobTree on the device (Galbraith et al. 2004 sec. 4 needed a
// minute; this takes well under a second for a whole tree on a 2-core CPU).
//
// Stages, each one launch or a few, on the world's queue:
//  1. field: F at every grid point, one bin of 8^3 points per work-group, each point
//     evaluating only its bin's primitives (cl/blobtree_field.cl; on CPUs a work-item
//     takes the SIMD width of points), in slabs of bins so progress can be reported;
//  2. count: vertices and triangles per grid row (cl/blobtree_mesh.cl);
//  3. the host scans the counts into each row's first vertex and triangle;
//  4. emit: marching cubes with the generated case table (cube_cases.h): vertices on the
//     sign-changing edges by linear interpolation, triangles indexing them;
//  5. attributes: normals from the field's gradient (differences of the exact field at
//     the corners of a tetrahedron around the vertex, not of the grid) and texture coordinates
//     blended from the primitives', the vertices read back and taken in the order of their
//     bins (vertices_by_bin) so that the lanes of a work-item walk few lists.
//
// Why marching cubes: the issue asks for a watertight manifold mesh, and a marching cubes
// table whose ambiguous faces are decided by the face alone gives exactly that by
// construction (cube_cases.h), with no vertex shared between two sheets. Surface nets and
// dual contouring put one vertex per cell, which joins separate sheets that pass through
// one cell into a non-manifold vertex — common at a tree's thin branches and crotches —
// and need a repair pass to be manifold.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "blobtree/blobtree_bins.h"
#include "blobtree/blobtree_model.h"
#include "runtime/launch.h"

namespace boreas::impl {

// fraction 0..1 of the whole polygonization, and the stage running.
using BlobProgress = std::function<void(double fraction, const char* stage)>;

struct BlobMesh {
  BlobGrid grid;
  std::vector<float> positions;   // 3 per vertex, m
  std::vector<float> normals;     // 3 per vertex, unit, outward
  std::vector<float> uvs;         // 2 per vertex
  std::vector<uint32_t> indices;  // 3 per triangle, counter-clockwise seen from outside
  int64_t bin_items = 0;          // primitive evaluations per bin's point, summed over bins

  size_t vertex_count() const { return positions.size() / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
};

// Device buffers kept from one polygonization to the next. On PoCL the first writes to a
// fresh 64 MiB field grid cost several times the field kernel itself (the pages are
// touched for the first time), so a world keeps its grid buffer while it is at most
// kMaxKeptBytes.
struct BlobScratch {
  static constexpr size_t kMaxKeptBytes = size_t(128) << 20;
  cl::Buffer field;
  size_t field_bytes = 0;
};

struct PolygonizeOptions {
  bool naive = false;              // every primitive at every point (the benchmark's baseline)
  BlobProgress progress;           // may be empty
  BlobScratch* scratch = nullptr;  // reused and updated when given
};

// Throws boreas::Error (BOREAS_ERROR_OUT_OF_MEMORY naming the sizes when the grid or the
// mesh does not fit the device, BOREAS_ERROR_OPENCL for a failed call).
BlobMesh polygonize_blobtree(Runtime& rt, const BlobModel& model, const BlobGrid& grid,
                             const PolygonizeOptions& options = {});

// Stage 1's range over z_points of the grid's planes (whole bins): each work-item evaluates
// the kernel's SIMD width of points (cl/shared/simd_width.h), at most a bin's 8 along x and
// the rest along y. The launch table (runtime/launch.cpp) makes a work-group span the bin
// along x and as much of it along y and z as the kernel can run, so no group straddles two
// bins.
Items blobtree_field_items(const BlobGrid& grid, int simd_width, size_t z_points);

// Stage 5's order of the vertices (positions: 3 floats each, in the grid's frame): by the
// bin holding each (x fastest, then y, z), in vertex order within a bin. A work-item's
// lanes then take vertices of one bin or a few, and walk few lists of primitives; the
// order changes the speed only, never a value.
std::vector<int32_t> vertices_by_bin(const std::vector<float>& positions, const BlobGrid& grid,
                                     const BlobBins& bins);

// Stage 1 alone, read back: F at every grid point, (z * ny + y) * nx + x.
std::vector<float> sample_blobtree_field(Runtime& rt, const BlobModel& model, const BlobGrid& grid,
                                         bool naive = false);

}  // namespace boreas::impl
