// boreas: what wind_sampling interpolated costs in accuracy (boreas.h, boreas_wind_sampling).
#pragma once

#include <vector>

#include "wind/wind_params.h"

namespace boreas::impl {

// The most the bilinear sine sum (cl/shared/wind_sample_width.inc,
// boreas_slab_bilinear) can differ from the exact one, in m/s, for these waves on a grid
// of cell_size: the sum over the waves of amplitude times interpolation_error(wave, h).
double interpolation_error_bound(const std::vector<WaveParams>& waves, double cell_size);

// One wave's part, per unit amplitude: see the derivation in wind_sampling.cpp.
double interpolation_error(const WaveParams& wave, double cell_size);

}  // namespace boreas::impl
