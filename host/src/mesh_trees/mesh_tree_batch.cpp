// boreas: imported trees on the device — table layout, the per-step launches and the
// readbacks (layouts in cl/shared/mesh_tree_types.h).
#include "mesh_trees/mesh_tree_batch.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "mesh_trees/mesh_tree_contact.h"
#include "runtime/launch.h"
#include "shared/mesh_tree_contact_types.h"
#include "shared/mesh_tree_types.h"
#include "validation.h"

namespace boreas::impl {

namespace {

template <typename T>
cl::Buffer make_buffer(Runtime& runtime, const std::vector<T>& data) {
  cl::Buffer b = runtime.buffer(CL_MEM_READ_WRITE, std::max<size_t>(data.size(), 1) * sizeof(T),
                                "imported trees");
  runtime.upload(b, data);
  return b;
}

}  // namespace

MeshTreeParams checked_mesh_tree_def(const boreas_mesh_tree_def& def) {
  MeshTreeParams p;
  if (!def.model || !*def.model)
    fail(BOREAS_ERROR_INVALID_ARGUMENT, "mesh tree model path is empty");
  p.model = def.model;
  ModelPartSelection defaults;
  p.trunk_part = def.trunk_part ? def.trunk_part : defaults.trunk;
  p.leaves_part = def.leaves_part ? def.leaves_part : defaults.leaves;
  if (p.trunk_part.empty()) fail(BOREAS_ERROR_INVALID_ARGUMENT, "mesh tree trunk_part is empty");
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(def.position[a]) || std::abs(def.position[a]) > 1e6f)
      fail(BOREAS_ERROR_INVALID_ARGUMENT, "mesh tree position[" + std::to_string(a) +
                                              "] must be finite and within 1e6 m (got " +
                                              std::to_string(def.position[a]) + ")");
    p.position[a] = def.position[a];
  }
  check_range(def.yaw, -1e3f, 1e3f, "mesh tree yaw (rad)");
  check_range(def.scale, 1e-4f, 1e4f, "mesh tree scale");
  check_range(def.noise_beta, 0.0f, 4.0f, "mesh tree noise_beta");
  check_range(def.bend_exponent, 0.25f, 4.0f, "mesh tree bend_exponent");
  for (int k = 0; k < 4; ++k) {
    const boreas_mesh_level_def& l = def.levels[k];
    std::string at = "mesh tree levels[" + std::to_string(k) + "].";
    check_range(l.bend, 0.0f, 1e3f, at + "bend (m)");
    check_range(l.sway, 0.0f, 1e3f, at + "sway (m)");
    check_range(l.frequency, 0.001f, 50.0f, at + "frequency (Hz)");
    check_range(l.response_time, 0.0f, 60.0f, at + "response_time (s)");
    p.levels[k] = l;
  }
  check_range(def.leaf_flutter, 0.0f, 1e3f, "mesh tree leaf_flutter (m)");
  check_range(def.leaf_turn, 0.0f, 1.0f, "mesh tree leaf_turn");
  check_range(def.flutter_wavelength, 1e-3f, 1e5f, "mesh tree flutter_wavelength (m)");
  if (def.cache != 0 && def.cache != 1)
    fail(BOREAS_ERROR_INVALID_ARGUMENT,
         "mesh tree cache must be 0 or 1 (got " + std::to_string(def.cache) + ")");
  p.yaw = def.yaw;
  p.scale = def.scale;
  p.seed = def.seed;
  p.noise_beta = def.noise_beta;
  p.bend_exponent = def.bend_exponent;
  p.leaf_flutter = def.leaf_flutter;
  p.leaf_turn = def.leaf_turn;
  p.flutter_wavelength = def.flutter_wavelength;
  p.cache = def.cache == 1;
  return p;
}

boreas_mesh_tree_info describe_mesh_tree(const MeshModel& model, const MeshTreeData& data,
                                         bool from_cache) {
  boreas_mesh_tree_info info{};
  info.trunk_vertices = int(model.trunk.vertex_count());
  info.trunk_triangles = int(model.trunk.triangle_count());
  info.leaf_vertices = int(model.leaves.vertex_count());
  info.leaf_triangles = int(model.leaves.triangle_count());
  info.branches = int(data.branches.size());
  info.leaves = int(data.leaf_length.size());
  info.levels = data.levels;
  info.orphans = data.orphans;
  info.from_cache = from_cache ? 1 : 0;
  return info;
}

void place_direction(const MeshTreeParams& p, const float in[3], float out[3]) {
  double c = std::cos(double(p.yaw)), s = std::sin(double(p.yaw));
  // Yaw turns +X towards -Z (counter-clockwise seen from above, right-handed about +Y).
  double x = c * in[0] + s * in[2], z = -s * in[0] + c * in[2];
  out[0] = float(x);
  out[1] = in[1];
  out[2] = float(z);
}

void place_local(const MeshTreeParams& p, const float in[3], float out[3]) {
  float scaled[3] = {in[0] * p.scale, in[1] * p.scale, in[2] * p.scale};
  place_direction(p, scaled, out);
}

void place_point(const MeshTreeParams& p, const float in[3], float out[3]) {
  place_local(p, in, out);
  for (int a = 0; a < 3; ++a) out[a] += p.position[a];
}

