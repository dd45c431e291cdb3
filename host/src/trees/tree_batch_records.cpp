// boreas: what a tree batch's kernels make from one tree's current state: its branch records
// (export_records.cl) and leaf records (tree_leaves.cl) into a caller's buffer, and its
// deformed mesh (tree_deform.cl; the indices built on the host). Each is one launch of the
// kernel that makes a whole view's records (tree_batch_view.cpp), over this tree's tiles
// alone: one code path, so one tree's records are the view's bits.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "runtime/launch.h"
#include "shared/tree_types.h"
#include "trees/tree_batch.h"
#include "trees/tree_record_tiles.h"

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

void TreeBatch::launch_branch_records(int32_t tile_first, int32_t tiles, bool one_tree,
                                      const cl::Buffer& out, size_t out_first) {
  if (tiles == 0) return;
  cl::Kernel& k =
      runtime_.kernel("export_records.cl", "boreas_export_branch_records", plane_defines());
  // The out table is not read for one tree (any buffer binds the argument).
  const cl::Buffer& table = one_tree ? record_tiles_.buffer(kRecordBranchList) : table_buffer_;
  launch(runtime_, k, Items(size_t(tiles) * runtime_.group_size()), state_[current_],
         motion_[current_], int(entries_.capacity), shape_, radius_, int(static_entries_.capacity),
         settled_buffer(), settled_stride(), posed_buffer(), posed_stride(),
         record_tiles_.buffer(kRecordBranchList), int(tile_first), table, int(one_tree), out,
         static_cast<int>(out_first), offsets_);
}

void TreeBatch::launch_leaf_records(int32_t tile_first, int32_t tiles, bool one_tree,
                                    const cl::Buffer& out, int64_t out_first) {
  launch_leaf_tiles(record_tiles_.buffer(kRecordLeafList), tile_first, tiles, one_tree, out, out_first);
}

void TreeBatch::launch_leaf_tiles(const cl::Buffer& list, int32_t tile_first, int32_t tiles, bool one_tree,
                                  const cl::Buffer& out, int64_t out_first) {
  if (tiles == 0) return;
  cl::Kernel& k = runtime_.kernel("tree_leaves.cl", "boreas_tree_leaves", plane_defines());
  const cl::Buffer& table = one_tree ? list : table_buffer_;
  // A group's work-items per tile, step_width() leaves each (tree_leaves.cl; the tiles
  // hold that many, record_tree): counted in work-items, since the launch table's groups
  // are of the group size.
  launch(runtime_, k, Items(size_t(tiles) * runtime_.group_size()),
         state_[current_], motion_[current_], int(entries_.capacity), shape_,
         int(static_entries_.capacity), settled_buffer(), settled_stride(), posed_buffer(),
         posed_stride(), leaves_,
         int(static_leaves_.capacity), list, int(tile_first),
         table, int(one_tree), out, static_cast<int>(out_first), offsets_);
}

const TileLists::Segment& TreeBatch::prepare_leaves(const Slot& slot) {
  // Its derived branches posed once each (cl/tree_derive.cl), for the leaves' many reads.
  pose_derived(slot.derive_tiles.first, slot.derive_tiles.count, false);
  refresh_records();  // may lay the tiles anew: read the segment after it
  return slot.record_tiles[kRecordLeafList];
}

void TreeBatch::enqueue_leaves(const Slot& slot, const cl::Buffer& out, int64_t first_record) {
  if (slot.leaf_count == 0) return;
  const TileLists::Segment& s = prepare_leaves(slot);
  pose_settled(&slot);
  launch_leaf_records(s.first, s.count, true, out, first_record);
  unpose_settled();
}

void TreeBatch::enqueue_branch_records(uint64_t key, const cl::Buffer& out, size_t first_record,
                                       const Origin& output_origin) {
  const Slot& slot = slot_of(key);
  if (slot.count <= 1) return;
  reader_offsets(&output_origin, &slot);
  refresh_records();  // may lay the tiles anew: read the segment after it
  const TileLists::Segment& s = slot.record_tiles[kRecordBranchList];
  launch_branch_records(s.first, s.count, true, out, first_record);
}

void TreeBatch::enqueue_leaf_records(uint64_t key, const cl::Buffer& out, size_t first_record,
                                     const Origin& output_origin) {
  const Slot& slot = slot_of(key);
  reader_offsets(&output_origin, &slot);
  enqueue_leaves(slot, out, int64_t(first_record));
}

