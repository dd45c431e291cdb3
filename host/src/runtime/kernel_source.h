// boreas: the OpenCL sources of the library, embedded at build time, with their
// #include "..." lines resolved, so programs build with no file lookups at run time.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace boreas::impl {

// The complete source of a kernel file (e.g. "wind_grid_step.cl") with every
// #include "shared/x.h" inlined once. With BOREAS_KERNEL_DIR set in the environment the
// files are read from that folder instead (for editing kernels without rebuilding).
// Throws BOREAS_ERROR_INTERNAL for an unknown file, BOREAS_ERROR_IO for an unreadable one.
std::string kernel_source(const std::string& file);

// Makes a further table of kernel files findable by kernel_source (tests' and benchmarks'
// probe kernels, which the library does not ship). The table must outlive every use;
// adding the same table twice adds it once. Thread-safe.
void add_kernel_files(const std::vector<std::pair<const char*, const char*>>& files);

}  // namespace boreas::impl
