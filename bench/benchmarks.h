// boreas: the benchmarks of boreas_bench (benchmarks.cpp), registered by name so that each
// reads BM_<Name>/<cl|native>/<items>.
#pragma once

#include <string>

namespace boreas::bench {

// Registers every benchmark pair with Google Benchmark, in the order they run.
void register_benchmarks();

// The OpenCL device the CL rows run on, in words (or why there is none).
std::string cl_device_description();

// Threads of the native rows' OpenMP loops.
int native_threads();

}  // namespace boreas::bench
