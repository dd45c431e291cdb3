// boreas tests and benchmarks: registering the probe kernels' embedded table and their
// rows of the launch table.
#include "reference/probe_kernels.h"

#include <utility>
#include <vector>

#include "runtime/kernel_source.h"
#include "runtime/launch.h"

namespace boreas::embedded {
const std::vector<std::pair<const char*, const char*>>& probe_kernel_files();
}

namespace boreas::impl {

void use_probe_kernels() {
  add_kernel_files(embedded::probe_kernel_files());
  // The driver's groups over exactly the items asked for; the scalar math probe's range
  // rounded to 64, as the fast math tests launched it before the table (their widths test
  // compares the wide probe with it bit for bit).
  const LaunchSizes exact = LaunchSizes::driver_groups(), by_64 = LaunchSizes::driver_groups(64);
  add_launch_rows({{"boreas_bandwidth_copy", exact, exact},
                   {"boreas_fast_math_probe", by_64, by_64},
                   {"boreas_fast_math_probe_wide", exact, exact}});
}

}  // namespace boreas::impl
