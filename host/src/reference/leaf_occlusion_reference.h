// boreas references: the crown's ambient occlusion (cl/leaf_occlusion.cl) in double
// precision, the same march and the same trilinear lookup, for the tests.
#pragma once

#include <vector>

#include "boreas/boreas.h"
#include "trees/leaf_occlusion.h"

namespace boreas::impl::reference {

// Per leaf (r, g, b): as leaf_occlusion, from the same grid and directions.
std::vector<double> leaf_occlusion(const LeafDensityGrid& grid,
                                   const std::vector<float>& directions,
                                   const double transmittance[3],
                                   const std::vector<boreas_leaf>& leaves);

}  // namespace boreas::impl::reference
