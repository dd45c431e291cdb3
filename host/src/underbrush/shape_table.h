// boreas: a part's precomputed shapes (Endo et al. sec. 3.1 and 4.2), in the layout of
// BoreasGpuPart (cl/shared/underbrush_types.h):
//  - forward: for a user-set number of load angles (the paper's angles between the
//    component and the terrain normal, generalized from gravity to any load) and load
//    norms, the equilibrium center of mass; each shape covers the interval of norms around
//    its own;
//  - inverse: for a center of mass anywhere in the bend plane, the shape that has it, so
//    the kernels rebuild the shape from the animated X alone;
//  - breaking: per angle, the load that breaks the part, and where.
// One forward and one inverse table per broken state (intact, broken at joint 0, 1, ...).
#pragma once

#include <vector>

#include "boreas/boreas.h"
#include "underbrush/rest_shape.h"

namespace boreas::impl {

struct ShapeTableSizes {
  // Load angles and norms: the meadow def's shape_angles and shape_norms, by default the
  // public def's (19, 10 degrees apart, and 24: boreas_default_meadow_def).
  int angles = boreas_default_meadow_def().shape_angles;
  int norms = boreas_default_meadow_def().shape_norms;
  int psi_count = 25;
  int rho_count = 12;
  double a_ref = 9.80665;          // m/s^2: gravity sits mid-axis
  double a_max = 2000.0 * 9.80665;  // m/s^2: the largest tabulated load
};

struct PartTables {
  ShapeTableSizes sizes;
  int sections = 0;
  double reach = 0.0;   // m, straight part
  double q_max = 0.0;
  double rho_min = 0.0;
  int forward_size = 0, inverse_size = 0;  // floats per broken state
  std::vector<float> forward;   // (sections + 1) * forward_size
  std::vector<float> inverse;   // (sections + 1) * inverse_size
  std::vector<float> breaking;  // angles * 2: load norm (m/s^2; 3e38 if never), joint
  std::vector<float> widths;    // BOREAS_UB_JOINTS half widths, m (tip repeated)
};

// Load norm of index position j (0..norms-1) of the forward table.
double table_norm(const PartTables& t, double j);

PartTables build_part_tables(const std::vector<SectionPhysics>& sections, const std::vector<double>& half_widths,
                             const ShapeTableSizes& sizes);

}  // namespace boreas::impl
