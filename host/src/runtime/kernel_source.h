// boreas: the OpenCL sources of the library, embedded at build time, with their
// #include "..." lines resolved, so programs build with no file lookups at run time.
#pragma once

#include <string>

namespace boreas::impl {

// The complete source of a kernel file (e.g. "wind_grid_step.cl") with every
// #include "shared/x.h" inlined once. With BOREAS_KERNEL_DIR set in the environment the
// files are read from that folder instead (for editing kernels without rebuilding).
// Throws BOREAS_ERROR_INTERNAL for an unknown file, BOREAS_ERROR_IO for an unreadable one.
std::string kernel_source(const std::string& file);

}  // namespace boreas::impl