// Tiles of the tree's own (its first tile's shared words, the item and static entry moved
// alike), each as wide as the tree's own at most: a tile starts at a run and takes in the
// runs after it while they fit and lie within a work-item's leaves of it (a work-item past
// a short tile's count returns at once: cl/tree_leaves.cl). A leaf's lanes are its own
// (the kernel gathers and computes lane by lane), so its bits do not depend on its tile.
void TreeBatch::enqueue_leaf_runs(uint64_t key, const cl::Buffer& out, size_t first_record,
                                  const std::vector<int32_t>& runs, const Origin& output_origin) {
  const Slot& slot = slot_of(key);
  if (slot.leaf_count == 0 || runs.empty()) return;
  reader_offsets(&output_origin, &slot);
  const TileLists::Segment& seg = prepare_leaves(slot);
  if (seg.count == 0) return;
  const int32_t* own = &record_tiles_.list(kRecordLeafList)[size_t(seg.first) * BOREAS_TILE_INTS];
  const int32_t width = int32_t(runtime_.group_size()) * step_width(), gap = step_width();
  std::vector<int32_t> tiles;
  auto tile = [&](int32_t first, int32_t count) {
    const size_t t = tiles.size();
    tiles.insert(tiles.end(), own, own + BOREAS_TILE_INTS);
    tiles[t + BOREAS_TILE_FIRST] = own[BOREAS_TILE_FIRST] + first;
    tiles[t + BOREAS_TILE_STATIC] = own[BOREAS_TILE_STATIC] + first;
    tiles[t + BOREAS_TILE_COUNT] = count;
  };
  int32_t start = -1, end = -1;  // the open tile's leaves
  for (size_t r = 0; r + 1 < runs.size(); r += 2) {
    const int32_t first = runs[r], last = runs[r] + runs[r + 1];
    if (start >= 0 && first - end <= gap && last - start <= width) {
      end = last;
      continue;
    }
    if (start >= 0) tile(start, end - start);
    for (start = first; last - start > width; start += width) tile(start, width);
    end = last;
  }
  if (start >= 0) tile(start, end - start);
  cl::Buffer list = runtime_.buffer(CL_MEM_READ_ONLY, tiles.size() * sizeof(int32_t), "tree leaf run tiles");
  runtime_.write(list, 0, tiles.size() * sizeof(int32_t), tiles.data());
  pose_settled(&slot);
  launch_leaf_tiles(list, 0, int32_t(tiles.size() / BOREAS_TILE_INTS), true, out, int64_t(first_record));
  unpose_settled();
}

void TreeBatch::mesh(uint64_t key, std::vector<boreas_vertex>* vertices,
                     std::vector<uint32_t>* indices, const Origin& output_origin) {
  const Slot& s = slot_of(key);
  const TreeModel& m = *s.tree->model;
  const TreeParams& params = s.tree->params;
  // The tree's levels as ranges of one launch into one output.
  int total = 0;
  const LevelVertices first_vertex = level_first_vertex(m, params, &total);
  vertices->assign(size_t(total), boreas_vertex{});
  indices->clear();
  if (total == 0) return;
  std::vector<DeformRange> ranges;
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    DeformRange r;
    r.count = m.level_begin[size_t(l) + 1] - m.level_begin[size_t(l)];
    if (r.count == 0) continue;
    const int offset = block_index(m.level_begin[size_t(l)]);
    r.first = (offset < settled_begin(s) ? s.first : settled_root(s)) + offset;
    r.static_first = template_of(s).first + offset;
    r.rings = params.levels[size_t(l)].rings;
    r.sides = params.levels[size_t(l)].sides;
    r.scale = float(params.scale);
    r.out_first = first_vertex[size_t(l)];
    ranges.push_back(r);
  }
  // Its derived branches posed once each (cl/tree_derive.cl), for the vertices' many reads.
  pose_derived(s.derive_tiles.first, s.derive_tiles.count, false);
  pose_settled(&s);
  const std::vector<int32_t> tiles = deform_tiles(ranges, int(runtime_.group_size()));
  cl::Buffer tile_buffer =
      runtime_.buffer(CL_MEM_READ_ONLY, tiles.size() * sizeof(int32_t), "tree mesh tiles");
  runtime_.write(tile_buffer, 0, tiles.size() * sizeof(int32_t), tiles.data());
  cl::Buffer out = runtime_.buffer(
      CL_MEM_WRITE_ONLY, size_t(BOREAS_TREE_VERTEX_PLANES) * total * sizeof(float), "tree mesh");
  cl::Kernel& k = runtime_.kernel("tree_deform.cl", "boreas_tree_deform", plane_defines());
  // step_width() vertices per work-item (tree_deform.cl).
  const size_t tile_count = tiles.size() / BOREAS_TILE_INTS;
  launch(runtime_, k, Items(tile_count * runtime_.group_size()).per_work_item(size_t(step_width())),
         state_[current_], motion_[current_], int(entries_.capacity), shape_, radius_,
         int(static_entries_.capacity), settled_buffer(), settled_stride(), posed_buffer(),
         posed_stride(), tile_buffer, 0, out, total, 0);
  unpose_settled();
  std::vector<float> planes(size_t(BOREAS_TREE_VERTEX_PLANES) * total);
  runtime_.read(out, 0, planes.size() * sizeof(float), planes.data());
  unpack_vertices(planes, total, vertices);
  // The deformer's positions are relative to the base (cl/shared/tree_origin.h): the
  // offset added as the record kernels add it.
  const std::array<float, 3> offset = offset_of(s, output_origin);
  for (boreas_vertex& v : *vertices)
    for (size_t a = 0; a < 3; ++a) v.position[a] += offset[a];
  append_mesh_indices(m, params, first_vertex, indices);
}

}  // namespace boreas::impl
