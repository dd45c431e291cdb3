// boreas tests and benchmarks: registering the probe kernels' embedded table.
#include "reference/probe_kernels.h"

#include <utility>
#include <vector>

#include "runtime/kernel_source.h"

namespace boreas::embedded {
const std::vector<std::pair<const char*, const char*>>& probe_kernel_files();
}

namespace boreas::impl {

void use_probe_kernels() { add_kernel_files(embedded::probe_kernel_files()); }

}  // namespace boreas::impl
