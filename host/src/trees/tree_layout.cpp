// boreas: the tree kernels' layout: template blocks, the rest placement of new trees.
#include "trees/tree_layout.h"

#include <algorithm>
#include <cmath>
#include <vector>

// The rest placement uses the kernels' own geometry (float, C++ build of the shared
// header); its polynomial math is only reached by the deformer's radius functions.
#define BOREAS_FAST_MATH 1
#include "errors.h"
#include "shared/leaf_pack.h"
#include "shared/tree_state.h"
#include "trees/wind_load.h"

namespace boreas::impl {
namespace {

// Entry i of a state (stride n) as the vertical unit segment at the origin, O along +x: a
// tree's root, and the layout's sink.
void store_root_segment(float* state, int n, int i) {
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P1, i, boreas_v3(0, 1.0f / 3.0f, 0));
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P2, i, boreas_v3(0, 2.0f / 3.0f, 0));
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P3, i, boreas_v3(0, 1.0f, 0));
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, i, boreas_v3(1, 0, 0));
}

// A block's planes for the model's entries and leaves, zero.
void size_block(TreeTemplateBlock& t, const TreeModel& m) {
  const int n = t.count = block_entries(m);
  const int ln = t.leaf_count = static_cast<int>(m.leaves.size());
  t.parents.assign(size_t(n), 0);
  t.shape.assign(size_t(BOREAS_TREE_SHAPE_PLANES) * n, 0.0f);
  t.radius.assign(size_t(BOREAS_TREE_RADIUS_PLANES) * n, 0.0f);
  t.omega.assign(size_t(n), 0.0);
  t.zeta.assign(size_t(n), 0.0);
  t.leaves.assign(size_t(BOREAS_TREE_LEAF_PLANES) * ln, 0);
}

// What a block's branches take from the tree's physics beyond the model: the bend
// exponent's w2, the drag compliance and the storm's planes (drag load: reconfiguration,
// break bend, hang) and the beams' radii (damped response).
struct BlockPhysics {
  double w2 = 1.0;
  bool drag = false;
  std::vector<double> drag_k, share, break_bend, hang, beam_radius, tip_k;
};

BlockPhysics block_physics(const TreeParams& params, const TreeModel& m) {
  BlockPhysics ph;
  ph.w2 = std::pow(2.0 / 3.0, params.bend_exponent);
  ph.drag = params.load == BOREAS_TREE_LOAD_DRAG;
  if (ph.drag) {
    ph.drag_k = drag_compliance(m, params);
    ph.share = reconfiguring_share(m);
    ph.break_bend = break_bend(m, params);
    ph.hang = drag_per_weight(m);
  }
  ph.beam_radius =
      params.response == BOREAS_TREE_DAMPED ? beam_base_radius(m) : std::vector<double>{};
  ph.tip_k = tip_stiffness(m, params);
  return ph;
}

