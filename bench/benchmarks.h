// boreas: the benchmarks of boreas_bench (bench_harness.cpp and one bench_<feature>.cpp per
// feature), registered by name so that each reads BM_<Name>/<cl|native>/<items>.
#pragma once

#include <string>

namespace boreas::bench {

// Registers every benchmark pair with Google Benchmark, in the order they run.
void register_benchmarks();

// The OpenCL device the CL rows run on, in words (or why there is none).
std::string cl_device_description();

// Steps one of each bench tree in a lagged and an exact batch side by side, under steady
// and gusty wind, quasi-static and damped, and prints a Markdown table of the tip (P3)
// distance between the two relative to tree height (boreas_bench --boreas_lag_error[=steps]).
int print_tree_lag_error(int steps);

// Steps the forest of BM_ForestStep/mixed/1000 (no meadow) with its focus in the middle
// and prints a Markdown table of how far branches' bases drift off their parents' curves
// by level of detail, stepped and carried (boreas_bench --boreas_carry_detach[=steps]).
int print_carry_detach(int steps);

// Steps one aspen, black oak and tupelo in the default wave with the grid's gusts and prints a
// Markdown table of how far the crown's drag taken at the trunk's tip, or at the leaves'
// centroid, is from the drag summed leaf by leaf (boreas_bench --boreas_wind_point[=steps]).
int print_tree_wind_point(int steps);

// Threads of the native rows' OpenMP loops.
int native_threads();

}  // namespace boreas::bench
