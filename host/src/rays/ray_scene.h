// boreas: the ray structure of a world — what boreas_world_cast_rays traverses.
//
// Two levels. Each object instance (a tree, an imported tree's part, a meadow, a BlobTree,
// the solid boxes) has its own bounding volume hierarchy (rays/bvh_build.h), built once on
// the host when it enters the structure and refitted on the device when rays are cast
// after a step; one hierarchy over the instances is built on the host from their refitted
// root boxes at each update (hundreds to thousands of boxes: microseconds).
//
// Why this and not one hierarchy rebuilt per step (a linear BVH from Morton codes): the
// plants sway about fixed places, so a hierarchy built at rest stays good when refitted,
// and refitting costs one pass over the primitives with no sort. A tree's primitives are
// the bands of its bark (a ring of a branch) and its leaves. A band is kept coarse: its box
// is refitted from its branch's curve (15 floats a branch), and its swept triangles are
// made only for the rays that reach that box and pass within the capsule about its piece
// of curve (cl/shared/ray_cast.h, boreas_ray_band_near: about one band in ten whose box a
// ray enters), so a forest's hundreds of millions of bark triangles never exist in
// memory. A leaf is placed at each update by the renderer's own kernel (cl/tree_leaves.cl,
// 9 floats a leaf) and has its own box: a ray tests the few leaves whose boxes it
// crosses. The kernels that make a tree's boxes also write each primitive's record for the
// cast in its hierarchy's item order (cl/shared/ray_types.h, BOREAS_RAY_PRIM_*: 48 bytes a
// band or leaf), so that the cast reads a leaf node's primitives together in one load each. (Leaves made per ray
// from their branch, the first design, cost a ray hundreds of leaf placements in a crown:
// bench/RESULTS.md, "Rays".) The update is a pass over the branches and leaves in reach
// and the meadows' strips, which the renderer makes anyway.
//
// What an update covers: the instances the rays can reach (rays/ray_reach.h: the rays' box,
// and the cones over runs of rays). A tree is skipped while the rays miss a sphere about
// its base that holds everything it can bend into (each branch keeps its control polygon's
// length when it bends); where they meet it, its branches' curves are made and it goes on
// (its bands boxed, its leaves placed) only if the rays reach the hull of its curves, each
// branch's widened by its bark's bound, widened by its leaves' reach (the tree as it
// stands: that sphere is about twice the tree), so a LiDAR's slice pays for the trees it
// sweeps. In a tree that goes on, only the branches the rays reach have their bands and
// leaves boxed (a branch's hull widened by its leaves' reach, asked of a map of the rays'
// directions in constant time, a bough's subtree before its twigs: rays/ray_directions.h);
// those that held boxes and are not reached have them emptied once (ray_scene.cpp,
// select_branches). A meadow is laid in as runs of components (a patch of ground each: ray_scene.cpp,
// add_meadow); a run or an imported tree is skipped while the rays miss its first refitted
// box widened by that box's largest side (its parts are fixed at bases inside it and reach
// no farther than it is large). Only the reached branches' leaves are placed (the
// tree's own leaf kernel over tiles cut to their runs: TreeBatch::enqueue_leaf_runs). The
// refit of the hierarchies above the primitives' boxes is two launches (rays/refit_runs.h),
// and of a tree only its subtree runs that hold a box the update wrote (the others' nodes
// are still their items'). A world nobody casts into pays
// nothing: the structure is made at the first cast.
//
// What the cast walks: each instance's hierarchy as wide nodes (rays/bvh_wide.h), four
// child boxes a node stored together and tested as one 4-lane operation, made once from the
// binary nodes when the instance enters and their boxes copied from the refitted binary
// nodes at each update (one more launch, cl/ray_wide.cl; in a tree, only the wide nodes over
// the runs refitted). The binary nodes stay what the
// refit walks (its runs are the binary subtrees); the wide ones halve the cast's dependent
// node loads, which were its largest wait (bench/RESULTS.md, "Issue 37, tenth round: wide").
//
// Far from the origin (issues 40 and 37). The structure's coordinates count from a frame:
// the world's output origin (boreas_world_set_output_origin) when it was built, and rays
// come in and hits go out relative to that same origin. Every position laid into it is
// world - frame in double, rounded once (a tree's base for its curves and leaves, an
// imported tree's and a meadow's vertices, the ground, BlobTree meshes, solid boxes), so
// plants near the origin a caller sets are as precise as float is near 0, wherever they
// stand. Why this and not a frame per instance (each hierarchy relative to its own base,
// the ray moved into it at each instance visited): it changes nothing in the traversal and
// costs the cast nothing, boreas_ray and boreas_hit stay the device's float records, and
// the rays' own origins must in any case come in relative to something near them (a float
// world coordinate at 100 km is already 8 mm off), which a frame per instance would need
// too. What it costs: a caller that moves the output origin has the structure rebuilt at
// its next cast (current() compares the frame), as an add or a remove does; a renderer
// moves it seldom (once over kilometres).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "blobtree/blobtree_instance.h"
#include "boreas/boreas.h"
#include "mesh_trees/mesh_tree_batch.h"
#include "rays/bvh_build.h"
#include "rays/ray_reach.h"
#include "runtime/runtime.h"
#include "trees/tree_batch.h"
#include "underbrush/underbrush_batch.h"
#include "wind/solid_boxes.h"

