// boreas: the ray structure (ray_scene.h): building instances, refitting them after a
// step, the hierarchy over them, and the cast's launch.
#include "rays/ray_scene.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "rays/bvh_wide.h"
#include "rays/refit_runs.h"
#include "runtime/launch.h"
#include "boreas/boreas_cl.h"
#include "trees/tree_layout.h"
#include "trees/tree_templates.h"

#define BOREAS_FAST_MATH 1
#include "shared/leaf_outline.h"
#include "shared/ray_math.h"
#include "shared/ray_types.h"
#include "shared/tree_types.h"

namespace boreas::impl {

namespace {

// A meadow's components an instance (add_meadow): some ten square metres of ground at a
// meadow's densities, so that a slice of rays makes the strips of the patches it crosses.
constexpr int kMeadowRun = 1024;
constexpr int kJobWords = 8;    // cl/ray_refit.cl's BOREAS_RAY_JOB_WORDS
constexpr int kRunWords = 4;    // cl/ray_refit.cl's BOREAS_RAY_RUN_WORDS
constexpr int kBranchWords = 8;  // cl/ray_refit.cl's BOREAS_RAY_BRANCH_WORDS
// The refit and cast kernels are scalar; tree states are read with 64-bit offsets.
const char* const kRayDefines = "#define BOREAS_WIDE_PLANES 1\n#define BOREAS_W 1\n";

template <typename Id>
void put_id(int32_t* words, Id id) {
  words[BOREAS_RAY_INST_ID] = int32_t(id.index);
  words[BOREAS_RAY_INST_ID + 1] = int32_t(id.generation);
  words[BOREAS_RAY_INST_ID + 2] = int32_t(id.tag);
}

BoreasBranchRadius radius_of(const BranchModel& b, float scale) {
  BoreasBranchRadius p;
  p.radius = float(b.radius) * scale;
  p.taper_depth = float(b.taper_depth);
  p.taper_exponent = float(b.taper_exponent);
  p.flare = float(b.flare);
  p.bulge_count = float(b.bulge_count);
  p.bulge_depth = float(b.bulge_depth);
  p.lobe_count = float(b.lobe_count);
  p.lobe_depth = float(b.lobe_depth);
  p.lobe_taper = float(b.lobe_taper);
  p.tip_cap = float(b.tip_cap);
  p.bulge_phase = float(b.bulge_phase);
  return p;
}


}  // namespace

// A tree template's branches as the update selects them (ray_scene.cpp, select_branches):
// each branch's parent (a smaller index: the model keeps branches by level), its bands
// [band_first[i], band_first[i + 1]) among the tree's primitives (bands lie branch by
// branch, ring by ring) and, where the model keeps its leaves by parent branch, its leaves
// [leaf_first[i], leaf_first[i + 1]).
struct BranchLayout {
  std::vector<int32_t> parent, band_first, leaf_first;
  bool leaves_by_branch = false;
  // The refit's subtree runs (refit_runs.h) that hold branch i's bands or leaves:
  // runs[run_first[i] .. run_first[i + 1]). Only those of the branches boxed or emptied at
  // an update are refitted (refit_levels).
  std::vector<int32_t> run_first, runs;
  int run_count = 0;
};

// What one instance is and where its parts lie in the structure's buffers.
struct RayInstance {
  std::array<int32_t, BOREAS_RAY_INST_WORDS> words{};
  enum class Moves { kNo, kTree, kTrunk, kCrown, kStrips } moves = Moves::kNo;
  int node_first = 0, node_count = 0;  // its hierarchy's nodes
  int box_first = 0, prims = 0;        // its primitives' boxes
  int item_first = 0;                  // its hierarchy's first item
  Box bound = empty_box();             // what it can reach (trees), for the reach test
  std::array<double, 3> center{};      // a sphere inside `bound` holding the same: its center
  double radius = 0.0;                 // and radius, m
  float leaf_reach = 0.0f;             // trees: how far a leaf reaches from its branch's curve, m
  std::array<float, 3> base{};         // trees: the base in the structure's frame (Built::frame)
  Box box = empty_box();               // its root box as of the last refit
  // Refit inputs: trees (batch, key, first state entry, shape base, scale), imported trees
  // and meadows (key, first vertex or component).
  TreeBatch* batch = nullptr;
  int branches = 0;  // trees: branches (their curves are copied at each refit)
  uint64_t key = 0;
  int first = 0;
  int run = 0;  // meadows: its first component in the meadow (a run of kMeadowRun)
  uint64_t refit_step = ~uint64_t(0);  // the world's step it was last refitted in
  uint64_t curve_step = ~uint64_t(0);  // trees: the step its branches' curves were made in
  bool band_records = false;  // trees: its bands' records written (they never change)
  const BranchLayout* layout = nullptr;  // trees: its template's (Built::templates)
  // Trees: per branch, whether its bands' and leaves' boxes hold anything: those boxed at
  // the tree's last refit (1 until its first: the buffers start unwritten). A branch no ray
  // reaches has them emptied at the next refit and is then left alone (select_branches).
  std::vector<uint8_t> live;
  RefitRuns runs;  // moving instances: its nodes' runs in the refit order (refit_runs.h)
  // Trees: its subtree runs whose primitives' boxes the update writes (list_branches); the
  // others are left as last made. Empty: every run.
  std::vector<uint8_t> dirty_runs;
  int wide_first = 0, wide_count = 0;  // its hierarchy's wide nodes (bvh_wide.h)
  // Moving instances: its wide nodes as segments (first wide node relative to wide_first,
  // count, run), consecutive nodes whose slots all lie in one subtree run `run` (-1: some
  // slot in the top run, or slots in several): gather_wide copies only the segments of
  // the runs an update refits, and every -1 segment.
  std::vector<std::array<int32_t, 3>> wide_runs;
};

struct RayScene::Built {
  // Where the structure's coordinates count from: the world's output origin when it was
  // built (ray_scene.h, "Far from the origin"). Every position put into it is world - frame,
  // taken in double and rounded once.
  std::array<double, 3> frame{};
  std::vector<RayInstance> instances;
  // Host copies of what the device buffers hold, while building.
  std::vector<float> nodes, shapes, bands, leaves, positions;
  std::vector<int32_t> items, ints;
  int boxes = 0, records = 0, branches = 0, placed = 0, trunk_vertices = 0, crown_vertices = 0, components = 0;
  cl::Buffer nodes_buf, order_buf, items_buf, instances_buf, branches_buf, shapes_buf, bands_buf,
      leaves_buf, placed_buf, positions_buf, trunks_buf, crowns_buf, strips_buf, ints_buf, boxes_buf,
      slots_buf, records_buf;
  cl::Buffer top_buf, top_items_buf;
  // The instances' wide nodes (what the cast walks) and, four a node, the binary node
  // each slot's box is gathered from after a refit (bvh_wide.h).
  std::vector<float> wide;
  std::vector<int32_t> wide_gather;
  cl::Buffer wide_buf, wide_gather_buf;
  // The moving instances' nodes in refit order (RayInstance::runs says where each run
  // lies in order_buf).
  std::vector<int32_t> order;
  int top_root = -1;
  // Template trees already laid out: their first shape and leaf, the hierarchy over their
  // branches, the reach of their branches from the base and that of a leaf from the point
  // of its branch it sits on (scale 1).
  struct Template {
    int shapes = 0, bands = 0, band_count = 0, leaves = 0;
    Bvh bvh;
    double reach = 0.0, leaf_reach = 0.0;
    BranchLayout branches;
  };
  std::unordered_map<std::string, Template> templates;

  // Appends an instance's hierarchy (indices offset into the shared buffers) and, where
  // it moves, its nodes' runs to the refit order.
  void add_bvh(RayInstance& inst, const Bvh& bvh) {
    // From an even node, so that its pairs of children share a cache line (bvh_build.h).
    if (nodes.size() / BOREAS_RAY_NODE_WORDS % 2 != 0) {
      nodes.resize(nodes.size() + BOREAS_RAY_NODE_WORDS);
      write_pad_node(&nodes[nodes.size() - BOREAS_RAY_NODE_WORDS]);
    }
    inst.node_first = int(nodes.size() / BOREAS_RAY_NODE_WORDS);
    inst.node_count = bvh.node_count();
    const int item_base = int(items.size());
    inst.item_first = item_base;
    for (int n = 0; n < bvh.node_count(); ++n) {
      const float* w = &bvh.nodes[size_t(n) * BOREAS_RAY_NODE_WORDS];
      const int count = boreas_as_int(w[7]);
      const int a = boreas_as_int(w[3]) + (count > 0 ? item_base : inst.node_first);
      const size_t at = nodes.size();
      nodes.insert(nodes.end(), w, w + BOREAS_RAY_NODE_WORDS);
      nodes[at + 3] = boreas_as_float(a);
    }
    items.insert(items.end(), bvh.items.begin(), bvh.items.end());
    if (inst.moves != RayInstance::Moves::kNo) inst.runs = refit_runs(bvh, inst.node_first, kRefitRun, &order);
    inst.words[BOREAS_RAY_INST_ROOT] = inst.node_first;
    if (bvh.node_count() > 0) {
      const float* w = bvh.nodes.data();
      inst.box = {w[0], w[1], w[2], w[4], w[5], w[6]};
    }
    add_wide(inst, bvh, item_base);
  }

