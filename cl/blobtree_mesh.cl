/* boreas: marching cubes over the BlobTree's sampled field, in three launches — count
 * (vertices and triangles per grid row), emit (at the rows' offsets, which the host scans
 * from the counts), attributes (normals from the field's gradient, blended texture
 * coordinates). A row is the nx points (x, y, z) of one (y, z); row r = z * ny + y. A grid
 * point owns the edges that leave it along +x, +y and +z; a vertex sits on every owned edge
 * whose ends are on either side of the iso-value, numbered in row order, then x, then the
 * axis. The cube at point (x, y, z) has its triangles in row order, then x. This is the
 * order of the host's marching_cubes (host/src/blobtree/cube_cases.h). Conventions for
 * corners, edges and the case table: shared/blobtree_types.h. */
#include "shared/blobtree_field.h"

#define BOREAS_BT_INSIDE(v) ((v) > BOREAS_BT_ISO)

/* Bits 0..2: the owned x, y, z edges of point (x, y, z) that cross the surface. */
BOREAS_FN int boreas_bt_crossings(__global const float* field, int nx, int ny, int nz, int x, int y,
                                  int z) {
  size_t i = ((size_t)z * ny + y) * nx + x;
  int in = BOREAS_BT_INSIDE(field[i]);
  int bits = 0;
  if (x + 1 < nx && BOREAS_BT_INSIDE(field[i + 1]) != in) bits |= 1;
  if (y + 1 < ny && BOREAS_BT_INSIDE(field[i + nx]) != in) bits |= 2;
  if (z + 1 < nz && BOREAS_BT_INSIDE(field[i + (size_t)nx * ny]) != in) bits |= 4;
  return bits;
}

BOREAS_FN int boreas_bt_bit_count(int bits) {
  return (bits & 1) + ((bits >> 1) & 1) + ((bits >> 2) & 1);
}

/* The marching cubes case of the cube whose corner 0 is point (x, y, z). */
BOREAS_FN int boreas_bt_cube_case(__global const float* field, int nx, int ny, int x, int y,
                                  int z) {
  size_t i = ((size_t)z * ny + y) * nx + x;
  size_t sy = nx, sz = (size_t)nx * ny;
  return BOREAS_BT_INSIDE(field[i]) | (BOREAS_BT_INSIDE(field[i + 1]) << 1) | (BOREAS_BT_INSIDE(field[i + sy]) << 2) |
         (BOREAS_BT_INSIDE(field[i + sy + 1]) << 3) | (BOREAS_BT_INSIDE(field[i + sz]) << 4) |
         (BOREAS_BT_INSIDE(field[i + sz + 1]) << 5) | (BOREAS_BT_INSIDE(field[i + sz + sy]) << 6) |
         (BOREAS_BT_INSIDE(field[i + sz + sy + 1]) << 7);
}

/* Per row, BOREAS_W points of it at a time (simd_width.h): the field of the four rows a
 * row's cubes touch, (y, z), (y+1, z), (y, z+1), (y+1, z+1), at x and x+1, each one
 * contiguous load; where y + 1 or z + 1 is beyond the grid's end it is clamped back to the
 * last row or plane, read and not counted (those edges and cubes are masked). 1 for a
 * point inside the surface, else 0. */
BOREAS_FN BOREAS_I boreas_bt_inside_w(__global const float* row, int x0, int nx) {
  return (boreas_load_w(row, x0, nx) > BOREAS_BT_ISO) & 1;
}

