// boreas command: `boreas info`. Lists every device first, then resolves the request, so
// a request that matches nothing still shows what there is to choose from.
#include "cli/info_command.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "boreas/boreas.hpp"
#include "interop/strategy.h"

namespace boreas::render {

namespace {

std::string gibibytes(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / (1024.0 * 1024.0 * 1024.0));
  return text;
}

const char* yes_no(int flag) { return flag ? "yes" : "no"; }

// What `boreas run --interop auto` takes on this device (interop/strategy.h): sharing where
// the driver offers cl_khr_gl_sharing, zero-copy on CPUs, copies otherwise.
interop::Strategy automatic_strategy(const boreas_device_info& d) {
  return interop::choose_strategy({!d.is_gpu, d.has_gl_sharing != 0});
}

void print_device(int index, const boreas_device_info& d) {
  std::cout << "  [" << index << "] " << d.platform_index << ":" << d.device_index << "  "
            << d.device_name << "\n"
            << "      platform      " << d.platform_name << "\n"
            << "      type          " << (d.is_gpu ? "GPU" : "CPU") << ", " << d.compute_units
            << " compute units, " << gibibytes(d.global_memory) << "\n"
            << "      version       " << d.device_version << " (driver " << d.driver_version
            << ")\n"
            << "      gl sharing    " << yes_no(d.has_gl_sharing) << " (cl_khr_gl_sharing)\n"
            << "      fp64          " << yes_no(d.has_fp64) << " (cl_khr_fp64)\n"
            << "      fast math     " << yes_no(d.uses_fast_math)
            << (d.uses_fast_math ? " (boreas's polynomial sin/exp/log)" : " (OpenCL builtins)")
            << "\n"
            << "      interop       " << interop::strategy_name(automatic_strategy(d)) << " (boreas run --interop auto"
            << (d.has_gl_sharing ? ", when the GL context can be shared; else " +
                                       std::string(interop::strategy_name(interop::choose_strategy({!d.is_gpu, false})))
                                 : "")
            << ")\n";
}

// Why the pick is what it is, in the words of the request that made it.
std::string request_source(const InfoOptions& options) {
  if (options.device && !options.device->empty()) return "--device '" + *options.device + "'";
  const char* env = std::getenv("BOREAS_DEVICE");
  if (env && *env) return std::string("BOREAS_DEVICE='") + env + "'";
  return "the best device: a GPU before a CPU, then the most compute units";
}

}  // namespace

int run_info_command(const InfoOptions& options) {
  std::vector<boreas_device_info> devices = boreas::list_devices();
  std::cout << "OpenCL devices (" << devices.size() << "):\n";
  for (size_t i = 0; i < devices.size(); ++i) print_device(int(i), devices[i]);
  std::cout.flush();

  int picked = -1;
  const char* request = options.device ? options.device->c_str() : nullptr;
  boreas::check(boreas_choose_device(request, &picked));
  const boreas_device_info& d = devices.at(size_t(picked));
  std::cout << "boreas picks [" << picked << "] " << d.platform_index << ":" << d.device_index
            << "  " << d.device_name << " (" << request_source(options) << ")\n";
  return 0;
}

}  // namespace boreas::render