  // Appends the instance's hierarchy as wide nodes (after add_bvh placed its binary nodes
  // from inst.node_first and its items from item_base), indices made absolute.
  void add_wide(RayInstance& inst, const Bvh& bvh, int item_base) {
    const WideBvh w = collapse_bvh(bvh);
    inst.wide_first = int(wide.size() / BOREAS_RAY_WIDE_WORDS);
    inst.wide_count = w.node_count();
    inst.words[BOREAS_RAY_INST_WIDE_ROOT] = inst.wide_first;
    for (int n = 0; n < w.node_count(); ++n) {
      const size_t at = wide.size();
      wide.insert(wide.end(), &w.nodes[size_t(n) * BOREAS_RAY_WIDE_WORDS],
                  &w.nodes[size_t(n + 1) * BOREAS_RAY_WIDE_WORDS]);
      for (int k = 0; k < 4; ++k) {
        const int count = boreas_as_int(wide[at + BOREAS_RAY_WIDE_COUNT + size_t(k)]);
        const int a = boreas_as_int(wide[at + BOREAS_RAY_WIDE_A + size_t(k)]);
        if (count >= 0)
          wide[at + BOREAS_RAY_WIDE_A + size_t(k)] = boreas_as_float(a + (count > 0 ? item_base : inst.wide_first));
        const int32_t g = w.gather[size_t(n) * 4 + size_t(k)];
        wide_gather.push_back(g < 0 ? -1 : g + inst.node_first);
      }
    }
    if (!inst.runs.subtrees.empty()) inst.wide_runs = wide_run_segments(inst, w);
  }