__kernel void boreas_blobtree_count(__global const float* field, int nx, int ny, int nz,
                                    __global const int* case_triangles, __global int* row_vertices,
                                    __global int* row_triangles) {
  int r = min((int)get_global_id(0), ny * nz - 1);
  int y = r % ny;
  int z = r / ny;
  int has_y = y + 1 < ny;
  int has_z = z + 1 < nz;
  int cubes = has_y && has_z;
  __global const float* row = field + ((size_t)z * ny + y) * nx;
  __global const float* row_y = field + ((size_t)z * ny + min(y + 1, ny - 1)) * nx;
  __global const float* row_z = field + ((size_t)min(z + 1, nz - 1) * ny + y) * nx;
  __global const float* row_yz = field + ((size_t)min(z + 1, nz - 1) * ny + min(y + 1, ny - 1)) * nx;
  BOREAS_I vertices = 0, triangles = 0;
  for (int x0 = 0; x0 < nx; x0 += BOREAS_W) {
    BOREAS_I x = x0 + BOREAS_LANES;
    /* Lanes past the row's end (its last work of W) count nothing; x + 1 past it has no
     * x edge and no cube. */
    BOREAS_I point = (x < nx) & 1;
    BOREAS_I next = (x + 1 < nx) & 1;
    BOREAS_I c0 = boreas_bt_inside_w(row, x0, nx), c1 = boreas_bt_inside_w(row, x0 + 1, nx);
    BOREAS_I c2 = boreas_bt_inside_w(row_y, x0, nx), c3 = boreas_bt_inside_w(row_y, x0 + 1, nx);
    BOREAS_I c4 = boreas_bt_inside_w(row_z, x0, nx), c5 = boreas_bt_inside_w(row_z, x0 + 1, nx);
    BOREAS_I c6 = boreas_bt_inside_w(row_yz, x0, nx), c7 = boreas_bt_inside_w(row_yz, x0 + 1, nx);
    /* The owned edges crossing the surface (boreas_bt_crossings). */
    vertices += point * ((c0 ^ c1) * next + (c0 ^ c2) * has_y + (c0 ^ c4) * has_z);
    /* The cube at x (boreas_bt_cube_case's corner order). */
    BOREAS_I c =
        c0 | (c1 << 1) | (c2 << 2) | (c3 << 3) | (c4 << 4) | (c5 << 5) | (c6 << 6) | (c7 << 7);
    triangles += (next * cubes) * BOREAS_GATHER_INT(case_triangles, c);
  }
  row_vertices[r] = BOREAS_HSUM(vertices);
  row_triangles[r] = BOREAS_HSUM(triangles);
}

/* Vertex index of the owned edge along axis a of point x of a row: the row's first vertex,
 * the row's vertices before x (count), and the point's crossing edges before a (bits). */
BOREAS_FN uint boreas_bt_vertex_index(int first, int count, int bits, int a) {
  return (uint)(first + count + boreas_bt_bit_count(bits & ((1 << a) - 1)));
}

__kernel void boreas_blobtree_emit(__global const float* field, int nx, int ny, int nz, float cell,
                                   __global const char* table,
                                   __global const int* vertex_first, __global const int* triangle_first,
                                   __global const int* row_vertices, __global const int* row_triangles,
                                   __global float* positions, __global uint* indices) {
  int r = min((int)get_global_id(0), ny * nz - 1);
  if (row_vertices[r] == 0 && row_triangles[r] == 0) return;
  int y = r % ny;
  int z = r / ny;
  int cubes = y + 1 < ny && z + 1 < nz;
  /* The four rows a cube touches: (y, z), (y+1, z), (y, z+1), (y+1, z+1). */
  int first[4], count[4], bits_x[4], bits_x1[4];
  for (int k = 0; k < 4; ++k) {
    int yy = y + (k & 1), zz = z + (k >> 1);
    int valid = cubes || k == 0;
    first[k] = valid ? vertex_first[zz * ny + yy] : 0;
    count[k] = 0;
    bits_x[k] = valid ? boreas_bt_crossings(field, nx, ny, nz, 0, yy, zz) : 0;
  }
  int tri = triangle_first[r];
  for (int x = 0; x < nx; ++x) {
    /* This row's vertices. */
    size_t i = ((size_t)z * ny + y) * nx + x;
    float f0 = field[i];
    size_t step[3] = {1, (size_t)nx, (size_t)nx * ny};
    for (int a = 0; a < 3; ++a) {
      if (!(bits_x[0] & (1 << a))) continue;
      float f1 = field[i + step[a]];
      float t = (BOREAS_BT_ISO - f0) / (f1 - f0);
      t = clamp(t, 1e-4f, 1.0f - 1e-4f);
      uint v = boreas_bt_vertex_index(first[0], count[0], bits_x[0], a);
      positions[3 * v + 0] = cell * ((float)x + (a == 0 ? t : 0.0f));
      positions[3 * v + 1] = cell * ((float)y + (a == 1 ? t : 0.0f));
      positions[3 * v + 2] = cell * ((float)z + (a == 2 ? t : 0.0f));
    }
    for (int k = 0; k < 4; ++k) {
      int yy = y + (k & 1), zz = z + (k >> 1);
      int valid = (cubes || k == 0) && x + 1 < nx;
      bits_x1[k] = valid ? boreas_bt_crossings(field, nx, ny, nz, x + 1, yy, zz) : 0;
    }
    if (cubes && x + 1 < nx) {
      int c = boreas_bt_cube_case(field, nx, ny, x, y, z);
      __global const char* row = table + c * BOREAS_BT_CASE_ENTRIES;
      int e = 0;
      for (; e < BOREAS_BT_CASE_ENTRIES && row[e] >= 0; ++e) {
        int edge = row[e];
        /* Edges 0-3 along x from corners 0, 2, 4, 6: rows 0-3 at x. 4-7 along y from
         * corners 0, 1, 4, 5: rows 0, 0, 2, 2 at x, x+1. 8-11 along z from corners 0-3:
         * rows 0, 0, 1, 1 at x, x+1. */
        int axis = edge >> 2;
        int j = edge & 3;
        int k = axis == 0 ? j : (axis == 1 ? (j >> 1) * 2 : (j >> 1));
        int plus = axis == 0 ? 0 : (j & 1);
        uint v = plus ? boreas_bt_vertex_index(first[k], count[k] + boreas_bt_bit_count(bits_x[k]), bits_x1[k], axis)
                      : boreas_bt_vertex_index(first[k], count[k], bits_x[k], axis);
        indices[3 * (size_t)tri + e] = v;
      }
      tri += e / 3;
    }
    for (int k = 0; k < 4; ++k) {
      count[k] += boreas_bt_bit_count(bits_x[k]);
      bits_x[k] = bits_x1[k];
    }
  }
}

