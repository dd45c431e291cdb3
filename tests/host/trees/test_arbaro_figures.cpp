// boreas tests: a few species grown as Arbaro 1.9.9 grows them, on figures that do not depend
// on how a generator stores a split stem's pieces (arbaro_figures.h): the means over many
// seeds within 10 % of Arbaro's own, recorded in tests/data/arbaro_figures.csv by
// tests/tools/ArbaroFigures.java (Arbaro is not a Debian package; the recorded figures are
// the reference). The species: the aspen (no splits; leaves along stems), rush (a tuft of 19
// trunks, fans of leaves, level-2 splits: the lopsided forks), wheat (49 trunks), desert_bush
// (splits on every level, leaves along split stems, stems walked over 12-17 segments with
// nCurveV up to 480) and barley (19 stalks arching ~100 degrees over 49 segments: the fit of
// a long walk by one Bezier, tree_generator.cpp polygon_directions).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "host/trees/arbaro_figures.h"
#include "trees/species.h"

namespace boreas::impl {
namespace {

// Arbaro's mean and seed standard deviation of each figure, by species and column name.
struct Recorded {
  int seeds = 0;
  std::map<std::string, double> mean, sd;
};

std::map<std::string, Recorded> read_recorded() {
  const std::filesystem::path path =
      std::filesystem::path(BOREAS_TEST_DATA_DIR) / "arbaro_figures.csv";
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::map<std::string, Recorded> out;
  std::vector<std::string> columns;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (columns.empty()) {
      columns = cells;
      continue;
    }
    EXPECT_EQ(cells.size(), columns.size()) << line;
    Recorded& r = out[cells[0]];
    r.seeds = std::stoi(cells[1]);
    for (size_t c = 2; c + 1 < cells.size() && c + 1 < columns.size(); c += 2) {
      r.mean[columns[c]] = std::stod(cells[c]);
      r.sd[columns[c]] = std::stod(cells[c + 1]);
    }
  }
  return out;
}

std::map<std::string, double> figures_by_name(const ArbaroFigures& f) {
  std::map<std::string, double> m{{"height", f.height}, {"width", f.width}, {"leaves", f.leaves}};
  for (size_t l = 0; l < 4; ++l) {
    m["length" + std::to_string(l)] = f.length[l];
    m["stems" + std::to_string(l)] = f.stems[l];
  }
  return m;
}

// Seeds per species: enough that the seed spread (coefficient of variation up to 30 %,
// rush's, 35 % desert_bush's level-1 length) leaves the mean's standard error at or below
// about 5 % (desert_bush: 2.5 %, its spread comes from per-tree draws of Scale and
// 1Length), still in a few seconds.
TEST(ArbaroFigures, FiveSpeciesGrowWithinTenPercentOfArbaro) {
  const std::map<std::string, Recorded> recorded = read_recorded();
  const std::map<std::string, int> seeds{{"quaking_aspen", 24}, {"rush", 40}, {"wheat", 60},
                                         {"desert_bush", 200}, {"barley", 40}};
  for (const auto& [name, n] : seeds) {
    SCOPED_TRACE(name);
    const auto it = recorded.find(name);
    ASSERT_NE(it, recorded.end()) << "no recorded figures";
    const Species s = load_species(
        (std::filesystem::path(BOREAS_TEST_DATA_DIR) / "arbaro" / (name + ".xml")).string());
    std::map<std::string, double> sum;
    for (int seed = 1; seed <= n; ++seed)
      for (const auto& [figure, value] : figures_by_name(arbaro_figures(grow_tree(s, uint64_t(seed)))))
        sum[figure] += value / n;
    int compared = 0;
    for (const auto& [figure, want] : it->second.mean) {
      const double got = sum[figure];
      if (want == 0.0) {
        EXPECT_EQ(got, 0.0) << figure;
        continue;
      }
      std::printf("    %-14s %-8s boreas %10.4g  Arbaro %10.4g (sd %.3g over %d seeds)  %+5.1f %%\n",
                  name.c_str(), figure.c_str(), got, want, it->second.sd.at(figure),
                  it->second.seeds, 100.0 * (got / want - 1.0));
      EXPECT_NEAR(got / want, 1.0, 0.10) << figure;
      ++compared;
    }
    EXPECT_GE(compared, 6);
  }
}

}  // namespace
}  // namespace boreas::impl
