// boreas: the order a hierarchy is refitted in (cl/ray_refit.cl, boreas_ray_refit_runs):
// runs of nodes, each made by one work-item in sequence.
//
// The builder (bvh_build.h) gives a node's children larger indices than the node, so nodes
// taken by falling index are each made after their children. A hierarchy is cut into its
// largest subtrees of at most kRefitRun nodes (each a run: one launch makes them all, in
// parallel) and the nodes above them (one run per instance: a second launch). Two launches
// an update, whatever the depth, and a work-item walks a subtree whose nodes lie close
// together, where a launch per level (the refit before) made every instance's nodes of one
// depth apart and cost a launch per level: 35-85 ms of the update at 100 trees
// (bench/RESULTS.md, "Rays").
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rays/bvh_build.h"

namespace boreas::impl {

// Nodes a subtree run holds at most: large enough that a run's sequential work outweighs
// a work-item's dispatch, small enough that a lone tree's hierarchy still makes dozens of
// runs for the cores (bench/RESULTS.md, "Issue 37, third round: rays").
inline constexpr int kRefitRun = 1024;

struct RefitRuns {
  std::vector<std::array<int32_t, 2>> subtrees;  // (first entry in the order, count)
  std::array<int32_t, 2> top{0, 0};              // the nodes above the subtrees
  // Per item (a position in the hierarchy's items), the subtree run whose leaf holds it:
  // a run whose items' boxes did not change since it was last made need not be made again.
  std::vector<int32_t> item_run;
};

// Appends the hierarchy's nodes (indices offset by node_first) to `order` in runs of at
// most max_run nodes (the top run may be longer) and says where the runs lie.
RefitRuns refit_runs(const Bvh& bvh, int node_first, int max_run, std::vector<int32_t>* order);

}  // namespace boreas::impl
