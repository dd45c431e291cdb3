// boreas benchmarks: the reporter both benchmark programs (boreas_bench and
// boreas_render_bench) report through, so that rows keep the names they were registered
// with (BM_WindSineSum/cl/1048576, BM_FrameStages/zero_copy) and RESULTS.md can match them.
#pragma once

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

namespace boreas::bench_support {

// Forwards to another reporter, without the iteration-count and time-type suffixes
// ("/iterations:5", "/real_time") in run names. The library points this reporter's streams
// at the console or the --benchmark_out file; they are handed on to the inner reporter when
// the run starts.
class ExactNameReporter : public benchmark::BenchmarkReporter {
 public:
  // Takes ownership of inner.
  explicit ExactNameReporter(benchmark::BenchmarkReporter* inner) : inner_(inner) {}

  bool ReportContext(const Context& context) override;
  void ReportRuns(const std::vector<Run>& runs) override;
  void Finalize() override;

 private:
  std::unique_ptr<benchmark::BenchmarkReporter> inner_;
};

}  // namespace boreas::bench_support
