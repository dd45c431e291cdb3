// boreas: the BlobTree's grid, float planes and spatial bins (see blobtree_bins.h).
#include "blobtree/blobtree_bins.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "shared/blobtree_types.h"

namespace boreas::impl {
namespace {

using glm::dvec3;

// A primitive is binned as if it reached this much further, so that float rounding of a
// point's position or of its distance never gives a non-zero term in a bin that left the
// primitive out (which would break binned == every primitive, bit for bit).
constexpr double kReachMargin = 1.02;
// Bends below this (rad) are packed straight: the arc's radius L / angle would overflow
// the kernels' squares, and the bend would move nothing a float can see.
constexpr double kStraightBelow = 1e-4;

int round_up_to_bins(double points) {
  int n = static_cast<int>(std::ceil(points));
  return std::max(BOREAS_BT_BIN, (n + BOREAS_BT_BIN - 1) / BOREAS_BT_BIN * BOREAS_BT_BIN);
}

}  // namespace

BlobGrid blob_grid(const BlobModel& model, int resolution, bool cubic) {
  if (resolution < 16 || resolution > 1024)
    throw std::invalid_argument("blobtree: resolution must be 16..1024 grid points, not " +
                                std::to_string(resolution));
  if (model.primitives.empty() || !(model.bounds_min.x <= model.bounds_max.x))
    throw std::invalid_argument("blobtree: the model has no primitives (every branch left out?)");
  dvec3 size = model.bounds_max - model.bounds_min;
  double longest = std::max({size.x, size.y, size.z});
  // resolution points span the longest side plus one empty cell at each end.
  double cell = longest / double(resolution - 3);
  BlobGrid g;
  g.cell = cell;
  if (cubic) {
    g.nx = g.ny = g.nz = round_up_to_bins(resolution);
  } else {
    g.nx = round_up_to_bins(size.x / cell + 3.0);
    g.ny = round_up_to_bins(size.y / cell + 3.0);
    g.nz = round_up_to_bins(size.z / cell + 3.0);
  }
  // Centre the bounds in the grid.
  dvec3 span = cell * dvec3(g.nx - 1, g.ny - 1, g.nz - 1);
  g.origin = 0.5 * (model.bounds_min + model.bounds_max) - 0.5 * span;
  return g;
}

BlobPlanes blob_planes(const BlobModel& model, const dvec3& origin) {
  BlobPlanes t;
  t.origin = origin;
  t.count = static_cast<int>(model.primitives.size());
  const int n = t.n = std::max(t.count, 1);
  t.prims.assign(size_t(BOREAS_BT_FLOATS) * n, 0.0f);
  t.ints.assign(size_t(BOREAS_BT_INTS) * n, 0);
  auto put3 = [&](int plane, int i, const dvec3& v) {
    for (int k = 0; k < 3; ++k) t.prims[size_t(plane + k) * n + i] = static_cast<float>(v[k]);
  };
  auto put = [&](int plane, int i, double v) {
    t.prims[size_t(plane) * n + i] = static_cast<float>(v);
  };
  for (int i = 0; i < t.count; ++i) {
    const BlobPrimitive& p = model.primitives[i];
    put3(BOREAS_BT_BASE, i, p.base - origin);
    put3(BOREAS_BT_AXIS, i, p.axis);
    put(BOREAS_BT_LENGTH, i, p.length);
    put(BOREAS_BT_CONE, i, p.cone_radius);
    put(BOREAS_BT_ISO_DIST, i, p.iso_distance);
    put(BOREAS_BT_INV_R2, i, 1.0 / (p.influence * p.influence));
    put(BOREAS_BT_WEIGHT, i, p.weight);
    put(BOREAS_BT_PCM_WIDTH, i, p.pcm_width);
    put(BOREAS_BT_PCM_PEAK, i, p.pcm_peak);
    put(BOREAS_BT_SLOPE, i, BOREAS_BT_ISO_SLOPE / p.influence);
    put3(BOREAS_BT_BEND_DIR, i, p.bend_direction);
    if (p.bend_angle > kStraightBelow) {
      put(BOREAS_BT_BEND_RHO, i, p.length / p.bend_angle);
      put(BOREAS_BT_BEND_SIN, i, std::sin(0.5 * p.bend_angle));
      put(BOREAS_BT_BEND_COS, i, std::cos(0.5 * p.bend_angle));
    } else {
      put(BOREAS_BT_BEND_COS, i, 1.0);
    }
    put3(BOREAS_BT_U_DIR, i, p.u_direction);
    put(BOREAS_BT_V0, i, p.v0);
    put(BOREAS_BT_V_SCALE, i, p.v_scale);
    t.ints[size_t(BOREAS_BT_GROUP) * n + i] = p.group;
    t.ints[size_t(BOREAS_BT_PCM) * n + i] = p.pcm ? 1 : 0;
  }
  t.cut_count = static_cast<int>(model.cuts.size());
  const int nc = t.nc = std::max(t.cut_count, 1);
  t.cuts.assign(size_t(BOREAS_BT_CUT_FLOATS) * nc, 0.0f);
  for (int k = 0; k < t.cut_count; ++k) {
    const BlobCut& c = model.cuts[k];
    for (int a = 0; a < 3; ++a) {
      t.cuts[size_t(BOREAS_BT_CUT_POINT + a) * nc + k] = static_cast<float>(c.point[a] - origin[a]);
      t.cuts[size_t(BOREAS_BT_CUT_NORMAL + a) * nc + k] = static_cast<float>(c.normal[a]);
    }
    t.cuts[size_t(BOREAS_BT_CUT_RADIUS) * nc + k] = static_cast<float>(c.radius);
    t.cuts[size_t(BOREAS_BT_CUT_RAMP) * nc + k] = static_cast<float>(c.ramp);
  }
  return t;
}

BlobBins blob_bins(const BlobModel& model, const BlobGrid& grid) {
  BlobBins b;
  b.bx = grid.bins_x();
  b.by = grid.bins_y();
  b.bz = grid.bins_z();
  const size_t bins = size_t(b.bx) * b.by * b.bz;
  const std::vector<double> widths = blob_group_widths(model);
  const double bin_size = BOREAS_BT_BIN * grid.cell;
  // Each primitive's range of bins, from the box around its skeleton grown by its reach.
  struct Range {
    int lo[3], hi[3];
  };
  std::vector<Range> ranges(model.primitives.size());
  std::vector<int32_t> counts(bins + 1, 0);
  const int limit[3] = {b.bx, b.by, b.bz};
  for (size_t i = 0; i < model.primitives.size(); ++i) {
    const BlobPrimitive& p = model.primitives[i];
    dvec3 lo, hi;
    blob_skeleton_box(p, kReachMargin * blob_reach(p, widths[i]) + 1e-3 * grid.cell, &lo, &hi);
    lo = (lo - grid.origin) / bin_size;
    hi = (hi - grid.origin) / bin_size;
    Range& r = ranges[i];
    for (int a = 0; a < 3; ++a) {
      r.lo[a] = static_cast<int>(std::clamp(std::floor(lo[a]), 0.0, double(limit[a] - 1)));
      r.hi[a] = static_cast<int>(std::clamp(std::floor(hi[a]), -1.0, double(limit[a] - 1)));
      if (hi[a] < 0.0 || lo[a] >= limit[a]) r.hi[a] = r.lo[a] - 1;  // outside the grid
    }
    for (int z = r.lo[2]; z <= r.hi[2]; ++z)
      for (int y = r.lo[1]; y <= r.hi[1]; ++y)
        for (int x = r.lo[0]; x <= r.hi[0]; ++x) ++counts[(size_t(z) * b.by + y) * b.bx + x];
  }
  b.first.assign(bins + 1, 0);
  for (size_t k = 0; k < bins; ++k) b.first[k + 1] = b.first[k] + counts[k];
  b.items.assign(std::max<size_t>(b.first[bins], 1), 0);
  std::vector<int32_t> fill(b.first.begin(), b.first.end() - 1);
  for (size_t i = 0; i < model.primitives.size(); ++i) {
    const Range& r = ranges[i];
    for (int z = r.lo[2]; z <= r.hi[2]; ++z)
      for (int y = r.lo[1]; y <= r.hi[1]; ++y)
        for (int x = r.lo[0]; x <= r.hi[0]; ++x)
          b.items[fill[(size_t(z) * b.by + y) * b.bx + x]++] = int32_t(i);
  }
  return b;
}

}  // namespace boreas::impl
