// boreas: the native C++ twin of the BlobTree field kernel (boreas_blobtree_field,
// cl/blobtree_field.cl), the yardstick boreas_bench compares it with: the field is
// cl/shared/blobtree_field.h itself (its C++ build, polynomials on), on the same float
// planes and the same bins (host/src/blobtree/blobtree_bins.h). OpenMP threads over bins,
// SIMD over a bin's 8^3 points.
#pragma once

#include "blobtree/blobtree_bins.h"

namespace boreas::bench {

// F at every point of `grid` into field[(z * ny + y) * nx + x] (grid.points() floats),
// each bin's points from the bin's list, as boreas_blobtree_field computes it. The bin's
// list is walked once for all its points (primitive by primitive, a SIMD loop over the
// points inside), the same operations in the same order per point as boreas_bt_field.
void native_blobtree_field(const impl::BlobPlanes& planes, const impl::BlobBins& bins,
                           const impl::BlobGrid& grid, float* field);

// The same through boreas_bt_field itself, one point at a time (scalar: the header's
// per-point loops over the list do not vectorize across points): the check that the SIMD
// twin above does the header's math.
void native_blobtree_field_per_point(const impl::BlobPlanes& planes, const impl::BlobBins& bins,
                                     const impl::BlobGrid& grid, float* field);

}  // namespace boreas::bench