namespace {

// Each tree's first entry in every table, and the tables' entry counts.
void count_entries(MeshTreeTables& m, const std::vector<const MeshTreeInstance*>& trees) {
  size_t nb = 0, nv = 0, nl = 0, nlv = 0;
  for (const MeshTreeInstance* tree : trees) {
    m.first_branch.push_back(nb);
    m.first_trunk.push_back(nv);
    m.first_leaf.push_back(nl);
    m.first_leaf_vertex.push_back(nlv);
    nb += tree->data.branches.size();
    nv += tree->model.trunk.vertex_count();
    nl += tree->data.leaf_length.size();
    nlv += tree->model.leaves.vertex_count();
  }
  m.branches = nb;
  m.trunk_vertices = nv;
  m.leaves_count = nl;
  m.leaf_vertices_count = nlv;
}

// Every table at its size for nt trees, zero.
void size_tables(MeshTreeTables& m, size_t nt) {
  const size_t nb = m.branches, nv = m.trunk_vertices, nl = m.leaves_count,
               nlv = m.leaf_vertices_count;
  m.branch_table.assign(BOREAS_MESH_TREE_BRANCH_FLOATS * nb, 0.0f);
  m.links.assign(BOREAS_MESH_TREE_BRANCH_INTS * nb, 0);
  m.noise.assign(nt * 2 * BOREAS_MESH_TREE_NOISE_SIZE * BOREAS_MESH_TREE_NOISE_SIZE, 0.0f);
  m.trunk.assign(BOREAS_MESH_TREE_TRUNK_FLOATS * nv, 0.0f);
  m.trunk_rest.assign(3 * nv, 0.0f);
  m.trunk_branch.assign(nv, 0);
  m.leaf_branch.assign(nl, 0);
  m.vertex_leaf.assign(nlv, 0);
  m.leaves.assign(BOREAS_MESH_TREE_LEAF_FLOATS * nl, 0.0f);
  m.leaf_vertices.assign(BOREAS_MESH_TREE_LEAF_VERTEX_FLOATS * nlv, 0.0f);
  m.leaf_rest.assign(6 * nlv, 0.0f);
  m.contact.assign(BOREAS_MESH_TREE_CONTACT_FLOATS * nb, 0.0f);
}

// Tree ti's branches: frames placed in the world, phases, response times and links.
void place_branches(MeshTreeTables& m, const MeshTreeInstance& tree, size_t ti) {
  const MeshTreeParams& params = tree.params;
  const MeshTreeData& d = tree.data;
  const int t = int(ti);
  const size_t nb = m.branches, first_branch = m.first_branch[ti];
  std::vector<float>& branches = m.branch_table;
  std::vector<int32_t>& links = m.links;
  // Response times per level; branches beyond level 3 answer as fast as level 3.
  for (size_t j = 0; j < d.branches.size(); ++j) {
    const MeshTreeBranch& b = d.branches[j];
    const size_t i = first_branch + j;
    float dir[3];
    place_direction(params, b.axis.data(), dir);
    for (int a = 0; a < 3; ++a) branches[(BOREAS_MESH_TREE_BRANCH_AXIS + a) * nb + i] = dir[a];
    place_direction(params, b.up.data(), dir);
    for (int a = 0; a < 3; ++a) branches[(BOREAS_MESH_TREE_BRANCH_UP + a) * nb + i] = dir[a];
    place_direction(params, b.right.data(), dir);
    for (int a = 0; a < 3; ++a) branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + a) * nb + i] = dir[a];
    place_local(params, b.center.data(), dir);
    for (int a = 0; a < 3; ++a) branches[(BOREAS_MESH_TREE_BRANCH_CENTER + a) * nb + i] = dir[a];
    branches[(BOREAS_MESH_TREE_BRANCH_PHASE + 0) * nb + i] = b.phase[0];
    branches[(BOREAS_MESH_TREE_BRANCH_PHASE + 1) * nb + i] = b.phase[1];
    branches[BOREAS_MESH_TREE_BRANCH_TAU * nb + i] =
        params.levels[std::min(b.level, 3)].response_time;
    for (int k = 0; k < 4; ++k)
      links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + k) * nb + i] =
          int32_t(first_branch) + b.animated_by[k];
    links[BOREAS_MESH_TREE_BRANCH_TREE * nb + i] = t;
    links[BOREAS_MESH_TREE_BRANCH_IS_STEM * nb + i] = b.parent < 0 ? 1 : 0;
  }
}

// Tree ti's noise texture as two planes.
void place_noise(MeshTreeTables& m, const MeshTreeInstance& tree, size_t ti) {
  const int t = int(ti);
  // The texture is interleaved (2 channels per texel); the kernels read two planes.
  const size_t texels = size_t(BOREAS_MESH_TREE_NOISE_SIZE) * BOREAS_MESH_TREE_NOISE_SIZE;
  if (tree.noise.texels.size() != 2 * texels)
    fail(BOREAS_ERROR_INTERNAL,
         "mesh tree noise must be " + std::to_string(BOREAS_MESH_TREE_NOISE_SIZE) + " texels wide");
  float* planes = m.noise.data() + size_t(t) * 2 * texels;
  for (size_t x = 0; x < texels; ++x) {
    planes[x] = tree.noise.texels[2 * x];
    planes[texels + x] = tree.noise.texels[2 * x + 1];
  }
}

// A trunk vertex's or a leaf's four level weights raised to the tree's bend_exponent (so
// branches bend more toward their tips), into planes first..first+3 (n entries each) at i.
void put_weights(const MeshTreeParams& params, const float* weights, std::vector<float>& planes,
                 int first, size_t n, size_t i) {
  for (int k = 0; k < 4; ++k)
    planes[(size_t(first) + size_t(k)) * n + i] =
        float(std::pow(double(weights[k]), double(params.bend_exponent)));
}

// Tree ti's trunk vertices: rest positions (also the output's rest pose), weights, branch.
void place_trunk(MeshTreeTables& m, const MeshTreeInstance& tree, size_t ti) {
  const MeshTreeParams& params = tree.params;
  const MeshTreeData& d = tree.data;
  const size_t nv = m.trunk_vertices, first_branch = m.first_branch[ti],
               first_trunk = m.first_trunk[ti];
  std::vector<float>& trunk = m.trunk;
  std::vector<float>& trunk_out = m.trunk_rest;
  const MeshPart& tm = tree.model.trunk;
  for (size_t v = 0; v < tm.vertex_count(); ++v) {
    const size_t i = first_trunk + v;
    float local[3];
    place_local(params, &tm.positions[3 * v], local);
    for (int a = 0; a < 3; ++a) {
      trunk[(BOREAS_MESH_TREE_TRUNK_REST + a) * nv + i] = local[a];
      trunk_out[3 * i + a] = local[a];
    }
    put_weights(params, &d.trunk_weights[4 * v], trunk, BOREAS_MESH_TREE_TRUNK_WEIGHT, nv, i);
    m.trunk_branch[i] = int32_t(first_branch) + d.trunk_branch[v];
  }
}