namespace boreas::impl {

// What a world holds, as the ray structure reads it (made by World at each cast). The lists
// of objects are filled only when the structure is to be rebuilt (`objects`: RayScene::
// current said it is not): a cast in a world that did not change reads no list.
struct RaySources {
  struct Tree {
    boreas_tree_id id;
    const TreeInstance* tree;
    TreeBatch* batch;
  };
  struct MeshTree {
    boreas_mesh_tree_id id;
    const MeshTreeInstance* tree;
  };
  struct Meadow {
    boreas_meadow_id id;
    const MeadowInstance* meadow;
  };
  struct Blob {
    boreas_blobtree_id id;
    const BlobTreeInstance* blob;
  };
  std::vector<Tree> trees;
  std::vector<MeshTree> mesh_trees;
  std::vector<Meadow> meadows;
  std::vector<Blob> blobtrees;
  bool objects = false;  // the lists above are filled: rebuild from them
  const std::vector<SolidBox>* solid_boxes = nullptr;  // the wind's, as they are now
  MeshTreeBatch* mesh_batch = nullptr;
  std::vector<UnderbrushBatch*> underbrush;  // the world's meadow chunks
  uint64_t changes = 0;  // the world's count of adds and removes
  uint64_t steps = 0;    // the world's count of steps
  std::array<double, 3> origin{};  // m: the world's output origin, the structure's frame
};

struct RayInstance;  // one object in the structure (ray_scene.cpp)

class RayScene {
 public:
  explicit RayScene(Runtime& runtime);
  ~RayScene();

  // Whether the structure holds the world's objects as of its count of adds and removes
  // and these solid boxes, in the frame `origin` (false before the first update).
  bool current(uint64_t changes, const std::vector<SolidBox>& solid_boxes,
               const std::array<double, 3>& origin) const;
  // Makes the structure current for rays within `reach` (rays/ray_reach.h): rebuilt from
  // the sources' objects when they carry them, refitted where the plants moved since the
  // last update that covered them.
  void update(const RaySources& sources, const RayReach& reach);
  // Enqueues the cast of count rays (boreas_ray records from first_ray) into hits
  // (boreas_hit records from first_hit).
  void enqueue_cast(const cl::Buffer& rays, size_t first_ray, int count, const cl::Buffer& hits,
                    size_t first_hit);

  // For tests and the Embree comparison: instances and refits of the last update.
  int instance_count() const;
  int refitted_instances() const { return refitted_; }
  // Tree branches whose bands and leaves the last update boxed (the rest were left out).
  int boxed_branches() const { return boxed_branches_; }

  // The structure as of the last update, read back from the device (blocking): every
  // buffer enqueue_cast passes, whole, for the native twin of the cast (bench/native_rays)
  // and tests that run cl/shared/ray_cast.h in C++ on it. Empty before the first update.
  struct HostCopy {
    std::vector<float> top, nodes, wide, branches, shapes, bands, leaves, placed, records, positions, trunks, crowns, strips;
    std::vector<int32_t> top_items, items, instances, ints;
    int top_root = -1;
  };
  HostCopy host_copy() const;

 struct Built;  // the structure's host and device parts (ray_scene.cpp)

 private:
  void build(const RaySources& sources);
  // refit()'s steps (ray_scene.cpp).
  struct RefitPlan;
  void refit(const RaySources& sources, const RayReach& reach);
  void plan_instance(RayInstance& inst, RefitPlan& plan);
  std::vector<size_t> reached_trees(const std::vector<size_t>& candidates, const RayReach& reach,
                                    RefitPlan& plan);
  bool select_branches(RayInstance& inst, const float* own, const RayReach& reach, RefitPlan& plan);
  void list_branches(RayInstance& inst, const std::vector<uint8_t>& mode, RefitPlan& plan);
  void launch_branches(RefitPlan& plan);
  void launch_bands(RefitPlan& plan);
  void launch_boxes(RefitPlan& plan);
  void refit_levels(RefitPlan& plan);
  void gather_wide(RefitPlan& plan);
  void build_top(uint64_t steps);

  Runtime& runtime_;
  std::unique_ptr<Built> built_;
  uint64_t built_changes_ = ~uint64_t(0);
  std::vector<SolidBox> built_boxes_;
  int refitted_ = 0;
  int boxed_branches_ = 0;
};

}  // namespace boreas::impl
