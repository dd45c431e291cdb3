// boreas render: filling the renderer's buffers from a world (world_buffers.h).
#include "gl/world_buffers.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "boreas/boreas_cl.h"
#include "gl/crown_light.h"
#include "gl/impostor_math.h"
#include "gl/mesh_tree_surface.h"

namespace boreas::render {

namespace {

void check(boreas_status status, const char* what) {
  if (status != BOREAS_OK) throw std::runtime_error(std::string(what) + ": " + boreas_last_error());
}

glm::vec3 vec(const float* v) { return glm::vec3(v[0], v[1], v[2]); }

// An imported tree's part at rest, with its triangles.
struct RestPart {
  std::vector<boreas_vertex> vertices;
  std::vector<uint32_t> indices;
};

RestPart rest_part(boreas_world world, boreas_mesh_tree_id tree, boreas_mesh_part part) {
  RestPart out;
  int n = 0;
  check(boreas_mesh_tree_get_vertices(world, tree, part, nullptr, 0, &n), "boreas_mesh_tree_get_vertices");
  out.vertices.resize(size_t(n));
  check(boreas_mesh_tree_get_vertices(world, tree, part, out.vertices.data(), n, &n), "boreas_mesh_tree_get_vertices");
  check(boreas_mesh_tree_get_indices(world, tree, part, nullptr, 0, &n), "boreas_mesh_tree_get_indices");
  out.indices.resize(size_t(n));
  check(boreas_mesh_tree_get_indices(world, tree, part, out.indices.data(), n, &n), "boreas_mesh_tree_get_indices");
  return out;
}

template <typename T>
GlObject static_buffer_of(const std::vector<T>& data) {
  GlObject b = make_buffer();
  glNamedBufferStorage(b.id(), GLsizeiptr(std::max<size_t>(data.size(), 1) * sizeof(T)),
                       data.empty() ? nullptr : data.data(), 0);
  return b;
}

}  // namespace

void WorldBuffers::add_mesh_trees(const std::vector<boreas_mesh_tree_id>& ids, cl_context context,
                                  cl_command_queue queue, Bounds* bounds) {
  std::vector<float> trunk_static, leaf_static;
  std::vector<uint32_t> trunk_indices, leaf_indices;
  size_t trunk_vertices = 0, leaf_vertices = 0;
  for (boreas_mesh_tree_id id : ids) {
    RestPart trunk = rest_part(world_, id, BOREAS_MESH_TRUNK);
    RestPart leaves = rest_part(world_, id, BOREAS_MESH_LEAVES);
    Bounds wood, crown;
    for (const boreas_vertex& v : trunk.vertices) wood.add(vec(v.position));
    for (const boreas_vertex& v : leaves.vertices) crown.add(vec(v.position));
    if (crown.empty()) crown = wood;
    MeshTrunkDraw draw;
    draw.first_index = int(trunk_indices.size());
    draw.index_count = int(trunk.indices.size());
    draw.crown_center = 0.5f * (crown.min + crown.max);
    draw.crown_radius = 0.5f * (crown.max - crown.min);
    geometry_.mesh_trunk_draws.push_back(draw);
    for (uint32_t i : trunk.indices) trunk_indices.push_back(uint32_t(trunk_vertices) + i);
    for (uint32_t i : leaves.indices) leaf_indices.push_back(uint32_t(leaf_vertices) + i);
    std::vector<float> bark = bark_attributes(trunk.vertices, trunk.indices, kBarkTileM);
    std::vector<float> leaf = leaf_attributes(leaves.vertices, leaves.indices, crown);
    trunk_static.insert(trunk_static.end(), bark.begin(), bark.end());
    leaf_static.insert(leaf_static.end(), leaf.begin(), leaf.end());
    if (!wood.empty()) {
      glm::vec3 lo = crown.empty() ? wood.min : glm::min(wood.min, crown.min);
      glm::vec3 hi = crown.empty() ? wood.max : glm::max(wood.max, crown.max);
      bounds->add(lo - 0.1f * (hi - lo));  // room for the sway, as for generated trees
      bounds->add(hi + 0.1f * (hi - lo));
    }
    mesh_trees_.push_back(id);
    first_mesh_trunk_.push_back(trunk_vertices);
    first_mesh_leaf_.push_back(leaf_vertices);
    trunk_vertices += trunk.vertices.size();
    leaf_vertices += leaves.vertices.size();
  }
  if (trunk_vertices > 0) {
    mesh_trunk_positions_ = std::make_unique<interop::SharedBuffer>(
        strategy_, context, queue, trunk_vertices * BOREAS_MESH_TRUNK_VERTEX_FLOATS * sizeof(float));
    mesh_trunk_static_ = static_buffer_of(trunk_static);
    mesh_trunk_indices_ = static_buffer_of(trunk_indices);
    geometry_.mesh_trunk_positions = mesh_trunk_positions_->gl();
    geometry_.mesh_trunk_static = mesh_trunk_static_.id();
    geometry_.mesh_trunk_indices = mesh_trunk_indices_.id();
  }
  if (leaf_vertices > 0 && !leaf_indices.empty()) {
    mesh_leaf_vertices_ = std::make_unique<interop::SharedBuffer>(
        strategy_, context, queue, leaf_vertices * BOREAS_MESH_LEAF_VERTEX_FLOATS * sizeof(float));
    mesh_leaf_static_ = static_buffer_of(leaf_static);
    mesh_leaf_indices_ = static_buffer_of(leaf_indices);
    geometry_.mesh_leaf_vertices = mesh_leaf_vertices_->gl();
    geometry_.mesh_leaf_static = mesh_leaf_static_.id();
    geometry_.mesh_leaf_indices = mesh_leaf_indices_.id();
    geometry_.mesh_leaf_index_count = int(leaf_indices.size());
  }
}

WorldBuffers::WorldBuffers(boreas_world world, interop::Strategy strategy,
                           const std::vector<TreeToDraw>& trees,
                           const std::vector<MeadowToDraw>& meadows,
                           const std::vector<boreas_mesh_tree_id>& mesh_trees, size_t whole_records_bytes)
    : world_(world), strategy_(strategy), whole_records_bytes_(whole_records_bytes) {
  boreas_cl_objects cl{};
  check(boreas_world_get_cl(world, &cl), "boreas_world_get_cl");
  Bounds bounds;
  std::vector<float> leaf_static;
  size_t branches = 0, leaves = 0;
  for (const TreeToDraw& tree : trees) add_tree(tree, &branches, &leaves, &leaf_static, &bounds);
  std::vector<float> styles;
  size_t components = 0;
  for (const MeadowToDraw& meadow : meadows) add_meadow(meadow, &components, &styles, &bounds);
  make_buffers(cl.context, cl.queue, branches, leaves, components, leaf_static, styles);
  context_ = cl.context;
  queue_ = cl.queue;
  if (branches > 0) make_tree_record_buffers(branches, leaves);
  add_mesh_trees(mesh_trees, cl.context, cl.queue, &bounds);
  if (!bounds.empty()) {
    geometry_.bounds_min = bounds.min;
    geometry_.bounds_max = bounds.max;
  }
}

void WorldBuffers::add_tree(const TreeToDraw& tree, size_t* branches, size_t* leaves,
                            std::vector<float>* leaf_static, Bounds* bounds) {
  trees_.push_back(tree.id);
  int nb = 0, nl = 0;
  check(boreas_tree_get_branches(world_, tree.id, nullptr, 0, &nb), "boreas_tree_get_branches");
  std::vector<boreas_branch> b(static_cast<size_t>(nb));
  check(boreas_tree_get_branches(world_, tree.id, b.data(), nb, &nb), "boreas_tree_get_branches");
  check(boreas_tree_get_leaves(world_, tree.id, nullptr, 0, &nl), "boreas_tree_get_leaves");
  std::vector<boreas_leaf> l(static_cast<size_t>(nl));
  check(boreas_tree_get_leaves(world_, tree.id, l.data(), nl, &nl), "boreas_tree_get_leaves");
  Bounds wood, crown;
  for (const boreas_branch& branch : b) {
    for (const auto& p : branch.control_points) wood.add(vec(p));
  }
  for (const boreas_leaf& leaf : l) crown.add(vec(leaf.position));
  if (crown.empty()) crown = wood;
  // Room for the sway: a tenth of the tree's size around it (a strong gust bends a crown
  // by about that much); the renderer skips the tree where this box is out of view.
  Bounds sway;
  if (!wood.empty()) {
    glm::vec3 margin = 0.1f * (glm::max(wood.max, crown.max) - glm::min(wood.min, crown.min));
    sway.add(glm::min(wood.min, crown.min) - margin);
    sway.add(glm::max(wood.max, crown.max) + margin);
  }
  add_tree_instance(tree, b, int(geometry_.branch_draws.size()), int(*branches), wood, crown);
  add_branch_draws(tree, b, int(*branches), crown, sway);
  if (nl > 0) {
    geometry_.trees.back().leaf_draw = int(geometry_.leaf_draws.size());
    LeafDraw d;
    d.first = int(*leaves);
    add_leaf_static(tree, l, leaf_static, &d);
    d.count = nl;
    double area = 0.0;
    for (const boreas_leaf& leaf : l) area += double(leaf.length) * double(leaf.width);
    d.mean_area = float(area / double(nl));
    if (!sway.empty()) {
      d.bounds_min = sway.min;
      d.bounds_max = sway.max;
    }
    geometry_.leaf_draws.push_back(d);
  }
  if (!sway.empty()) {
    bounds->add(sway.min);
    bounds->add(sway.max);
  }
  first_branch_.push_back(*branches);
  first_leaf_.push_back(*leaves);
  *branches += size_t(nb);
  *leaves += size_t(nl);
}

void WorldBuffers::add_tree_instance(const TreeToDraw& tree, const std::vector<boreas_branch>& b,
                                     int first_branch_draw, int first_record, const Bounds& wood,
                                     const Bounds& crown) {
  TreeInstance t;
  t.first_branch_draw = first_branch_draw;
  t.position = tree.position;
  t.rotation = tree.rotation;
  t.scale = tree.scale;
  auto trunk = std::find_if(b.begin(), b.end(), [](const boreas_branch& x) { return x.level == 0; });
  if (trunk != b.end()) {
    t.trunk_record = first_record + int(trunk - b.begin());
    t.rest_tip = vec(trunk->control_points[3]);
  }
  t.id_index = int(tree.id.index);
  t.id_generation = int(tree.id.generation);
  check(boreas_tree_get_template(world_, tree.id, &t.world_template), "boreas_tree_get_template");
  // A model's first tree, at rest, is its template: the bounding sphere of its box and the
  // trunk tip's height, both in the model's own space (before the tree's placement).
  if (!tree.model.empty() && trunk != b.end() && !wood.empty()) {
    auto [found, is_new] = templates_.try_emplace(tree.model, int(geometry_.impostor_templates.size()));
    if (is_new) {
      const glm::mat4 to_model = tree_placement_inverse(tree.position, tree.rotation, tree.scale);
      Bounds box;
      for (const glm::vec3& corner : {glm::min(wood.min, crown.min), glm::max(wood.max, crown.max)}) box.add(corner);
      ImpostorTemplate m;
      m.tree = int(geometry_.trees.size());
      m.center = glm::vec3(to_model * glm::vec4(0.5f * (box.min + box.max), 1.0f));
      m.radius = 0.5f * glm::length(box.max - box.min) / tree.scale;
      m.tip_height = glm::vec3(to_model * glm::vec4(t.rest_tip, 1.0f)).y;
      m.leaf_transmittance = tree.leaf_transmittance;
      geometry_.impostor_templates.push_back(m);
    }
    t.impostor_template = found->second;
  }
  geometry_.trees.push_back(t);
}

void WorldBuffers::add_branch_draws(const TreeToDraw& tree, const std::vector<boreas_branch>& b,
                                    int first_record, const Bounds& crown, const Bounds& sway) {
  // Branches are listed level by level: one draw per level.
  for (int level = 0, first = 0; level < 4; ++level) {
    int count = int(std::count_if(b.begin(), b.end(),
                                  [&](const boreas_branch& x) { return x.level == level; }));
    if (count == 0) continue;
    BranchDraw d;
    d.first_record = first_record + first;
    d.count = count;
    d.rings = tree.levels[level].rings;
    d.sides = tree.levels[level].sides;
    d.crown_center = 0.5f * (crown.min + crown.max);
    d.crown_radius = 0.5f * (crown.max - crown.min);
    if (!sway.empty()) {
      d.bounds_min = sway.min;
      d.bounds_max = sway.max;
    }
    geometry_.branch_draws.push_back(d);
    geometry_.trees.back().branch_draw_count += 1;
    first += count;
  }
}

void WorldBuffers::add_leaf_static(const TreeToDraw& tree, const std::vector<boreas_leaf>& l,
                                   std::vector<float>* leaf_static, LeafDraw* draw) {
  const int nl = int(l.size());
  // Trees of one template are one model at rest, placed (boreas_tree_get_template): their
  // leaves' sizes differ by the scale alone, and their occlusion by how the crown's voxels
  // fall as it is turned, which the template's first tree stands for.
  // The scale is the leaves' own (their summed lengths over the first tree's), whatever
  // the caller's placement says.
  const int world_template = geometry_.trees.back().world_template;
  const glm::vec3& tr = tree.leaf_transmittance;
  const StaticKey key{world_template, tree.leaf_layer, tree.crown_occlusion, tr.x, tr.y, tr.z, nl};
  double lengths = 0.0;
  for (const boreas_leaf& leaf : l) lengths += double(leaf.length);
  if (world_template >= 0 && lengths > 0.0) {
    auto found = leaf_statics_.find(key);
    if (found != leaf_statics_.end()) {
      draw->first_static = found->second.first;
      draw->static_scale = float(lengths / found->second.second);
      return;
    }
    leaf_statics_.emplace(key, std::pair{int(static_leaves_), lengths});
  }
  draw->first_static = int(static_leaves_);
  static_leaves_ += size_t(nl);
  // The crown's occlusion at each leaf, computed once on the device at rest.
  std::vector<float> occlusion(size_t(nl) * 3, 1.0f);
  if (nl > 0 && tree.crown_occlusion) {
    int n = 0;
    check(boreas_tree_get_leaf_occlusion(world_, tree.id, &tree.leaf_transmittance.x,
                                         occlusion.data(), nl, &n),
          "boreas_tree_get_leaf_occlusion");
  }
  for (size_t i = 0; i < l.size(); ++i) {
    leaf_static->insert(leaf_static->end(),
                        {l[i].length, l[i].width, occlusion[3 * i], occlusion[3 * i + 1],
                         occlusion[3 * i + 2], float(tree.leaf_layer)});
  }
}

void WorldBuffers::add_meadow(const MeadowToDraw& meadow, size_t* components,
                              std::vector<float>* styles, Bounds* bounds) {
  meadows_.push_back(meadow.id);
  int n = 0;
  check(boreas_meadow_get_components(world_, meadow.id, nullptr, 0, &n),
        "boreas_meadow_get_components");
  if (meadow.styles.size() != size_t(n) * 6) {
    throw std::invalid_argument("WorldBuffers: meadow styles hold " +
                                std::to_string(meadow.styles.size()) + " floats for " +
                                std::to_string(n) + " components (6 each)");
  }
  std::vector<boreas_component> c(static_cast<size_t>(n));
  check(boreas_meadow_get_components(world_, meadow.id, c.data(), n, &n),
        "boreas_meadow_get_components");
  Bounds own;
  for (const boreas_component& x : c) {
    own.add(vec(x.base));
    own.add(vec(x.rest_center_of_mass) * 2.0f - vec(x.base));  // about the tip
  }
  if (!own.empty()) {
    bounds->add(own.min);
    bounds->add(own.max);
    // Room for the blades' bend: they lean by at most their height.
    const float lean = own.max.y - own.min.y;
    MeadowDraw d;
    d.first = int(*components);
    d.count = n;
    d.bounds_min = own.min - glm::vec3(lean, 0.0f, lean);
    d.bounds_max = own.max + glm::vec3(lean, 0.0f, lean);
    geometry_.meadow_draws.push_back(d);
  }
  add_meadow_styles(meadow, n, styles);
  first_component_.push_back(*components);
  *components += size_t(n);
}

void WorldBuffers::add_meadow_styles(const MeadowToDraw& meadow, int n,
                                     std::vector<float>* styles) {
  // Each component's widest, from its strip at rest (widths do not change as it moves):
  // the shader's coverage rule reads it instead of measuring the strip every frame.
  int vertex_count = 0;
  check(boreas_meadow_get_vertices(world_, meadow.id, nullptr, nullptr, 0, &vertex_count, nullptr),
        "boreas_meadow_get_vertices");
  std::vector<boreas_meadow_vertex> strips(static_cast<size_t>(vertex_count));
  check(boreas_meadow_get_vertices(world_, meadow.id, nullptr, strips.data(), vertex_count,
                                   &vertex_count, nullptr),
        "boreas_meadow_get_vertices");
  for (size_t i = 0; i < size_t(n); ++i) {
    float widest = 0.0f;
    for (size_t j = 0; j + 1 < BOREAS_MEADOW_VERTEX_STRIDE; j += 2) {
      const boreas_meadow_vertex& left = strips[i * BOREAS_MEADOW_VERTEX_STRIDE + j];
      const boreas_meadow_vertex& right = strips[i * BOREAS_MEADOW_VERTEX_STRIDE + j + 1];
      widest = std::max(widest, glm::distance(vec(left.position), vec(right.position)));
    }
    styles->insert(styles->end(), meadow.styles.begin() + long(6 * i),
                   meadow.styles.begin() + long(6 * i + 6));
    styles->insert(styles->end(), {widest, 0.0f});
  }
}

void WorldBuffers::make_buffers(cl_context context, cl_command_queue queue, size_t branches,
                                size_t leaves, size_t components,
                                const std::vector<float>& leaf_static,
                                const std::vector<float>& styles) {
  // The records' buffers grow to what the views ask for (grow_tree_records).
  all_branches_ = branches;
  all_leaves_ = leaves;
  if (leaves > 0) {
    leaf_static_ = static_buffer_of(leaf_static);
    geometry_.leaf_static = leaf_static_.id();
    geometry_.leaf_count = int(leaves);
  }
  if (components > 0) {
    meadow_vertices_ = std::make_unique<interop::SharedBuffer>(
        strategy_, context, queue,
        components * BOREAS_MEADOW_VERTEX_STRIDE * sizeof(boreas_meadow_vertex));
    cl_int err = CL_SUCCESS;
    strip_counts_ =
        clCreateBuffer(context, CL_MEM_READ_WRITE, components * sizeof(int32_t), nullptr, &err);
    if (err != CL_SUCCESS) throw std::runtime_error("WorldBuffers: clCreateBuffer (strip counts) failed: " + std::to_string(err));
    meadow_styles_ = static_buffer_of(styles);
    geometry_.meadow_vertices = meadow_vertices_->gl();
    geometry_.meadow_styles = meadow_styles_.id();
    geometry_.meadow_components = int(components);
  }
}

void WorldBuffers::make_tree_record_buffers(size_t branches, size_t leaves) {
  cl_int err = CL_SUCCESS;
  indirect_ = clCreateBuffer(context_, CL_MEM_READ_WRITE, BOREAS_TREE_INDIRECT_UINTS * sizeof(uint32_t), nullptr, &err);
  if (err != CL_SUCCESS) throw std::runtime_error("WorldBuffers: clCreateBuffer (indirect) failed: " + std::to_string(err));
  tree_indirect_ = std::make_unique<interop::SharedBuffer>(strategy_, context_, queue_,
                                                           BOREAS_TREE_INDIRECT_UINTS * sizeof(uint32_t));
  tree_ranges_ = std::make_unique<interop::SharedBuffer>(
      strategy_, context_, queue_, trees_.size() * BOREAS_TREE_RANGE_RECORD_INTS * sizeof(int32_t));
  // Every tree in full where that is at most whole_records_bytes_ (a few dozen trees): never
  // grown, so no frame ever misses a tree's records. Else a thirty-second of it to start,
  // which the first view's counts size and later views grow a frame late (update()).
  const size_t whole = branches * BOREAS_BRANCH_RECORD_FLOATS * sizeof(float) +
                       leaves * BOREAS_LEAF_RECORD_FLOATS * sizeof(float);
  const size_t part = whole <= whole_records_bytes_ ? 1 : 32;
  size_t want[3] = {std::max<size_t>(branches / part, 1), std::max<size_t>(leaves / part, 1),
                    std::max<size_t>(trees_.size(), 1)};
  resize_tree_records(want);
  geometry_.tree_ranges = tree_ranges_->gl();
  geometry_.tree_indirect = tree_indirect_->gl();
  geometry_.tree_range_capacity = int(trees_.size());
  // The call's impostor records name the world's templates: each must be one impostor.
  std::map<int, int> impostor_of_template;
  for (const TreeInstance& t : geometry_.trees) {
    auto [it, is_new] = impostor_of_template.try_emplace(t.world_template, t.impostor_template);
    if (t.impostor_template < 0 || t.world_template < 0 || it->second != t.impostor_template)
      every_tree_has_template_ = false;
  }
}

void WorldBuffers::resize_tree_records(const size_t records[3]) {
  const size_t floats[3] = {BOREAS_BRANCH_RECORD_FLOATS, BOREAS_LEAF_RECORD_FLOATS, BOREAS_TREE_IMPOSTOR_RECORD_FLOATS};
  std::unique_ptr<interop::SharedBuffer>* buffers[3] = {&branch_records_, &leaf_records_, &tree_impostors_};
  for (int k = 0; k < 3; ++k) {
    if (*buffers[k] && capacity_[k] >= records[k]) continue;
    buffers[k]->reset();  // before the new one: the two need not be held at once
    *buffers[k] = std::make_unique<interop::SharedBuffer>(strategy_, context_, queue_,
                                                          records[k] * floats[k] * sizeof(float));
    capacity_[k] = records[k];
  }
  geometry_.branch_records = branch_records_->gl();
  geometry_.leaf_records = leaf_records_->gl();
  geometry_.tree_impostors = tree_impostors_->gl();
}

void WorldBuffers::enqueue_tree_records(const boreas_tree_view_def& view) {
  boreas_tree_record_buffers out{branch_records_->cl(), leaf_records_->cl(), tree_impostors_->cl(),
                                 tree_ranges_->cl(), indirect_};
  check(boreas_world_enqueue_tree_records(world_, &view, &out), "boreas_world_enqueue_tree_records");
  if (clEnqueueCopyBuffer(queue_, indirect_, tree_indirect_->cl(), 0, 0, BOREAS_TREE_INDIRECT_UINTS * sizeof(uint32_t),
                          0, nullptr, nullptr) != CL_SUCCESS)
    throw std::runtime_error("WorldBuffers: copying the indirect words failed");
}

void WorldBuffers::read_needed(bool blocking) {
  // The call's "needed" words (16 bytes) into needed_; never while another read is in
  // flight or a landed one is not yet taken (it would write what grow_tree_records reads).
  if (clEnqueueReadBuffer(queue_, indirect_, blocking ? CL_TRUE : CL_FALSE, BOREAS_TREE_INDIRECT_NEEDED * sizeof(uint32_t),
                          sizeof needed_, needed_, 0, nullptr, blocking ? nullptr : &needed_read_) != CL_SUCCESS)
    throw std::runtime_error("WorldBuffers: reading the tree records' needed counts failed");
  if (!blocking) clFlush(queue_);  // on its way while the frame is drawn
  needed_landed_ = blocking;
  ++reads_enqueued_;
  if (blocking) ++blocking_reads_;
}

bool WorldBuffers::read_in_flight() {
  if (!needed_read_) return false;
  cl_int status = CL_QUEUED;
  if (clGetEventInfo(needed_read_, CL_EVENT_COMMAND_EXECUTION_STATUS, sizeof status, &status, nullptr) != CL_SUCCESS)
    throw std::runtime_error("WorldBuffers: asking after the needed counts' read failed");
  if (status < 0) throw std::runtime_error("WorldBuffers: the needed counts' read failed: " + std::to_string(status));
  if (status != CL_COMPLETE) return true;
  clReleaseEvent(needed_read_);
  needed_read_ = nullptr;
  needed_landed_ = true;
  return false;
}

bool WorldBuffers::grow_tree_records() {
  if (read_in_flight() || !needed_landed_) return false;  // a later frame grows them
  needed_landed_ = false;
  const uint32_t* needed = needed_;
  if (needed[0] <= capacity_[0] && needed[1] <= capacity_[1] && needed[2] <= capacity_[2]) return false;
  // A quarter more than asked, so that a camera moving about does not grow them every frame.
  size_t want[3];
  for (int k = 0; k < 3; ++k) want[k] = std::max<size_t>(capacity_[k], size_t(needed[k]) + size_t(needed[k]) / 4 + 1);
  resize_tree_records(want);
  return true;
}

const uint32_t* WorldBuffers::tree_counts() {
  if (indirect_ &&
      clEnqueueReadBuffer(queue_, indirect_, CL_TRUE, 0, sizeof tree_counts_, tree_counts_, 0, nullptr, nullptr) != CL_SUCCESS)
    throw std::runtime_error("WorldBuffers: reading the tree records' counts failed");
  return tree_counts_;
}

std::vector<interop::SharedBuffer*> WorldBuffers::tree_shared() const {
  std::vector<interop::SharedBuffer*> out;
  for (auto* b : {branch_records_.get(), leaf_records_.get(), tree_impostors_.get(), tree_ranges_.get(),
                  tree_indirect_.get()})
    if (b) out.push_back(b);
  return out;
}

WorldBuffers::~WorldBuffers() {
  if (needed_read_) {
    clWaitForEvents(1, &needed_read_);  // it writes into this object
    clReleaseEvent(needed_read_);
  }
  for (cl_mem m : {strip_counts_, indirect_})
    if (m) clReleaseMemObject(m);
}

std::vector<interop::SharedBuffer*> WorldBuffers::shared() const {
  std::vector<interop::SharedBuffer*> out = tree_shared();
  for (auto* b : {meadow_vertices_.get(), mesh_trunk_positions_.get(), mesh_leaf_vertices_.get(),
                  rest_branch_records_.get(), rest_leaf_records_.get()}) {
    if (b) out.push_back(b);
  }
  return out;
}

bool WorldBuffers::maps_in_place() const {
  std::vector<interop::SharedBuffer*> buffers = shared();
  return !buffers.empty() && std::all_of(buffers.begin(), buffers.end(),
                                         [](interop::SharedBuffer* b) { return b->maps_in_place(); });
}

size_t WorldBuffers::bytes_per_frame() const {
  size_t bytes = 0;
  for (interop::SharedBuffer* b : shared()) bytes += b->bytes();
  return bytes;
}

void WorldBuffers::update(const glm::vec3& camera, const boreas_tree_view_def& trees) {
  rest_branch_records_.reset();  // the bake's, done with
  rest_leaf_records_.reset();
  boreas_tree_view_def view = trees;
  // A tree with no impostor of its own is drawn in full at any distance: the call then
  // makes none (tree_ranges.comp hands the others over to theirs all the same).
  if (!every_tree_has_template_) view.impostor_distance = 0.0f;
  // The records' buffers grown first, from the last call's needs where its read has landed
  // (a frame late, without a wait); the first call of all sizes them with the one blocking
  // read (below). In the frame a view first needs more than they hold, the call writes the
  // records that fit and counts those alone in the indirect commands (boreas_cl.h): the
  // trees past the end are not drawn that one frame, and nothing is written past a buffer.
  if (branch_records_) grow_tree_records();
  for (interop::SharedBuffer* b : shared()) b->begin_write();
  if (branch_records_) enqueue_tree_records(view);
  // Every imported tree's part and every meadow's strips: one launch a list.
  const int mesh_count = int(mesh_trees_.size());
  if (mesh_trunk_positions_)
    check(boreas_world_enqueue_mesh_tree_vertices(world_, mesh_trees_.data(), first_mesh_trunk_.data(), mesh_count,
                                                  BOREAS_MESH_TRUNK, mesh_trunk_positions_->cl()),
          "boreas_world_enqueue_mesh_tree_vertices");
  if (mesh_leaf_vertices_)
    check(boreas_world_enqueue_mesh_tree_vertices(world_, mesh_trees_.data(), first_mesh_leaf_.data(), mesh_count,
                                                  BOREAS_MESH_LEAVES, mesh_leaf_vertices_->cl()),
          "boreas_world_enqueue_mesh_tree_vertices");
  const float eye[3] = {camera.x, camera.y, camera.z};
  if (meadow_vertices_)
    check(boreas_world_enqueue_meadow_vertices(world_, meadows_.data(), first_component_.data(), int(meadows_.size()),
                                               eye, meadow_vertices_->cl(), strip_counts_),
          "boreas_world_enqueue_meadow_vertices");
  for (interop::SharedBuffer* b : shared()) b->end_write();
  if (!branch_records_) return;
  if (reads_enqueued_ > 0) {
    // This call's needs, unless the last read is still in flight or landed untaken (then
    // the next frame grows from that one, and reads again after its call).
    if (!read_in_flight() && !needed_landed_) read_needed(false);
    return;
  }
  // The first frame: its buffers were a guess (a thirty-second of every tree), so the call
  // is sized once with a blocking read and made again, rather than a first frame drawn
  // with trees missing.
  read_needed(true);
  if (!grow_tree_records()) return;
  for (interop::SharedBuffer* b : tree_shared()) b->begin_write();
  enqueue_tree_records(view);
  for (interop::SharedBuffer* b : tree_shared()) b->end_write();
  read_needed(false);
}

void WorldBuffers::update_at_rest() {
  if (!branch_records_) return;
  // Only the trees the templates are baked from, one after the other: the bake reads
  // nothing else (the forest's 60 of 1,000 trees).
  rest_geometry_ = geometry_;
  size_t branches = 0, leaves = 0;
  for (ImpostorTemplate& m : rest_geometry_.impostor_templates) {
    const size_t i = size_t(m.tree);
    m.rest_branch_shift = int(first_branch_[i] - branches);
    m.rest_leaf_shift = int(first_leaf_[i] - leaves);
    branches += (i + 1 < trees_.size() ? first_branch_[i + 1] : all_branches_) - first_branch_[i];
    leaves += (i + 1 < trees_.size() ? first_leaf_[i + 1] : all_leaves_) - first_leaf_[i];
  }
  rest_branch_records_ = std::make_unique<interop::SharedBuffer>(
      strategy_, context_, queue_, std::max<size_t>(branches, 1) * BOREAS_BRANCH_RECORD_FLOATS * sizeof(float));
  if (leaves > 0) {
    rest_leaf_records_ = std::make_unique<interop::SharedBuffer>(
        strategy_, context_, queue_, leaves * BOREAS_LEAF_RECORD_FLOATS * sizeof(float));
  }
  rest_branch_records_->begin_write();
  if (rest_leaf_records_) rest_leaf_records_->begin_write();
  for (const ImpostorTemplate& m : rest_geometry_.impostor_templates) {
    const size_t i = size_t(m.tree);
    check(boreas_tree_enqueue_branch_records(world_, trees_[i], rest_branch_records_->cl(),
                                             first_branch_[i] - size_t(m.rest_branch_shift)),
          "boreas_tree_enqueue_branch_records");
    if (rest_leaf_records_ && first_leaf_[i] < (i + 1 < trees_.size() ? first_leaf_[i + 1] : all_leaves_)) {
      check(boreas_tree_enqueue_leaf_records(world_, trees_[i], rest_leaf_records_->cl(),
                                             first_leaf_[i] - size_t(m.rest_leaf_shift)),
            "boreas_tree_enqueue_leaf_records");
    }
  }
  rest_branch_records_->end_write();
  if (rest_leaf_records_) rest_leaf_records_->end_write();
  rest_geometry_.branch_records = rest_branch_records_->gl();
  rest_geometry_.leaf_records = rest_leaf_records_ ? rest_leaf_records_->gl() : 0;
  rest_geometry_.tree_ranges = rest_geometry_.tree_impostors = rest_geometry_.tree_indirect = 0;
}

void WorldBuffers::end_draw() {
  for (interop::SharedBuffer* b : shared()) b->end_draw();
}

}  // namespace boreas::render
