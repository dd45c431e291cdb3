// boreas: the marching cubes case table, generated from the face rule in cube_cases.h, and
// the host marching cubes that is the reference for the device polygonizer's meshes.
#include "blobtree/cube_cases.h"

#include <algorithm>
#include <cassert>
#include <stdexcept>

namespace boreas::impl {

namespace {

using Table = std::array<int8_t, 256 * BOREAS_BT_CASE_ENTRIES>;

// Edge e runs along axis e / 4 from the (e % 4)-th corner, ascending, whose bit `axis` is
// clear: the numbering of blobtree_types.h, derived rather than typed in.
int edge_start(int e) {
  const int axis = e / 4;
  int k = e % 4;
  for (int c = 0; c < 8; ++c)
    if (!(c >> axis & 1) && k-- == 0) return c;
  return -1;
}

int edge_end(int e) { return edge_start(e) | 1 << (e / 4); }

int edge_between(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if ((edge_start(e) == a && edge_end(e) == b) || (edge_start(e) == b && edge_end(e) == a))
      return e;
  return -1;
}

// Two edges lie on one face when all four endpoints agree on some coordinate.
bool share_face(int e, int f) {
  const int all = edge_start(e) & edge_end(e) & edge_start(f) & edge_end(f);
  const int any = edge_start(e) | edge_end(e) | edge_start(f) | edge_end(f);
  return e != f && (all | (~any & 7)) != 0;
}

// Twice a corner's or an edge midpoint's coordinates, so the orientation test is exact.
struct Point2 {
  int v[3];
};

Point2 corner_point(int c) { return {{2 * (c & 1), 2 * (c >> 1 & 1), 2 * (c >> 2 & 1)}}; }

Point2 midpoint(int e) {
  Point2 a = corner_point(edge_start(e)), b = corner_point(edge_end(e));
  return {{(a.v[0] + b.v[0]) / 2, (a.v[1] + b.v[1]) / 2, (a.v[2] + b.v[2]) / 2}};
}

// The face's segments, each from edge `from` to edge `to`: joined as the rule says, then
// directed so that, seen from outside the cube, the face's inside part lies on the right.
// That is the boundary direction of a polygon that is counter-clockwise seen from the
// lower values (checked on case 1: edges 0, 4, 8 have normal (1, 1, 1)).
void face_segments(int config, int axis, int side, int next[12]) {
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const int base = side << axis;
  const int ring[4] = {base, base | 1 << u, base | 1 << u | 1 << w, base | 1 << w};
  auto inside = [&](int i) { return (config >> ring[(i + 4) % 4] & 1) != 0; };

  int pairs[2][2];
  int count = 0;
  if (inside(0) == inside(2) && inside(1) == inside(3) && inside(0) != inside(1)) {
    // Ambiguous: cut each inside corner off on its own, with its two edges.
    for (int i = 0; i < 4; ++i)
      if (inside(i)) {
        pairs[count][0] = edge_between(ring[(i + 3) % 4], ring[i]);
        pairs[count][1] = edge_between(ring[i], ring[(i + 1) % 4]);
        ++count;
      }
  } else {
    int crossing[2], n = 0;
    for (int i = 0; i < 4; ++i)
      if (inside(i) != inside(i + 1)) crossing[n++] = edge_between(ring[i], ring[(i + 1) % 4]);
    if (n == 2) {
      pairs[0][0] = crossing[0];
      pairs[0][1] = crossing[1];
      count = 1;
    }
  }

  for (int p = 0; p < count; ++p) {
    int from = pairs[p][0], to = pairs[p][1];
    const int c = config >> edge_start(from) & 1 ? edge_start(from) : edge_end(from);
    const Point2 a = midpoint(from), b = midpoint(to), in = corner_point(c);
    const int d[3] = {b.v[0] - a.v[0], b.v[1] - a.v[1], b.v[2] - a.v[2]};
    const int r[3] = {in.v[0] - a.v[0], in.v[1] - a.v[1], in.v[2] - a.v[2]};
    // (n x d) . r with n = +-e_axis, the cube's outward normal on this face.
    const int left = (d[u] * r[w] - d[w] * r[u]) * (side ? 1 : -1);
    if (left > 0) std::swap(from, to);
    next[from] = to;
  }
}

// A fan from `apex` adds diagonals from it; one joining two points of the same face would
// lie in that face, where the neighbouring cube could put the same diagonal (an edge of
// four triangles). So the apex is the first vertex of the loop with no such diagonal.
int fan_apex(const std::vector<int>& loop) {
  const int k = int(loop.size());
  for (int i = 0; i < k; ++i) {
    bool ok = true;
    for (int j = 0; j < k && ok; ++j) {
      const int gap = (j - i + k) % k;
      if (gap > 1 && gap < k - 1 && share_face(loop[i], loop[j])) ok = false;
    }
    if (ok) return i;
  }
  throw std::logic_error("cube case table: a polygon with no apex free of face diagonals");
}

Table build_table() {
  Table table;
  table.fill(-1);
  for (int config = 0; config < 256; ++config) {
    int next[12];
    std::fill(next, next + 12, -1);
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) face_segments(config, axis, side, next);

    // Every crossing point is on two faces, leaving one segment and entering the other, so
    // the segments close into loops. Loops go by their lowest edge, each starting there.
    int out = 0;
    bool used[12] = {};
    for (int e = 0; e < 12; ++e) {
      if (next[e] < 0 || used[e]) continue;
      std::vector<int> loop;
      for (int f = e; !used[f]; f = next[f]) {
        used[f] = true;
        loop.push_back(f);
      }
      const int apex = fan_apex(loop);
      std::rotate(loop.begin(), loop.begin() + apex, loop.end());
      for (size_t j = 1; j + 1 < loop.size(); ++j) {
        if (out + 3 > BOREAS_BT_CASE_ENTRIES)
          throw std::logic_error("cube case table: raise BOREAS_BT_CASE_TRIANGLES");
        table[config * BOREAS_BT_CASE_ENTRIES + out++] = int8_t(loop[0]);
        table[config * BOREAS_BT_CASE_ENTRIES + out++] = int8_t(loop[j]);
        table[config * BOREAS_BT_CASE_ENTRIES + out++] = int8_t(loop[j + 1]);
      }
    }
  }
  return table;
}

}  // namespace

