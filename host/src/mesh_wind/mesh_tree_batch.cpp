// boreas: imported trees on the device — table layout, the per-step launches and the
// readbacks (layouts in cl/shared/mesh_wind_types.h).
#include "mesh_wind/mesh_tree_batch.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "shared/mesh_wind_types.h"
#include "wind/wind_params.h"

namespace boreas::impl {

namespace {

void check_range(float value, float lo, float hi, const std::string& name) {
  if (!std::isfinite(value) || value < lo || value > hi)
    fail(BOREAS_ERROR_INVALID_ARGUMENT, "mesh tree " + name + " must be in [" + std::to_string(lo) +
                                            ", " + std::to_string(hi) + "] (got " +
                                            std::to_string(value) + ")");
}

template <typename T>
cl::Buffer make_buffer(Runtime& runtime, const std::vector<T>& data) {
  cl::Buffer b = runtime.buffer(CL_MEM_READ_WRITE, std::max<size_t>(data.size(), 1) * sizeof(T));
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
  check_range(def.yaw, -1e3f, 1e3f, "yaw (rad)");
  check_range(def.scale, 1e-4f, 1e4f, "scale");
  check_range(def.noise_beta, 0.0f, 4.0f, "noise_beta");
  check_range(def.bend_exponent, 0.25f, 4.0f, "bend_exponent");
  for (int k = 0; k < 4; ++k) {
    const boreas_mesh_level_def& l = def.levels[k];
    std::string at = "levels[" + std::to_string(k) + "].";
    check_range(l.bend, 0.0f, 1e3f, at + "bend (m)");
    check_range(l.sway, 0.0f, 1e3f, at + "sway (m)");
    check_range(l.frequency, 0.001f, 50.0f, at + "frequency (Hz)");
    check_range(l.response_time, 0.0f, 60.0f, at + "response_time (s)");
    p.levels[k] = l;
  }
  check_range(def.leaf_flutter, 0.0f, 1e3f, "leaf_flutter (m)");
  check_range(def.leaf_turn, 0.0f, 1.0f, "leaf_turn");
  check_range(def.flutter_wavelength, 1e-3f, 1e5f, "flutter_wavelength (m)");
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

boreas_mesh_tree_info describe_mesh_tree(const MeshModel& model, const MeshWindData& data,
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

void place_point(const MeshTreeParams& p, const float in[3], float out[3]) {
  float scaled[3] = {in[0] * p.scale, in[1] * p.scale, in[2] * p.scale};
  place_direction(p, scaled, out);
  for (int a = 0; a < 3; ++a) out[a] += p.position[a];
}

MeshWindTables mesh_wind_tables(const std::vector<const MeshTreeInstance*>& trees) {
  MeshWindTables m;
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
  const size_t nt = trees.size();
  m.branches = nb;
  m.trunk_vertices = nv;
  m.leaves_count = nl;
  m.leaf_vertices_count = nlv;
  std::vector<float>& branches = m.branch_table;
  std::vector<int32_t>& links = m.links;
  std::vector<float>& noise = m.noise;
  std::vector<float>& trunk = m.trunk;
  std::vector<float>& trunk_out = m.trunk_rest;
  std::vector<int32_t>& trunk_branch = m.trunk_branch;
  std::vector<float>& leaves = m.leaves;
  std::vector<int32_t>& leaf_branch = m.leaf_branch;
  std::vector<float>& leaf_vertices = m.leaf_vertices;
  std::vector<int32_t>& vertex_leaf = m.vertex_leaf;
  std::vector<float>& leaf_out = m.leaf_rest;
  branches.assign(BOREAS_MW_BRANCH_FLOATS * nb, 0.0f);
  links.assign(BOREAS_MW_BRANCH_INTS * nb, 0);
  noise.assign(nt * 2 * BOREAS_MW_NOISE_SIZE * BOREAS_MW_NOISE_SIZE, 0.0f);
  trunk.assign(BOREAS_MW_TRUNK_FLOATS * nv, 0.0f);
  trunk_out.assign(3 * nv, 0.0f);
  trunk_branch.assign(nv, 0);
  leaf_branch.assign(nl, 0);
  vertex_leaf.assign(nlv, 0);
  leaves.assign(BOREAS_MW_LEAF_FLOATS * nl, 0.0f);
  leaf_vertices.assign(BOREAS_MW_LEAF_VERTEX_FLOATS * nlv, 0.0f);
  leaf_out.assign(6 * nlv, 0.0f);
  for (size_t ti = 0; ti < nt; ++ti) {
    const MeshTreeInstance& tree = *trees[ti];
    const MeshTreeParams& params = tree.params;
    const MeshWindData& d = tree.data;
    const int t = int(ti);
    const size_t first_branch = m.first_branch[ti], first_trunk = m.first_trunk[ti];
    const size_t first_leaf = m.first_leaf[ti], first_leaf_vertex = m.first_leaf_vertex[ti];
    // Response times per level; branches beyond level 3 answer as fast as level 3.
    for (size_t j = 0; j < d.branches.size(); ++j) {
      const MeshWindBranch& b = d.branches[j];
      const size_t i = first_branch + j;
      float dir[3];
      place_direction(params, b.axis.data(), dir);
      for (int a = 0; a < 3; ++a) branches[(BOREAS_MW_BRANCH_AXIS + a) * nb + i] = dir[a];
      place_direction(params, b.up.data(), dir);
      for (int a = 0; a < 3; ++a) branches[(BOREAS_MW_BRANCH_UP + a) * nb + i] = dir[a];
      place_direction(params, b.right.data(), dir);
      for (int a = 0; a < 3; ++a) branches[(BOREAS_MW_BRANCH_RIGHT + a) * nb + i] = dir[a];
      place_point(params, b.center.data(), dir);
      for (int a = 0; a < 3; ++a) branches[(BOREAS_MW_BRANCH_CENTER + a) * nb + i] = dir[a];
      branches[(BOREAS_MW_BRANCH_PHASE + 0) * nb + i] = b.phase[0];
      branches[(BOREAS_MW_BRANCH_PHASE + 1) * nb + i] = b.phase[1];
      branches[BOREAS_MW_BRANCH_TAU * nb + i] = params.levels[std::min(b.level, 3)].response_time;
      for (int k = 0; k < 4; ++k)
        links[(BOREAS_MW_BRANCH_ANIMATED_BY + k) * nb + i] =
            int32_t(first_branch) + b.animated_by[k];
      links[BOREAS_MW_BRANCH_TREE * nb + i] = t;
      links[BOREAS_MW_BRANCH_IS_STEM * nb + i] = b.parent < 0 ? 1 : 0;
    }
    // The texture is interleaved (2 channels per texel); the kernels read two planes.
    const size_t texels = size_t(BOREAS_MW_NOISE_SIZE) * BOREAS_MW_NOISE_SIZE;
    if (tree.noise.texels.size() != 2 * texels)
      fail(BOREAS_ERROR_INTERNAL,
           "mesh tree noise must be " + std::to_string(BOREAS_MW_NOISE_SIZE) + " texels wide");
    float* planes = noise.data() + size_t(t) * 2 * texels;
    for (size_t x = 0; x < texels; ++x) {
      planes[x] = tree.noise.texels[2 * x];
      planes[texels + x] = tree.noise.texels[2 * x + 1];
    }
    const MeshPart& tm = tree.model.trunk;
    for (size_t v = 0; v < tm.vertex_count(); ++v) {
      const size_t i = first_trunk + v;
      float world[3];
      place_point(params, &tm.positions[3 * v], world);
      for (int a = 0; a < 3; ++a) {
        trunk[(BOREAS_MW_TRUNK_REST + a) * nv + i] = world[a];
        trunk_out[3 * i + a] = world[a];
      }
      for (int k = 0; k < 4; ++k)
        trunk[(BOREAS_MW_TRUNK_WEIGHT + k) * nv + i] =
            float(std::pow(double(d.trunk_weights[4 * v + k]), double(params.bend_exponent)));
      trunk_branch[i] = int32_t(first_branch) + d.trunk_branch[v];
    }
    for (size_t l = 0; l < d.leaf_length.size(); ++l) {
      const size_t i = first_leaf + l;
      float world[3];
      place_point(params, &d.leaf_petiole[3 * l], world);
      for (int a = 0; a < 3; ++a) leaves[(BOREAS_MW_LEAF_PETIOLE + a) * nl + i] = world[a];
      place_direction(params, &d.leaf_axis[3 * l], world);
      for (int a = 0; a < 3; ++a) leaves[(BOREAS_MW_LEAF_AXIS + a) * nl + i] = world[a];
      for (int k = 0; k < 4; ++k)
        leaves[(BOREAS_MW_LEAF_WEIGHT + k) * nl + i] =
            float(std::pow(double(d.leaf_weights[4 * l + k]), double(params.bend_exponent)));
      leaf_branch[i] = int32_t(first_branch) + d.leaf_branch[l];
    }
    const MeshPart& lm = tree.model.leaves;
    for (size_t v = 0; v < lm.vertex_count(); ++v) {
      const size_t i = first_leaf_vertex + v;
      const int l = d.leaf_of_vertex[v];
      float world[3], normal[3];
      place_point(params, &lm.positions[3 * v], world);
      place_direction(params, &lm.normals[3 * v], normal);
      for (int a = 0; a < 3; ++a) {
        leaf_vertices[(BOREAS_MW_LEAF_VERTEX_REST + a) * nlv + i] = world[a];
        leaf_vertices[(BOREAS_MW_LEAF_VERTEX_NORMAL + a) * nlv + i] = normal[a];
        leaf_out[6 * i + a] = world[a];
        leaf_out[6 * i + 3 + a] = normal[a];
      }
      float length = d.leaf_length[l];
      double r = 0.0;
      for (int a = 0; a < 3; ++a) {
        double o = double(lm.positions[3 * v + a]) - d.leaf_petiole[3 * l + a];
        r += o * o;
      }
      leaf_vertices[BOREAS_MW_LEAF_VERTEX_TIP * nlv + i] =
          length > 0.0f ? float(std::sqrt(r) / length) : 0.0f;
      vertex_leaf[i] = int32_t(first_leaf) + l;
    }
  }
  return m;
}

std::vector<float> mesh_wind_tree_params(const std::vector<const MeshTreeInstance*>& trees,
                                         const std::vector<bool>& fresh, double time) {
  const size_t nt = trees.size();
  std::vector<float> t(BOREAS_MW_TREE_FLOATS * nt);
  for (size_t i = 0; i < nt; ++i) {
    const MeshTreeParams& p = trees[i]->params;
    for (int k = 0; k < 4; ++k) {
      t[(BOREAS_MW_TREE_BEND + k) * nt + i] = p.levels[k].bend;
      t[(BOREAS_MW_TREE_SWAY + k) * nt + i] = p.levels[k].sway;
      // Reduced in double: the kernel only ever sees a phase within one tile.
      double clock = double(p.levels[k].frequency) * time;
      t[(BOREAS_MW_TREE_CLOCK + k) * nt + i] = float(clock - std::floor(clock));
    }
    t[BOREAS_MW_TREE_FLUTTER * nt + i] = p.leaf_flutter;
    t[BOREAS_MW_TREE_TURN * nt + i] = p.leaf_turn;
    t[BOREAS_MW_TREE_INV_TILE * nt + i] = 1.0f / p.flutter_wavelength;
    t[BOREAS_MW_TREE_FRESH * nt + i] = fresh[i] ? 1.0f : 0.0f;
  }
  return t;
}

MeshTreeBatch::MeshTreeBatch(Runtime& runtime) : runtime_(runtime) {}

const MeshTreeBatch::Placed& MeshTreeBatch::placed(uint64_t key) const {
  for (const Placed& p : trees_)
    if (p.tree->key == key) return p;
  fail(BOREAS_ERROR_INTERNAL, "mesh tree batch has no tree " + std::to_string(key));
}

void MeshTreeBatch::add(std::shared_ptr<const MeshTreeInstance> tree, double time) {
  std::vector<Placed> trees = trees_;
  Placed p;
  p.tree = std::move(tree);
  trees.push_back(p);
  rebuild(std::move(trees), time);
}

void MeshTreeBatch::remove(uint64_t key, double time) {
  std::vector<Placed> trees;
  for (const Placed& p : trees_)
    if (p.tree->key != key) trees.push_back(p);
  rebuild(std::move(trees), time);
}

void MeshTreeBatch::rebuild(std::vector<Placed> trees, double time) {
  // The state of the trees that stay, read before anything is replaced.
  const size_t old_nb = branches_, old_nt = trees_.size();
  std::vector<float> old_state, old_roll;
  if (old_nb > 0) {
    old_state.resize(BOREAS_MW_STATE_FLOATS * old_nb);
    old_roll.resize(BOREAS_MW_ROLL_FLOATS * old_nt);
    BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(state_[current_], CL_TRUE, 0,
                                                       old_state.size() * 4, old_state.data()));
    BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(roll_[current_], CL_TRUE, 0,
                                                       old_roll.size() * 4, old_roll.data()));
  }
  std::vector<Placed> old = trees_;

  std::vector<const MeshTreeInstance*> instances;
  for (const Placed& p : trees) instances.push_back(p.tree.get());
  MeshWindTables tables = mesh_wind_tables(instances);
  const size_t nb = tables.branches, nt = trees.size();
  std::vector<float> state(BOREAS_MW_STATE_FLOATS * nb, 0.0f),
      roll(BOREAS_MW_ROLL_FLOATS * nt, 0.0f);
  for (size_t i = 0; i < nt; ++i) {
    Placed& p = trees[i];
    p.index = int(i);
    p.first_branch = tables.first_branch[i];
    p.first_trunk = tables.first_trunk[i];
    p.first_leaf = tables.first_leaf[i];
    p.first_leaf_vertex = tables.first_leaf_vertex[i];
    const MeshTreeInstance& tree = *p.tree;
    const int t = p.index;
    const MeshWindData& d = tree.data;
    // A tree that stays keeps its wind and rolled noise.
    for (const Placed& o : old) {
      if (o.tree->key != tree.key) continue;
      const size_t count = d.branches.size();
      for (int a = 0; a < BOREAS_MW_STATE_FLOATS; ++a)
        for (size_t j = 0; j < count; ++j)
          state[a * nb + p.first_branch + j] = old_state[a * old_nb + o.first_branch + j];
      for (int a = 0; a < BOREAS_MW_ROLL_FLOATS; ++a)
        roll[a * nt + t] = old_roll[a * old_nt + o.index];
    }
  }
  // New buffers first; members change only when every allocation and upload succeeded.
  cl::Buffer branch_table = make_buffer(runtime_, tables.branch_table),
             links_buffer = make_buffer(runtime_, tables.links);
  cl::Buffer state_a = make_buffer(runtime_, state), state_b = make_buffer(runtime_, state);
  cl::Buffer roll_a = make_buffer(runtime_, roll), roll_b = make_buffer(runtime_, roll);
  cl::Buffer noise_buffer = make_buffer(runtime_, tables.noise);
  cl::Buffer trunk_buffer = make_buffer(runtime_, tables.trunk),
             trunk_branch_buffer = make_buffer(runtime_, tables.trunk_branch);
  cl::Buffer trunk_out_buffer = make_buffer(runtime_, tables.trunk_rest);
  cl::Buffer leaf_table = make_buffer(runtime_, tables.leaves),
             leaf_branch_buffer = make_buffer(runtime_, tables.leaf_branch);
  cl::Buffer leaf_vertex_table = make_buffer(runtime_, tables.leaf_vertices);
  cl::Buffer vertex_leaf_buffer = make_buffer(runtime_, tables.vertex_leaf);
  cl::Buffer leaf_out_buffer = make_buffer(runtime_, tables.leaf_rest);
  std::vector<bool> fresh;
  for (const Placed& p : trees) fresh.push_back(p.fresh);
  std::vector<float> params = mesh_wind_tree_params(instances, fresh, time);
  cl::Buffer tree_table = make_buffer(runtime_, params);

  branch_table_ = branch_table;
  links_ = links_buffer;
  state_[0] = state_a;
  state_[1] = state_b;
  roll_[0] = roll_a;
  roll_[1] = roll_b;
  current_ = 0;
  noise_ = noise_buffer;
  trunk_ = trunk_buffer;
  trunk_branch_ = trunk_branch_buffer;
  trunk_out_ = trunk_out_buffer;
  leaf_table_ = leaf_table;
  leaf_branch_ = leaf_branch_buffer;
  leaf_vertex_table_ = leaf_vertex_table;
  vertex_leaf_ = vertex_leaf_buffer;
  leaf_out_ = leaf_out_buffer;
  tree_table_ = tree_table;
  branches_ = nb;
  trunk_vertices_ = tables.trunk_vertices;
  leaves_ = tables.leaves_count;
  leaf_vertices_ = tables.leaf_vertices_count;
  trees_ = std::move(trees);
  // The trees that stay show their last pose again (the new one its rest pose).
  if (!trees_.empty()) {
    enqueue_vertices(state_[current_], roll_[current_]);
    BOREAS_CL_CHECK(runtime_.queue().finish());
  }
}

void MeshTreeBatch::enqueue_vertices(const cl::Buffer& state, const cl::Buffer& roll,
                                     MeshWindStepEvents* events) {
  const int nb = int(branches_), nt = int(trees_.size());
  if (trunk_vertices_ > 0) {
    cl::Kernel& k = runtime_.kernel("mesh_wind_vertices.cl", "boreas_mesh_wind_trunk");
    bind_args(k, trunk_, trunk_branch_, int(trunk_vertices_), int(trunk_vertices_), branch_table_,
              links_, nb, state, tree_table_, nt, noise_, trunk_out_);
    runtime_.launch(k, trunk_vertices_, events ? &events->trunk : nullptr);
  }
  if (leaf_vertices_ > 0) {
    cl::Kernel& k = runtime_.kernel("mesh_wind_vertices.cl", "boreas_mesh_wind_leaves");
    bind_args(k, leaf_vertex_table_, vertex_leaf_, int(leaf_vertices_), int(leaf_vertices_),
              leaf_table_, leaf_branch_, int(leaves_), branch_table_, links_, nb, state,
              tree_table_, nt, roll, noise_, leaf_out_);
    runtime_.launch(k, leaf_vertices_, events ? &events->leaves : nullptr);
  }
}

void MeshTreeBatch::enqueue_step(double dt, double time, const TreeWindInput& wind,
                                 MeshWindStepEvents* events) {
  if (trees_.empty()) return;
  std::vector<const MeshTreeInstance*> instances;
  std::vector<bool> fresh;
  for (const Placed& p : trees_) {
    instances.push_back(p.tree.get());
    fresh.push_back(p.fresh);
  }
  tree_staging_ = mesh_wind_tree_params(instances, fresh, time);
  runtime_.upload_async(tree_table_, tree_staging_);
  const int next = 1 - current_;
  cl::Kernel& k = runtime_.kernel("mesh_wind_branches.cl", "boreas_mesh_wind_branches",
                                  slot_define("BOREAS_WAVE_SLOTS", wind.wave_slots));
  bind_args(k, branch_table_, links_, int(branches_), int(branches_), state_[current_],
            state_[next], tree_table_, int(trees_.size()), roll_[current_], roll_[next], float(dt),
            *wind.waves, wind.wave_count, *wind.grid, wind.grid_layout);
  runtime_.launch(k, branches_, events ? &events->branches : nullptr);
  enqueue_vertices(state_[next], roll_[next], events);
}

void MeshTreeBatch::commit() {
  if (trees_.empty()) return;
  current_ = 1 - current_;
  for (Placed& p : trees_) p.fresh = false;
}

std::vector<boreas_vertex> MeshTreeBatch::trunk_vertices(uint64_t key) {
  const Placed& p = placed(key);
  const MeshPart& m = p.tree->model.trunk;
  std::vector<float> positions(3 * m.vertex_count());
  if (!positions.empty())
    BOREAS_CL_CHECK(
        runtime_.queue().enqueueReadBuffer(trunk_out_, CL_TRUE, 3 * p.first_trunk * sizeof(float),
                                           positions.size() * sizeof(float), positions.data()));
  std::vector<boreas_vertex> out(m.vertex_count());
  for (size_t v = 0; v < out.size(); ++v) {
    for (int a = 0; a < 3; ++a) out[v].position[a] = positions[3 * v + a];
    place_direction(p.tree->params, &m.normals[3 * v], out[v].normal);
    out[v].uv[0] = m.uvs[2 * v];
    out[v].uv[1] = m.uvs[2 * v + 1];
  }
  return out;
}

std::vector<boreas_vertex> MeshTreeBatch::leaf_vertices(uint64_t key) {
  const Placed& p = placed(key);
  const MeshPart& m = p.tree->model.leaves;
  std::vector<float> data(6 * m.vertex_count());
  if (!data.empty())
    BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(leaf_out_, CL_TRUE,
                                                       6 * p.first_leaf_vertex * sizeof(float),
                                                       data.size() * sizeof(float), data.data()));
  std::vector<boreas_vertex> out(m.vertex_count());
  for (size_t v = 0; v < out.size(); ++v) {
    for (int a = 0; a < 3; ++a) {
      out[v].position[a] = data[6 * v + a];
      out[v].normal[a] = data[6 * v + 3 + a];
    }
    out[v].uv[0] = m.uvs[2 * v];
    out[v].uv[1] = m.uvs[2 * v + 1];
  }
  return out;
}

void MeshTreeBatch::enqueue_copy(uint64_t key, boreas_mesh_part part, const cl::Buffer& out,
                                 size_t first) {
  const Placed& p = placed(key);
  const bool trunk = part == BOREAS_MESH_TRUNK;
  const size_t floats = trunk ? 3 : 6;
  const size_t count =
      trunk ? p.tree->model.trunk.vertex_count() : p.tree->model.leaves.vertex_count();
  if (count == 0) return;
  const size_t from = (trunk ? p.first_trunk : p.first_leaf_vertex) * floats * sizeof(float);
  BOREAS_CL_CHECK(runtime_.queue().enqueueCopyBuffer(trunk ? trunk_out_ : leaf_out_, out, from,
                                                     first * floats * sizeof(float),
                                                     count * floats * sizeof(float)));
}

std::vector<float> MeshTreeBatch::branch_wind(uint64_t key) {
  const Placed& p = placed(key);
  std::vector<float> state(BOREAS_MW_STATE_FLOATS * branches_);
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(state_[current_], CL_TRUE, 0, state.size() * 4,
                                                     state.data()));
  const size_t count = p.tree->data.branches.size();
  std::vector<float> out(3 * count);
  for (size_t j = 0; j < count; ++j)
    for (int a = 0; a < 3; ++a)
      out[3 * j + a] = state[(BOREAS_MW_STATE_WIND + a) * branches_ + p.first_branch + j];
  return out;
}

std::vector<float> MeshTreeBatch::noise_roll(uint64_t key) {
  const Placed& p = placed(key);
  const size_t nt = trees_.size();
  std::vector<float> roll(BOREAS_MW_ROLL_FLOATS * nt);
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(roll_[current_], CL_TRUE, 0,
                                                     roll.size() * sizeof(float), roll.data()));
  std::vector<float> out;
  for (int a = 0; a < BOREAS_MW_ROLL_FLOATS; ++a)
    out.push_back(roll[(BOREAS_MW_ROLL + a) * nt + size_t(p.index)]);
  return out;
}

}  // namespace boreas::impl