/* The bins holding the lanes' points (clamped to the grid). */
BOREAS_FN BOREAS_I boreas_bt_bin_of(BOREAS_V3 p, float inv_bin, int bx, int by, int bz) {
  BOREAS_I x = clamp(BOREAS_TO_INT(floor(p.x * inv_bin)), 0, bx - 1);
  BOREAS_I y = clamp(BOREAS_TO_INT(floor(p.y * inv_bin)), 0, by - 1);
  BOREAS_I z = clamp(BOREAS_TO_INT(floor(p.z * inv_bin)), 0, bz - 1);
  return (z * by + y) * bx + x;
}

/* A walk over the primitives of the lanes' bins: at width 1 the bin's list, above it each
 * lane's list merged (shared/blobtree_field_width.inc; neighbouring vertices lie in
 * different bins). */
#if BOREAS_W == 1
#define BOREAS_BT_WALK_OF_BINS BoreasBtList
#define BOREAS_BT_BINS_WALK(items, begin, end) boreas_bt_list((begin), (end))
#else
#define BOREAS_BT_WALK_OF_BINS BOREAS_BT_CURSOR
#define BOREAS_BT_BINS_WALK(items, begin, end) boreas_bt_cursor((items), (begin), (end))
#endif

/* Per vertex: the outward normal -grad F / |grad F| by differences over h, and the
 * texture coordinates blended from the primitives' own (sec. 3.6): the average of each
 * positive primitive's (u, v) weighted by its fall-off there. Planes of `stride`:
 * BOREAS_BT_VERTEX_*, slot s for vertex order[s] (the host orders the vertices by bin, so
 * that neighbouring slots walk the same lists). A work-item takes BOREAS_W consecutive
 * slots (simd_width.h). The global size may exceed the vertices: extra lanes redo the
 * last one. */
