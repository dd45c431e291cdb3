// boreas: the native twin of the BlobTree field kernel, built with -O3 -march=native
// -fopenmp (see bench/CMakeLists.txt). The per-primitive math is cl/shared/blobtree_field.h
// itself (its C++ build, polynomials on); boreas_bt_field's walk over a bin's list is
// written out again around it, so that one SIMD loop runs over the bin's points per
// primitive. The loops are shaped so that GCC vectorizes each (checked with
// -fopt-info-vec-missed).
#include "native_blobtree.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#define BOREAS_FAST_MATH 1
#include "shared/blobtree_field.h"

namespace boreas::bench {

namespace {

constexpr int kBin = BOREAS_BT_BIN;
constexpr int kBinPoints = kBin * kBin * kBin;

// How the SIMD loops are written (each checked with -fopt-info-vec-missed):
//  - one loop per primitive over the bin's points, not one loop over the points calling
//    boreas_bt_field: the walk over the list (a group's members found by a while loop,
//    two passes over them) is the same for every point of a bin, but GCC vectorizes no
//    loop with inner loops like these, so the per-point version
//    (native_blobtree_field_per_point) stays scalar. Turned inside out, every loop left
//    has a fixed trip count and straight-line code.
//  - `#pragma omp simd` over the points; unlike tree_math.h's out-parameters in
//    native_trees.cpp, the header's here inline to registers (`GCC ivdep` vectorizes the
//    same loops equally fast); [[gnu::flatten]] on the bin's function inlines the
//    header's `static inline` functions into them.
//  - each primitive's floats copied out to a table of one (One), and one copy of the loop
//    for a straight primitive and one for a bent one (for_points): see there.

// A bin's points and the running values of boreas_bt_field for each of them.
struct alignas(64) BinPoints {
  float x[kBinPoints], y[kBinPoints], z[kBinPoints];
  float total[kBinPoints];
  // The open PCM group: the two largest fields and the two nearest surfaces (with the
  // slope of whose), and which member holds the first of each.
  float f1[kBinPoints], f2[kBinPoints], r1[kBinPoints], r2[kBinPoints], k1[kBinPoints],
      k2[kBinPoints];
  int32_t f_at[kBinPoints], r_at[kBinPoints];
  float best[kBinPoints];
  float cutter[kBinPoints];
};

// Point q of a bin: x fastest, then y, then z.
inline int bin_x(int q) { return q % kBin; }
inline int bin_y(int q) { return (q / kBin) % kBin; }
inline int bin_z(int q) { return q / (kBin * kBin); }

struct Tables {
  const float* prims;
  const int32_t* ints;
  int n;
  const float* cuts;
  int nc;  // the cut count, as the kernel gets it (0: no cuts)
};

// Primitive i's floats as a table of one (stride 1, index 0), for the header's functions
// in the point loops. Reading the planes themselves, GCC keeps the loads in the loop (the
// bin's arrays might alias them) and gives up on the bent case's, which are conditional
// ("unsupported access type for masked load"); from a local copy it hoists them all.
struct One {
  float prims[BOREAS_BT_FLOATS];
};

inline One one_primitive(const Tables& t, int i) {
  One o;
  for (int p = 0; p < BOREAS_BT_FLOATS; ++p) o.prims[p] = t.prims[p * t.n + i];
  return o;
}

// body(q) for every point of the bin, in one copy of the loop for a straight primitive
// and one for a bent one. boreas_bt_local branches on the bend; GCC does not unswitch
// that branch out of the loop but if-converts it, so every point would pay for the bent
// case's atan2 too (2-2.5x slower for a tree without bends, measured). In each copy here
// the branch folds away.
template <typename Body>
[[gnu::always_inline]] inline void for_points(const One& o, Body&& body) {
  if (o.prims[BOREAS_BT_BEND_RHO] == 0.0f) {
#pragma omp simd
    for (int q = 0; q < kBinPoints; ++q) body(q);
  } else {
#pragma omp simd
    for (int q = 0; q < kBinPoints; ++q) body(q);
  }
}

// A lone primitive i: total += weight * its fall-off.
void add_primitive(BinPoints& b, const Tables& t, int i) {
  const One o = one_primitive(t, i);
  const float weight = o.prims[BOREAS_BT_WEIGHT];
  for_points(o, [&](int q) {
    float d2;
    b.total[q] +=
        weight * boreas_bt_primitive(boreas_v3(b.x[q], b.y[q], b.z[q]), o.prims, 1, 0, &d2);
  });
}

// A PCM group, items[k, e): boreas_bt_field's two passes over the members.
void add_pcm_group(BinPoints& b, const Tables& t, const int32_t* items, int k, int e) {
  for (int q = 0; q < kBinPoints; ++q) {
    b.f1[q] = 0.0f;
    b.f2[q] = 0.0f;
    b.r1[q] = BOREAS_BT_FAR;
    b.r2[q] = BOREAS_BT_FAR;
    b.k1[q] = 0.0f;
    b.k2[q] = 0.0f;
    b.f_at[q] = -1;
    b.r_at[q] = -1;
    b.best[q] = 0.0f;
  }
  for (int j = k; j < e; ++j) {
    const One o = one_primitive(t, items[j]);
    const float iso = o.prims[BOREAS_BT_ISO_DIST];
    const float slope = o.prims[BOREAS_BT_SLOPE];
    for_points(o, [&](int q) {
      float d2;
      const float f = boreas_bt_primitive(boreas_v3(b.x[q], b.y[q], b.z[q]), o.prims, 1, 0, &d2);
      const float r = BOREAS_SQRT(d2) - iso;
      const float f1 = b.f1[q], f2 = b.f2[q], r1 = b.r1[q], r2 = b.r2[q], k1 = b.k1[q],
                  k2 = b.k2[q];
      const bool top_f = f > f1;
      b.f2[q] = top_f ? f1 : (f > f2 ? f : f2);
      b.f1[q] = top_f ? f : f1;
      b.f_at[q] = top_f ? j : b.f_at[q];
      const bool top_r = r < r1;
      const bool second_r = !top_r && r < r2;
      b.r2[q] = top_r ? r1 : (second_r ? r : r2);
      b.k2[q] = top_r ? k1 : (second_r ? slope : k2);
      b.r1[q] = top_r ? r : r1;
      b.k1[q] = top_r ? slope : k1;
      b.r_at[q] = top_r ? j : b.r_at[q];
    });
  }
  for (int j = k; j < e; ++j) {
    const One o = one_primitive(t, items[j]);
    const float width = o.prims[BOREAS_BT_PCM_WIDTH];
    const float peak = o.prims[BOREAS_BT_PCM_PEAK];
    for_points(o, [&](int q) {
      float d2;
      const float f = boreas_bt_primitive(boreas_v3(b.x[q], b.y[q], b.z[q]), o.prims, 1, 0, &d2);
      const float other_f = j == b.f_at[q] ? b.f2[q] : b.f1[q];
      const float other_r = j == b.r_at[q] ? b.r2[q] : b.r1[q];
      const float other_k = j == b.r_at[q] ? b.k2[q] : b.k1[q];
      const float expansion =
          boreas_bt_pcm_expansion(other_r < 0.0f ? 0.0f : other_r, width, peak, other_k);
      float support = f * (2.0f / BOREAS_BT_ISO);
      support = support < 1.0f ? support : 1.0f;
      const float s = other_r < 0.0f ? BOREAS_BT_ISO - other_f : expansion * support;
      const float deformed = f + s;
      b.best[q] = deformed > b.best[q] ? deformed : b.best[q];
    });
  }
  for (int q = 0; q < kBinPoints; ++q) {
    const float best = b.f2[q] > b.best[q] ? b.f2[q] : b.best[q];  // overlaps stay solid
    b.total[q] += best;
  }
}

// min(F, 1 - the largest cutter) where F > 0.
void apply_cuts(BinPoints& b, const Tables& t) {
  if (t.nc <= 0) return;
  for (int q = 0; q < kBinPoints; ++q) b.cutter[q] = 0.0f;
  for (int c = 0; c < t.nc; ++c) {
    float cut[BOREAS_BT_CUT_FLOATS];  // as One, for the cut's floats
    for (int p = 0; p < BOREAS_BT_CUT_FLOATS; ++p) cut[p] = t.cuts[p * t.nc + c];
#pragma omp simd
    for (int q = 0; q < kBinPoints; ++q) {
      const float f = boreas_bt_cutter(boreas_v3(b.x[q], b.y[q], b.z[q]), cut, 1, 0);
      b.cutter[q] = f > b.cutter[q] ? f : b.cutter[q];
    }
  }
  for (int q = 0; q < kBinPoints; ++q) {
    const float keep = 1.0f - b.cutter[q];
    const float total = b.total[q];
    b.total[q] = total > 0.0f ? (total < keep ? total : keep) : total;
  }
}

// One bin (bx, by, bz) into the field.
[[gnu::flatten]] void bin_field(BinPoints& b, const Tables& t, const impl::BlobBins& bins,
                                const impl::BlobGrid& grid, int bx, int by, int bz, float* field) {
  const int bin = (bz * bins.by + by) * bins.bx + bx;
  const int begin = bins.first[size_t(bin)], end = bins.first[size_t(bin) + 1];
  const int x0 = bx * kBin, y0 = by * kBin, z0 = bz * kBin;
  float* const out = field + (size_t(z0) * grid.ny + y0) * grid.nx + x0;
  if (begin == end) {  // nothing reaches the bin: F = 0 (and no cut applies)
    for (int q = 0; q < kBinPoints; q += kBin)
      std::memset(out + (size_t(bin_z(q)) * grid.ny + bin_y(q)) * grid.nx, 0, kBin * sizeof(float));
    return;
  }
  // The kernel's point: cell * (float)index in the grid's frame, in float.
  const float cell = float(grid.cell);
  for (int q = 0; q < kBinPoints; ++q) {
    b.x[q] = cell * float(x0 + bin_x(q));
    b.y[q] = cell * float(y0 + bin_y(q));
    b.z[q] = cell * float(z0 + bin_z(q));
    b.total[q] = 0.0f;
  }
  // boreas_bt_field's walk over the list: lone primitives, and runs of PCM members of one
  // group.
  const int32_t* items = bins.items.data();
  int k = begin;
  while (k < end) {
    const int i = items[k];
    if (t.ints[BOREAS_BT_PCM * t.n + i] == 0) {
      add_primitive(b, t, i);
      ++k;
      continue;
    }
    const int group = t.ints[BOREAS_BT_GROUP * t.n + i];
    int e = k + 1;
    while (e < end && t.ints[BOREAS_BT_GROUP * t.n + items[e]] == group &&
           t.ints[BOREAS_BT_PCM * t.n + items[e]] != 0)
      ++e;
    add_pcm_group(b, t, items, k, e);
    k = e;
  }
  apply_cuts(b, t);
  for (int q = 0; q < kBinPoints; q += kBin)
    std::memcpy(out + (size_t(bin_z(q)) * grid.ny + bin_y(q)) * grid.nx, b.total + q,
                kBin * sizeof(float));
}

Tables tables(const impl::BlobPlanes& planes) {
  return {planes.prims.data(), planes.ints.data(), planes.n, planes.cuts.data(), planes.cut_count};
}

}  // namespace

void native_blobtree_field(const impl::BlobPlanes& planes, const impl::BlobBins& bins,
                           const impl::BlobGrid& grid, float* field) {
  const Tables t = tables(planes);
  const int bin_count = bins.bx * bins.by * bins.bz;
  // Dynamic: bins range from empty (most of the box around a tree) to dozens of
  // primitives.
#pragma omp parallel
  {
    BinPoints b;
#pragma omp for schedule(dynamic, 4)
    for (int bin = 0; bin < bin_count; ++bin) {
      const int bx = bin % bins.bx, by = (bin / bins.bx) % bins.by, bz = bin / (bins.bx * bins.by);
      bin_field(b, t, bins, grid, bx, by, bz, field);
    }
  }
}

void native_blobtree_field_per_point(const impl::BlobPlanes& planes, const impl::BlobBins& bins,
                                     const impl::BlobGrid& grid, float* field) {
  const Tables t = tables(planes);
  const int bin_count = bins.bx * bins.by * bins.bz;
  const float cell = float(grid.cell);
#pragma omp parallel for schedule(dynamic, 4)
  for (int bin = 0; bin < bin_count; ++bin) {
    const int bx = bin % bins.bx, by = (bin / bins.bx) % bins.by, bz = bin / (bins.bx * bins.by);
    const int begin = bins.first[size_t(bin)], end = bins.first[size_t(bin) + 1];
    for (int q = 0; q < kBinPoints; ++q) {
      const int x = bx * kBin + bin_x(q), y = by * kBin + bin_y(q), z = bz * kBin + bin_z(q);
      const BoreasV3 p = boreas_v3(cell * float(x), cell * float(y), cell * float(z));
      field[(size_t(z) * grid.ny + y) * grid.nx + x] =
          boreas_bt_field(p, t.prims, t.ints, t.n, bins.items.data(), begin, end, t.cuts, t.nc);
    }
  }
}

}  // namespace boreas::bench
