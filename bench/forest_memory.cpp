// boreas: what a forest holds, through the C API alone — the process's resident memory
// (/proc/self/statm) and the world's device bytes after adding trees (one
// boreas_world_add_trees call) and a meadow, and after stepping. The program behind
// bench/RESULTS.md's forest memory tables: memory does not depend on the machine's load,
// so it is measured in a fresh process per row, not in the benchmark run.
//
//   boreas_forest_memory TREES TEMPLATES [COMPONENTS [STEPS [mixed] [focus]]]
// TREES quaking aspens on a lattice 8 m apart, from TEMPLATES seeds (0: every tree its own
// seed), over a meadow of COMPONENTS grass components spread over the forest (0: none),
// stepped STEPS times at 60 Hz (0: none). With `mixed`, the trees take BM_ForestStep's
// three species in turn (TEMPLATES seeds each). With `focus`, a viewer stands at the
// forest's middle (one focus point, 1.8 m up): the trees take their levels of detail from
// it, set before the trees are added, and the finest levels of those past full detail go
// straight into the settled space (before this round they were derived and settled once
// carried for kSettleTime, 180 steps; trees/tree_batch.h), so memory follows the view.
// Without it every tree is at full detail.
#include <malloc.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace {

double resident_mb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / 1e6;
}

void check(boreas_status status, const char* what) {
  if (status == BOREAS_OK) return;
  std::fprintf(stderr, "%s: %s\n", what, boreas_last_error());
  std::exit(1);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void report(boreas_world world, const char* when, double seconds) {
  boreas_memory_info memory{};
  check(boreas_world_get_memory(world, &memory), "boreas_world_get_memory");
  // The host heap in use (malloc's arenas and its large blocks): what the library holds
  // besides the device's buffers (PoCL's come from its own allocations) and the code.
  const struct mallinfo2 heap = mallinfo2();
  std::printf("%-16s resident %8.1f MB  device %8.1f MB  heap %8.1f MB  %7.2f s\n", when,
              resident_mb(), double(memory.device_bytes) / 1e6,
              double(heap.uordblks + heap.hblkhd) / 1e6, seconds);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s TREES TEMPLATES [COMPONENTS [STEPS [mixed] [focus]]]\n", argv[0]);
    return 2;
  }
  const int trees = std::atoi(argv[1]), templates = std::atoi(argv[2]);
  const long long components = argc > 3 ? std::atoll(argv[3]) : 0;
  const int steps = argc > 4 ? std::atoi(argv[4]) : 0;
  bool mixed = false, focus = false;
  for (int a = 5; a < argc; ++a) {
    const std::string option = argv[a];
    if (option == "mixed") {
      mixed = true;
    } else if (option == "focus") {
      focus = true;
    } else {
      std::fprintf(stderr, "unknown option '%s' (argument %d): mixed or focus\n", argv[a], a);
      return 2;
    }
  }
  const char* species[3] = {"quaking_aspen", "black_tupelo", "ca_black_oak"};
  const int side = int(std::ceil(std::sqrt(double(trees))));
  const float spacing = 8.0f, extent = float(side) * spacing;

  boreas_world world = nullptr;
  boreas_world_def wd = boreas_default_world_def();
  check(boreas_world_create(&wd, &world), "boreas_world_create");
  report(world, "empty world", 0.0);

  std::vector<boreas_tree_def> defs(size_t(trees), boreas_default_tree_def());
  for (int i = 0; i < trees; ++i) {
    boreas_tree_def& d = defs[size_t(i)];
    if (mixed) d.species = species[i % 3];
    const int k = mixed ? i / 3 : i;
    d.seed = uint64_t(templates > 0 ? k % templates : k) + 1;
    d.position[0] = (float(i % side) - 0.5f * float(side)) * spacing;
    d.position[2] = (float(i / side) - 0.5f * float(side)) * spacing;
  }
  // The viewer first: trees whose level of detail derives their finest level settle as
  // they are added (trees/tree_batch.h), so the add's peak follows the view too.
  if (focus) {
    const float middle[3] = {0.0f, 1.8f, 0.0f};
    check(boreas_world_set_focus(world, middle, 1), "boreas_world_set_focus");
  }
  auto start = std::chrono::steady_clock::now();
  check(boreas_world_add_trees(world, defs.data(), trees, nullptr), "boreas_world_add_trees");
  report(world, "trees added", seconds_since(start));

  if (components > 0) {
    boreas_meadow_def m = boreas_default_meadow_def();
    m.size[0] = m.size[1] = extent;
    m.density = float(double(components) / (double(extent) * double(extent)));
    m.terrain_relief = 0.0f;
    start = std::chrono::steady_clock::now();
    check(boreas_world_add_meadow(world, &m, nullptr), "boreas_world_add_meadow");
    report(world, "meadow added", seconds_since(start));
  }
  if (steps > 0) {
    start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) check(boreas_world_step(world, 1.0f / 60.0f), "boreas_world_step");
    report(world, "stepped", seconds_since(start));
  }
  boreas_world_destroy(world);
  return 0;
}