__kernel void boreas_blobtree_attributes(__global const float* prims, __global const int* ints, int n,
                                         __global const int* bin_first, __global const int* bin_items,
                                         int bx, int by, int bz, __global const float* cuts, int nc,
                                         float cell, float h, __global const float* positions,
                                         __global const int* order, int count, int stride,
                                         __global float* out) {
  int first = (int)get_global_id(0) * BOREAS_W;
  BOREAS_I i = BOREAS_GATHER_INT(order, min(first + BOREAS_LANES, count - 1));
  BOREAS_V3 p = boreas_v3(BOREAS_GATHER(positions, 3 * i + 0), BOREAS_GATHER(positions, 3 * i + 1),
                          BOREAS_GATHER(positions, 3 * i + 2));
  float inv_bin = 1.0f / (cell * (float)BOREAS_BT_BIN);
  /* The lanes' own h, so that p + h d fuses alike at every width. */
  BOREAS_F hw = h;
  /* The gradient from four samples at the corners of a tetrahedron around p,
   * p + h (+-1, +-1, +-1) with an even number of minus signs: sum_k F_k d_k / (4 h) is the
   * gradient to second order, as central differences are, at 4 field evaluations instead
   * of 6 (the field is the attributes' whole cost). */
  BOREAS_F g0 = 0.0f, g1 = 0.0f, g2 = 0.0f;
  for (int k = 0; k < 4; ++k) {
    float dx = (k == 0 || k == 3) ? 1.0f : -1.0f;
    float dy = (k == 2 || k == 3) ? 1.0f : -1.0f;
    float dz = (k == 1 || k == 3) ? 1.0f : -1.0f;
    BOREAS_V3 q = boreas_v3(p.x + hw * dx, p.y + hw * dy, p.z + hw * dz);
    BOREAS_I bq = boreas_bt_bin_of(q, inv_bin, bx, by, bz);
    BOREAS_F f =
        boreas_bt_field_walk(q, prims, ints, n, bin_items,
                             BOREAS_BT_BINS_WALK(bin_items, BOREAS_GATHER_INT(bin_first, bq),
                                                 BOREAS_GATHER_INT(bin_first, bq + 1)),
                             cuts, nc);
    g0 += f * dx;
    g1 += f * dy;
    g2 += f * dz;
  }
  BOREAS_V3 normal = boreas_v3_normalize(boreas_v3(-g0, -g1, -g2));

  BOREAS_I bin = boreas_bt_bin_of(p, inv_bin, bx, by, bz);
  BOREAS_F weight = 0.0f, u = 0.0f, v = 0.0f;
  for (BOREAS_BT_WALK_OF_BINS c = BOREAS_BT_BINS_WALK(bin_items, BOREAS_GATHER_INT(bin_first, bin),
                                                      BOREAS_GATHER_INT(bin_first, bin + 1));
       ;) {
    int m = boreas_bt_next(bin_items, c);
    if (m == BOREAS_BT_NONE) break;
    boreas_bt_advance(bin_items, &c, m);
    if (prims[BOREAS_BT_WEIGHT * n + m] <= 0.0f) continue;
    BOREAS_F t, c0, c1;
    boreas_bt_local(p, prims, n, m, &t, &c0, &c1);
    BOREAS_F r = sqrt(c0 * c0 + c1 * c1);
    BOREAS_F d2 = boreas_bt_cone_distance2(t, r, (BOREAS_F)(prims[BOREAS_BT_LENGTH * n + m]),
                                           (BOREAS_F)(prims[BOREAS_BT_CONE * n + m]));
    BOREAS_F f = boreas_bt_falloff(d2, (BOREAS_F)(prims[BOREAS_BT_INV_R2 * n + m]));
    BOREAS_F turn = boreas_atan2(c1, c0) * (1.0f / BOREAS_TM_TWO_PI);
    turn = select(turn, turn + 1.0f, turn < 0.0f);
    weight += f;
    u += f * turn;
    v += f * ((BOREAS_F)(prims[BOREAS_BT_V0 * n + m]) +
              (BOREAS_F)(prims[BOREAS_BT_V_SCALE * n + m]) * t);
  }
  BOREAS_F inv = select((BOREAS_F)(0.0f), 1.0f / weight, weight > 0.0f);
  boreas_store_w(normal.x, out + (BOREAS_BT_VERTEX_NORMAL + 0) * stride, first, count);
  boreas_store_w(normal.y, out + (BOREAS_BT_VERTEX_NORMAL + 1) * stride, first, count);
  boreas_store_w(normal.z, out + (BOREAS_BT_VERTEX_NORMAL + 2) * stride, first, count);
  boreas_store_w(u * inv, out + (BOREAS_BT_VERTEX_UV + 0) * stride, first, count);
  boreas_store_w(v * inv, out + (BOREAS_BT_VERTEX_UV + 1) * stride, first, count);
}
