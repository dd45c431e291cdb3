// boreas render: the trees' tables on the GPU (tree_table.h).
#include "gl/tree_table.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>
#include <map>

#include <glm/vec2.hpp>

#include "gl/crown_light.h"

namespace boreas::render {

namespace {

// std430 layouts of shaders/tree_table.glsl.
struct TreeEntry {
  glm::vec4 position_scale, rest_tip_rotation, bounds_min, bounds_max;
  int32_t draws[4];  // its branch draws [0], [1]), its leaf draw [2] (-1 none), 0
};
struct TemplateEntry {
  glm::vec4 center_radius, transmittance_tip_height;
  glm::vec4 layer;  // x: its layer of the atlases; y: 1 once baked
  glm::vec4 unused;
};
struct DrawEntry {
  int32_t range[4];  // first record, count, tree, element indices (0: leaves)
  int32_t grid[4];   // rings, sides, first element index, 0; leaves: first static, 0, 0, 0
  glm::vec4 crown_center, crown_radius;  // leaves: center x the static lengths' factor
};
static_assert(sizeof(TreeEntry) == 80 && sizeof(TemplateEntry) == 64 && sizeof(DrawEntry) == 64);

// Every instance of a draw reads its base instance: the divisor exceeds any instance count.
constexpr GLuint kPerDrawDivisor = 1u << 30;

template <typename T>
GlObject buffer_of(const std::vector<T>& data, GLbitfield flags = 0) {
  GlObject b = make_buffer();
  glNamedBufferStorage(b.id(), GLsizeiptr(std::max<size_t>(data.size(), 1) * sizeof(T)),
                       data.empty() ? nullptr : data.data(), flags);
  return b;
}

GlObject zero_buffer(size_t bytes) {
  GlObject b = make_buffer();
  glNamedBufferStorage(b.id(), GLsizeiptr(std::max<size_t>(bytes, 16)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glClearNamedBufferData(b.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  return b;
}

// The element indices of a (rings + 1) x (sides + 1) grid: two counter-clockwise
// triangles per quad, seen from outside (boreas_tree_get_mesh).
void append_grid(int rings, int sides, std::vector<GLuint>* out) {
  const GLuint row = GLuint(sides + 1);
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < sides; ++s) {
      GLuint a = GLuint(r) * row + GLuint(s), b = a + 1, c = a + row + 1, d = a + row;
      out->insert(out->end(), {a, b, c, a, c, d});
    }
  }
}

}  // namespace

TreeTable::Key TreeTable::key_of(const FrameGeometry& g) {
  Key k;
  k.branch_draws = g.branch_draws.size();
  k.leaf_draws = g.leaf_draws.empty() && g.leaf_count > 0 ? 1 : g.leaf_draws.size();
  k.trees = g.trees.size();
  k.templates = g.impostor_templates.size();
  if (!g.branch_draws.empty()) k.last_branch_record = g.branch_draws.back().first_record;
  if (!g.leaf_draws.empty()) k.last_leaf = g.leaf_draws.back().first;
  return k;
}

void TreeTable::sync(const FrameGeometry& g) {
  Key k = key_of(g);
  if (built_ && k == key_) return;
  build(g);
  key_ = k;
  built_ = true;
}

void TreeTable::build(const FrameGeometry& g) {
  // The leaves as one draw where the geometry lists none.
  std::vector<LeafDraw> leaf_draws = g.leaf_draws;
  if (leaf_draws.empty() && g.leaf_records != 0 && g.leaf_count > 0) leaf_draws.push_back({0, g.leaf_count});
  if (g.branch_records == 0) branch_draws_ = 0;
  else branch_draws_ = int(g.branch_draws.size());
  leaf_draws_ = (g.leaf_records != 0 && g.leaf_static != 0) ? int(leaf_draws.size()) : 0;

  // Owners: each draw's tree; draws no tree claims are trees of their own (no impostor).
  std::vector<TreeEntry> trees;
  std::vector<int> branch_owner(size_t(branch_draws_), -1), leaf_owner(size_t(leaf_draws_), -1);
  tree_draws_.assign(g.trees.size(), {});
  for (size_t t = 0; t < g.trees.size(); ++t) {
    const TreeInstance& tree = g.trees[t];
    Bounds box;
    for (int d = tree.first_branch_draw; d < tree.first_branch_draw + tree.branch_draw_count && d < branch_draws_; ++d) {
      branch_owner[size_t(d)] = int(t);
      box.add(g.branch_draws[size_t(d)].bounds_min);
      box.add(g.branch_draws[size_t(d)].bounds_max);
    }
    if (tree.leaf_draw >= 0 && tree.leaf_draw < leaf_draws_) {
      leaf_owner[size_t(tree.leaf_draw)] = int(t);
      box.add(leaf_draws[size_t(tree.leaf_draw)].bounds_min);
      box.add(leaf_draws[size_t(tree.leaf_draw)].bounds_max);
    }
    if (box.empty()) box.add(tree.position);
    const int first = std::min(tree.first_branch_draw, branch_draws_);
    const int end = std::min(tree.first_branch_draw + tree.branch_draw_count, branch_draws_);
    const int leaf = tree.leaf_draw >= 0 && tree.leaf_draw < leaf_draws_ ? branch_draws_ + tree.leaf_draw : -1;
    trees.push_back({glm::vec4(tree.position, tree.scale), glm::vec4(tree.rest_tip, tree.rotation),
                     glm::vec4(box.min, float(tree.impostor_template)),
                     glm::vec4(box.max, float(tree.trunk_record)), {first, end, leaf, 0}});
  }
  auto own_tree = [&](const glm::vec3& lo, const glm::vec3& hi, int draw, bool leaves) {
    trees.push_back({glm::vec4(0.5f * (lo + hi), 1.0f), glm::vec4(0.0f), glm::vec4(lo, -1.0f), glm::vec4(hi, -1.0f),
                     {leaves ? 0 : draw, leaves ? 0 : draw + 1, leaves ? draw : -1, 0}});
    return int(trees.size()) - 1;
  };

  std::map<std::pair<int, int>, int> grid_first;  // (rings, sides) -> first element index
  std::vector<GLuint> indices;
  std::vector<DrawEntry> draws;
  entry_index_count_.clear();
  entry_first_index_.clear();
  entry_instances_.clear();
  entry_first_record_.clear();
  for (int d = 0; d < branch_draws_; ++d) {
    const BranchDraw& b = g.branch_draws[size_t(d)];
    auto [it, is_new] = grid_first.try_emplace({b.rings, b.sides}, int(indices.size()));
    if (is_new) append_grid(b.rings, b.sides, &indices);
    int owner = branch_owner[size_t(d)] >= 0 ? branch_owner[size_t(d)] : own_tree(b.bounds_min, b.bounds_max, d, false);
    if (branch_owner[size_t(d)] >= 0) tree_draws_[size_t(owner)].branch_entries.push_back(d);
    const int count = 6 * b.rings * b.sides;
    draws.push_back({{b.first_record, b.count, owner, count}, {b.rings, b.sides, it->second, 0},
                     glm::vec4(b.crown_center, 0.0f), glm::vec4(b.crown_radius, 0.0f)});
    entry_index_count_.push_back(count);
    entry_first_index_.push_back(it->second);
    entry_instances_.push_back(b.count);
    entry_first_record_.push_back(b.first_record);
  }
  for (int d = 0; d < leaf_draws_; ++d) {
    const LeafDraw& l = leaf_draws[size_t(d)];
    int owner = leaf_owner[size_t(d)] >= 0 ? leaf_owner[size_t(d)] : own_tree(l.bounds_min, l.bounds_max, branch_draws_ + d, true);
    if (leaf_owner[size_t(d)] >= 0) tree_draws_[size_t(owner)].leaf_entry = branch_draws_ + d;
    const int first_static = l.first_static >= 0 ? l.first_static : l.first;
    draws.push_back({{l.first, l.count, owner, 0}, {first_static, 0, 0, 0},
                     glm::vec4(l.static_scale, 0.0f, 0.0f, l.mean_area), glm::vec4(0.0f)});
    entry_index_count_.push_back(0);
    entry_first_index_.push_back(0);
    entry_instances_.push_back(l.count);
    entry_first_record_.push_back(l.first);
  }
  trees_ = int(trees.size());
  std::vector<TemplateEntry> templates;
  for (size_t t = 0; t < g.impostor_templates.size(); ++t) {
    const ImpostorTemplate& m = g.impostor_templates[t];
    templates.push_back({glm::vec4(m.center, m.radius), glm::vec4(m.leaf_transmittance, m.tip_height),
                         glm::vec4(float(t), 0.0f, 0.0f, 0.0f), glm::vec4(0.0f)});
  }
  templates_ = int(templates.size());

  tree_buffer_ = buffer_of(trees);
  template_buffer_ = buffer_of(templates, GL_DYNAMIC_STORAGE_BIT);
  draw_buffer_ = buffer_of(draws);
  element_indices_ = buffer_of(indices);
  std::vector<GLuint> ids(draws.size());
  for (size_t i = 0; i < ids.size(); ++i) ids[i] = GLuint(i);
  draw_ids_ = buffer_of(ids);
  // Two sets of commands and handover lists: the scene pass's, then the shadow pass's.
  branch_commands_ = zero_buffer(2 * size_t(branch_draws_) * 5 * sizeof(GLuint));
  leaf_commands_ = zero_buffer(2 * size_t(leaf_draws_) * 4 * sizeof(GLuint));
  handover_records_ = zero_buffer(2 * size_t(trees_) * 12 * sizeof(float));
  handover_commands_ = zero_buffer(8 * sizeof(GLuint));
  entry_frame_ = zero_buffer(draws.size() * 2 * sizeof(GLint));
  build_id_tables(g);

  vao_ = make_vertex_array();
  glEnableVertexArrayAttrib(vao_.id(), 0);
  glVertexArrayAttribIFormat(vao_.id(), 0, 1, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(vao_.id(), 0, 0);
  glVertexArrayVertexBuffer(vao_.id(), 0, draw_ids_.id(), 0, sizeof(GLuint));
  glVertexArrayBindingDivisor(vao_.id(), 0, kPerDrawDivisor);
  glVertexArrayElementBuffer(vao_.id(), element_indices_.id());
}

void TreeTable::build_id_tables(const FrameGeometry& g) {
  // Per boreas_tree_id index its tree and generation; per world template the renderer's.
  std::vector<glm::ivec2> tree_of_id;
  std::vector<GLint> template_of_world;
  for (size_t t = 0; t < g.trees.size(); ++t) {
    const TreeInstance& tree = g.trees[t];
    if (tree.id_index < 0) continue;
    if (size_t(tree.id_index) >= tree_of_id.size()) tree_of_id.resize(size_t(tree.id_index) + 1, glm::ivec2(-1));
    tree_of_id[size_t(tree.id_index)] = glm::ivec2(int(t), tree.id_generation);
    if (tree.world_template < 0 || tree.impostor_template < 0) continue;
    if (size_t(tree.world_template) >= template_of_world.size()) template_of_world.resize(size_t(tree.world_template) + 1, -1);
    template_of_world[size_t(tree.world_template)] = tree.impostor_template;
  }
  ids_ = int(tree_of_id.size());
  world_templates_ = int(template_of_world.size());
  tree_of_id_ = buffer_of(tree_of_id);
  template_of_world_ = buffer_of(template_of_world);
}

void TreeTable::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, tree_buffer_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, template_buffer_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, draw_buffer_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 13, branch_commands_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 14, leaf_commands_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 15, handover_records_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 16, handover_commands_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 20, entry_frame_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 23, tree_of_id_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 24, template_of_world_.id());
}

void TreeTable::mark_baked(const std::vector<int>& templates) const {
  const float baked = 1.0f;
  for (int t : templates) {
    glNamedBufferSubData(template_buffer_.id(), GLintptr(size_t(t) * sizeof(TemplateEntry) + offsetof(TemplateEntry, layer) + sizeof(float)),
                         sizeof baked, &baked);
  }
}

void TreeTable::reset_commands() const {
  glClearNamedBufferData(branch_commands_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  glClearNamedBufferData(leaf_commands_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  const GLuint strips[8] = {4, 0, 0, 0, 4, 0, 0, 0};  // four vertices a quad; instances counted on the GPU
  glNamedBufferSubData(handover_commands_.id(), 0, sizeof strips, strips);
}

}  // namespace boreas::render
