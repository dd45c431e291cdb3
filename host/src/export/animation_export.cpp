// boreas: boreas_world_export_animation (export/animation_export.h). The bind pose is the
// world as the call finds it: a template's mesh is its first tree's, brought back into the
// template's own space (the inverse of the tree's placement), so trees of one template
// share it exactly when they are at rest (just added, or healed) at the call. A warm-up
// steps the world after the bind pose is taken: the keys start later, the skins and the
// morphed meshes' bases stay at rest.
#include "export/animation_export.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>

#include "boreas_gltf/animation_gltf.h"
#include "errors.h"
#include "export/morph_export.h"
#include "trees/tree_skin.h"
#include "world.h"

namespace boreas::impl {
namespace {

using gltf::SkinnedPart;

// World point to the tree's template space: R_y(-rotation) (p - position) / scale.
struct Unplace {
  double c, s, k, at[3];
  explicit Unplace(const TreeParams& p)
      : c(std::cos(p.rotation)), s(std::sin(p.rotation)), k(1.0 / p.scale),
        at{p.position[0], p.position[1], p.position[2]} {}
  void point(const float* in, float* out) const {
    direction(in, out, at, k);
  }
  void direction(const float* in, float* out, const double* origin = nullptr, double scale = 1.0) const {
    const double x = in[0] - (origin ? origin[0] : 0), y = in[1] - (origin ? origin[1] : 0),
                 z = in[2] - (origin ? origin[2] : 0);
    out[0] = float(scale * (c * x - s * z));
    out[1] = float(scale * y);
    out[2] = float(scale * (s * x + c * z));
  }
};

void append_weight(SkinnedPart* part, const boreas_skin_weight& w) {
  for (int i = 0; i < 4; ++i) {
    part->joints.push_back(w.joints[i]);
    part->weights.push_back(w.weights[i]);
  }
}

SkinnedPart bark_part(World& world, boreas_tree_id id, const SkinParams& p) {
  std::vector<boreas_vertex> vertices;
  std::vector<uint32_t> indices;
  world.tree_mesh(id, &vertices, &indices);
  const TreeParams& params = world.tree(id).params;
  LevelGrids grids{};
  for (size_t l = 0; l < grids.size(); ++l)
    grids[l] = {params.levels[l].rings, params.levels[l].sides};
  const std::vector<boreas_skin_weight> weights =
      skin_vertex_weights(world.tree_branches(id), skin_tip_caps(world.tree(id).model), grids, p);
  const Unplace unplace(params);
  SkinnedPart part;
  part.positions.resize(3 * vertices.size());
  part.normals.resize(3 * vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) {
    unplace.point(vertices[v].position, &part.positions[3 * v]);
    unplace.direction(vertices[v].normal, &part.normals[3 * v]);
    part.uvs.push_back(vertices[v].uv[0]);
    part.uvs.push_back(vertices[v].uv[1]);
    append_weight(&part, weights[v]);
  }
  part.indices = std::move(indices);
  return part;
}

// Each leaf a quad (as `boreas export-mesh` draws it), every corner with its leaf's weights.
// No normals: a quad is flat, its plane (across x axis, the winding below) is the leaf's
// normal, and glTF clients compute flat normals where a primitive has none (4 bytes a
// corner, 11 MB of the default scene's file).
SkinnedPart leaf_part(World& world, boreas_tree_id id, const SkinParams& p) {
  const std::vector<boreas_leaf> leaves = world.tree_leaves(id);
  const std::vector<boreas_skin_weight> weights =
      skin_leaf_weights(world.tree_branches(id), leaves, p);
  const Unplace unplace(world.tree(id).params);
  SkinnedPart part;
  for (size_t i = 0; i < leaves.size(); ++i) {
    const boreas_leaf& leaf = leaves[i];
    const float* a = leaf.axis;
    const float* n = leaf.normal;
    float across[3] = {a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2], a[0] * n[1] - a[1] * n[0]};
    const float len = std::sqrt(across[0] * across[0] + across[1] * across[1] + across[2] * across[2]);
    for (float& c : across) c /= len > 0 ? len : 1.0f;
    const uint32_t first = uint32_t(part.vertex_count());
    const float side[4] = {-0.5f, 0.5f, 0.5f, -0.5f}, along[4] = {0, 0, 1, 1};
    for (int c = 0; c < 4; ++c) {
      float world_corner[3], local[3];
      for (int k = 0; k < 3; ++k)
        world_corner[k] = leaf.position[k] + across[k] * side[c] * leaf.width + a[k] * along[c] * leaf.length;
      unplace.point(world_corner, local);
      part.positions.insert(part.positions.end(), local, local + 3);
      append_weight(&part, weights[i]);
    }
    part.indices.insert(part.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  return part;
}

gltf::JointPose pose_of(const boreas_joint& j) {
  gltf::JointPose p;
  for (int a = 0; a < 3; ++a) p.position[size_t(a)] = j.position[a];
  for (int a = 0; a < 4; ++a) p.rotation[size_t(a)] = j.rotation[a];
  return p;
}

std::vector<gltf::JointPose> poses(World& world, boreas_tree_id id, const SkinParams& p) {
  std::vector<gltf::JointPose> out;
  for (const boreas_joint& j : skin_joints(world.tree_branches(id), p)) out.push_back(pose_of(j));
  return out;
}

// The meadows and imported trees asked for (their ids are checked against the world in
// export_animation), the frames they allow and the tolerance.
void check_morph_fields(const boreas_animation_def& d, AnimationParams* p) {
  if (d.meadow_count < 0 || (d.meadow_count > 0 && !d.meadows))
    fail_argument("boreas_animation_def.meadows is NULL or meadow_count " +
                  std::to_string(d.meadow_count) + " is negative");
  if (d.mesh_tree_count < 0 || (d.mesh_tree_count > 0 && !d.mesh_trees))
    fail_argument("boreas_animation_def.mesh_trees is NULL or mesh_tree_count " +
                  std::to_string(d.mesh_tree_count) + " is negative");
  if (!(d.morph_tolerance >= 1e-4f) || !(d.morph_tolerance <= 1.0f))
    fail_argument("boreas_animation_def.morph_tolerance must be 1e-4..1 m (got " +
                  std::to_string(d.morph_tolerance) + ")");
  if ((d.meadow_count > 0 || d.mesh_tree_count > 0) && d.frames > BOREAS_ANIMATION_MAX_MORPH_FRAMES)
    fail_argument("boreas_animation_def.frames must be 1..BOREAS_ANIMATION_MAX_MORPH_FRAMES (" +
                  std::to_string(BOREAS_ANIMATION_MAX_MORPH_FRAMES) +
                  ") with meadows or mesh trees (got " + std::to_string(d.frames) + ")");
  if (d.meadow_clumps < 0 || d.meadow_clumps > BOREAS_ANIMATION_MAX_CLUMPS)
    fail_argument("boreas_animation_def.meadow_clumps must be 0..BOREAS_ANIMATION_MAX_CLUMPS (" +
                  std::to_string(BOREAS_ANIMATION_MAX_CLUMPS) + ") (got " + std::to_string(d.meadow_clumps) + ")");
  if (!(d.clump_size >= 0.1f) || !(d.clump_size <= 100.0f))
    fail_argument("boreas_animation_def.clump_size must be 0.1..100 m (got " + std::to_string(d.clump_size) + ")");
  p->meadow_clumps = d.meadow_clumps;
  p->clump_size = d.clump_size;
  if (d.meadow_count > 0) p->meadows.assign(d.meadows, d.meadows + d.meadow_count);
  if (d.mesh_tree_count > 0) p->mesh_trees.assign(d.mesh_trees, d.mesh_trees + d.mesh_tree_count);
  p->morph_tolerance = d.morph_tolerance;
}

}  // namespace

AnimationParams checked_animation_def(const boreas_animation_def* def) {
  const boreas_animation_def d = def ? *def : boreas_default_animation_def();
  if (d.frames < 1 || d.frames > BOREAS_ANIMATION_MAX_FRAMES)
    fail_argument("boreas_animation_def.frames must be 1..BOREAS_ANIMATION_MAX_FRAMES (" +
                  std::to_string(BOREAS_ANIMATION_MAX_FRAMES) + ") (got " +
                  std::to_string(d.frames) + ")");
  if (!(d.frame_time > 0.0f) || !(d.frame_time <= BOREAS_STEP_MAX_SECONDS))
    fail_argument("boreas_animation_def.frame_time must be in (0, BOREAS_STEP_MAX_SECONDS] s (got " +
                  std::to_string(d.frame_time) + ")");
  if (d.steps_per_frame < 1 || d.steps_per_frame > 1000)
    fail_argument("boreas_animation_def.steps_per_frame must be 1..1000 (got " +
                  std::to_string(d.steps_per_frame) + ")");
  if (!(d.warmup >= 0.0f) || !(d.warmup <= BOREAS_ANIMATION_MAX_WARMUP_SECONDS))
    fail_argument("boreas_animation_def.warmup must be 0..BOREAS_ANIMATION_MAX_WARMUP_SECONDS (" +
                  std::to_string(BOREAS_ANIMATION_MAX_WARMUP_SECONDS) + ") s (got " +
                  std::to_string(d.warmup) + ")");
  if (d.leaves != 0 && d.leaves != 1)
    fail_argument("boreas_animation_def.leaves must be 0 or 1 (got " + std::to_string(d.leaves) + ")");
  AnimationParams p;
  check_morph_fields(d, &p);
  p.frames = d.frames;
  p.frame_time = d.frame_time;
  p.steps_per_frame = d.steps_per_frame;
  // As many warm-up steps as an animation's keys may take at most.
  const double warmup_steps = std::round(double(d.warmup) / (double(d.frame_time) / d.steps_per_frame));
  if (warmup_steps > double(BOREAS_ANIMATION_MAX_FRAMES) * 1000.0)
    fail_argument("boreas_animation_def.warmup of " + std::to_string(d.warmup) + " s is " +
                  std::to_string(warmup_steps) + " steps of frame_time / steps_per_frame, past " +
                  std::to_string(BOREAS_ANIMATION_MAX_FRAMES * 1000));
  p.warmup_steps = int(warmup_steps);
  const SkinParams skin = checked_skin_def(&d.skin);
  p.skin.max_level = skin.max_level;
  p.skin.segments = skin.segments;
  p.leaves = d.leaves == 1;
  return p;
}

void export_animation(World& world, const AnimationParams& p, const std::vector<boreas_tree_id>& trees,
                      const std::string& path) {
  if (path.empty()) fail_argument("path is empty");
  for (size_t i = 0; i < trees.size(); ++i) {
    try {
      world.tree(trees[i]);
    } catch (const Error& e) {
      fail(e.status(), "trees[" + std::to_string(i) + "]: " + e.what());
    }
  }
  const SkinParams skin{p.skin.max_level, p.skin.segments};
  gltf::ForestAnimation a;
  a.generator = std::string("boreas ") + boreas_version();
  a.frame_time = p.frame_time;
  a.morph_tolerance = p.morph_tolerance;
  MorphGather morphs(world, p.meadows, p.mesh_trees, {p.meadow_clumps, p.clump_size, p.frames},
                     &a);  // checks their ids first
  std::map<int, int> template_index;  // the world's template number -> the file's mesh
  for (size_t i = 0; i < trees.size(); ++i) {
    const boreas_tree_id id = trees[i];
    const TreeParams& params = world.tree(id).params;
    const int number = world.tree_template(id);
    auto [it, added] = template_index.emplace(number, int(a.templates.size()));
    if (added) {
      gltf::TreeTemplate t;
      t.name = "template" + std::to_string(number);
      t.bark = bark_part(world, id, skin);
      if (p.leaves) t.leaves = leaf_part(world, id, skin);
      a.templates.push_back(std::move(t));
    }
    gltf::AnimatedTree t;
    t.name = "tree" + std::to_string(i);
    t.template_index = it->second;
    t.position = {params.position[0], params.position[1], params.position[2]};
    t.rotation = params.rotation;
    t.scale = params.scale;
    for (const boreas_joint& j : skin_joints(world.tree_branches(id), skin))
      t.joint_parents.push_back(j.parent);
    t.bind = poses(world, id, skin);
    a.trees.push_back(std::move(t));
  }
  const float dt = float(p.frame_time / p.steps_per_frame);
  for (int s = 0; s < p.warmup_steps; ++s) world.step(dt);
  for (int f = 0; f < p.frames; ++f) {
    if (f > 0)
      for (int s = 0; s < p.steps_per_frame; ++s) world.step(dt);
    for (size_t i = 0; i < trees.size(); ++i) a.trees[i].frames.push_back(poses(world, trees[i], skin));
    morphs.key();
  }
  for (int f = 0; f < morphs.loop_search_keys(p.frames); ++f) {
    for (int s = 0; s < p.steps_per_frame; ++s) world.step(dt);
    morphs.search_key();
  }
  morphs.finish(p.frames);
  // Written straight to the file: no copy of its bytes in memory (the meadows' targets
  // make files of hundreds of MB); a file that could not be finished is removed.
  std::ofstream out(path, std::ios::binary);
  if (!out) fail(BOREAS_ERROR_IO, "cannot write " + path);
  std::string error;
  const bool built = gltf::write_animation_glb(std::move(a), out, &error);
  out.close();
  if (built && out) return;
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  if (!out) fail(BOREAS_ERROR_IO, "cannot write " + path);
  fail(BOREAS_ERROR_INTERNAL, error);
}

}  // namespace boreas::impl
