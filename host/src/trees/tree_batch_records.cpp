// boreas: what a tree batch's kernels make from one tree's current state: its branch records
// (export_records.cl) and leaf records (tree_leaves.cl) into a caller's buffer, and its
// deformed mesh (tree_deform.cl, one launch per level; the indices built on the host).
#include <array>
#include <cstdint>
#include <vector>

#include "runtime/launch.h"
#include "shared/tree_types.h"
#include "trees/tree_batch.h"

namespace boreas::impl {

namespace {

// Where each level's vertices start in a tree's mesh, rings + 1 by sides + 1 per branch.
using LevelVertices = std::array<int, kMaxTreeLevels>;

LevelVertices level_first_vertex(const TreeModel& m, const TreeParams& params, int* total) {
  LevelVertices first_vertex{};
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    const TreeLevelParams& lp = params.levels[size_t(l)];
    first_vertex[size_t(l)] = *total;
    *total +=
        (m.level_begin[size_t(l) + 1] - m.level_begin[size_t(l)]) * (lp.rings + 1) * (lp.sides + 1);
  }
  return first_vertex;
}

// The vertices from tree_deform.cl's planes (stride total).
void unpack_vertices(const std::vector<float>& planes, int total,
                     std::vector<boreas_vertex>* vertices) {
  for (int v = 0; v < total; ++v) {
    boreas_vertex& o = (*vertices)[size_t(v)];
    for (int a = 0; a < 3; ++a) {
      o.position[a] = planes[size_t(BOREAS_TREE_VERTEX_POSITION + a) * total + v];
      o.normal[a] = planes[size_t(BOREAS_TREE_VERTEX_NORMAL + a) * total + v];
    }
    o.uv[0] = planes[size_t(BOREAS_TREE_VERTEX_UV) * total + v];
    o.uv[1] = planes[size_t(BOREAS_TREE_VERTEX_UV + 1) * total + v];
  }
}

// Two triangles per quad, counter-clockwise seen from outside (the normal is
// X_theta x X_v, so (side+1, ring+1) turns counter-clockwise from (side, ring)).
void append_mesh_indices(const TreeModel& m, const TreeParams& params,
                         const LevelVertices& first_vertex, std::vector<uint32_t>* indices) {
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    const TreeLevelParams& lp = params.levels[size_t(l)];
    int count = m.level_begin[size_t(l) + 1] - m.level_begin[size_t(l)];
    int row = lp.sides + 1;
    for (int b = 0; b < count; ++b) {
      uint32_t base = uint32_t(first_vertex[size_t(l)] + b * (lp.rings + 1) * row);
      for (int r = 0; r < lp.rings; ++r)
        for (int sd = 0; sd < lp.sides; ++sd) {
          uint32_t i0 = base + uint32_t(r * row + sd), i1 = i0 + 1, i2 = i0 + uint32_t(row),
                   i3 = i2 + 1;
          indices->insert(indices->end(), {i0, i1, i2, i1, i3, i2});
        }
    }
  }
}

}  // namespace

void TreeBatch::enqueue_leaves(const Slot& slot, const cl::Buffer& out, size_t first_record) {
  if (slot.leaf_count == 0) return;
  const Template& tp = template_of(slot);
  cl::Kernel& k = runtime_.kernel("tree_leaves.cl", "boreas_tree_leaves", plane_defines());
  // step_width() leaves per work-item (tree_leaves.cl).
  launch(runtime_, k, Items(size_t(slot.leaf_count)).per_work_item(size_t(step_width())),
         state_[current_], int(entries_.capacity), leaf_parents_, leaf_shape_,
         int(static_leaves_.capacity), int(tp.leaf_first), slot.leaf_count, slot.first,
         float(slot.tree->params.scale), out, static_cast<int>(first_record));
}

void TreeBatch::enqueue_branch_records(uint64_t key, const cl::Buffer& out, size_t first_record) {
  const Slot& s = slot_of(key);
  const int count = s.count - 1;
  if (count <= 0) return;
  // A tree's branches are one contiguous range, in its model's order: one launch.
  cl::Kernel& k =
      runtime_.kernel("export_records.cl", "boreas_export_branch_records", plane_defines());
  launch(runtime_, k, Items(size_t(count)), state_[current_], motion_[current_],
         int(entries_.capacity), radius_,
         int(static_entries_.capacity), s.first + 1, template_of(s).first + 1, count,
         float(s.tree->params.scale), out, static_cast<int>(first_record));
}

void TreeBatch::enqueue_leaf_records(uint64_t key, const cl::Buffer& out, size_t first_record) {
  enqueue_leaves(slot_of(key), out, first_record);
}

void TreeBatch::mesh(uint64_t key, std::vector<boreas_vertex>* vertices,
                     std::vector<uint32_t>* indices) {
  const Slot& s = slot_of(key);
  const TreeModel& m = *s.tree->model;
  const TreeParams& params = s.tree->params;
  // Vertices per level, then one launch per level into one output.
  int total = 0;
  const LevelVertices first_vertex = level_first_vertex(m, params, &total);
  vertices->assign(size_t(total), boreas_vertex{});
  indices->clear();
  if (total == 0) return;
  cl::Buffer out = runtime_.buffer(
      CL_MEM_WRITE_ONLY, size_t(BOREAS_TREE_VERTEX_PLANES) * total * sizeof(float), "tree mesh");
  cl::Kernel& k = runtime_.kernel("tree_deform.cl", "boreas_tree_deform", plane_defines());
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    int count = m.level_begin[size_t(l) + 1] - m.level_begin[size_t(l)];
    if (count == 0) continue;
    const TreeLevelParams& lp = params.levels[size_t(l)];
    const int offset = block_index(m.level_begin[size_t(l)]);
    // step_width() vertices per work-item (tree_deform.cl).
    const size_t vertices = size_t(count) * (lp.rings + 1) * (lp.sides + 1);
    launch(runtime_, k, Items(vertices).per_work_item(size_t(step_width())), state_[current_],
           int(entries_.capacity), radius_, int(static_entries_.capacity), s.first + offset,
           template_of(s).first + offset, count, float(params.scale), lp.rings, lp.sides, out,
           total, first_vertex[size_t(l)]);
  }
  std::vector<float> planes(size_t(BOREAS_TREE_VERTEX_PLANES) * total);
  runtime_.read(out, 0, planes.size() * sizeof(float), planes.data());
  unpack_vertices(planes, total, vertices);
  append_mesh_indices(m, params, first_vertex, indices);
}

}  // namespace boreas::impl
