// boreas tests and benchmarks: Embree 3, the reference ray tracer, on a boreas world's
// current triangles, read through the public getters (or handed over as a flat labelled
// list), so that boreas_world_cast_rays can be checked hit for hit and timed against it.
// Embree lives here, in tests and bench only; the library never links it.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "boreas/boreas.h"
#include "shared/leaf_outline.h"

namespace boreas::reference {

// How the scene follows a step: both re-read the vertices through the getters into the
// geometries' buffers (rtcUpdateGeometryBuffer); then
//   kRefit:   a two-level scene (RTC_BUILD_QUALITY_LOW, RTC_SCENE_FLAG_DYNAMIC) whose
//             geometries refit their own BVH (RTC_BUILD_QUALITY_REFIT), topology kept;
//   kRebuild: a one-level scene of RTC_BUILD_QUALITY_MEDIUM rebuilt whole on commit.
enum class EmbreeUpdate { kRefit, kRebuild };

struct EmbreeOptions {
  EmbreeUpdate update = EmbreeUpdate::kRebuild;
  // RTC_SCENE_FLAG_ROBUST: watertight traversal, no accuracy-reducing shortcuts (rays
  // through the shared edge of two triangles hit one of them). On for the agreement test;
  // the benchmark's anchor may turn it off to time Embree at its fastest.
  bool robust = true;
  // Threads of cast() (OpenMP); 0: OpenMP's default. Embree's builds use its own TBB pool.
  int cast_threads = 0;
  // Bytes Embree may hold (its memory monitor refuses more; the build then fails with a
  // clear error instead of exhausting the machine); 0: no limit.
  int64_t memory_limit = 0;
};

// The leaf outline: whether a point of leaf `leaf`'s quad at (u, v) (the renderer's
// texture coordinates, u across 0..1, v from base to tip 0..1) lies on the blade.
using LeafOutline = std::function<bool(int32_t leaf, float u, float v)>;

// The renderer's leaf quad (render/shaders/leaf.vert): the blade from v = kLeafBaseV to
// kLeafTipV along the axis, kLeafHalfWidth at its widest either side of u = 0.5
// (cl/shared/leaf_outline.h, which the renderer's textures read too).
constexpr float kLeafBaseV = BOREAS_LEAF_BLADE_BASE_V;
constexpr float kLeafTipV = BOREAS_LEAF_BLADE_TIP_V;
constexpr float kLeafHalfWidth = BOREAS_LEAF_BLADE_HALF_WIDTH;

// The corner (u, v) in {0, 1}^2 of a leaf's quad, world space (3 floats into out).
void leaf_quad_corner(const boreas_leaf& leaf, float u, float v, float out[3]);

// What an Embree hit becomes, and why a hit is where it is: for the agreement test's
// report (which triangle, where on it) beside the boreas_hit.
struct EmbreeHit {
  boreas_hit hit;
  int32_t geometry = -1;  // EmbreeWorld's geometry index; -1 on a miss
  int32_t triangle = -1;  // within it
  float barycentric[3] = {0, 0, 0};
  float leaf_uv[2] = {0, 0};  // BOREAS_HIT_LEAF: where on the leaf's quad
  float cos_incidence = 0.0f;  // |cos| between the ray and the triangle's normal
  float edge_distance = 0.0f;  // m from the hit point to the triangle's nearest edge
};

class EmbreeWorld {
 public:
  explicit EmbreeWorld(const EmbreeOptions& options = {});
  ~EmbreeWorld();
  EmbreeWorld(const EmbreeWorld&) = delete;
  EmbreeWorld& operator=(const EmbreeWorld&) = delete;

  // A generated tree as of its world's last step: its branches (boreas_tree_get_mesh;
  // part: the branch) and its leaves (boreas_tree_get_leaves as the renderer's quads;
  // part: the leaf), two geometries. `levels` are the rings and sides the tree was added
  // with (its def's levels; NULL: boreas_default_tree_def()'s): the public API does not
  // give them back, and they map a triangle to its branch. Throws when the mesh's counts
  // do not match them. `outline`: the leaves' outline kind (cl/shared/leaf_outline.h: the
  // renderer's alpha test, applied by an intersection filter); -1: whole quads.
  void add_tree(boreas_world world, boreas_tree_id tree,
                const boreas_tree_level_def* levels = nullptr, int outline = -1);
  // A meadow's components at full detail (boreas_meadow_get_vertices, camera NULL), strip
  // k's triangle (v_k, v_k+1, v_k+2); part: the component.
  void add_meadow(boreas_world world, boreas_meadow_id meadow);
  // An imported tree's trunk and leaf parts (two geometries; part: the triangle).
  void add_mesh_tree(boreas_world world, boreas_mesh_tree_id tree);
  // A BlobTree's mesh (part: the triangle). It does not move: update() keeps it.
  void add_blobtree(boreas_world world, boreas_blobtree_id blobtree);
  // Triangles handed over as they are: 3 floats per vertex, 3 indices per triangle, one
  // part per triangle (empty: the triangle's index). They do not move unless replaced by
  // set_triangles. Returns the geometry's index.
  int add_triangles(boreas_hit_kind kind, boreas_object_id object, std::vector<float> positions,
                    std::vector<uint32_t> indices, std::vector<int32_t> parts = {});
  // New vertices (same count) for a geometry add_triangles made; the next commit takes them.
  void set_triangles(int geometry, const std::vector<float>& positions);

  // Leaves' hits are kept only where outline says the blade is (NULL: each tree's outline
  // kind given to add_tree); the next commit takes it.
  void set_leaf_outline(LeafOutline outline);

  // Re-reads every geometry from its world (as of its last step) into its buffers.
  void read(boreas_world world);
  // Builds (the first time) or updates the scene from the buffers (EmbreeOptions::update).
  void commit();
  // read() then commit(): what a step costs Embree's side.
  void update(boreas_world world) {
    read(world);
    commit();
  }

  // The nearest hit of each ray, as boreas_world_cast_rays reports it (the direction
  // normalized, tnear 0, tfar max_distance). Needs a commit after the last change.
  void cast(const boreas_ray* rays, int count, boreas_hit* hits) const;
  // One ray with what the agreement test reports of it.
  EmbreeHit cast_one(const boreas_ray& ray) const;

  int64_t triangle_count() const;
  int geometry_count() const;
  // Bytes Embree holds now (its memory monitor): BVHs, builders' temporaries, its copies.
  int64_t embree_bytes() const;

  struct Geometry;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace boreas::reference
