// boreas: the marching cubes case table of the BlobTree polygonizer, generated from one
// rule instead of typed in, and a host marching cubes over a grid of values that uses it
// (the reference the device polygonizer's meshes are compared with).
//
// Conventions: cl/shared/blobtree_types.h (corner and edge numbering, BOREAS_BT_CASE_*).
// The rule: a corner is inside when its value is > iso. On every face of the cube the
// crossing points of the face's sign-changing edges are joined in pairs; a face with two
// diagonally opposite inside corners joins them so that each inside corner is cut off on
// its own (the inside corners are separated). The rule looks at one face's four corners
// only, so two cubes sharing a face join its crossings the same way: the surface has no
// cracks, and every crossing point belongs to exactly one polygon in a cube, so it is a
// closed 2-manifold wherever the inside region does not touch the grid's border. Each
// polygon is fanned into triangles, counter-clockwise seen from outside (from the lower
// values).
//
// A row's order: polygons by their lowest edge, each walked in its counter-clockwise order
// from that edge; the fan's apex is the first vertex of that walk with no diagonal to a
// vertex on a face it shares. (Such a diagonal would lie in the face, where the cube
// beyond may lay the same one: an edge of four triangles. Every polygon the rule makes has
// such an apex.) A triangle is (apex, v_i, v_i+1). The largest case has 5 triangles; a
// value equal to iso is outside.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "shared/blobtree_types.h"

namespace boreas::impl {

// 256 rows of BOREAS_BT_CASE_ENTRIES edge indices, -1 after the last triangle.
const std::array<int8_t, 256 * BOREAS_BT_CASE_ENTRIES>& cube_case_table();

// Triangles of case `config` (0..255).
int cube_case_triangles(int config);

// A triangle mesh: positions, and three indices per triangle.
struct GridMesh {
  std::vector<glm::dvec3> positions;
  std::vector<uint32_t> indices;
};

// Marching cubes over values[(z * ny + y) * nx + x] at origin + cell * (x, y, z): one vertex
// per sign-changing grid edge, placed by linear interpolation to iso (its parameter along
// the edge clamped to [1e-4, 1 - 1e-4], so no triangle collapses to a point), shared by
// the cubes around the edge. Vertex order: by the grid point the edge starts at (its
// linear index), then the edge's axis (x, y, z). Triangle order: by cube (the linear index
// of its corner 0), then the table's order. The device polygonizer emits the same order.
GridMesh marching_cubes(const std::vector<double>& values, int nx, int ny, int nz,
                        const glm::dvec3& origin, double cell, double iso);

}  // namespace boreas::impl