// Tree ti's leaves: petioles and axes placed, weights, branch.
void place_leaves(MeshTreeTables& m, const MeshTreeInstance& tree, size_t ti) {
  const MeshTreeParams& params = tree.params;
  const MeshTreeData& d = tree.data;
  const size_t nl = m.leaves_count, first_branch = m.first_branch[ti],
               first_leaf = m.first_leaf[ti];
  std::vector<float>& leaves = m.leaves;
  for (size_t l = 0; l < d.leaf_length.size(); ++l) {
    const size_t i = first_leaf + l;
    float world[3];
    place_local(params, &d.leaf_petiole[3 * l], world);
    for (int a = 0; a < 3; ++a) leaves[(BOREAS_MESH_TREE_LEAF_PETIOLE + a) * nl + i] = world[a];
    place_direction(params, &d.leaf_axis[3 * l], world);
    for (int a = 0; a < 3; ++a) leaves[(BOREAS_MESH_TREE_LEAF_AXIS + a) * nl + i] = world[a];
    put_weights(params, &d.leaf_weights[4 * l], leaves, BOREAS_MESH_TREE_LEAF_WEIGHT, nl, i);
    m.leaf_branch[i] = int32_t(first_branch) + d.leaf_branch[l];
  }
}

// Tree ti's leaf vertices: rest positions and normals (also the output's rest pose), how
// far along its leaf each lies, its leaf.
void place_leaf_vertices(MeshTreeTables& m, const MeshTreeInstance& tree, size_t ti) {
  const MeshTreeData& d = tree.data;
  const MeshTreeParams& params = tree.params;
  const size_t nlv = m.leaf_vertices_count, first_leaf = m.first_leaf[ti],
               first_leaf_vertex = m.first_leaf_vertex[ti];
  std::vector<float>& leaf_vertices = m.leaf_vertices;
  std::vector<float>& leaf_out = m.leaf_rest;
  const MeshPart& lm = tree.model.leaves;
  for (size_t v = 0; v < lm.vertex_count(); ++v) {
    const size_t i = first_leaf_vertex + v;
    const int l = d.leaf_of_vertex[v];
    float world[3], normal[3];
    place_local(params, &lm.positions[3 * v], world);
    place_direction(params, &lm.normals[3 * v], normal);
    for (int a = 0; a < 3; ++a) {
      leaf_vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_REST + a) * nlv + i] = world[a];
      leaf_vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL + a) * nlv + i] = normal[a];
      leaf_out[6 * i + a] = world[a];
      leaf_out[6 * i + 3 + a] = normal[a];
    }
    float length = d.leaf_length[l];
    double r = 0.0;
    for (int a = 0; a < 3; ++a) {
      double o = double(lm.positions[3 * v + a]) - d.leaf_petiole[3 * l + a];
      r += o * o;
    }
    leaf_vertices[BOREAS_MESH_TREE_LEAF_VERTEX_TIP * nlv + i] =
        length > 0.0f ? float(std::sqrt(r) / length) : 0.0f;
    m.vertex_leaf[i] = int32_t(first_leaf) + l;
  }
}

}  // namespace

MeshTreeTables mesh_tree_tables(const std::vector<const MeshTreeInstance*>& trees) {
  MeshTreeTables m;
  count_entries(m, trees);
  size_tables(m, trees.size());
  for (size_t ti = 0; ti < trees.size(); ++ti) {
    const MeshTreeInstance& tree = *trees[ti];
    place_branches(m, tree, ti);
    place_noise(m, tree, ti);
    place_trunk(m, tree, ti);
    place_leaves(m, tree, ti);
    place_leaf_vertices(m, tree, ti);
    place_contact_table(tree, m.contact, m.branches, m.first_branch[ti]);
  }
  return m;
}

std::vector<float> mesh_tree_planes(const std::vector<const MeshTreeInstance*>& trees,
                                    const std::vector<bool>& fresh, double time, size_t stride) {
  const size_t nt = std::max(stride, trees.size());
  std::vector<float> t(BOREAS_MESH_TREE_TREE_FLOATS * nt, 0.0f);
  for (size_t i = 0; i < trees.size(); ++i) {
    if (trees[i] == nullptr) continue;
    const MeshTreeParams& p = trees[i]->params;
    for (int k = 0; k < 4; ++k) {
      t[(BOREAS_MESH_TREE_TREE_BEND + k) * nt + i] = p.levels[k].bend;
      t[(BOREAS_MESH_TREE_TREE_SWAY + k) * nt + i] = p.levels[k].sway;
      // Reduced in double: the kernel only ever sees a phase within one tile.
      double clock = double(p.levels[k].frequency) * time;
      t[(BOREAS_MESH_TREE_TREE_CLOCK + k) * nt + i] = float(clock - std::floor(clock));
    }
    t[BOREAS_MESH_TREE_TREE_FLUTTER * nt + i] = p.leaf_flutter;
    t[BOREAS_MESH_TREE_TREE_TURN * nt + i] = p.leaf_turn;
    t[BOREAS_MESH_TREE_TREE_INV_TILE * nt + i] = 1.0f / p.flutter_wavelength;
    t[BOREAS_MESH_TREE_TREE_FRESH * nt + i] = fresh[i] ? 1.0f : 0.0f;
    const MeshTreeDrag& drag = trees[i]->drag;
    t[BOREAS_MESH_TREE_TREE_DRAG * nt + i] = float(drag.load_per_speed2);
    t[BOREAS_MESH_TREE_TREE_VOGEL_B * nt + i] = float(drag.vogel_b);
    t[BOREAS_MESH_TREE_TREE_VOGEL_SPEED * nt + i] = float(1.0 / kMeshTreeVogelSpeed);
    for (int a = 0; a < 3; ++a) t[(BOREAS_MESH_TREE_TREE_ORIGIN + a) * nt + i] = p.position[a];
  }
  return t;
}

MeshTreeBatch::MeshTreeBatch(Runtime& runtime) : runtime_(runtime) {}

