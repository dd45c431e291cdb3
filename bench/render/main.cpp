// boreas render bench: entry point of boreas_render_bench. Google Benchmark's usual main,
// with names reported as registered (BM_FrameStages/zero_copy, without the "/iterations:5"
// and "/real_time" suffixes: bench/exact_name_reporter.h, which boreas_bench shares), the
// OpenGL and OpenCL devices in the context, and the GL objects freed before the GL context
// at the end. Needs a display: run it under `xvfb-run -a -s "-screen 0 1280x1024x24"` where
// there is none.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "boreas/boreas.hpp"
#include "exact_name_reporter.h"
#include "frame_scene.h"
#include "render_benchmarks.h"

namespace {

using boreas::bench_support::ExactNameReporter;

bool has_flag(int argc, char** argv, const char* prefix) {
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], prefix, std::strlen(prefix)) == 0) return true;
  }
  return false;
}

// The device a world made without a request runs on (BOREAS_DEVICE honoured).
std::string cl_device_description() {
  try {
    int index = 0;
    boreas::check(boreas_choose_device(nullptr, &index));
    const boreas_device_info d = boreas::list_devices().at(size_t(index));
    return std::string(d.device_name) + " | " + d.device_version + " | " +
           std::to_string(d.compute_units) + " compute units";
  } catch (const std::exception& e) {
    return std::string("none: ") + e.what();
  }
}

std::string gl_description() {
  try {
    return boreas::render::bench::gl_context().description();
  } catch (const std::exception& e) {
    return std::string("none: ") + e.what();
  }
}

}  // namespace

int main(int argc, char** argv) {
  // Only JSON files: the library refuses a file reporter without --benchmark_out.
  std::unique_ptr<ExactNameReporter> file;
  if (has_flag(argc, argv, "--benchmark_out=")) {
    file = std::make_unique<ExactNameReporter>(new benchmark::JSONReporter());
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("boreas_gl", gl_description());
  benchmark::AddCustomContext("boreas_cl_device", cl_device_description());
  boreas::render::bench::register_benchmarks();
  ExactNameReporter display(benchmark::CreateDefaultDisplayReporter());
  benchmark::RunSpecifiedBenchmarks(&display, file.get());
  try {
    // OpenGL errors and high-severity debug messages of the whole run (KHR_debug).
    for (const std::string& m : boreas::render::bench::gl_context().take_messages())
      std::fprintf(stderr, "boreas_render_bench: OpenGL: %s\n", m.c_str());
  } catch (const std::exception&) {
    // No context: every row has already said why.
  }
  boreas::render::bench::release_benchmarks();
  boreas::render::bench::release_gl_context();
  benchmark::Shutdown();
  return 0;
}
