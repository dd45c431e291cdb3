// boreas references: the crown's ambient occlusion (cl/leaf_occlusion.cl) in double
// precision, the same march and the same trilinear lookup, for the tests.
#pragma once

#include <vector>

#include "boreas/boreas.h"
#include "trees/leaf_occlusion.h"

namespace boreas::impl::reference {

// Per leaf (r, g, b) at its centre: as leaf_occlusion, from the same grid, directions,
// projections G per direction and clumping index.
std::vector<double> leaf_occlusion(const LeafDensityGrid& grid,
                                   const std::vector<float>& directions,
                                   const std::vector<float>& projection, double clumping,
                                   const double transmittance[3],
                                   const std::vector<boreas_leaf>& leaves);

}  // namespace boreas::impl::reference