const MeshTreeBatch::Placed& MeshTreeBatch::placed(uint64_t key) const {
  auto it = by_key_.find(key);
  if (it == by_key_.end())
    fail(BOREAS_ERROR_INTERNAL, "mesh tree batch has no tree " + std::to_string(key));
  return it->second;
}

namespace {

// A tree's tables with its indices made the batch's: branch links and the vertices' and
// leaves' branches count from its first branch, the vertices' leaves from its first leaf,
// and its branches name its tree slot.
void offset_indices(MeshTreeTables& t, int64_t first_branch, int64_t first_leaf, int64_t slot) {
  const size_t nb = t.branches;
  for (int k = 0; k < 4; ++k)
    for (size_t j = 0; j < nb; ++j)
      t.links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + k) * nb + j] += int32_t(first_branch);
  for (size_t j = 0; j < nb; ++j) t.links[BOREAS_MESH_TREE_BRANCH_TREE * nb + j] = int32_t(slot);
  for (int32_t& b : t.trunk_branch) b += int32_t(first_branch);
  for (int32_t& b : t.leaf_branch) b += int32_t(first_branch);
  for (int32_t& l : t.vertex_leaf) l += int32_t(first_leaf);
}

constexpr size_t kNoiseFloats =
    size_t(2) * BOREAS_MESH_TREE_NOISE_SIZE * BOREAS_MESH_TREE_NOISE_SIZE;

}  // namespace

// Every table of one tree written at its place (`at`): its own entries only.
void MeshTreeBatch::write_tree(const MeshTreeInstance& tree, const Placed& at) {
  MeshTreeTables t = mesh_tree_tables({&tree});
  offset_indices(t, at.first_branch, at.first_leaf, at.slot);
  const size_t nb = t.branches, nv = t.trunk_vertices, nl = t.leaves_count,
               nlv = t.leaf_vertices_count;
  const size_t cb = size_t(branches_.capacity), cv = size_t(trunk_.capacity),
               cl = size_t(leaves_.capacity), clv = size_t(leaf_vertices_.capacity),
               ct = size_t(slots_.capacity);
  Runtime& r = runtime_;
  r.write_planes(branch_table_, cb, at.first_branch, t.branch_table.data(), nb, nb,
                 BOREAS_MESH_TREE_BRANCH_FLOATS);
  r.write_planes(links_, cb, at.first_branch, t.links.data(), nb, nb, BOREAS_MESH_TREE_BRANCH_INTS,
                 sizeof(int32_t));
  r.write_planes(trunk_table_, cv, at.first_trunk, t.trunk.data(), nv, nv,
                 BOREAS_MESH_TREE_TRUNK_FLOATS);
  r.write_planes(trunk_branch_, cv, at.first_trunk, t.trunk_branch.data(), nv, nv, 1,
                 sizeof(int32_t));
  r.write_planes(trunk_out_, cv, at.first_trunk, t.trunk_rest.data(), nv, nv, 1, 3 * sizeof(float));
  r.write_planes(leaf_table_, cl, at.first_leaf, t.leaves.data(), nl, nl,
                 BOREAS_MESH_TREE_LEAF_FLOATS);
  r.write_planes(leaf_branch_, cl, at.first_leaf, t.leaf_branch.data(), nl, nl, 1, sizeof(int32_t));
  r.write_planes(leaf_vertex_table_, clv, at.first_leaf_vertex, t.leaf_vertices.data(), nlv, nlv,
                 BOREAS_MESH_TREE_LEAF_VERTEX_FLOATS);
  r.write_planes(vertex_leaf_, clv, at.first_leaf_vertex, t.vertex_leaf.data(), nlv, nlv, 1,
                 sizeof(int32_t));
  r.write_planes(leaf_out_, clv, at.first_leaf_vertex, t.leaf_rest.data(), nlv, nlv, 1,
                 6 * sizeof(float));
  r.write_planes(noise_, ct, at.slot, t.noise.data(), 1, 1, 1, kNoiseFloats * sizeof(float));
  r.write_planes(contact_table_, cb, at.first_branch, t.contact.data(), nb, nb,
                 BOREAS_MESH_TREE_CONTACT_FLOATS);
}

// The index tables of the trees at the places given, written whole into the buffers given
// (of the capacities given): after packing has moved the trees.
void MeshTreeBatch::write_indices(const std::vector<Placed>& trees, const Capacities& caps,
                                  const cl::Buffer& links_to, const cl::Buffer& trunk_branch_to,
                                  const cl::Buffer& leaf_branch_to,
                                  const cl::Buffer& vertex_leaf_to) {
  const size_t cb = size_t(caps.branches), cv = size_t(caps.trunk), cl = size_t(caps.leaves),
               clv = size_t(caps.leaf_vertices);
  std::vector<int32_t> links(BOREAS_MESH_TREE_BRANCH_INTS * cb, 0), trunk_branch(cv, 0),
      leaf_branch(cl, 0), vertex_leaf(clv, 0);
  for (const Placed& at : trees) {
    MeshTreeTables t = mesh_tree_tables({at.tree.get()});
    offset_indices(t, at.first_branch, at.first_leaf, at.slot);
    for (int k = 0; k < BOREAS_MESH_TREE_BRANCH_INTS; ++k)
      std::copy_n(t.links.begin() + ptrdiff_t(size_t(k) * t.branches), t.branches,
                  links.begin() + ptrdiff_t(size_t(k) * cb + size_t(at.first_branch)));
    std::copy(t.trunk_branch.begin(), t.trunk_branch.end(), trunk_branch.begin() + at.first_trunk);
    std::copy(t.leaf_branch.begin(), t.leaf_branch.end(), leaf_branch.begin() + at.first_leaf);
    std::copy(t.vertex_leaf.begin(), t.vertex_leaf.end(),
              vertex_leaf.begin() + at.first_leaf_vertex);
  }
  runtime_.upload(links_to, links);
  runtime_.upload(trunk_branch_to, trunk_branch);
  runtime_.upload(leaf_branch_to, leaf_branch);
  runtime_.upload(vertex_leaf_to, vertex_leaf);
}