// Branch b's entry: its parent, shape (local control points, attachment, compliance or
// drag, w2), radius fields and, damped, its natural frequency and damping.
void write_branch(TreeTemplateBlock& t, const TreeParams& params, const TreeModel& m,
                  const BlockPhysics& ph, int b) {
  const int n = t.count;
  const bool drag = ph.drag;
  const BranchModel& br = m.branches[size_t(b)];
  const TreeLevelParams& lp = params.levels[size_t(br.level)];
  const int i = block_index(b);
  const int p = br.parent < 0 ? 0 : block_index(br.parent);
  t.parents[size_t(i)] = p;
  for (int c = 1; c <= 3; ++c)
    for (int a = 0; a < 3; ++a)
      t.shape[size_t(3 * (c - 1) + a) * n + i] = float(br.local[size_t(c)][size_t(a)]);
  for (int a = 0; a < 3; ++a)
    t.shape[size_t(BOREAS_TREE_SHAPE_LOCAL_P0 + a) * n + i] = float(br.local[0][size_t(a)]);
  t.shape[size_t(BOREAS_TREE_SHAPE_V) * n + i] = float(br.v);
  t.shape[size_t(BOREAS_TREE_SHAPE_COS_THETA) * n + i] = float(std::cos(br.theta));
  t.shape[size_t(BOREAS_TREE_SHAPE_SIN_THETA) * n + i] = float(std::sin(br.theta));
  t.shape[size_t(BOREAS_TREE_SHAPE_COS_ALPHA) * n + i] = float(std::cos(br.alpha));
  t.shape[size_t(BOREAS_TREE_SHAPE_SIN_ALPHA) * n + i] = float(std::sin(br.alpha));
  // One signed plane: the drag negated, or the compliance (cl/shared/tree_types.h); the
  // sign says which, so neither may be negative.
  const double load = drag ? ph.drag_k[size_t(b)] : bend_compliance(br, lp);
  if (!(load >= 0.0))
    fail(BOREAS_ERROR_INTERNAL, "tree model of " + m.species + ": branch " + std::to_string(b) +
                                    (drag ? "'s drag " : "'s compliance ") + std::to_string(load) +
                                    " is not >= 0 (its plane's sign says which load it is)");
  t.shape[size_t(BOREAS_TREE_SHAPE_LOAD) * n + i] = drag ? -float(load) : float(load);
  t.shape[size_t(BOREAS_TREE_SHAPE_W2) * n + i] = float(ph.w2);
  const size_t bi = size_t(b);
  t.shape[size_t(BOREAS_TREE_SHAPE_VOGEL_B) * n + i] =
      drag ? float(ph.share[bi] * m.vogel_exponent) : 0.0f;
  t.shape[size_t(BOREAS_TREE_SHAPE_VOGEL_SPEED) * n + i] = drag ? float(1.0 / m.vogel_speed) : 0.0f;
  t.shape[size_t(BOREAS_TREE_SHAPE_BREAK) * n + i] =
      drag ? float(ph.break_bend[bi]) : BOREAS_TREE_NEVER_BREAKS;
  t.shape[size_t(BOREAS_TREE_SHAPE_HANG) * n + i] = drag ? float(ph.hang[bi]) : 0.0f;
  // The tip's stiffness per unit bend factor: the tip moves (1 + w2) F, and a load at the
  // contact point is referred to the tip by the same share (tree_contact.h).
  t.shape[size_t(BOREAS_TREE_SHAPE_CONTACT_STIFFNESS) * n + i] =
      float(ph.tip_k[size_t(b)] * (1.0 + ph.w2) * (1.0 + ph.w2));
  const double radius_fields[BOREAS_TREE_RADIUS_PLANES] = {
      br.radius,     br.taper_depth, std::max(br.taper_exponent, 1.0),
      br.flare,      br.bulge_count, br.bulge_depth,
      br.lobe_count, br.lobe_depth,  br.lobe_taper, br.tip_cap, br.bulge_phase};
  for (int c = 0; c < BOREAS_TREE_RADIUS_PLANES; ++c)
    t.radius[size_t(c) * n + i] = float(radius_fields[c]);
  if (params.response == BOREAS_TREE_DAMPED) {
    BranchModel beam = br;
    beam.radius = ph.beam_radius[size_t(b)];
    t.omega[size_t(i)] = natural_frequency(scaled_branch(beam, params.scale), lp, m.wood_modulus);
    t.zeta[size_t(i)] = lp.damping_ratio;
  }
}

// Entry i (of a state of stride n) placed unbent on its parent p, which (levels in order)
// is placed already, from the block's shape planes (stride n): the floats the kernels read.
void place_unbent(float* state, const float* shape, int n, int i, int p) {
  auto at = [&](int plane) { return shape[size_t(plane) * size_t(n) + size_t(i)]; };
  BoreasV3 parent_o;
  BoreasBezier parent = boreas_tree_load_curve(state, n, p, &parent_o);
  BoreasAttachFrame a = boreas_attach(parent, parent_o, at(BOREAS_TREE_SHAPE_V),
                                      at(BOREAS_TREE_SHAPE_COS_THETA), at(BOREAS_TREE_SHAPE_SIN_THETA),
                                      at(BOREAS_TREE_SHAPE_COS_ALPHA), at(BOREAS_TREE_SHAPE_SIN_ALPHA));
  for (int c = 1; c <= 3; ++c) {
    const int local = BOREAS_TREE_SHAPE_LOCAL_P1 + 3 * (c - 1);
    boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0 + 3 * c, i,
                       boreas_attach_place(a, at(local), at(local + 1), at(local + 2)));
  }
  const int base = BOREAS_TREE_SHAPE_LOCAL_P0;
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0, i,
                     boreas_tree_stand(&a, boreas_v3(at(base), at(base + 1), at(base + 2))));
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, i, a.y);
}

