// boreas: entry point of boreas_bench. Google Benchmark's usual main, except that names are
// reported as registered (BM_WindSineSum/cl/1048576, no "/real_time" suffix:
// exact_name_reporter.h) and the native rows' OpenMP threads sleep rather than spin while
// they wait (see main).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "benchmarks.h"
#include "exact_name_reporter.h"

namespace {

using boreas::bench_support::ExactNameReporter;

// The value of a --name=value flag, read before benchmark::Initialize consumes it.
std::string flag_value(int argc, char** argv, const std::string& name) {
  const std::string prefix = "--" + name + "=";
  std::string value;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], prefix.c_str(), prefix.size()) == 0) value = argv[i] + prefix.size();
  }
  return value;
}

// The reporter --benchmark_out_format asks for (json unless given).
benchmark::BenchmarkReporter* file_reporter(const std::string& format) {
  if (format == "console")
    return new benchmark::ConsoleReporter(benchmark::ConsoleReporter::OO_None);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"  // still the library's CSV output
  if (format == "csv") return new benchmark::CSVReporter();
#pragma GCC diagnostic pop
  return new benchmark::JSONReporter();
}

}  // namespace

int main(int argc, char** argv) {
  // OMP_WAIT_POLICY=passive unless the caller chose: with spinning waits, two OpenMP threads
  // on two cores that another process also uses wait out whole scheduler time slices at
  // every barrier (measured here: 20 ms instead of 0.25 ms for a 16384-cell step). PoCL's
  // worker threads sleep between commands too, so the comparison stays fair. libgomp reads
  // the variable when it is loaded, hence the restart.
  if (!std::getenv("OMP_WAIT_POLICY")) {
    setenv("OMP_WAIT_POLICY", "passive", 1);
    execv("/proc/self/exe", argv);  // returns only on failure; then run as we are
  }
  // --boreas_lag_error[=steps]: the lagged-versus-exact table instead of the benchmarks.
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--boreas_lag_error", 18) == 0) {
      const char* steps = std::strchr(argv[i], '=');
      return boreas::bench::print_tree_lag_error(steps ? std::atoi(steps + 1) : 600);
    }
    // --boreas_carry_detach[=steps]: the levels of detail's drift table instead.
    if (std::strncmp(argv[i], "--boreas_carry_detach", 21) == 0) {
      const char* steps = std::strchr(argv[i], '=');
      return boreas::bench::print_carry_detach(steps ? std::atoi(steps + 1) : 240);
    }
    // --boreas_wind_point[=steps]: where a trunk samples the wind, as a table.
    if (std::strncmp(argv[i], "--boreas_wind_point", 19) == 0) {
      const char* steps = std::strchr(argv[i], '=');
      return boreas::bench::print_tree_wind_point(steps ? std::atoi(steps + 1) : 600);
    }
  }
  // The library refuses a file reporter without --benchmark_out, so make one only then.
  std::unique_ptr<ExactNameReporter> file;
  if (!flag_value(argc, argv, "benchmark_out").empty()) {
    file = std::make_unique<ExactNameReporter>(
        file_reporter(flag_value(argc, argv, "benchmark_out_format")));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("boreas_cl_device", boreas::bench::cl_device_description());
  benchmark::AddCustomContext("boreas_native_threads",
                              std::to_string(boreas::bench::native_threads()) +
                                  " (OMP_WAIT_POLICY=" + std::getenv("OMP_WAIT_POLICY") + ")");
  boreas::bench::register_benchmarks();
  ExactNameReporter display(benchmark::CreateDefaultDisplayReporter());
  benchmark::RunSpecifiedBenchmarks(&display, file.get());
  benchmark::Shutdown();
  return 0;
}