void MeshTreeBatch::add(std::shared_ptr<const MeshTreeInstance> tree, double time) {
  (void)time;  // the tree's clock starts with the step's time, which every step uploads
  if (by_key_.count(tree->key))
    fail(BOREAS_ERROR_INTERNAL, "mesh tree key " + std::to_string(tree->key) + " added twice");
  const int64_t nb = int64_t(tree->data.branches.size()),
                nv = int64_t(tree->model.trunk.vertex_count()),
                nl = int64_t(tree->data.leaf_length.size()),
                nlv = int64_t(tree->model.leaves.vertex_count());
  // Room: each space grows (runtime/block_space.h: holes squeezed out on the way).
  if (!branches_.fits(nb) || !trunk_.fits(nv) || !leaves_.fits(nl) || !leaf_vertices_.fits(nlv) ||
      !slots_.fits(1)) {
    const bool pack = slots_.dead > 0;
    relayout({branches_.grown(nb, kMinBranches), trunk_.grown(nv, kMinVertices),
              leaves_.grown(nl, kMinBranches), leaf_vertices_.grown(nlv, kMinVertices),
              slots_.grown(1, kMinSlots)},
             pack);
  }
  Placed at;
  at.reach = mesh_tree_reach(*tree);
  at.tree = std::move(tree);
  at.slot = slots_.end;
  at.first_branch = branches_.end;
  at.first_trunk = trunk_.end;
  at.first_leaf = leaves_.end;
  at.first_leaf_vertex = leaf_vertices_.end;
  // Its tables, its rest pose in the outputs, and a calm state in both halves; the other
  // trees' entries are not touched.
  write_tree(*at.tree, at);
  const size_t cb = size_t(branches_.capacity), ct = size_t(slots_.capacity);
  for (int h = 0; h < 2; ++h) {
    for (int p = 0; p < BOREAS_MESH_TREE_STATE_FLOATS; ++p)
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          state_[h], 0.0f, (size_t(p) * cb + size_t(at.first_branch)) * sizeof(float),
          size_t(nb) * sizeof(float)));
    for (int p = 0; p < BOREAS_MESH_TREE_BEND_FLOATS; ++p)
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          bend_[h], 0.0f, (size_t(p) * cb + size_t(at.first_branch)) * sizeof(float),
          size_t(nb) * sizeof(float)));
    for (int p = 0; p < BOREAS_MESH_TREE_ROLL_FLOATS; ++p)
      BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
          roll_[h], 0.0f, (size_t(p) * ct + size_t(at.slot)) * sizeof(float), sizeof(float)));
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());
  // Everything is on the device: the batch takes the tree.
  branches_.end += nb;
  trunk_.end += nv;
  leaves_.end += nl;
  leaf_vertices_.end += nlv;
  slots_.end += 1;
  slot_trees_.resize(size_t(slots_.end));
  slot_trees_[size_t(at.slot)] = at.tree.get();
  fresh_.resize(size_t(slots_.end), false);
  fresh_[size_t(at.slot)] = true;
  const uint64_t key = at.tree->key;
  by_key_.emplace(key, std::move(at));
}

void MeshTreeBatch::remove(uint64_t key, double time) {
  (void)time;
  const Placed at = placed(key);
  // The tree's entries become holes (the last tree's just shorten the spaces); the
  // launches still run over holes, which hold a tree's last data and harm nothing.
  branches_.release(at.first_branch, int64_t(at.tree->data.branches.size()));
  trunk_.release(at.first_trunk, int64_t(at.tree->model.trunk.vertex_count()));
  leaves_.release(at.first_leaf, int64_t(at.tree->data.leaf_length.size()));
  leaf_vertices_.release(at.first_leaf_vertex, int64_t(at.tree->model.leaves.vertex_count()));
  slots_.release(at.slot, 1);
  slot_trees_[size_t(at.slot)] = nullptr;
  slot_trees_.resize(size_t(slots_.end));
  fresh_.resize(size_t(slots_.end));
  by_key_.erase(key);
  contact_keys_.erase(key);
  if (by_key_.empty()) {
    for (BlockSpace* s : {&branches_, &trunk_, &leaves_, &leaf_vertices_, &slots_}) s->clear();
    slot_trees_.assign(1, nullptr);
    fresh_.assign(1, false);
    for (std::vector<int32_t>& pairs : pair_collider_) pairs.clear();
    for (std::vector<uint64_t>& keys : bent_keys_) keys.clear();
  }
  // Once holes pass half, the trees are packed (lazily: a cost per removal of a tree's
  // size on average); once a space's live entries fall below a quarter of it, packed into
  // smaller buffers (runtime/block_space.h).
  const bool shrink =
      branches_.wants_shrinking(kMinBranches) || trunk_.wants_shrinking(kMinVertices) ||
      leaves_.wants_shrinking(kMinBranches) || leaf_vertices_.wants_shrinking(kMinVertices) ||
      slots_.wants_shrinking(kMinSlots);
  if (shrink || slots_.wants_packing() || branches_.wants_packing() ||
      leaf_vertices_.wants_packing())
    relayout({branches_.shrunk(kMinBranches), trunk_.shrunk(kMinVertices),
              leaves_.shrunk(kMinBranches), leaf_vertices_.shrunk(kMinVertices),
              slots_.shrunk(kMinSlots)},
             true);
}

// The buffers of every table, state and output, as the members of the same names hold them.
struct MeshTreeBatch::Buffers {
  cl::Buffer branch_table, links, state[2], roll[2], tree_table, noise, contact_table, bend[2];
  cl::Buffer trunk_table, trunk_branch, trunk_out;
  cl::Buffer leaf_table, leaf_branch, leaf_vertex_table, vertex_leaf, leaf_out;
};

