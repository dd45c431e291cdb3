// boreas: the counterpart of tests/tools/ArbaroFigures.java: the same figures (arbaro_figures.h)
// of boreas's trees grown from Arbaro species files for seeds 1..SEEDS, in the same CSV, so
// the two can be compared over any number of seeds (bench/RESULTS.md, "Issue 40, third
// round: arbaro2"). Not a test; built with the tree tests:
//
//   build/tests/host/boreas_figures [--per-seed] SEEDS file.xml... > figures.csv
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "host/trees/arbaro_figures.h"
#include "trees/species.h"

namespace {

using boreas::impl::ArbaroFigures;

constexpr int kFigures = 11;
const char* const kNames[kFigures] = {"height", "width",   "leaves",  "length0",
                                      "length1", "length2", "length3", "stems0",
                                      "stems1",  "stems2",  "stems3"};

std::vector<double> row(const ArbaroFigures& f) {
  return {f.height,    f.width,     f.leaves,   f.length[0], f.length[1], f.length[2],
          f.length[3], f.stems[0],  f.stems[1], f.stems[2],  f.stems[3]};
}

}  // namespace

int main(int argc, char** argv) {
  int a = 1;
  const bool per_seed = a < argc && std::string(argv[a]) == "--per-seed";
  if (per_seed) ++a;
  if (argc - a < 2) {
    std::fprintf(stderr, "usage: %s [--per-seed] SEEDS file.xml...\n", argv[0]);
    return 2;
  }
  const int seeds = std::atoi(argv[a++]);
  if (seeds < 1) {
    std::fprintf(stderr, "SEEDS must be a positive whole number, got '%s'\n", argv[a - 1]);
    return 2;
  }
  std::printf(per_seed ? "species,seed" : "species,seeds");
  for (const char* n : kNames) std::printf(per_seed ? ",%s" : ",%s,%s_sd", n, n);
  std::printf("\n");
  try {
    for (; a < argc; ++a) {
      const std::string name = std::filesystem::path(argv[a]).stem().string();
      const boreas::impl::Species s = boreas::impl::load_species(argv[a]);
      std::vector<std::vector<double>> rows;
      for (int seed = 1; seed <= seeds; ++seed) {
        rows.push_back(row(boreas::impl::arbaro_figures(boreas::impl::grow_tree(s, uint64_t(seed)))));
        if (!per_seed) continue;
        std::printf("%s,%d", name.c_str(), seed);
        for (double x : rows.back()) std::printf(",%.6g", x);
        std::printf("\n");
      }
      if (per_seed) continue;
      std::printf("%s,%d", name.c_str(), seeds);
      for (int i = 0; i < kFigures; ++i) {
        double m = 0.0, v = 0.0;
        for (const auto& x : rows) m += x[size_t(i)] / double(rows.size());
        for (const auto& x : rows)
          v += (x[size_t(i)] - m) * (x[size_t(i)] - m) / double(std::max<size_t>(1, rows.size() - 1));
        std::printf(",%.6g,%.4g", m, std::sqrt(v));
      }
      std::printf("\n");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[a], e.what());
    return 1;
  }
  return 0;
}
