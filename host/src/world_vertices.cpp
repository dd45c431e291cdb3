// boreas: meadows' strips and imported trees' vertices written into a caller's buffers, any
// list of them in one launch (boreas_world_enqueue_meadow_vertices,
// boreas_world_enqueue_mesh_tree_vertices, boreas_cl.h); the single-object calls are lists
// of one. Every entry is checked, its range against the buffer and the ranges against each
// other (overlapping writes would race), before anything is enqueued.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "runtime/caller_buffers.h"
#include "validation.h"
#include "world.h"

namespace boreas::impl {

namespace {

// The list's count and arrays: count >= 0, the arrays not NULL where it is positive.
void check_list(const void* ids, const size_t* firsts, int count, const char* ids_name,
                const char* firsts_name) {
  if (count < 0) fail_argument("count must be >= 0 (got " + std::to_string(count) + ")");
  if (count > 0 && ids == nullptr)
    fail_argument(std::string(ids_name) + " is NULL with count " + std::to_string(count));
  if (count > 0 && firsts == nullptr)
    fail_argument(std::string(firsts_name) + " is NULL with count " + std::to_string(count));
}

// Runs an entry's check; where the list's entries are named, a failure says which.
template <typename Check>
void check_entry(bool named, const char* list, int k, Check&& check) {
  try {
    check();
  } catch (const Error& e) {
    if (!named) throw;
    fail(e.status(), std::string(list) + "[" + std::to_string(k) + "]: " + e.what());
  }
}

}  // namespace

void World::enqueue_meadow_vertices(const boreas_meadow_id* ids, const size_t* firsts, int count,
                                    const float* camera, const cl::Buffer& vertices,
                                    const cl::Buffer& counts, bool named) {
  check_list(ids, firsts, count, "meadows", "first_components");
  if (camera) check_position(camera, "camera");
  // The draws of each meadow chunk that holds a listed meadow (world_chunks.cpp): one
  // launch a chunk, a world that fits one allocation has one.
  std::vector<std::pair<UnderbrushBatch*, std::vector<UnderbrushBatch::VertexDraw>>> chunks;
  std::vector<CallerRange> ranges;
  for (int k = 0; k < count; ++k) {
    check_entry(named, "meadows", k, [&] {
      const MeadowInstance& m = *meadows_.get(ids[k]);
      UnderbrushBatch* chunk = &meadow_batch(m);
      const size_t n = size_t(m.meadow.count);
      check_buffer_holds(vertices, firsts[k], n,
                         BOREAS_MEADOW_VERTEX_STRIDE * sizeof(boreas_meadow_vertex),
                         "meadow vertex");
      check_buffer_holds(counts, firsts[k], n, sizeof(int32_t), "strip count");
      auto it = std::find_if(chunks.begin(), chunks.end(),
                             [&](const auto& c) { return c.first == chunk; });
      if (it == chunks.end()) it = chunks.insert(chunks.end(), {chunk, {}});
      it->second.push_back({m.key, firsts[k]});
      ranges.push_back({firsts[k], n});
    });
  }
  check_disjoint(ranges, "meadows");
  for (const auto& [chunk, draws] : chunks)
    chunk->enqueue_vertices(draws, camera, vertices, counts, output_origin_);
}

void World::enqueue_mesh_tree_vertices(const boreas_mesh_tree_id* ids, const size_t* firsts,
                                       int count, const boreas_mesh_part& part,
                                       const cl::Buffer& out, bool named) {
  check_list(ids, firsts, count, "trees", "first_vertices");
  check_mesh_part(part);
  const bool trunk = part == BOREAS_MESH_TRUNK;
  std::vector<MeshTreeBatch::CopyTo> copies;
  std::vector<CallerRange> ranges;
  for (int k = 0; k < count; ++k) {
    check_entry(named, "trees", k, [&] {
      const MeshTreeInstance& tree = *mesh_trees_.get(ids[k]);
      const size_t n = trunk ? tree.model.trunk.vertex_count() : tree.model.leaves.vertex_count();
      if (trunk)
        check_buffer_holds(out, firsts[k], n, BOREAS_MESH_TRUNK_VERTEX_FLOATS * sizeof(float),
                           "mesh trunk vertex");
      else
        check_buffer_holds(out, firsts[k], n, BOREAS_MESH_LEAF_VERTEX_FLOATS * sizeof(float),
                           "mesh leaf vertex");
      copies.push_back({tree.key, firsts[k]});
      ranges.push_back({firsts[k], n});
    });
  }
  check_disjoint(ranges, "trees");
  mesh_batch_->enqueue_copy(copies, part, out, output_origin_);
}

}  // namespace boreas::impl