void MeshTreeBatch::relayout(const Capacities& to, bool pack) {
  // New buffers first, each space's stride its new capacity; the members change only once
  // every allocation and copy succeeded.
  Buffers b = new_buffers(to);
  Plans plans;
  const std::vector<Placed> moved = plan_moves(pack, plans);
  if (!moved.empty()) copy_moves(b, plans, to);
  // Packed trees' indices point into their old places: written again for the new ones.
  if (pack) write_indices(moved, to, b.links, b.trunk_branch, b.leaf_branch, b.vertex_leaf);
  BOREAS_CL_CHECK(runtime_.queue().finish());

  take_buffers(b);
  branches_.capacity = to.branches;
  trunk_.capacity = to.trunk;
  leaves_.capacity = to.leaves;
  leaf_vertices_.capacity = to.leaf_vertices;
  slots_.capacity = to.slots;
  if (!pack) return;
  take_packed(plans, moved);
}

MeshTreeBatch::Buffers MeshTreeBatch::new_buffers(const Capacities& to) {
  auto floats = [&](int64_t cap, int planes, size_t elem = sizeof(float)) {
    cl::Buffer b =
        runtime_.buffer(CL_MEM_READ_WRITE, size_t(cap) * size_t(planes) * elem, "imported trees");
    BOREAS_CL_CHECK(
        runtime_.queue().enqueueFillBuffer(b, 0.0f, 0, size_t(cap) * size_t(planes) * elem));
    return b;
  };
  Buffers b;
  b.branch_table = floats(to.branches, BOREAS_MESH_TREE_BRANCH_FLOATS);
  b.links = floats(to.branches, BOREAS_MESH_TREE_BRANCH_INTS);
  for (cl::Buffer& s : b.state) s = floats(to.branches, BOREAS_MESH_TREE_STATE_FLOATS);
  b.contact_table = floats(to.branches, BOREAS_MESH_TREE_CONTACT_FLOATS);
  for (cl::Buffer& s : b.bend) s = floats(to.branches, BOREAS_MESH_TREE_BEND_FLOATS);
  for (cl::Buffer& r : b.roll) r = floats(to.slots, BOREAS_MESH_TREE_ROLL_FLOATS);
  b.tree_table = floats(to.slots, BOREAS_MESH_TREE_TREE_FLOATS);
  b.noise = floats(to.slots, 1, kNoiseFloats * sizeof(float));
  b.trunk_table = floats(to.trunk, BOREAS_MESH_TREE_TRUNK_FLOATS);
  b.trunk_branch = floats(to.trunk, 1);
  b.trunk_out = floats(to.trunk, 3);
  b.leaf_table = floats(to.leaves, BOREAS_MESH_TREE_LEAF_FLOATS);
  b.leaf_branch = floats(to.leaves, 1);
  b.leaf_vertex_table = floats(to.leaf_vertices, BOREAS_MESH_TREE_LEAF_VERTEX_FLOATS);
  b.vertex_leaf = floats(to.leaf_vertices, 1);
  b.leaf_out = floats(to.leaf_vertices, 6);
  return b;
}

std::vector<MeshTreeBatch::Placed> MeshTreeBatch::plan_moves(bool pack, Plans& plans) {
  // Where each live tree goes in each space: where it is (growing), or packed in the order
  // it stands (the same order in every space).
  std::vector<Placed*> live;
  for (auto& [key, at] : by_key_) live.push_back(&at);
  auto firsts = [](Placed& p) {
    return std::array<int64_t*, 5>{&p.first_branch, &p.first_trunk, &p.first_leaf,
                                   &p.first_leaf_vertex, &p.slot};
  };
  std::vector<std::pair<int64_t, int64_t>>
      blocks[5];  // branches, trunk, leaves, leaf vertices, slots
  for (Placed* p : live) {
    const int64_t counts[5] = {int64_t(p->tree->data.branches.size()),
                               int64_t(p->tree->model.trunk.vertex_count()),
                               int64_t(p->tree->data.leaf_length.size()),
                               int64_t(p->tree->model.leaves.vertex_count()), 1};
    const auto first = firsts(*p);
    for (int s = 0; s < 5; ++s) blocks[s].push_back({*first[size_t(s)], counts[s]});
  }
  for (int s = 0; s < 5; ++s) plans[size_t(s)] = plan_block_moves(blocks[s], pack);
  std::vector<Placed> moved;
  for (size_t k = 0; k < live.size(); ++k) {
    Placed m = *live[k];
    const auto first = firsts(m);
    for (int s = 0; s < 5; ++s) *first[size_t(s)] = plans[size_t(s)].to[k];
    moved.push_back(m);
  }
  return moved;
}

void MeshTreeBatch::copy_moves(Buffers& b, const Plans& plans, const Capacities& to) {
  // Device copies of what each tree holds (tables, state, outputs), space by space.
  const PlanePair branch_sets[] = {
      {&branch_table_, &b.branch_table, BOREAS_MESH_TREE_BRANCH_FLOATS, 4},
      {&links_, &b.links, BOREAS_MESH_TREE_BRANCH_INTS, 4},
      {&state_[0], &b.state[0], BOREAS_MESH_TREE_STATE_FLOATS, 4},
      {&state_[1], &b.state[1], BOREAS_MESH_TREE_STATE_FLOATS, 4},
      {&contact_table_, &b.contact_table, BOREAS_MESH_TREE_CONTACT_FLOATS, 4},
      {&bend_[0], &b.bend[0], BOREAS_MESH_TREE_BEND_FLOATS, 4},
      {&bend_[1], &b.bend[1], BOREAS_MESH_TREE_BEND_FLOATS, 4}};
  const PlanePair trunk_sets[] = {{&trunk_table_, &b.trunk_table, BOREAS_MESH_TREE_TRUNK_FLOATS, 4},
                                  {&trunk_branch_, &b.trunk_branch, 1, 4},
                                  {&trunk_out_, &b.trunk_out, 1, 12}};
  const PlanePair leaf_sets[] = {{&leaf_table_, &b.leaf_table, BOREAS_MESH_TREE_LEAF_FLOATS, 4},
                                 {&leaf_branch_, &b.leaf_branch, 1, 4}};
  const PlanePair vertex_sets[] = {
      {&leaf_vertex_table_, &b.leaf_vertex_table, BOREAS_MESH_TREE_LEAF_VERTEX_FLOATS, 4},
      {&vertex_leaf_, &b.vertex_leaf, 1, 4},
      {&leaf_out_, &b.leaf_out, 1, 24}};
  const PlanePair slot_sets[] = {{&roll_[0], &b.roll[0], BOREAS_MESH_TREE_ROLL_FLOATS, 4},
                                 {&roll_[1], &b.roll[1], BOREAS_MESH_TREE_ROLL_FLOATS, 4},
                                 {&noise_, &b.noise, 1, kNoiseFloats * sizeof(float)}};
  copy_block_moves(runtime_, plans[0].moves, branch_sets, std::size(branch_sets),
                   size_t(branches_.capacity), size_t(to.branches));
  copy_block_moves(runtime_, plans[1].moves, trunk_sets, std::size(trunk_sets),
                   size_t(trunk_.capacity), size_t(to.trunk));
  copy_block_moves(runtime_, plans[2].moves, leaf_sets, std::size(leaf_sets),
                   size_t(leaves_.capacity), size_t(to.leaves));
  copy_block_moves(runtime_, plans[3].moves, vertex_sets, std::size(vertex_sets),
                   size_t(leaf_vertices_.capacity), size_t(to.leaf_vertices));
  copy_block_moves(runtime_, plans[4].moves, slot_sets, std::size(slot_sets),
                   size_t(slots_.capacity), size_t(to.slots));
}