  // The segments of RayInstance::wide_runs, from the runs add_bvh laid into `order`.
  std::vector<std::array<int32_t, 3>> wide_run_segments(const RayInstance& inst, const WideBvh& w) const {
    std::vector<int32_t> node_run(size_t(inst.node_count), -1);
    for (size_t r = 0; r < inst.runs.subtrees.size(); ++r) {
      const auto& run = inst.runs.subtrees[r];
      for (int32_t e = run[0]; e < run[0] + run[1]; ++e) node_run[size_t(order[size_t(e)] - inst.node_first)] = int32_t(r);
    }
    std::vector<std::array<int32_t, 3>> segments;
    for (int n = 0; n < w.node_count(); ++n) {
      int32_t run = -2;  // no slot yet
      for (size_t k = 0; k < 4; ++k) {
        const int32_t g = w.gather[size_t(n) * 4 + k];
        if (g < 0) continue;
        run = run == -2 || run == node_run[size_t(g)] ? node_run[size_t(g)] : -1;
      }
      run = std::max(run, int32_t(-1));
      if (!segments.empty() && segments.back()[2] == run && segments.back()[0] + segments.back()[1] == n)
        ++segments.back()[1];
      else
        segments.push_back({n, 1, run});
    }
    return segments;
  }
};

RayScene::RayScene(Runtime& runtime) : runtime_(runtime) {
  // A refit run is one work-item's walk over up to kRefitRun nodes: on CPUs a group of one,
  // so that a lone tree's few dozen runs spread over the cores (PoCL runs a group on one
  // thread); on GPUs the driver's groups.
  // The same for the trees' hulls of their curves (a work-item a tree).
  const LaunchSizes one = LaunchSizes::work_item_groups({1, 1, 1}), driver = LaunchSizes::driver_groups();
  static const bool rows =
      (add_launch_rows({{"boreas_ray_refit_runs", one, driver}, {"boreas_ray_branch_hulls", one, driver}}), true);
  (void)rows;
}
RayScene::~RayScene() = default;

int RayScene::instance_count() const { return built_ ? int(built_->instances.size()) : 0; }

namespace {

using Built = RayScene::Built;

// Branch i's curve and start vector O in a tree's state planes (stride n).
BoreasBezier state_curve(const std::vector<float>& state, size_t n, int i, BoreasV3* o) {
  const size_t e = size_t(block_index(int32_t(i)));
  auto at = [&](int plane) {
    return boreas_v3(state[size_t(plane) * n + e], state[size_t(plane + 1) * n + e],
                     state[size_t(plane + 2) * n + e]);
  };
  *o = at(BOREAS_TREE_STATE_O);
  BoreasBezier c;
  c.p0 = at(BOREAS_TREE_STATE_P0);
  c.p1 = at(BOREAS_TREE_STATE_P1);
  c.p2 = at(BOREAS_TREE_STATE_P2);
  c.p3 = at(BOREAS_TREE_STATE_P3);
  return c;
}

// The template's branch shapes and bark bands (at scale 1) and each band's box in this
// tree's state, as the refit kernel makes it; returns the farthest any branch reaches from
// the base at scale 1: every point of a branch lies within its polygon's length of its
// P0, and its P0 on its parent's curve (the polygon keeps its length when it bends) or, a
// trunk standing apart, base_offset from its tree's base.
double lay_branches(Built& b, const TreeInstance& tree, const TreeModel& m,
                    const std::vector<float>& state, std::vector<Box>* boxes) {
  const float scale = float(tree.params.scale);
  const size_t n = state.size() / BOREAS_TREE_STATE_PLANES;
  std::vector<double> from_base(m.branches.size(), 0.0);  // bound on |P0 - base|, scale 1
  double reach = 0.0;
  for (size_t i = 0; i < m.branches.size(); ++i) {
    const BranchModel& br = m.branches[i];
    const TreeLevelParams& lp = tree.params.levels[size_t(br.level)];
    const float shape[BOREAS_RAY_SHAPE_FLOATS] = {
        float(br.radius), float(br.taper_depth), float(br.taper_exponent), float(br.flare),
        float(br.bulge_count), float(br.bulge_depth), float(br.lobe_count), float(br.lobe_depth),
        float(br.lobe_taper), float(lp.rings), float(lp.sides), float(br.tip_cap),
        float(br.bulge_phase)};
    const size_t shape_at = b.shapes.size();
    b.shapes.insert(b.shapes.end(), shape, shape + BOREAS_RAY_SHAPE_FLOATS);
    BoreasV3 o;
    const BoreasBezier c = state_curve(state, n, int(i), &o);
    for (int ring = 0; ring < lp.rings; ++ring) {
      const float cap = float(br.tip_cap);
      const float v0 = boreas_ring_v(float(ring), lp.rings, cap);
      const float v1 = boreas_ring_v(float(ring + 1), lp.rings, cap);
      const float bound = boreas_ray_radius_bound(radius_of(br, 1.0f), v0, v1);
      b.bands.insert(b.bands.end(), {float(i), float(ring), bound, 0.0f});
      float& largest = b.shapes[shape_at + BOREAS_RAY_SHAPE_BOUND];
      largest = std::max(largest, bound);
      Box box = empty_box();
      for (const BoreasV3& p : {boreas_ray_blossom(c, v0, v0, v0), boreas_ray_blossom(c, v0, v0, v1),
                                boreas_ray_blossom(c, v0, v1, v1), boreas_ray_blossom(c, v1, v1, v1)}) {
        const float q[3] = {p.x, p.y, p.z};
        grow_box(box, q);
      }
      for (int k = 0; k < 3; ++k) box[size_t(k)] -= bound * scale, box[size_t(k) + 3] += bound * scale;
      boxes->push_back(box);
    }
    from_base[i] = base_offset(br);  // a trunk standing apart (0BranchDist)
    if (br.parent >= 0)
      from_base[i] += from_base[size_t(br.parent)] + m.branches[size_t(br.parent)].length;
    reach = std::max(reach, from_base[i] + br.length +
                                double(boreas_ray_radius_bound(radius_of(br, 1.0f), 0.0f, 1.0f)));
  }
  return reach;
}

// The template's leaf blades (at scale 1) and each leaf's box in this tree's state, placed
// as cl/tree_leaves.cl places it (its quad's corners); returns the farthest a leaf reaches
// beyond the point of its branch it sits on, at scale 1 (petiole, then the quad).
double lay_leaves(Built& b, const TreeInstance& tree, const TreeModel& m,
                  const std::vector<float>& state, std::vector<Box>* boxes) {
  const float scale = float(tree.params.scale);
  const size_t n = state.size() / BOREAS_TREE_STATE_PLANES;
  double reach = 0.0;
  for (const LeafModel& l : m.leaves) {
    b.leaves.insert(b.leaves.end(), {float(l.length), float(l.width)});
    BoreasV3 o;
    const BoreasBezier c = state_curve(state, n, l.parent, &o);
    const BoreasAttachFrame a = boreas_attach(c, o, float(l.v), float(l.cos_theta), float(l.sin_theta),
                                              float(l.cos_alpha), float(l.sin_alpha));
    const BoreasV3 base = boreas_v3_madd(a.origin, a.x, float(l.stem) * scale);
    const BoreasV3 normal = boreas_v3_lin2(a.y, float(l.cos_roll), a.z, float(l.sin_roll));
    BoreasV3 lo, hi;
    boreas_ray_leaf_box(base, a.x, normal, float(l.length) * scale, float(l.width) * scale, &lo, &hi);
    boxes->push_back({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
    // The quad's farthest corner from the blade's base, at scale 1.
    float a0, a1, s0, s1;
    boreas_leaf_offsets(0.0f, 0.0f, float(l.length), float(l.width), &a0, &s0);
    boreas_leaf_offsets(1.0f, 1.0f, float(l.length), float(l.width), &a1, &s1);
    const double far = std::hypot(std::max(std::fabs(double(a0)), std::fabs(double(a1))),
                                  std::max(std::fabs(double(s0)), std::fabs(double(s1))));
    reach = std::max(reach, l.stem + far);
  }
  return reach;
}

// The template's branches as select_branches reads them (BranchLayout), from the bands
// lay_branches laid out (branch by branch) and the model's leaves.
BranchLayout branch_layout(const Built& b, const TreeModel& m, const Built::Template& t) {
  BranchLayout l;
  const size_t n = m.branches.size();
  l.parent.resize(n);
  for (size_t i = 0; i < n; ++i) l.parent[i] = m.branches[i].parent;
  l.band_first.assign(n + 1, 0);
  for (int k = 0; k < t.band_count; ++k)
    ++l.band_first[size_t(b.bands[size_t(t.bands + k) * BOREAS_RAY_BAND_FLOATS + BOREAS_RAY_BAND_BRANCH]) + 1];
  for (size_t i = 0; i < n; ++i) l.band_first[i + 1] += l.band_first[i];
  l.leaves_by_branch = std::is_sorted(m.leaves.begin(), m.leaves.end(),
                                      [](const LeafModel& a, const LeafModel& c) { return a.parent < c.parent; });
  l.leaf_first.assign(n + 1, 0);
  if (l.leaves_by_branch) {
    for (const LeafModel& leaf : m.leaves) ++l.leaf_first[size_t(leaf.parent) + 1];
    for (size_t i = 0; i < n; ++i) l.leaf_first[i + 1] += l.leaf_first[i];
  }
  return l;
}

// Which refit subtree runs hold each branch's primitives (bands first, then leaves: the
// template's boxes' order), from the runs refit_runs makes of the template's hierarchy
// (every instance's are the same). Leaves not kept by branch are in no branch's list: their
// tree refits every run (refit_levels).
void branch_runs(const Bvh& bvh, int band_count, BranchLayout* l) {
  std::vector<int32_t> order;
  const RefitRuns runs = refit_runs(bvh, 0, kRefitRun, &order);
  l->run_count = int(runs.subtrees.size());
  std::vector<int32_t> prim_run(bvh.items.size(), -1);
  for (size_t k = 0; k < bvh.items.size(); ++k) prim_run[size_t(bvh.items[k])] = runs.item_run[k];
  const size_t n = l->parent.size();
  l->run_first.assign(n + 1, 0);
  std::vector<int32_t> mine;
  for (size_t i = 0; i < n; ++i) {
    mine.clear();
    for (int p = l->band_first[i]; p < l->band_first[i + 1]; ++p) mine.push_back(prim_run[size_t(p)]);
    if (l->leaves_by_branch)
      for (int p = l->leaf_first[i]; p < l->leaf_first[i + 1]; ++p) mine.push_back(prim_run[size_t(band_count + p)]);
    std::sort(mine.begin(), mine.end());
    mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
    l->runs.insert(l->runs.end(), mine.begin(), mine.end());
    l->run_first[i + 1] = int32_t(l->runs.size());
  }
}

// A tree's template: its branches' shapes and leaves' blades at scale 1, and the hierarchy
// over its branches and leaves from this tree's current state (every tree of the template
// shares the topology; built at rest or near it, refits hold it as the branches sway).
Built::Template lay_template(Built& b, const TreeInstance& tree, const std::vector<float>& state) {
  Built::Template t;
  t.shapes = int(b.shapes.size() / BOREAS_RAY_SHAPE_FLOATS);
  t.bands = int(b.bands.size() / BOREAS_RAY_BAND_FLOATS);
  t.leaves = int(b.leaves.size() / BOREAS_RAY_LEAF_FLOATS);
  std::vector<Box> boxes;
  // A world keeps its models packed: the whole one grows again here, once per template.
  const std::shared_ptr<const TreeModel> whole = whole_model(tree.model);
  const double branches = lay_branches(b, tree, *whole, state, &boxes);
  t.band_count = int(b.bands.size() / BOREAS_RAY_BAND_FLOATS) - t.bands;
  const double leaves = lay_leaves(b, tree, *whole, state, &boxes);
  t.reach = branches + leaves;  // a leaf sits on a branch
  t.leaf_reach = leaves;
  t.bvh = build_instance_bvh(boxes);
  t.branches = branch_layout(b, *whole, t);
  branch_runs(t.bvh, t.band_count, &t.branches);
  return t;
}

// The key of a template's layout: its model and the mesh's rings and sides per level.
std::string template_layout_key(const TreeInstance& tree) {
  std::string key = tree.template_key;
  for (const TreeLevelParams& lp : tree.params.levels)
    key += "/" + std::to_string(lp.rings) + "x" + std::to_string(lp.sides);
  return key;
}

void add_tree(Built& b, const RaySources::Tree& t) {
  const TreeInstance& tree = *t.tree;
  const std::string key = template_layout_key(tree);
  auto it = b.templates.find(key);
  if (it == b.templates.end())
    it = b.templates.emplace(key, lay_template(b, tree, t.batch->read_tree_state(tree.key))).first;
  const Built::Template& tp = it->second;
  RayInstance inst;
  inst.moves = RayInstance::Moves::kTree;
  inst.batch = t.batch;
  inst.key = tree.key;
  inst.first = t.batch->branch_index(tree.key, 0);
  inst.words[BOREAS_RAY_INST_TYPE] = BOREAS_RAY_TYPE_TREE;
  inst.words[BOREAS_RAY_INST_HIT_KIND] = BOREAS_RAY_HIT_BRANCH;
  put_id(inst.words.data(), t.id);
  const int branches = tree.model->branch_count(), leaves = tree.model->leaf_count();
  inst.branches = branches;
  inst.prims = tp.band_count + leaves;  // bark bands first, then leaves
  inst.words[BOREAS_RAY_INST_BAND_COUNT] = tp.band_count;
  inst.words[BOREAS_RAY_INST_BANDS] = tp.bands;
  inst.words[BOREAS_RAY_INST_BRANCHES] = b.branches;
  inst.words[BOREAS_RAY_INST_PLACED] = b.placed;
  inst.words[BOREAS_RAY_INST_SHAPES] = tp.shapes;
  inst.words[BOREAS_RAY_INST_LEAVES] = tp.leaves;
  inst.words[BOREAS_RAY_INST_SCALE] = boreas_as_int(float(tree.params.scale));
  inst.words[BOREAS_RAY_INST_OUTLINE] = tree.params.leaf_outline;
  b.branches += branches;
  b.placed += leaves;
  const float r = float(tp.reach * tree.params.scale);
  const float p[3] = {float(tree.params.position[0] - b.frame[0]),
                      float(tree.params.position[1] - b.frame[1]),
                      float(tree.params.position[2] - b.frame[2])};
  inst.base = {p[0], p[1], p[2]};
  inst.bound = {p[0] - r, p[1] - r, p[2] - r, p[0] + r, p[1] + r, p[2] + r};
  inst.center = {p[0], p[1], p[2]};
  inst.radius = r;
  inst.leaf_reach = float(tp.leaf_reach * tree.params.scale);
  inst.layout = &tp.branches;
  inst.live.assign(size_t(branches), 1);
  b.add_bvh(inst, tp.bvh);
  b.instances.push_back(inst);
}

// Boxes of triangles over 3-float positions (stride floats apart).
std::vector<Box> triangle_boxes(const float* positions, int stride, const uint32_t* indices,
                                size_t triangles) {
  std::vector<Box> boxes(triangles, empty_box());
  for (size_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) grow_box(boxes[t], positions + size_t(indices[3 * t + k]) * stride);
  return boxes;
}

// Indexed triangles: static (positions copied now) or swayed (positions copied at each
// refit into the trunks' or crowns' buffer).
void add_triangles(Built& b, RayInstance inst, int kind, const float* positions, int stride,
                   size_t vertices, const std::vector<uint32_t>& indices) {
  inst.words[BOREAS_RAY_INST_TYPE] = BOREAS_RAY_TYPE_TRIANGLES;
  inst.words[BOREAS_RAY_INST_HIT_KIND] = kind;
  inst.words[BOREAS_RAY_INST_STRIDE] = stride;
  inst.words[BOREAS_RAY_INST_INDICES] = int(b.ints.size());
  inst.prims = int(indices.size() / 3);
  b.ints.insert(b.ints.end(), indices.begin(), indices.end());
  if (inst.moves == RayInstance::Moves::kNo) {
    inst.words[BOREAS_RAY_INST_BUFFER] = 0;
    inst.words[BOREAS_RAY_INST_VERTICES] = int(b.positions.size());
    b.positions.insert(b.positions.end(), positions, positions + vertices * 3);
  } else {
    // The swayed copies' layout (boreas_cl.h): trunks 3 floats a vertex, leaves 6.
    const bool trunk = inst.moves == RayInstance::Moves::kTrunk;
    const int device_stride = trunk ? BOREAS_MESH_TRUNK_VERTEX_FLOATS : BOREAS_MESH_LEAF_VERTEX_FLOATS;
    int& used = trunk ? b.trunk_vertices : b.crown_vertices;
    inst.first = used;
    inst.words[BOREAS_RAY_INST_BUFFER] = trunk ? 1 : 2;
    inst.words[BOREAS_RAY_INST_STRIDE] = device_stride;
    inst.words[BOREAS_RAY_INST_VERTICES] = used * device_stride;
    used += int(vertices);
  }
  b.add_bvh(inst, build_instance_bvh(triangle_boxes(positions, stride, indices.data(), size_t(inst.prims))));
  b.instances.push_back(inst);
}

void add_mesh_tree(Built& b, const RaySources::MeshTree& t, MeshTreeBatch& batch) {
  for (const bool trunk : {true, false}) {
    const MeshPart& part = trunk ? t.tree->model.trunk : t.tree->model.leaves;
    if (part.indices.empty()) continue;
    std::vector<boreas_vertex> now = trunk ? batch.trunk_vertices(t.tree->key, b.frame)
                                           : batch.leaf_vertices(t.tree->key, b.frame);
    std::vector<float> positions;
    positions.reserve(now.size() * 3);
    for (const boreas_vertex& v : now) positions.insert(positions.end(), v.position, v.position + 3);
    RayInstance inst;
    inst.moves = trunk ? RayInstance::Moves::kTrunk : RayInstance::Moves::kCrown;
    inst.key = t.tree->key;
    put_id(inst.words.data(), t.id);
    add_triangles(b, inst, trunk ? BOREAS_RAY_HIT_MESH_TRUNK : BOREAS_RAY_HIT_MESH_LEAF,
                  positions.data(), 3, now.size(), part.indices);
  }
}

// A meadow: its components' strips, made at each refit into the strips' buffer; the
// topology from where the components stand. One instance a run of kMeadowRun components:
// a meadow keeps its components in Z-order of where they stand (underbrush/meadow.h,
// sort_plantings_by_place), so a run covers a patch of ground, and the update makes the
// strips of the patches the rays can reach (a LiDAR's slice, a camera's view) rather than
// the whole meadow's at every step.
void add_meadow(Built& b, const RaySources::Meadow& m, int first_component, UnderbrushBatch& batch) {
  const Meadow& meadow = m.meadow->meadow;
  const size_t n = size_t(meadow.count);
  // The component planes are on the device alone (underbrush/meadow.h, drop_uploaded).
  const std::vector<float> frame = batch.read_meadow_frame(m.meadow->key);
  // The planes are the meadow's local coordinates (underbrush/meadow.h): the frame's here.
  const std::array<double, 3> o = {meadow.origin[0] - b.frame[0], meadow.origin[1] - b.frame[1],
                                   meadow.origin[2] - b.frame[2]};
  for (int run = 0, count = 0; run < meadow.count; run += count) {
    // The last run takes the rest where less than half a run would be left: no run covers
    // less ground than its sway bound assumes (sway_bound: a box as large as a blade).
    const int left = meadow.count - run;
    count = left < kMeadowRun + kMeadowRun / 2 ? left : kMeadowRun;
    RayInstance inst;
    inst.moves = RayInstance::Moves::kStrips;
    inst.key = m.meadow->key;
    inst.first = first_component + run;
    inst.run = run;
    put_id(inst.words.data(), m.id);
    inst.words[BOREAS_RAY_INST_TYPE] = BOREAS_RAY_TYPE_STRIPS;
    inst.words[BOREAS_RAY_INST_HIT_KIND] = BOREAS_RAY_HIT_UNDERBRUSH;
    inst.words[BOREAS_RAY_INST_VERTICES] =
        inst.first * BOREAS_RAY_STRIP_STRIDE * BOREAS_RAY_STRIP_VERTEX_FLOATS;
    inst.words[BOREAS_RAY_INST_INDICES] = inst.first;
    inst.words[BOREAS_RAY_INST_PART_FIRST] = run;
    inst.prims = count;
    std::vector<Box> boxes(size_t(count), empty_box());
    for (size_t k = 0; k < size_t(count); ++k) {
      const size_t c = size_t(run) + k;
      const float p[3] = {float(frame[BOREAS_UB_FRAME_BASE * n + c] + o[0]),
                          float(frame[(BOREAS_UB_FRAME_BASE + 1) * n + c] + o[1]),
                          float(frame[(BOREAS_UB_FRAME_BASE + 2) * n + c] + o[2])};
      grow_box(boxes[k], p);
    }
    b.add_bvh(inst, build_instance_bvh(boxes));
    b.instances.push_back(inst);
  }
}

// A meadow's ground: its height grid's cells, two triangles each split as the branches'
// quads are ((i0, i1, i2), (i1, i3, i2)); part: the triangle's index, cell (x, z) giving
// triangles 2 (x + (nx - 1) z) and the one after.
void add_ground(Built& b, const RaySources::Meadow& m) {
  const Terrain& ground = m.meadow->meadow.terrain;
  const GroundGrid& g = ground.grid;
  if (g.nx < 2 || g.nz < 2) return;
  std::vector<float> positions;
  positions.reserve(size_t(g.nx) * size_t(g.nz) * 3);
  for (int z = 0; z < g.nz; ++z)
    for (int x = 0; x < g.nx; ++x)
      positions.insert(positions.end(),
                       {float(g.origin_x + g.size_x * x / (g.nx - 1) - b.frame[0]),
                        float(double(ground.height[size_t(z) * size_t(g.nx) + size_t(x)]) - b.frame[1]),
                        float(g.origin_z + g.size_z * z / (g.nz - 1) - b.frame[2])});
  std::vector<uint32_t> indices;
  for (int z = 0; z + 1 < g.nz; ++z)
    for (int x = 0; x + 1 < g.nx; ++x) {
      const uint32_t i0 = uint32_t(z * g.nx + x), i1 = i0 + 1, i2 = i0 + uint32_t(g.nx), i3 = i2 + 1;
      indices.insert(indices.end(), {i0, i1, i2, i1, i3, i2});
    }
  RayInstance inst;
  put_id(inst.words.data(), m.id);
  add_triangles(b, inst, BOREAS_RAY_HIT_GROUND, positions.data(), 3, positions.size() / 3, indices);
}

// Points (3 floats each, world) in the structure's frame: world - frame in double, rounded
// once (the identity when the frame is the world's 0).
std::vector<float> in_frame(const std::array<double, 3>& frame, const std::vector<float>& world) {
  std::vector<float> out(world.size());
  for (size_t i = 0; i < world.size(); ++i) out[i] = float(double(world[i]) - frame[i % 3]);
  return out;
}

void add_blobtree(Built& b, const RaySources::Blob& t) {
  RayInstance inst;
  put_id(inst.words.data(), t.id);
  const BlobMesh& mesh = t.blob->mesh;
  const std::vector<float> positions = in_frame(b.frame, mesh.positions);
  add_triangles(b, inst, BOREAS_RAY_HIT_BLOBTREE, positions.data(), 3, mesh.vertex_count(),
                mesh.indices);
}

void add_solid_boxes(Built& b, const std::vector<SolidBox>& solids) {
  if (solids.empty()) return;
  RayInstance inst;
  inst.words[BOREAS_RAY_INST_TYPE] = BOREAS_RAY_TYPE_BOXES;
  inst.words[BOREAS_RAY_INST_HIT_KIND] = BOREAS_RAY_HIT_SOLID_BOX;
  inst.words[BOREAS_RAY_INST_VERTICES] = int(b.positions.size());
  inst.prims = int(solids.size());
  std::vector<Box> boxes;
  for (const SolidBox& world : solids) {
    const std::vector<float> corners = in_frame(b.frame, std::vector<float>(world.begin(), world.end()));
    SolidBox s;
    std::copy(corners.begin(), corners.end(), s.begin());
    b.positions.insert(b.positions.end(), s.begin(), s.end());
    boxes.push_back(s);
  }
  b.add_bvh(inst, build_instance_bvh(boxes));
  b.instances.push_back(inst);
}

template <typename T>
cl::Buffer device_copy(Runtime& runtime, const std::vector<T>& data, const char* what) {
  cl::Buffer buf = runtime.buffer(CL_MEM_READ_WRITE, std::max<size_t>(data.size(), 1) * sizeof(T), what);
  runtime.upload(buf, data);
  return buf;
}

}  // namespace

void RayScene::build(const RaySources& sources) {
  auto b = std::make_unique<Built>();
  b->frame = sources.origin;
  for (const RaySources::Meadow& m : sources.meadows) b->components += m.meadow->meadow.count;
  b->ints.assign(size_t(b->components), 0);  // the strips' counts come first
  int component = 0;
  for (const RaySources::Meadow& m : sources.meadows) {
    for (UnderbrushBatch* chunk : sources.underbrush)
      if (chunk->holds(m.meadow->key)) add_meadow(*b, m, component, *chunk);
    component += m.meadow->meadow.count;
  }
  for (const RaySources::Tree& t : sources.trees) add_tree(*b, t);
  for (const RaySources::MeshTree& t : sources.mesh_trees) add_mesh_tree(*b, t, *sources.mesh_batch);
  for (const RaySources::Meadow& m : sources.meadows) add_ground(*b, m);
  for (const RaySources::Blob& t : sources.blobtrees) add_blobtree(*b, t);
  add_solid_boxes(*b, *sources.solid_boxes);
  // Trees' boxes first: a tree primitive's box slot is its record's index (ray_types.h).
  for (const bool trees : {true, false})
    for (RayInstance& inst : b->instances) {
      if (inst.moves == RayInstance::Moves::kNo || (inst.moves == RayInstance::Moves::kTree) != trees) continue;
      inst.box_first = b->boxes;
      b->boxes += inst.prims;
      if (trees) {
        inst.words[BOREAS_RAY_INST_RECORDS] = inst.box_first - inst.item_first;
        b->records = b->boxes;
      }
    }
  // Where each moving primitive's box is kept: at its place in its hierarchy's items, so
  // that the refit reads a leaf's boxes together (cl/ray_refit.cl, boreas_ray_store_slot;
  // through the items they were a cache miss a primitive: bench/RESULTS.md, "Issue 37,
  // fifth round").
  std::vector<int32_t> slots(size_t(b->boxes));
  for (const RayInstance& inst : b->instances) {
    if (inst.moves == RayInstance::Moves::kNo) continue;
    for (int k = 0; k < inst.prims; ++k)
      slots[size_t(inst.box_first + b->items[size_t(inst.item_first + k)])] = inst.box_first + k;
  }
  b->slots_buf = device_copy(runtime_, slots, "ray box slots");
  std::vector<int32_t> words;
  for (const RayInstance& inst : b->instances) words.insert(words.end(), inst.words.begin(), inst.words.end());
  b->nodes_buf = device_copy(runtime_, b->nodes, "ray nodes");
  b->wide_buf = device_copy(runtime_, b->wide, "ray wide nodes");
  b->wide_gather_buf = device_copy(runtime_, b->wide_gather, "ray wide node gather");
  b->order_buf = device_copy(runtime_, b->order, "ray refit order");
  b->items_buf = device_copy(runtime_, b->items, "ray items");
  b->instances_buf = device_copy(runtime_, words, "ray instances");
  b->shapes_buf = device_copy(runtime_, b->shapes, "ray branch shapes");
  b->bands_buf = device_copy(runtime_, b->bands, "ray bark bands");
  b->leaves_buf = device_copy(runtime_, b->leaves, "ray leaves");
  b->positions_buf = device_copy(runtime_, b->positions, "ray positions");
  b->ints_buf = device_copy(runtime_, b->ints, "ray indices");
  auto sized = [&](size_t floats, const char* what) {
    return runtime_.buffer(CL_MEM_READ_WRITE, std::max<size_t>(floats, 1) * sizeof(float), what);
  };
  b->branches_buf = sized(size_t(b->branches) * BOREAS_RAY_BRANCH_FLOATS, "ray branch curves");
  b->placed_buf = sized(size_t(b->placed) * BOREAS_RAY_PLACED_FLOATS, "ray placed leaves");
  b->trunks_buf = sized(size_t(b->trunk_vertices) * BOREAS_MESH_TRUNK_VERTEX_FLOATS, "ray trunks");
  b->crowns_buf = sized(size_t(b->crown_vertices) * BOREAS_MESH_LEAF_VERTEX_FLOATS, "ray crowns");
  b->strips_buf = sized(size_t(b->components) * BOREAS_RAY_STRIP_STRIDE * BOREAS_RAY_STRIP_VERTEX_FLOATS,
                        "ray strips");
  b->boxes_buf = sized(size_t(b->boxes) * 6, "ray boxes");
  b->records_buf = sized(size_t(b->records) * BOREAS_RAY_PRIM_FLOATS, "ray tree records");
  b->nodes.clear();
  b->wide.clear();
  b->wide_gather.clear();
  b->shapes.clear();
  b->bands.clear();
  b->leaves.clear();
  b->positions.clear();
  b->ints.clear();
  b->order.clear();
  built_ = std::move(b);
}

namespace {

// Jobs of one refit launch (cl/ray_refit.cl): kJobWords ints each, the first two the
// job's first work-item and count.
struct Jobs {
  std::vector<int32_t> words;
  int items = 0;
  void add(int count, std::initializer_list<int32_t> payload) {
    if (count <= 0) return;
    const size_t at = words.size();
    words.resize(at + kJobWords, 0);
    words[at] = items;
    words[at + 1] = count;
    size_t k = at + 2;
    for (int32_t w : payload) words[k++] = w;
    items += count;
  }
  int count() const { return int(words.size() / kJobWords); }
};

// What a meadow's run or an imported tree can sway into, from its box as first refitted:
// its parts are fixed at their bases inside that box and none reaches farther from its
// base than the box is large (a run holds 512 components or more, or its whole meadow:
// metres of ground, far more than a blade is long), so the box widened by its largest side
// on every side holds every shape the wind can give them. Before the first refit the bound
// is empty: it is refitted.
Box sway_bound(const Box& first) {
  const float size = std::max({first[3] - first[0], first[4] - first[1], first[5] - first[2]});
  return {first[0] - size, first[1] - size, first[2] - size,
          first[3] + size, first[4] + size, first[5] + size};
}

}  // namespace

// What one update refits: the jobs of the box kernels, the instances refitted (flags, for
// the levels' refit), and their order (for their root boxes).
struct RayScene::RefitPlan {
  std::unordered_map<TreeBatch*, Jobs> tree_jobs;
  Jobs trunk_jobs, crown_jobs, strip_jobs;
  // The reached trees' branches whose bands are boxed or emptied (kBranchWords each,
  // cl/ray_refit.cl boreas_ray_branch_bands) and their leaves' runs (boreas_ray_leaf_runs).
  std::vector<int32_t> branch_items;
  Jobs leaf_jobs;
  uint64_t steps = 0;  // the world's count of steps
  std::vector<size_t> refitted;
  std::vector<cl::Buffer> keep;  // the jobs' device copies, alive until the update's read
  // The imported trees' and meadows' geometry, each list made in one launch.
  std::vector<MeshTreeBatch::CopyTo> trunk_copies, crown_copies;
  std::vector<UnderbrushBatch::VertexDraw> strip_draws;
};

// One instance's part of the update: its geometry placed where the library makes it (trees'
// leaves; imported trees' vertices and meadows' strips listed for one launch each), and
// its box jobs.
void RayScene::plan_instance(RayInstance& inst, RefitPlan& plan) {
  const int32_t* w = inst.words.data();
  switch (inst.moves) {
    case RayInstance::Moves::kTree:
      // Its curves, bands and leaves are listed by reached_trees (select_branches).
      break;
    case RayInstance::Moves::kTrunk:
    case RayInstance::Moves::kCrown: {
      const bool trunk = inst.moves == RayInstance::Moves::kTrunk;
      (trunk ? plan.trunk_copies : plan.crown_copies).push_back({inst.key, size_t(inst.first)});
      (trunk ? plan.trunk_jobs : plan.crown_jobs)
          .add(inst.prims, {w[BOREAS_RAY_INST_VERTICES], w[BOREAS_RAY_INST_STRIDE],
                            w[BOREAS_RAY_INST_INDICES], inst.box_first});
      break;
    }
    case RayInstance::Moves::kStrips:
      plan.strip_draws.push_back({inst.key, size_t(inst.first), inst.run, inst.prims});
      plan.strip_jobs.add(inst.prims, {w[BOREAS_RAY_INST_VERTICES], w[BOREAS_RAY_INST_INDICES],
                                       inst.box_first});
      break;
    case RayInstance::Moves::kNo:
      break;
  }
}

// The candidate trees' curves, then each branch's hull of its control points widened by
// its bark's bound (cl/ray_refit.cl, boreas_ray_branch_hulls), read back. That holds the
// branch's bark, and each of its leaves lies within the tree's leaf reach of its curve, so
// the hull widened by that holds the branch as it stands, and their union the tree: the
// trees whose union the rays miss go no further (no band boxed, no leaf placed, their
// hierarchy not refitted), though the sphere they can sway into met the rays. That sphere,
// about the base with the longest chain of branches as its radius, is some twice the tree
// (bench/RESULTS.md, "Issue 37, third round: rays"), and a LiDAR's slice meets many such
// spheres whose trees it misses: their curves cost a work-item a branch, their bands
// (several a branch) nothing. In the trees reached, only the branches reached are boxed
// (select_branches).
std::vector<size_t> RayScene::reached_trees(const std::vector<size_t>& candidates, const RayReach& reach,
                                            RefitPlan& plan) {
  Built& b = *built_;
  if (candidates.empty()) return {};
  std::vector<int32_t> runs, out_first;  // out_first: each candidate's first hull
  int32_t hulls_count = 0;
  for (size_t i : candidates) {
    RayInstance& inst = b.instances[i];
    const int32_t* w = inst.words.data();
    // A tree's branches from its own entries, then from its settled ones (tree_batch.h).
    int32_t own = 0, settled = 0;
    inst.batch->settled_split(inst.key, &own, &settled);
    // Its base in the frame (words 4..6, float bits): the state is relative to it
    // (trees/tree_batch.h).
    const std::array<float, 3>& at = inst.base;
    const int32_t bx = boreas_as_int(at[0]), by = boreas_as_int(at[1]), bz = boreas_as_int(at[2]);
    if (inst.curve_step != plan.steps) {  // not made for another cast of this step
      plan.tree_jobs[inst.batch].add(own, {inst.first, w[BOREAS_RAY_INST_BRANCHES], bx, by, bz});
      plan.tree_jobs[inst.batch].add(inst.branches - own,
                                     {settled, w[BOREAS_RAY_INST_BRANCHES] + own, bx, by, bz});
      inst.curve_step = plan.steps;
    }
    runs.insert(runs.end(), {w[BOREAS_RAY_INST_BRANCHES], inst.branches, w[BOREAS_RAY_INST_SHAPES],
                             w[BOREAS_RAY_INST_SCALE]});
    out_first.push_back(hulls_count);
    hulls_count += inst.branches;
  }
  launch_branches(plan);
  const int count = int(candidates.size());
  cl::Buffer runs_buf = device_copy(runtime_, runs, "ray tree branch runs");
  cl::Kernel& k = runtime_.kernel("ray_refit.cl", "boreas_ray_branch_hulls", kRayDefines);
  // The candidates' branches' boxes, packed candidate by candidate (made at each update: a
  // forest's whole would cost 24 bytes a branch held for good, and the span of branch
  // records from the first candidate's to the last's holds the trees between them too: a
  // LiDAR's slice asks some 40-70 trees spread over the stand's records).
  std::vector<float> hulls(size_t(hulls_count) * 6);
  cl::Buffer firsts_buf = device_copy(runtime_, out_first, "ray branch hull places");
  cl::Buffer out = runtime_.buffer(CL_MEM_WRITE_ONLY, std::max<size_t>(hulls.size(), 1) * sizeof(float),
                                   "ray branch hulls");
  launch(runtime_, k, Items(size_t(count)), b.branches_buf, b.shapes_buf, runs_buf, count, firsts_buf, out);
  runtime_.read(out, 0, hulls.size() * sizeof(float), hulls.data());
  std::vector<size_t> reached;
  for (size_t c = 0; c < candidates.size(); ++c) {
    RayInstance& inst = b.instances[candidates[c]];
    if (select_branches(inst, &hulls[size_t(out_first[c]) * 6], reach, plan)) reached.push_back(candidates[c]);
  }
  launch_bands(plan);
  return reached;
}

namespace {

// A box's sphere (center, radius: half its diagonal), as the reach tests take it.
double box_sphere(const Box& box, std::array<double, 3>* center) {
  double diagonal = 0.0;
  for (size_t a = 0; a < 3; ++a) {
    (*center)[a] = 0.5 * (double(box[a]) + double(box[a + 3]));
    diagonal += std::pow(double(box[a + 3]) - double(box[a]), 2);
  }
  return 0.5 * std::sqrt(diagonal);
}

bool box_reached(const RayReach& reach, const Box& box, bool part) {
  if (!(box[0] <= box[3])) return false;
  std::array<double, 3> center;
  const double radius = box_sphere(box, &center);
  return part ? reach.meets_part(box, center, radius) : reach.meets(box, center, radius);
}

void grow_by_box(Box& into, const Box& box) {
  for (size_t a = 0; a < 3; ++a) {
    into[a] = std::min(into[a], box[a]);
    into[a + 3] = std::max(into[a + 3], box[a + 3]);
  }
}

// How a branch's primitives are made at this update (cl/ray_refit.cl's flags).
constexpr int32_t kBoxNone = 0, kBoxFull = 1, kBoxEmpty = 2;

}  // namespace

// Which of a candidate tree's branches the rays reach, from each branch's hull (`own`, 6
// floats a branch read back): each widened by the tree's leaf reach where the branch bears
// leaves, and a millimetre more for rounding (the blossoms the bands' boxes hold are
// computed in float; the leaves' boxes are padded by 1e-6 m; a ray's reach is
// conservative). The tree goes on if the union of them meets the rays (the cones'
// test); then a branch's subtree (it and the branches on it: parents come first) is asked
// before its own box (meets_part: the map of directions), so a crown above a LiDAR's top
// channel costs a test a bough. The branches reached have their bands and leaves boxed;
// those that held boxes and are not reached have them emptied, which no ray enters (a leaf
// left in a node a ray enters is turned away by its record's zero normal), so their stale
// places are never hit; the rest are left as they are. Returns whether the tree is to be
// refitted.
bool RayScene::select_branches(RayInstance& inst, const float* own, const RayReach& reach, RefitPlan& plan) {
  const BranchLayout& l = *inst.layout;
  const size_t n = size_t(inst.branches);
  std::vector<Box> boxes(n), subtree(n);
  Box tree = empty_box();
  for (size_t i = 0; i < n; ++i) {
    const bool leafy = !l.leaves_by_branch || l.leaf_first[i + 1] > l.leaf_first[i];
    const float pad = (leafy ? inst.leaf_reach : 0.0f) + 1e-3f;
    for (size_t a = 0; a < 3; ++a) {
      boxes[i][a] = own[i * 6 + a] - pad;
      boxes[i][a + 3] = own[i * 6 + a + 3] + pad;
    }
    grow_by_box(tree, boxes[i]);
  }
  if (!box_reached(reach, tree, false)) return false;
  subtree = boxes;
  for (size_t i = n; i-- > 1;)
    if (l.parent[i] >= 0) grow_by_box(subtree[size_t(l.parent[i])], subtree[i]);
  std::vector<uint8_t> open(n, 0), reached(n, 0), mode(n, uint8_t(kBoxNone));
  for (size_t i = 0; i < n; ++i) {
    const int p = l.parent[i];
    if (p >= 0 && !open[size_t(p)]) continue;
    open[i] = box_reached(reach, subtree[i], true);
    // A branch with nothing on it (most are: the last level) is its subtree.
    reached[i] = open[i] && (subtree[i] == boxes[i] || box_reached(reach, boxes[i], true));
  }
  // Another cast in the step the tree was refitted in: its live branches are current, and
  // only those reached now and not then are boxed (nothing emptied).
  const bool again = inst.refit_step == plan.steps;
  bool changed = false;
  for (size_t i = 0; i < n; ++i) {
    if (reached[i]) mode[i] = uint8_t(again && inst.live[i] ? kBoxNone : kBoxFull);
    else if (!again && (inst.live[i] || !inst.band_records)) mode[i] = kBoxEmpty;
    if (mode[i] != kBoxNone) inst.live[i] = mode[i] == kBoxFull;
    changed |= mode[i] != kBoxNone;
    boxed_branches_ += mode[i] == kBoxFull;
  }
  // Leaves not kept by branch are boxed with their tree (list_branches).
  changed |= !l.leaves_by_branch && !again;
  // Nothing to make: its boxes are current (this step's) or all empty (it holds nothing a
  // ray can hit, and stays out of the hierarchy over the instances).
  if (!changed) return false;
  list_branches(inst, mode, plan);
  return true;
}

namespace {

// The subtree runs of a tree's hierarchy that hold a branch boxed or emptied now (all of them
// where its leaves are not kept by branch: they are boxed with the tree).
void mark_runs(RayInstance& inst, const std::vector<uint8_t>& mode) {
  const BranchLayout& l = *inst.layout;
  if (!l.leaves_by_branch) {
    inst.dirty_runs.clear();
    return;
  }
  inst.dirty_runs.assign(size_t(l.run_count), 0);
  for (size_t i = 0; i < mode.size(); ++i)
    if (mode[i] != kBoxNone)
      for (int32_t r = l.run_first[i]; r < l.run_first[i + 1]; ++r) inst.dirty_runs[size_t(l.runs[size_t(r)])] = 1;
}

}  // namespace

// The items of the branches select_branches chose (mode per branch): their bands' boxes (a
// branch a work-item, with the records at the tree's first update) and their leaves' runs,
// a run over consecutive branches of one mode; the boxed runs' leaves placed (TreeBatch::
// enqueue_leaf_runs: a LiDAR's slice reaches some 60 % of a tree's branches, and placing
// was a sixth of its step while every leaf of a reached tree was placed).
void RayScene::list_branches(RayInstance& inst, const std::vector<uint8_t>& mode, RefitPlan& plan) {
  Built& b = *built_;
  const BranchLayout& l = *inst.layout;
  const int32_t* w = inst.words.data();
  const int bands = w[BOREAS_RAY_INST_BAND_COUNT], leaves = inst.prims - bands;
  const int32_t records = inst.band_records ? 0 : 4;
  mark_runs(inst, mode);
  for (size_t i = 0; i < mode.size(); ++i) {
    const int rings = l.band_first[i + 1] - l.band_first[i];
    if (mode[i] == kBoxNone || rings == 0) continue;
    plan.branch_items.insert(plan.branch_items.end(),
                             {w[BOREAS_RAY_INST_BRANCHES] + int32_t(i), w[BOREAS_RAY_INST_SHAPES] + int32_t(i),
                              w[BOREAS_RAY_INST_BANDS] + l.band_first[i], rings,
                              inst.box_first + l.band_first[i], w[BOREAS_RAY_INST_SCALE], mode[i] | records, 0});
  }
  inst.band_records = true;
  std::vector<int32_t> placed;  // the boxed runs (first leaf, count)
  auto run = [&](int first, int count, int32_t m) {
    if (count <= 0 || m == kBoxNone) return;
    if (m == kBoxFull) placed.insert(placed.end(), {first, count});
    plan.leaf_jobs.add(count, {w[BOREAS_RAY_INST_PLACED] + first, w[BOREAS_RAY_INST_LEAVES] + first,
                               w[BOREAS_RAY_INST_SCALE], inst.box_first + bands + first, first, m});
  };
  if (!l.leaves_by_branch) {
    // Leaves not kept by branch: all of them with the tree.
    run(0, leaves, kBoxFull);
  } else {
    size_t start = 0;
    for (size_t i = 1; i <= mode.size(); ++i) {
      if (i < mode.size() && mode[i] == mode[start]) continue;
      run(l.leaf_first[start], l.leaf_first[i] - l.leaf_first[start], mode[start]);
      start = i;
    }
  }
  inst.batch->enqueue_leaf_runs(inst.key, b.placed_buf, size_t(w[BOREAS_RAY_INST_PLACED]), placed, b.frame);
}

// The trees' curves (the jobs reached_trees lists).
void RayScene::launch_branches(RefitPlan& plan) {
  Built& b = *built_;
  for (auto& [batch, jobs] : plan.tree_jobs) {
    plan.keep.push_back(device_copy(runtime_, jobs.words, "ray refit jobs"));
    cl::Kernel& k = runtime_.kernel("ray_refit.cl", "boreas_ray_tree_branches", kRayDefines);
    launch(runtime_, k, Items(size_t(jobs.items)), batch->state_buffer(), batch->motion_buffer(),
           batch->shape_buffer(), batch->settled_buffer(), batch->stride(), batch->static_stride(),
           batch->settled_stride(), plan.keep.back(), jobs.count(), jobs.items, b.branches_buf);
  }
}

// The listed branches' bands' boxes, from their curves, a branch a work-item.
void RayScene::launch_bands(RefitPlan& plan) {
  Built& b = *built_;
  const int count = int(plan.branch_items.size() / kBranchWords);
  if (count == 0) return;
  plan.keep.push_back(device_copy(runtime_, plan.branch_items, "ray branch items"));
  cl::Kernel& k = runtime_.kernel("ray_refit.cl", "boreas_ray_branch_bands", kRayDefines);
  launch(runtime_, k, Items(size_t(count)), b.branches_buf, b.bands_buf, b.shapes_buf, plan.keep.back(),
         count, b.slots_buf, b.boxes_buf, b.records_buf);
}

// The other primitives' boxes: the reached trees' leaves (their runs from select_branches),
// imported trees' triangles and meadows' strips.
void RayScene::launch_boxes(RefitPlan& plan) {
  Built& b = *built_;
  auto upload = [&](const Jobs& jobs) {
    plan.keep.push_back(device_copy(runtime_, jobs.words, "ray refit jobs"));
    return plan.keep.back();
  };
  const Jobs& leaves = plan.leaf_jobs;
  if (leaves.items > 0) {
    cl::Kernel& k = runtime_.kernel("ray_refit.cl", "boreas_ray_leaf_runs", kRayDefines);
    launch(runtime_, k, Items(size_t(leaves.items)), b.placed_buf, b.leaves_buf, upload(leaves), leaves.count(),
           leaves.items, b.slots_buf, b.boxes_buf, b.records_buf);
  }
  for (const bool trunk : {true, false}) {
    const Jobs& jobs = trunk ? plan.trunk_jobs : plan.crown_jobs;
    if (jobs.items == 0) continue;
    cl::Kernel& k = runtime_.kernel("ray_refit.cl", "boreas_ray_triangle_boxes", kRayDefines);
    launch(runtime_, k, Items(size_t(jobs.items)), trunk ? b.trunks_buf : b.crowns_buf, b.ints_buf,
           upload(jobs), jobs.count(), jobs.items, b.slots_buf, b.boxes_buf);
  }
  const Jobs& strips = plan.strip_jobs;
  if (strips.items > 0) {
    cl::Kernel& k = runtime_.kernel("ray_refit.cl", "boreas_ray_strip_boxes", kRayDefines);
    launch(runtime_, k, Items(size_t(strips.items)), b.strips_buf, b.ints_buf, upload(strips),
           strips.count(), strips.items, b.slots_buf, b.boxes_buf);
  }
}

// The refitted instances' hierarchies, their subtrees' runs in one launch and the nodes
// above them in another (refit_runs.h), then their root boxes read back.
void RayScene::refit_levels(RefitPlan& plan) {
  Built& b = *built_;
  std::vector<int32_t> subtrees, tops;
  for (size_t i : plan.refitted) {
    const RayInstance& inst = b.instances[i];
    // A leaf's item i has its box at i + shift (the boxes kept in item order).
    const int shift = inst.box_first - inst.item_first;
    // A tree's runs whose primitives kept their boxes keep theirs (mark_runs).
    const bool some = inst.moves == RayInstance::Moves::kTree && !inst.dirty_runs.empty();
    for (size_t r = 0; r < inst.runs.subtrees.size(); ++r) {
      if (some && !inst.dirty_runs[r]) continue;
      subtrees.insert(subtrees.end(), {inst.runs.subtrees[r][0], inst.runs.subtrees[r][1], shift, 0});
    }
    if (inst.runs.top[1] > 0) tops.insert(tops.end(), {inst.runs.top[0], inst.runs.top[1], shift, 0});
  }
  static_assert(kRunWords == 4, "the job records above");
  cl::Kernel& runs = runtime_.kernel("ray_refit.cl", "boreas_ray_refit_runs", kRayDefines);
  for (const std::vector<int32_t>* jobs : {&subtrees, &tops}) {
    if (jobs->empty()) continue;
    const int count = int(jobs->size() / kRunWords);
    plan.keep.push_back(device_copy(runtime_, *jobs, "ray refit runs"));
    launch(runtime_, runs, Items(size_t(count)), b.nodes_buf, b.boxes_buf, b.order_buf,
           plan.keep.back(), count);
  }
  std::vector<int32_t> roots;
  for (size_t i : plan.refitted) roots.push_back(b.instances[i].node_first);
  cl::Buffer roots_buf = device_copy(runtime_, roots, "ray roots");
  cl::Buffer out = runtime_.buffer(CL_MEM_WRITE_ONLY, roots.size() * 6 * sizeof(float), "ray root boxes");
  cl::Kernel& gather = runtime_.kernel("ray_refit.cl", "boreas_ray_roots", kRayDefines);
  launch(runtime_, gather, Items(roots.size()), b.nodes_buf, roots_buf, int(roots.size()), out);
  std::vector<float> boxes(roots.size() * 6);
  runtime_.read(out, 0, boxes.size() * sizeof(float), boxes.data());
  for (size_t r = 0; r < plan.refitted.size(); ++r) {
    RayInstance& inst = b.instances[plan.refitted[r]];
    std::copy(&boxes[r * 6], &boxes[r * 6 + 6], inst.box.begin());
    if (inst.moves != RayInstance::Moves::kTree && inst.bound[0] > inst.bound[3]) {
      inst.bound = sway_bound(inst.box);
      double diagonal = 0.0;
      for (size_t a = 0; a < 3; ++a) {
        inst.center[a] = 0.5 * (double(inst.bound[a]) + inst.bound[a + 3]);
        diagonal += std::pow(double(inst.bound[a + 3]) - inst.bound[a], 2);
      }
      inst.radius = 0.5 * std::sqrt(diagonal);
    }
  }
}

void RayScene::refit(const RaySources& sources, const RayReach& reach) {
  Built& b = *built_;
  RefitPlan plan;
  plan.steps = sources.steps;
  auto refit_now = [&](size_t i) {
    plan_instance(b.instances[i], plan);
    plan.refitted.push_back(i);
    b.instances[i].refit_step = sources.steps;
  };
  boxed_branches_ = 0;
  std::vector<size_t> trees;
  for (size_t i = 0; i < b.instances.size(); ++i) {
    RayInstance& inst = b.instances[i];
    if (inst.moves == RayInstance::Moves::kNo) continue;
    // A tree refitted in this step is asked again: these rays may reach branches those did not.
    if (inst.refit_step == sources.steps && inst.moves != RayInstance::Moves::kTree) continue;
    // Trees have their bound from the start; meadows and imported trees after their first
    // refit (sway_bound).
    const bool bounded = inst.bound[0] <= inst.bound[3];
    if (bounded && !reach.meets(inst.bound, inst.center, inst.radius)) continue;
    if (inst.moves == RayInstance::Moves::kTree) trees.push_back(i);
    else refit_now(i);
  }
  for (size_t i : reached_trees(trees, reach, plan)) refit_now(i);
  refitted_ = int(plan.refitted.size());
  if (plan.refitted.empty()) return;
  // The imported trees' and meadows' geometry, one launch a list (a meadow chunk's list),
  // before the boxes read it.
  if (!plan.trunk_copies.empty())
    sources.mesh_batch->enqueue_copy(plan.trunk_copies, BOREAS_MESH_TRUNK, b.trunks_buf, b.frame);
  if (!plan.crown_copies.empty())
    sources.mesh_batch->enqueue_copy(plan.crown_copies, BOREAS_MESH_LEAVES, b.crowns_buf, b.frame);
  for (UnderbrushBatch* chunk : sources.underbrush) {
    std::vector<UnderbrushBatch::VertexDraw> draws;
    for (const UnderbrushBatch::VertexDraw& d : plan.strip_draws)
      if (chunk->holds(d.key)) draws.push_back(d);
    if (!draws.empty()) chunk->enqueue_vertices(draws, nullptr, b.strips_buf, b.ints_buf, b.frame);
  }
  launch_boxes(plan);
  refit_levels(plan);
  gather_wide(plan);
}

// The refitted instances' wide nodes take their slots' boxes from the binary nodes just
// refitted (cl/ray_wide.cl): a work-item a run of up to kWideRun wide nodes of one instance,
// in a tree only those over the subtree runs refitted (refit_levels) and those with a slot
// in its top run (RayInstance::wide_runs): a run left as it was keeps the boxes its wide
// nodes were last given, as its binary nodes keep theirs (copying every wide node of a
// refitted tree was 7 % of a LiDAR's step: bench/RESULTS.md, "Issue 37, eleventh round:
// reach2"; tests/host/rays/test_ray_history.cpp guards what is left as it was).
void RayScene::gather_wide(RefitPlan& plan) {
  constexpr int kWideRun = 64;
  Built& b = *built_;
  std::vector<int32_t> jobs;
  auto add = [&](int first, int count) {
    for (int w = 0; w < count; w += kWideRun) jobs.insert(jobs.end(), {first + w, std::min(kWideRun, count - w)});
  };
  for (size_t i : plan.refitted) {
    const RayInstance& inst = b.instances[i];
    // A tree's runs left as they were keep their wide nodes as last gathered (refit_levels).
    const bool some = inst.moves == RayInstance::Moves::kTree && !inst.dirty_runs.empty();
    if (!some) {
      add(inst.wide_first, inst.wide_count);
      continue;
    }
    for (const std::array<int32_t, 3>& seg : inst.wide_runs)
      if (seg[2] < 0 || inst.dirty_runs[size_t(seg[2])]) add(inst.wide_first + seg[0], seg[1]);
  }
  if (jobs.empty()) return;
  const int count = int(jobs.size() / 2);
  plan.keep.push_back(device_copy(runtime_, jobs, "ray wide gather runs"));
  cl::Kernel& k = runtime_.kernel("ray_wide.cl", "boreas_ray_wide_gather", kRayDefines);
  launch(runtime_, k, Items(size_t(count)), b.nodes_buf, b.wide_gather_buf, plan.keep.back(), count,
         b.wide_buf);
}

void RayScene::build_top(uint64_t steps) {
  Built& b = *built_;
  // Every instance current for this step: the static ones, and the moving ones refitted in
  // it (a tree out of every reach of this step keeps an old box: it is left out).
  std::vector<Box> boxes;
  std::vector<int32_t> which;
  for (size_t i = 0; i < b.instances.size(); ++i) {
    const RayInstance& inst = b.instances[i];
    if (inst.node_count == 0) continue;
    if (inst.moves != RayInstance::Moves::kNo && inst.refit_step != steps) continue;
    if (inst.box[0] == BOREAS_RAY_NOWHERE) continue;  // nothing in it (boreas_ray_refit_node)
    boxes.push_back(inst.box);
    which.push_back(int32_t(i));
  }
  Bvh top = build_bvh(boxes, BOREAS_RAY_TOP_DEPTH);
  for (int32_t& item : top.items) item = which[size_t(item)];
  b.top_root = top.node_count() > 0 ? 0 : -1;
  b.top_buf = device_copy(runtime_, top.nodes, "ray top nodes");
  b.top_items_buf = device_copy(runtime_, top.items, "ray top items");
}

bool RayScene::current(uint64_t changes, const std::vector<SolidBox>& solid_boxes,
                       const std::array<double, 3>& origin) const {
  return built_ && built_changes_ == changes && built_boxes_ == solid_boxes && built_->frame == origin;
}

void RayScene::update(const RaySources& sources, const RayReach& reach) {
  if (sources.objects) {
    built_.reset();
    build(sources);
    built_changes_ = sources.changes;
    built_boxes_ = *sources.solid_boxes;
  }
  refit(sources, reach);
  build_top(sources.steps);
}

namespace {

// A buffer's whole contents (its size from OpenCL).
template <typename T>
std::vector<T> read_all(Runtime& runtime, const cl::Buffer& buf) {
  std::vector<T> out(buf.getInfo<CL_MEM_SIZE>() / sizeof(T));
  if (!out.empty()) runtime.read(buf, 0, out.size() * sizeof(T), out.data());
  return out;
}

}  // namespace

RayScene::HostCopy RayScene::host_copy() const {
  HostCopy c;
  if (!built_) return c;
  const Built& b = *built_;
  c.top = read_all<float>(runtime_, b.top_buf);
  c.top_items = read_all<int32_t>(runtime_, b.top_items_buf);
  c.top_root = b.top_root;
  c.nodes = read_all<float>(runtime_, b.nodes_buf);
  c.wide = read_all<float>(runtime_, b.wide_buf);
  c.items = read_all<int32_t>(runtime_, b.items_buf);
  c.instances = read_all<int32_t>(runtime_, b.instances_buf);
  c.branches = read_all<float>(runtime_, b.branches_buf);
  c.shapes = read_all<float>(runtime_, b.shapes_buf);
  c.bands = read_all<float>(runtime_, b.bands_buf);
  c.leaves = read_all<float>(runtime_, b.leaves_buf);
  c.placed = read_all<float>(runtime_, b.placed_buf);
  c.records = read_all<float>(runtime_, b.records_buf);
  c.positions = read_all<float>(runtime_, b.positions_buf);
  c.trunks = read_all<float>(runtime_, b.trunks_buf);
  c.crowns = read_all<float>(runtime_, b.crowns_buf);
  c.strips = read_all<float>(runtime_, b.strips_buf);
  c.ints = read_all<int32_t>(runtime_, b.ints_buf);
  return c;
}

void RayScene::enqueue_cast(const cl::Buffer& rays, size_t first_ray, int count,
                            const cl::Buffer& hits, size_t first_hit) {
  if (count <= 0) return;
  Built& b = *built_;
  cl::Kernel& k = runtime_.kernel("ray_cast.cl", "boreas_ray_cast", "#define BOREAS_W 1\n");
  launch(runtime_, k, Items(size_t(count)), b.top_buf, b.top_items_buf, b.top_root, b.wide_buf,
         b.items_buf, b.instances_buf, b.branches_buf, b.shapes_buf, b.records_buf, b.positions_buf,
         b.trunks_buf, b.crowns_buf, b.strips_buf, b.ints_buf, rays, int(first_ray), hits,
         int(first_hit), count);
}

}  // namespace boreas::impl