const Table& cube_case_table() {
  static const Table table = build_table();
  return table;
}

int cube_case_triangles(int config) {
  const int8_t* row = cube_case_table().data() + config * BOREAS_BT_CASE_ENTRIES;
  int n = 0;
  while (n < BOREAS_BT_CASE_TRIANGLES && row[3 * n] >= 0) ++n;
  return n;
}

GridMesh marching_cubes(const std::vector<double>& values, int nx, int ny, int nz,
                        const glm::dvec3& origin, double cell, double iso) {
  constexpr double kMinT = 1e-4;
  if (nx < 0 || ny < 0 || nz < 0 || values.size() != size_t(nx) * ny * nz)
    throw std::invalid_argument("marching_cubes: values must hold nx * ny * nz samples");
  const int64_t layer = int64_t(nx) * ny;
  const int64_t step[3] = {1, nx, layer};
  const int size[3] = {nx, ny, nz};
  GridMesh mesh;

  // The vertex of each (point, axis) of two z layers, -1 where the edge does not change
  // sign: a cube needs only its own two layers, so memory stays 2 layers, not the grid.
  std::vector<int32_t> vertex(2 * 3 * layer, -1);
  auto emit_layer = [&](int z) {
    int32_t* out = vertex.data() + (z & 1) * 3 * layer;
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const int p[3] = {x, y, z};
        const int64_t i = z * layer + int64_t(y) * nx + x;
        for (int axis = 0; axis < 3; ++axis) {
          int32_t& v = out[3 * (i - z * layer) + axis];
          v = -1;
          if (p[axis] + 1 >= size[axis]) continue;
          const double a = values[i], b = values[i + step[axis]];
          if ((a > iso) == (b > iso)) continue;
          const double t = std::clamp((iso - a) / (b - a), kMinT, 1.0 - kMinT);
          glm::dvec3 q(x, y, z);
          q[axis] += t;
          v = int32_t(mesh.positions.size());
          mesh.positions.push_back(origin + cell * q);
        }
      }
  };

  // Edge e of a cube: the offset of its (point, axis) slot from the slot of corner 0, with
  // the layer above at +3 * layer (the other buffer half, wrapped below).
  int64_t edge_slot[12];
  for (int e = 0; e < 12; ++e) {
    const int c = edge_start(e);
    edge_slot[e] =
        3 * ((c & 1) * step[0] + (c >> 1 & 1) * step[1] + (c >> 2 & 1) * step[2]) + e / 4;
  }

  const Table& table = cube_case_table();
  if (nz > 0) emit_layer(0);
  for (int z = 0; z + 1 < nz; ++z) {
    // Vertices of layer z + 1 all follow those of layer z, and triangles are a separate
    // list, so emitting layer by layer keeps both orders.
    emit_layer(z + 1);
    for (int y = 0; y + 1 < ny; ++y)
      for (int x = 0; x + 1 < nx; ++x) {
        const int64_t i = z * layer + int64_t(y) * nx + x;
        int config = 0;
        for (int c = 0; c < 8; ++c) {
          const int64_t j = i + (c & 1) * step[0] + (c >> 1 & 1) * step[1] + (c >> 2 & 1) * step[2];
          if (values[j] > iso) config |= 1 << c;
        }
        const int64_t slot = 3 * ((z & 1) * layer + int64_t(y) * nx + x);
        const int8_t* row = table.data() + config * BOREAS_BT_CASE_ENTRIES;
        for (int k = 0; k < BOREAS_BT_CASE_ENTRIES && row[k] >= 0; ++k) {
          const int32_t v = vertex[(slot + edge_slot[row[k]]) % (6 * layer)];
          assert(v >= 0);
          mesh.indices.push_back(uint32_t(v));
        }
      }
  }
  return mesh;
}

}  // namespace boreas::impl