// The model's children (tree_children) of a block whose parents are written.
void write_children(TreeTemplateBlock& t, const TreeModel& m) {
  t.children = tree_children(t.parents, "tree model of " + m.species);
}

// The farthest any branch's surface reaches from the base, scale 1: its P0 lies within
// its ancestors' polygons' lengths (and a trunk's distance apart, local[0]) of the base,
// every point of it within its own beyond, and its surface within its radius's bound
// (flare, bulges and lobes at their widest).
double branch_reach(const TreeModel& m) {
  std::vector<double> from_base(m.branches.size(), 0.0);
  double reach = 0.0;
  for (size_t i = 0; i < m.branches.size(); ++i) {
    const BranchModel& br = m.branches[i];
    from_base[i] = base_offset(br);
    if (br.parent >= 0)
      from_base[i] += from_base[size_t(br.parent)] + m.branches[size_t(br.parent)].length;
    const double widest = br.radius * (1.0 + 0.99 * std::fabs(br.flare)) *
                          (1.0 + std::fabs(br.bulge_depth)) * (1.0 + std::fabs(br.lobe_depth));
    reach = std::max(reach, from_base[i] + br.length + widest);
  }
  return reach;
}

// One leaf's words into planes of stride ln at j (cl/shared/leaf_pack.h).
void pack_leaf(std::vector<int32_t>& planes, size_t ln, size_t j, int32_t entry, const LeafModel& leaf) {
  if (entry < 0 || entry >= (int32_t(1) << BOREAS_LEAF_ENTRY_BITS))  // GrowthLimits keeps within
    fail(BOREAS_ERROR_INTERNAL, "a leaf's parent entry " + std::to_string(entry) +
                                    " passes the packed leaves' 2^" +
                                    std::to_string(BOREAS_LEAF_ENTRY_BITS));
  int words[BOREAS_TREE_LEAF_PLANES];
  boreas_leaf_pack(entry, leaf.v, leaf.cos_theta, leaf.sin_theta, leaf.cos_alpha, leaf.sin_alpha,
                   leaf.cos_roll, leaf.sin_roll, words);
  planes[BOREAS_TREE_LEAF_PLACE * ln + j] = words[BOREAS_TREE_LEAF_PLACE];
  planes[BOREAS_TREE_LEAF_TURN * ln + j] = words[BOREAS_TREE_LEAF_TURN];
}

// Every leaf's parent entry and placement, packed; the petiole they share. A grown tree's
// leaves share their size (tree_generator.cpp): a model whose leaves differ is refused,
// not misdrawn.
void write_leaves(TreeTemplateBlock& t, const TreeModel& m) {
  const size_t ln = size_t(t.leaf_count);
  if (ln == 0) return;
  t.leaf_petiole = float(m.leaves[0].stem);
  for (size_t j = 0; j < ln; ++j) {
    const LeafModel& leaf = m.leaves[j];
    if (leaf.stem != m.leaves[0].stem || leaf.length != m.leaves[0].length ||
        leaf.width != m.leaves[0].width)
      fail(BOREAS_ERROR_INTERNAL, "tree model of " + m.species + ": leaf " + std::to_string(j) +
                                      " differs in size from leaf 0 (a tree's leaves share it)");
    pack_leaf(t.leaves, ln, j, block_index(leaf.parent), leaf);
  }
}

}  // namespace

std::vector<int32_t> tree_children(const std::vector<int32_t>& parents, const std::string& what) {
  // Entries in order, each appended to its parent's first run or, where it does not follow
  // it, to the second; the generator's order makes two enough, and a model that breaks it
  // is refused, not misread.
  const size_t n = parents.size();
  std::vector<int32_t> children(size_t(BOREAS_TREE_CHILD_PLANES) * n, 0);
  for (size_t i = 1; i < n; ++i) {
    const size_t at = size_t(parents[i]);
    if (at == 0) continue;  // a trunk: the root takes no load
    int32_t* first_a = &children[BOREAS_TREE_CHILD_FIRST_A * n + at];
    int32_t* count_a = &children[BOREAS_TREE_CHILD_COUNT_A * n + at];
    int32_t* first_b = &children[BOREAS_TREE_CHILD_FIRST_B * n + at];
    int32_t* count_b = &children[BOREAS_TREE_CHILD_COUNT_B * n + at];
    if (*count_a == 0 || *first_a + *count_a == int32_t(i)) {
      if (*count_a == 0) *first_a = int32_t(i);
      ++*count_a;
    } else if (*count_b == 0 || *first_b + *count_b == int32_t(i)) {
      if (*count_b == 0) *first_b = int32_t(i);
      ++*count_b;
    } else {
      fail(BOREAS_ERROR_INTERNAL, what + ": entry " + std::to_string(at) +
                                      "'s children lie in more than two runs");
    }
  }
  return children;
}