void MeshTreeBatch::take_buffers(const Buffers& b) {
  branch_table_ = b.branch_table;
  links_ = b.links;
  contact_table_ = b.contact_table;
  for (int h = 0; h < 2; ++h) {
    state_[h] = b.state[h];
    bend_[h] = b.bend[h];
    roll_[h] = b.roll[h];
  }
  tree_table_ = b.tree_table;
  noise_ = b.noise;
  trunk_table_ = b.trunk_table;
  trunk_branch_ = b.trunk_branch;
  trunk_out_ = b.trunk_out;
  leaf_table_ = b.leaf_table;
  leaf_branch_ = b.leaf_branch;
  leaf_vertex_table_ = b.leaf_vertex_table;
  vertex_leaf_ = b.vertex_leaf;
  leaf_out_ = b.leaf_out;
}

void MeshTreeBatch::take_packed(const Plans& plans, const std::vector<Placed>& moved) {
  BlockSpace* spaces[5] = {&branches_, &trunk_, &leaves_, &leaf_vertices_, &slots_};
  for (int s = 0; s < 5; ++s) spaces[s]->packed(plans[size_t(s)].end);
  std::vector<const MeshTreeInstance*> slot_trees(size_t(slots_.end), nullptr);
  std::vector<bool> fresh(size_t(slots_.end), false);
  for (const Placed& m : moved) {
    slot_trees[size_t(m.slot)] = m.tree.get();
    fresh[size_t(m.slot)] = fresh_[size_t(by_key_.at(m.tree->key).slot)];
    by_key_.at(m.tree->key) = m;
  }
  slot_trees_ = std::move(slot_trees);
  fresh_ = std::move(fresh);
}

void MeshTreeBatch::enqueue_vertices(const cl::Buffer& state, const cl::Buffer& roll,
                                     MeshTreeStepEvents* events) {
  // Strides are the spaces' capacities, counts their ends (holes included).
  const int nb = int(branches_.capacity), nt = int(slots_.capacity);
  if (trunk_.end > 1) {
    cl::Kernel& k = runtime_.kernel("mesh_tree_vertices.cl", "boreas_mesh_tree_trunk");
    cl::Event e = launch(runtime_, k, Items(size_t(trunk_.end)), trunk_table_, trunk_branch_,
                         int(trunk_.capacity), int(trunk_.end), branch_table_, links_, nb, state,
                         tree_table_, nt, noise_, trunk_out_);
    if (events) events->trunk = e;
  }
  if (leaf_vertices_.end > 1) {
    cl::Kernel& k = runtime_.kernel("mesh_tree_vertices.cl", "boreas_mesh_tree_leaves");
    cl::Event e = launch(runtime_, k, Items(size_t(leaf_vertices_.end)), leaf_vertex_table_,
                         vertex_leaf_, int(leaf_vertices_.capacity), int(leaf_vertices_.end),
                         leaf_table_, leaf_branch_, int(leaves_.capacity), branch_table_, links_,
                         nb, state, tree_table_, nt, roll, noise_, leaf_out_);
    if (events) events->leaves = e;
  }
}

void MeshTreeBatch::upload_phases(const PlantWind& wind) {
  // Row t: the waves' phases at slot t's tree (zeros for holes and the sink).
  const size_t count = size_t(std::max(wind.wave_count, 1));
  phase_staging_.assign(size_t(slots_.capacity) * count, 0.0f);
  for (size_t t = 0; t < slot_trees_.size(); ++t) {
    if (slot_trees_[t] == nullptr) continue;
    const std::array<float, 3>& o = slot_trees_[t]->params.position;
    wind.phases_at(o[0], o[2], phase_staging_.data() + t * count);
  }
  if (phase_capacity_ < phase_staging_.size() || phases_() == nullptr) {
    phase_capacity_ = std::max(phase_staging_.size(), 2 * phase_capacity_);
    phases_ = runtime_.buffer(CL_MEM_READ_ONLY, phase_capacity_ * sizeof(float),
                              "mesh tree wave phases");
  }
  runtime_.upload_async(phases_, phase_staging_);
}

void MeshTreeBatch::enqueue_step(double dt, double time, const PlantWind& wind,
                                 const StepColliders& colliders, MeshTreeStepEvents* events) {
  if (by_key_.empty()) return;
  // The trees' per-step constants by slot (holes and the sink slot 0 zero).
  tree_staging_ = mesh_tree_planes(slot_trees_, fresh_, time, size_t(slots_.capacity));
  runtime_.upload_async(tree_table_, tree_staging_);
  upload_phases(wind);
  const int next = 1 - current_;
  cl::Kernel& k =
      runtime_.kernel("mesh_tree_branches.cl", "boreas_mesh_tree_branches", wind.defines());
  cl::Event e = launch(runtime_, k, Items(size_t(branches_.end)), branch_table_, links_,
                       int(branches_.capacity), int(branches_.end), state_[current_], state_[next],
                       tree_table_, int(slots_.capacity), roll_[current_], roll_[next], float(dt),
                       *wind.waves, wind.wave_count, phases_, *wind.grid, wind.grid_layout);
  if (events) events->branches = e;
  const bool bent = enqueue_contacts(dt, colliders, state_[next], next);
  enqueue_vertices(state_[next], roll_[next], events);
  if (bent) enqueue_bends(bend_[next]);
}

