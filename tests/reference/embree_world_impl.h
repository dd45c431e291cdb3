// boreas tests and benchmarks: the inside of EmbreeWorld (embree_world.h), shared by its
// files: the scene and its labels (embree_world.cpp), reading a world through the public
// getters (embree_read.cpp) and casting (embree_cast.cpp).
#pragma once

#include <embree3/rtcore.h>

#include <array>
#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "embree_world.h"

namespace boreas::reference {

// Where a geometry's triangles come from, so read() knows which getter to ask.
enum class Source { kTreeBranches, kTreeLeaves, kMeadow, kMeshTrunk, kMeshLeaves, kFixed };

inline void check(boreas_status status, const char* call) {
  if (status != BOREAS_OK)
    throw std::runtime_error(std::string("EmbreeWorld: ") + call + ": " + boreas_last_error());
}

template <typename Id>
boreas_object_id object_of(Id id) {
  return boreas_object_id{id.index, id.generation, id.tag};
}

// Where on a leaf's quad triangle `triangle` (even: corners (0,0), (1,0), (0,1); odd:
// (1,0), (1,1), (0,1), as read_leaves lays them out) Embree's barycentrics (b1, b2) of its
// second and third vertex fall, as the quad's (u, v).
inline void leaf_uv(uint32_t triangle, float b1, float b2, float* u, float* v) {
  if ((triangle & 1u) == 0) {
    *u = b1;
    *v = b2;
  } else {
    *u = 1.0f - b2;
    *v = b1 + b2;
  }
}

// One Embree geometry: one part of one object, with its own copy of the vertices.
struct EmbreeWorld::Geometry {
  boreas_hit_kind kind = BOREAS_HIT_NONE;
  boreas_object_id object{0, 0, 0};
  Source source = Source::kFixed;
  std::array<boreas_tree_level_def, 4> levels{};  // kTreeBranches: rings and sides
  boreas_blobtree_id blobtree{0, 0, 0};           // BlobTrees: read once, never moved
  std::vector<float> positions;  // 3 floats a vertex, then one of padding (Embree's loads)
  std::vector<uint32_t> indices;
  std::vector<int32_t> parts;    // per triangle; empty: the triangle's index (leaves: / 2)
  RTCGeometry handle = nullptr;
  // What Embree was last given (shared anew only when these change).
  const float* shared_positions = nullptr;
  const uint32_t* shared_indices = nullptr;
  size_t shared_vertex_count = 0, shared_triangle_count = 0;
  bool changed = true;                   // to be committed
  const LeafOutline* outline = nullptr;  // kTreeLeaves: the world's
  int outline_kind = -1;                 // kTreeLeaves: the tree's outline (-1: none)

  size_t vertex_count() const { return positions.empty() ? 0 : (positions.size() - 1) / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
  int32_t part(uint32_t triangle) const {
    if (!parts.empty()) return parts[triangle];
    return source == Source::kTreeLeaves ? int32_t(triangle / 2) : int32_t(triangle);
  }
};

// Embree's allocations, counted (and refused past a limit) by its memory monitor.
struct MemoryMonitor {
  std::atomic<int64_t> bytes{0};
  int64_t limit = 0;  // 0: none
};

struct EmbreeWorld::Impl {
  EmbreeOptions options;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<Geometry>> geometries;
  LeafOutline outline;
  std::string error;  // Embree's last message, from its error callback
  MemoryMonitor memory;
  bool committed = false;
  // The getters' scratch, kept across reads.
  std::vector<boreas_vertex> vertices;
  std::vector<uint32_t> scratch_indices;
  std::vector<boreas_branch> branches;
  std::vector<boreas_meadow_vertex> meadow_vertices;
  std::vector<int32_t> strip_counts;
  std::vector<boreas_leaf> leaves;

  void throw_if_failed(const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e == RTC_ERROR_NONE) return;
    throw std::runtime_error(std::string("EmbreeWorld: ") + what + " failed: " +
                             (error.empty() ? "Embree error " + std::to_string(int(e)) : error));
  }
  Geometry& add(Source source, boreas_hit_kind kind, boreas_object_id object);
  void share(Geometry& g);
  // embree_read.cpp: the geometry's current triangles from its world, then share().
  void read(boreas_world world, Geometry& g);
  void read_branches(boreas_world world, Geometry& g);
  void read_leaves(boreas_world world, Geometry& g);
  void read_meadow(boreas_world world, Geometry& g);
  void read_mesh_part(boreas_world world, Geometry& g, boreas_mesh_part part);
  void read_blobtree(boreas_world world, Geometry& g);
};

}  // namespace boreas::reference