TreeTemplateBlock tree_template_block(const TreeParams& params, const TreeModel& m) {
  TreeTemplateBlock t;
  size_block(t, m);
  const BlockPhysics physics = block_physics(params, m);
  for (int b = 0; b < static_cast<int>(m.branches.size()); ++b) write_branch(t, params, m, physics, b);
  t.rest = rest_state(t.shape, t.parents);
  write_children(t, m);
  write_leaves(t, m);
  t.reach = branch_reach(m);
  const size_t n = size_t(t.count);
  if (n > 1)
    for (size_t a = 0; a < 3; ++a) t.trunk_rest_tip[a] = t.rest[(size_t(BOREAS_TREE_STATE_P3) + a) * n + 1];
  for (const LeafModel& leaf : m.leaves) {
    t.leaf_area += leaf.length * leaf.width;
    t.leaf_reach = std::max(t.leaf_reach, leaf.stem + leaf.length);
  }
  if (!m.leaves.empty()) t.leaf_area /= double(m.leaves.size());
  return t;
}

std::vector<float> rest_state(const std::vector<float>& shape, const std::vector<int32_t>& parents) {
  const int n = static_cast<int>(parents.size());
  std::vector<float> rest(size_t(BOREAS_TREE_STATE_PLANES) * size_t(n), 0.0f);
  float* state = rest.data();
  // The root at the origin, O along +x: place_rest turns and moves it.
  store_root_segment(state, n, 0);
  for (int i = 1; i < n; ++i) place_unbent(state, shape.data(), n, i, parents[size_t(i)]);
  return rest;
}

void place_rest(const std::vector<float>& rest, const TreeParams& params, float* state,
                size_t stride, size_t first, size_t entries) {
  // p -> position + R_y(rotation) (scale p); O -> R_y(rotation) O. Turning the root's O
  // turns the whole tree (the attachment is built from the parent's tangent and O only),
  // so this is the placement the kernels would make, up to rounding.
  const float c = float(std::cos(params.rotation)), s = float(std::sin(params.rotation));
  const float k = float(params.scale);
  const float at[3] = {float(params.position[0]), float(params.position[1]),
                       float(params.position[2])};
  const size_t n = rest.size() / BOREAS_TREE_STATE_PLANES, placed = std::min(n, entries);
  for (int v = 0; v < BOREAS_TREE_STATE_PLANES / 3; ++v) {
    const bool direction = 3 * v == BOREAS_TREE_STATE_O;
    const float* x = &rest[size_t(3 * v) * n];
    const float* y = x + n;
    const float* z = y + n;
    float* ox = state + size_t(3 * v) * stride + first;
    float* oy = ox + stride;
    float* oz = oy + stride;
    for (size_t i = 0; i < placed; ++i) {
      const float px = direction ? x[i] : k * x[i], py = direction ? y[i] : k * y[i],
                  pz = direction ? z[i] : k * z[i];
      const float rx = c * px + s * pz, rz = -s * px + c * pz;
      ox[i] = direction ? rx : at[0] + rx;
      oy[i] = direction ? py : at[1] + py;
      oz[i] = direction ? rz : at[2] + rz;
    }
  }
}

namespace {

// Rows of a block's planes (stride from_n) into a layout's (stride to_n) at `first`.
template <typename T>
void place_planes(std::vector<T>& to, int to_n, int first, const std::vector<T>& from, int from_n,
                  int planes) {
  for (int k = 0; k < planes; ++k)
    std::copy_n(from.begin() + ptrdiff_t(k) * from_n, from_n,
                to.begin() + ptrdiff_t(k) * to_n + first);
}

}  // namespace