void MeshTreeBatch::commit() {
  if (by_key_.empty()) return;
  current_ = 1 - current_;
  commit_contacts();
  std::fill(fresh_.begin(), fresh_.end(), false);
}

std::array<double, 3> MeshTreeBatch::shift(const Placed& p, const Origin& output_origin) {
  std::array<double, 3> s{};
  for (size_t a = 0; a < 3; ++a) s[a] = double(p.tree->params.position[a]) - output_origin[a];
  return s;
}

std::vector<boreas_vertex> MeshTreeBatch::trunk_vertices(uint64_t key, const Origin& output_origin) {
  const Placed& p = placed(key);
  const MeshPart& m = p.tree->model.trunk;
  std::vector<float> positions(3 * m.vertex_count());
  if (!positions.empty())
    BOREAS_CL_CHECK(
        runtime_.queue().enqueueReadBuffer(trunk_out_, CL_TRUE, 3 * p.first_trunk * sizeof(float),
                                           positions.size() * sizeof(float), positions.data()));
  // From the tree's coordinates to the output's, in double.
  const std::array<double, 3> to = shift(p, output_origin);
  std::vector<boreas_vertex> out(m.vertex_count());
  for (size_t v = 0; v < out.size(); ++v) {
    for (size_t a = 0; a < 3; ++a) out[v].position[a] = float(positions[3 * v + a] + to[a]);
    place_direction(p.tree->params, &m.normals[3 * v], out[v].normal);
    out[v].uv[0] = m.uvs[2 * v];
    out[v].uv[1] = m.uvs[2 * v + 1];
  }
  return out;
}

std::vector<boreas_vertex> MeshTreeBatch::leaf_vertices(uint64_t key, const Origin& output_origin) {
  const Placed& p = placed(key);
  const MeshPart& m = p.tree->model.leaves;
  std::vector<float> data(6 * m.vertex_count());
  if (!data.empty())
    BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(leaf_out_, CL_TRUE,
                                                       6 * p.first_leaf_vertex * sizeof(float),
                                                       data.size() * sizeof(float), data.data()));
  const std::array<double, 3> to = shift(p, output_origin);
  std::vector<boreas_vertex> out(m.vertex_count());
  for (size_t v = 0; v < out.size(); ++v) {
    for (size_t a = 0; a < 3; ++a) {
      out[v].position[a] = float(data[6 * v + a] + to[a]);
      out[v].normal[a] = data[6 * v + 3 + a];
    }
    out[v].uv[0] = m.uvs[2 * v];
    out[v].uv[1] = m.uvs[2 * v + 1];
  }
  return out;
}

void MeshTreeBatch::enqueue_copy(const std::vector<CopyTo>& trees, boreas_mesh_part part,
                                 const cl::Buffer& out, const Origin& output_origin) {
  const bool trunk = part == BOREAS_MESH_TRUNK;
  copy_staging_.clear();
  int64_t items = 0;
  for (const CopyTo& t : trees) {
    const Placed& p = placed(t.key);
    const size_t count =
        trunk ? p.tree->model.trunk.vertex_count() : p.tree->model.leaves.vertex_count();
    if (count == 0) continue;
    BoreasCopyRange r{int32_t(items), int32_t(trunk ? p.first_trunk : p.first_leaf_vertex),
                      int32_t(t.first), int32_t(count), {0.0f, 0.0f, 0.0f}, 0};
    const std::array<double, 3> to = shift(p, output_origin);
    for (size_t a = 0; a < 3; ++a) r.offset[a] = float(to[a]);
    copy_staging_.push_back(r);
    items += int64_t(count);
  }
  if (items == 0) return;
  if (copy_capacity_ < copy_staging_.size()) {
    copy_capacity_ = std::max(copy_staging_.size(), 2 * copy_capacity_);
    copy_ranges_ = runtime_.buffer(CL_MEM_READ_ONLY, copy_capacity_ * sizeof(BoreasCopyRange),
                                   "mesh tree copy table");
  }
  // Blocking: the table is a few bytes a tree, and the next call may rewrite it.
  runtime_.write(copy_ranges_, 0, copy_staging_.size() * sizeof(BoreasCopyRange),
                 copy_staging_.data());
  cl::Kernel& k = runtime_.kernel("range_copy.cl", "boreas_range_copy");
  launch(runtime_, k, Items(size_t(items)), trunk ? trunk_out_ : leaf_out_, out, copy_ranges_,
         int(copy_staging_.size()), int(items), trunk ? 3 : 6);
}

std::vector<float> MeshTreeBatch::branch_wind(uint64_t key) {
  const Placed& p = placed(key);
  const size_t count = p.tree->data.branches.size();
  std::vector<float> planes(3 * count);
  runtime_.read_planes(
      state_[current_], size_t(branches_.capacity),
      size_t(BOREAS_MESH_TREE_STATE_WIND) * size_t(branches_.capacity) + size_t(p.first_branch),
      planes.data(), count, count, 3);
  std::vector<float> out(3 * count);
  for (size_t j = 0; j < count; ++j)
    for (size_t a = 0; a < 3; ++a) out[3 * j + a] = planes[a * count + j];
  return out;
}

std::vector<float> MeshTreeBatch::noise_roll(uint64_t key) {
  const Placed& p = placed(key);
  std::vector<float> out(BOREAS_MESH_TREE_ROLL_FLOATS);
  runtime_.read_planes(roll_[current_], size_t(slots_.capacity),
                       size_t(BOREAS_MESH_TREE_ROLL) * size_t(slots_.capacity) + size_t(p.slot),
                       out.data(), 1, 1, BOREAS_MESH_TREE_ROLL_FLOATS);
  return out;
}

}  // namespace boreas::impl
