// boreas: the inputs every benchmark uses, the same for the OpenCL kernels and their native
// twins: four waves, a grid with a solid box, a source and a vortex, points in the grid, a
// meadow of grass tufts and two balls in it.
#pragma once

#include <cstdint>
#include <vector>

#include "boreas/boreas.h"
#include "shared/collider_types.h"
#include "shared/underbrush_types.h"
#include "shared/wind_types.h"
#include "colliders/contacts.h"
#include "underbrush/meadow.h"
#include "wind/wind_grid.h"

namespace boreas::bench {

// Time step of the grid benchmarks, s (one 60 Hz frame).
constexpr double kStepSeconds = 1.0 / 60.0;

// Four waves across the ground plane; sharpness 2.5 so that pow really runs.
std::vector<BoreasGpuWave> scene_waves();

// A grid of nx * ny * nz cells of 2 m, centred on the origin in x and z, from y = 0 up.
boreas_grid_def scene_grid_def(int nx, int ny, int nz);

// The grid's device form (BoreasGpuGrid) without solids counted.
BoreasGpuGrid scene_gpu_grid(const boreas_grid_def& def);

// A solid box in the middle of the grid (about 1/8 of the cells' extent per axis, on the
// ground), one byte per cell.
std::vector<uint8_t> scene_solids(const boreas_grid_def& def);

// A source and a vortex (steady) and a gust held at its peak (varying) inside the grid,
// as a world hands them to WindGrid::step.
impl::WindGrid::Forcing scene_forcing(const boreas_grid_def& def);

// A smooth grid wind for the point samples, as the device holds it: 4 planes of cells (x,
// y, z wind in m/s, then 1 in solid cells, else 0).
std::vector<float> scene_grid_cells(const boreas_grid_def& def, const std::vector<uint8_t>& solids);

// count points spread uniformly (fixed seed) over the grid's extent, as the sample kernel
// reads them: 3 planes of count floats (x, then y, then z).
std::vector<float> scene_points(int count, const boreas_grid_def& def);

// Distance between neighbouring tufts of the bench meadow, m (about 44 tufts per m^2).
constexpr double kMeadowSpacing = 0.15;

// A meadow of exactly `components` blades: tufts of the built-in meadow_grass (7 blades
// each, all fixed to the ground) on flat ground at y = 0, on a square lattice of
// kMeadowSpacing centred on the origin, filled row by row (x fastest); the last tuft is cut
// short so the count is exact. Made with meadow_from_plantings, so every blade is at rest.
impl::Meadow scene_meadow(int components);

// Two balls resting in the meadow (of any size scene_meadow makes: both lie within the
// smallest, 2^16 blades over about 14 m x 14 m), as the step kernel reads them.
std::vector<BoreasGpuCollider> scene_colliders();
// The same as the world hands them to UnderbrushBatch::enqueue_step (with their bounds).
impl::StepColliders scene_step_colliders();

}  // namespace boreas::bench
