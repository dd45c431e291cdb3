// boreas benchmarks: run names as registered (see exact_name_reporter.h).
#include "exact_name_reporter.h"

namespace boreas::bench_support {

bool ExactNameReporter::ReportContext(const Context& context) {
  inner_->SetOutputStream(&GetOutputStream());
  inner_->SetErrorStream(&GetErrorStream());
  return inner_->ReportContext(context);
}

void ExactNameReporter::ReportRuns(const std::vector<Run>& runs) {
  std::vector<Run> renamed = runs;
  for (Run& run : renamed) {
    run.run_name.iterations.clear();
    run.run_name.time_type.clear();
  }
  inner_->ReportRuns(renamed);
}

void ExactNameReporter::Finalize() { inner_->Finalize(); }

}  // namespace boreas::bench_support
