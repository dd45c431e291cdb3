// boreas_program_residue: the host memory a kernel program costs on this OpenCL driver and
// what it leaves behind once released: the first compile from source (a driver's one-time
// compiler state), each later compile, and each reload from the on-disk cache (what the
// runtime does when a kernel's kept variants turn over, runtime.h). The soak's memory
// checks are read against these figures (README, "Soak").
//
//   boreas_program_residue [--file tree_step.cl] [--kernel boreas_tree_step]
//                          [--compiles N] [--reloads N] [--variants K]
//
// It compiles K + N distinct variants of one kernel (a define no kernel reads makes each a
// new program and a disk-cache miss), through Runtime::kernel, so past
// Runtime::kKernelVariantsKept each new one releases the least recently used; then it asks
// for the first K + 1 in turn, N times over, so each ask releases one and reloads another
// from the disk cache. The heap in use (mallinfo2) after each step gives the residue: a
// flat heap once the kept variants are full means nothing stays behind.
#include <malloc.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "runtime/runtime.h"
#include "support/temp_dir.h"

namespace {

double heap_mib() {
  const struct mallinfo2 m = mallinfo2();
  return (double(m.uordblks) + double(m.hblkhd)) / 1048576.0;
}

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Least-squares slope of y over its index, per step.
double slope(const std::vector<double>& y) {
  const double n = double(y.size());
  if (n < 2) return 0.0;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < y.size(); ++i) {
    sx += double(i), sy += y[i], sxx += double(i) * double(i), sxy += double(i) * y[i];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  std::string file = "tree_step.cl", name = "boreas_tree_step";
  std::string base = "#define BOREAS_WAVE_SLOTS 4\n";
  bool throwaway = false, teardown = true;
  int compiles = 12, reloads = 40, kept = boreas::impl::Runtime::kKernelVariantsKept;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--file") file = v;
    else if (a == "--kernel") name = v;
    else if (a == "--defines") base = v;
    else if (a == "--compiles") compiles = std::atoi(v.c_str());
    else if (a == "--reloads") reloads = std::atoi(v.c_str());
    else if (a == "--throwaway") throwaway = v == "1";
    else if (a == "--teardown") teardown = v == "1";
    else {
      std::fprintf(stderr, "boreas_program_residue: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  boreas::test::TempDir cache;
  // A nonce, so no earlier run's binaries (or PoCL's own cache) can answer.
  const std::string nonce = std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
  // --throwaway 1: first a compile in a runtime (an OpenCL context) of its own, gone before
  // the measured one is made: does the driver's compiler state outlive its context?
  if (throwaway) {
    const double h = heap_mib();
    {
      boreas::impl::Runtime other(nullptr, cache.str().c_str());
      other.kernel("range_copy.cl", "boreas_range_copy",
                   "#define BOREAS_PROBE_VARIANT " + nonce + "0\n");
      std::printf("throwaway runtime, one small compile: heap %+.1f MiB\n", heap_mib() - h);
    }
    std::printf("throwaway runtime gone: heap %+.1f MiB\n", heap_mib() - h);
  }
  boreas::impl::Runtime rt(nullptr, cache.str().c_str());
  auto variant = [&](int i) {
    return base + "#define BOREAS_PROBE_VARIANT " + nonce + std::to_string(i) + "\n";
  };
  const double h0 = heap_mib();
  std::printf("runtime made: heap %.1f MiB\n", h0);
  std::vector<double> after_full;
  for (int i = 0; i < kept + compiles; ++i) {
    const double t = now_seconds(), h = heap_mib();
    rt.kernel(file, name, variant(i));
    const double after = heap_mib();
    std::printf("compile %2d: heap %7.1f MiB (%+7.2f)  %.2f s  variants %zu\n", i, after,
                after - h, now_seconds() - t, rt.kernel_variants());
    if (i >= kept) after_full.push_back(after);
  }
  std::vector<double> reload;
  double t = now_seconds();
  for (int r = 0; r < reloads; ++r) {
    for (int i = 0; i <= kept; ++i) rt.kernel(file, name, variant(i));
    reload.push_back(heap_mib());
  }
  const double per_round = slope(reload);
  std::printf(
      "compiles past the kept %d: %+.3f MiB each (slope over %zu)\n"
      "reloads from the disk cache: %d rounds of %d, heap %.1f -> %.1f MiB, %+.1f KiB a reload "
      "(slope), %.1f ms a reload; compiles %d, disk hits %d\n",
      kept, slope(after_full), after_full.size(), reloads,
      kept + 1, reload.empty() ? 0.0 : reload.front(), reload.empty() ? 0.0 : reload.back(),
      per_round / (kept + 1) * 1024.0, (now_seconds() - t) * 1e3 / std::max(1, reloads * (kept + 1)),
      rt.programs().compiles(), rt.programs().disk_hits());
  // --teardown 0: exit with the context alive, so a heap profiler (heaptrack) reports what
  // the driver holds for it, and what grew with the reloads, as not freed.
  if (!teardown) std::_Exit(0);
  return 0;
}