TreeLayout tree_layout(const std::vector<TreeLayoutSource>& trees) {
  std::vector<TreeTemplateBlock> blocks;
  blocks.reserve(trees.size());
  TreeLayout t;
  t.tree_count = static_cast<int>(trees.size());
  int g = 1, leaf_g = 1;  // after the sinks
  for (const TreeLayoutSource& source : trees) {
    blocks.push_back(tree_template_block(*source.params, *source.model));
    t.tree_first.push_back(g);
    t.tree_leaf_first.push_back(leaf_g);
    t.tree_scale.push_back(float(source.params->scale));
    t.tree_leaf_petiole.push_back(blocks.back().leaf_petiole * float(source.params->scale));
    g += blocks.back().count;
    leaf_g += blocks.back().leaf_count;
  }
  t.branch_count = g - 1 - t.tree_count;
  t.leaf_count = leaf_g - 1;
  const int n = t.n = g;
  const int ln = t.leaf_n = leaf_g;
  t.parents.assign(size_t(n), 0);
  t.shape.assign(size_t(BOREAS_TREE_SHAPE_PLANES) * n, 0.0f);
  t.radius.assign(size_t(BOREAS_TREE_RADIUS_PLANES) * n, 0.0f);
  t.state.assign(size_t(BOREAS_TREE_STATE_PLANES) * n, 0.0f);
  t.motion.assign(size_t(BOREAS_TREE_MOTION_PLANES) * n, 0.0f);
  t.omega.assign(size_t(n), 0.0);
  t.zeta.assign(size_t(n), 0.0);
  t.leaves.assign(size_t(BOREAS_TREE_LEAF_PLANES) * ln, 0);
  // The sinks: a root-like vertical segment whose shape re-attaches it to itself at v = 0,
  // unbent (compliance 0), and a leaf on it.
  float* state = t.state.data();
  store_root_segment(state, n, 0);
  for (int c = 1; c <= 3; ++c) t.shape[size_t(3 * (c - 1)) * n] = float(c) / 3.0f;
  t.shape[size_t(BOREAS_TREE_SHAPE_COS_THETA) * n] = 1.0f;
  t.shape[size_t(BOREAS_TREE_SHAPE_COS_ALPHA) * n] = 1.0f;
  pack_leaf(t.leaves, size_t(ln), 0, 0, LeafModel{});
  for (size_t k = 0; k < blocks.size(); ++k) {
    const TreeTemplateBlock& b = blocks[k];
    const int first = t.tree_first[k], leaf_first = t.tree_leaf_first[k];
    std::copy(b.parents.begin(), b.parents.end(), t.parents.begin() + first);
    std::copy(b.omega.begin(), b.omega.end(), t.omega.begin() + first);
    std::copy(b.zeta.begin(), b.zeta.end(), t.zeta.begin() + first);
    place_planes(t.shape, n, first, b.shape, b.count, BOREAS_TREE_SHAPE_PLANES);
    place_planes(t.radius, n, first, b.radius, b.count, BOREAS_TREE_RADIUS_PLANES);
    place_rest(b.rest, *trees[k].params, t.state.data(), size_t(n), size_t(first));
    if (b.leaf_count > 0)
      place_planes(t.leaves, ln, leaf_first, b.leaves, b.leaf_count, BOREAS_TREE_LEAF_PLANES);
  }
  return t;
}

std::vector<float> tree_response_planes(const std::vector<double>& omega,
                                        const std::vector<double>& zeta, double dt) {
  const size_t n = omega.size();
  std::vector<float> response(size_t(BOREAS_TREE_RESPONSE_PLANES) * n, 0.0f);
  for (size_t i = 0; i < n; ++i) {
    if (omega[i] <= 0.0) continue;  // quasi-static: a = b = c = d = 0, F = F*
    std::array<double, 4> m = oscillator_step(omega[i], zeta[i], dt);
    for (int k = 0; k < 4; ++k) response[size_t(k) * n + i] = float(m[k]);
    // What the drag's aerodynamic damping needs (cl/shared/tree_math.h, boreas_damped_step).
    response[size_t(BOREAS_TREE_RESPONSE_ALPHA_DT) * n + i] = float(zeta[i] * omega[i] * dt);
    response[size_t(BOREAS_TREE_RESPONSE_OMEGA_DT) * n + i] = float(omega[i] * dt);
    response[size_t(BOREAS_TREE_RESPONSE_DT) * n + i] = float(dt);
    response[size_t(BOREAS_TREE_RESPONSE_OMEGA2_DT) * n + i] = float(omega[i] * omega[i] * dt);
  }
  return response;
}

}  // namespace boreas::impl
