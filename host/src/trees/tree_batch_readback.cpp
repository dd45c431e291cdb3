// boreas: a tree batch's blocking readbacks — state and motion planes, one tree's branches
// and the leaves made from them now.
#include <algorithm>
#include <string>

#include "errors.h"
#include "shared/leaf_pack.h"
#include "shared/tree_types.h"
#include "trees/tree_tiles.h"
#include "trees/tree_batch.h"

namespace boreas::impl {

std::vector<float> TreeBatch::read_state_prefix(int64_t count) {
  const size_t n = size_t(std::min(count, entries_.capacity));
  std::vector<float> out(size_t(BOREAS_TREE_STATE_PLANES) * n);
  runtime_.read_planes(state_[current_], size_t(entries_.capacity), 0, out.data(), n, n,
                       BOREAS_TREE_STATE_PLANES);
  return out;
}

std::vector<float> TreeBatch::read_tree_planes(const cl::Buffer& buffer, uint64_t key, int planes) {
  // A settled tree's own entries (the rest zero: read_tree_state and read_tree_motion
  // fill them).
  const Slot& s = slot_of(key);
  std::vector<float> out(size_t(planes) * size_t(s.count));
  runtime_.read_planes(buffer, size_t(entries_.capacity), size_t(s.first), out.data(),
                       size_t(s.count), size_t(own_count(s)), size_t(planes));
  return out;
}

std::vector<float> TreeBatch::read_tree_state(uint64_t key) {
  std::vector<float> state = read_tree_planes(state_[current_], key, BOREAS_TREE_STATE_PLANES);
  const Slot& s = slot_of(key);
  if (!s.derived) return state;
  // Its derived branches' poses as the device derives them (export_records.cl reads every
  // pose through boreas_tree_pose), over their marks.
  const TreeModel& m = *s.tree->model;
  const int32_t begin = m.level_begin[size_t(derivable_level(m, s.lod))];
  const size_t n = size_t(s.count), records = size_t(m.branch_count());
  std::vector<float> made(records * BOREAS_TREE_RECORD_FLOATS);
  cl::Buffer out = runtime_.buffer(CL_MEM_WRITE_ONLY, made.size() * sizeof(float), "tree poses");
  // In the state's own coordinates, relative to the base: zero offsets.
  reader_offsets(nullptr, &s);
  refresh_records();  // may lay the tiles anew: read the segment after it
  const TileLists::Segment& seg = s.record_tiles[kRecordBranchList];
  launch_branch_records(seg.first, seg.count, true, out, 0);
  runtime_.read(out, 0, made.size() * sizeof(float), made.data());
  for (size_t b = size_t(begin); b < records; ++b)
    for (int p = 0; p < BOREAS_TREE_STATE_PLANES; ++p)
      state[size_t(p) * n + size_t(block_index(int32_t(b)))] = made[b * BOREAS_TREE_RECORD_FLOATS + size_t(p)];
  return state;
}

std::vector<float> TreeBatch::read_tree_motion(uint64_t key) {
  // Every plane: a batch without dF/dt planes (holds_rates) reads its zeros as such.
  std::vector<float> motion = read_tree_planes(motion_[current_], key, motion_planes_);
  const Slot& s = slot_of(key);
  const size_t n = size_t(s.count), own = size_t(own_count(s)), c = size_t(settled_entries_.capacity);
  motion.resize(size_t(BOREAS_TREE_MOTION_PLANES) * n, 0.0f);
  if (own == n) return motion;
  // Settled: F and the broken flag (and dF/dt) from the settled planes.
  const size_t at = size_t(s.settled_first);
  runtime_.read_planes(settled_, c, at + size_t(BOREAS_TREE_SETTLED_F) * c, motion.data() + own, n,
                       n - own, BOREAS_TREE_MOTION_STILL_PLANES);
  if (settled_planes_ == BOREAS_TREE_SETTLED_RATE_PLANES)
    runtime_.read_planes(settled_, c, at + size_t(BOREAS_TREE_SETTLED_DF) * c,
                         motion.data() + size_t(BOREAS_TREE_MOTION_DF) * n + own, n, n - own, 3);
  return motion;
}

std::vector<boreas_branch> TreeBatch::branches(uint64_t key, const Origin& output_origin) {
  const Slot& s = slot_of(key);
  const TreeModel& m = *s.tree->model;
  const double scale = s.tree->params.scale;
  const std::vector<float> state = read_tree_state(key);
  const std::vector<float> motion = read_tree_motion(key);
  const size_t n = size_t(s.count);
  const std::array<float, 3> offset = offset_of(s, output_origin);  // as the records add it
  std::vector<boreas_branch> out(size_t(m.branch_count()));
  int level = 0;  // a packed model's: levels are in order
  for (size_t b = 0; b < out.size(); ++b) {
    while (m.packed && level + 1 < kMaxTreeLevels && int32_t(b) >= m.level_begin[size_t(level) + 1])
      ++level;
    const size_t i = size_t(block_index(int32_t(b)));
    boreas_branch& o = out[b];
    for (int k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a)
        o.control_points[k][a] = state[size_t(3 * k + a) * n + i] + offset[size_t(a)];
    for (int a = 0; a < 3; ++a) o.orientation[a] = state[size_t(BOREAS_TREE_STATE_O + a) * n + i];
    // A packed model keeps the fields read here (TreeModel::Packed::Branch).
    if (m.packed) {
      const TreeModel::Packed::Branch& br = m.packed->branches[b];
      o.level = level;
      o.parent = br.parent;
      o.parent_v = br.v;
      o.radius = float(br.radius * scale);
      o.length = float(br.length * scale);
    } else {
      const BranchModel& br = m.branches[b];
      o.level = br.level;
      o.parent = br.parent;
      o.parent_v = float(br.v);
      o.radius = float(br.radius * scale);
      o.length = float(br.length * scale);
    }
    o.broken = motion[size_t(BOREAS_TREE_MOTION_BROKEN) * n + i] > 0.0f ? 1 : 0;
  }
  return out;
}

void TreeBatch::read_leaf_records(const Slot& s, std::vector<float>* records) {
  constexpr size_t kRecord = BOREAS_TREE_LEAF_OUT_PLANES * sizeof(float);
  const size_t n = size_t(s.leaf_count);
  records->assign(size_t(BOREAS_TREE_LEAF_OUT_PLANES) * n, 0.0f);
  const uint64_t largest = runtime_.max_allocation();
  const size_t most =
      std::min(n, largest > 0 ? size_t(std::max<uint64_t>(largest / kRecord, 1)) : n);
  // Runs of the tree's consecutive leaf tiles (one run, unless its records pass one
  // allocation: a small device, or BOREAS_MAX_ALLOCATION), each made into the scratch
  // buffer from its first leaf on (the kernel writes record first_record + leaf: a
  // negative first_record puts the run at the buffer's start) and read to its place.
  const TileLists::Segment& seg = prepare_leaves(s);
  const std::vector<int32_t>& ints = record_tiles_.list(kRecordLeafList);
  auto field = [&](int32_t tile, int f) { return ints[size_t(tile) * BOREAS_TILE_INTS + size_t(f)]; };
  cl::Buffer scratch = runtime_.buffer(CL_MEM_WRITE_ONLY, most * kRecord, "tree leaves");
  pose_settled(&s);
  for (int32_t t = seg.first, end = seg.first + seg.count; t < end;) {
    const int32_t first = field(t, BOREAS_TILE_FIRST);
    int32_t next = t;
    size_t run = 0;
    while (next < end && field(next, BOREAS_TILE_FIRST) == first + int32_t(run) &&
           run + size_t(field(next, BOREAS_TILE_COUNT)) <= most)
      run += size_t(field(next++, BOREAS_TILE_COUNT));
    if (next == t)
      fail(BOREAS_ERROR_OUT_OF_MEMORY, "a tile of " + std::to_string(field(t, BOREAS_TILE_COUNT)) +
                                           " leaf records passes the device's largest allocation");
    launch_leaf_records(t, next - t, true, scratch, -int64_t(first));
    runtime_.read(scratch, 0, run * kRecord,
                  records->data() + size_t(first) * BOREAS_TREE_LEAF_OUT_PLANES);
    t = next;
  }
  unpose_settled();
}

std::vector<boreas_leaf> TreeBatch::leaves(uint64_t key, const Origin& output_origin) {
  const Slot& s = slot_of(key);
  const TreeModel& m = *s.tree->model;
  const double scale = s.tree->params.scale;
  std::vector<boreas_leaf> out(size_t(m.leaf_count()));
  if (out.empty()) return out;
  const size_t n = size_t(s.leaf_count);
  std::vector<float> records;
  reader_offsets(&output_origin, &s);
  read_leaf_records(s, &records);
  // A packed model keeps what every leaf shares, and the device each leaf's branch (its
  // template's packed leaves: 1 + the branch).
  std::vector<int32_t> places;
  if (m.packed) {
    places.resize(n);
    const size_t at = size_t(BOREAS_TREE_LEAF_PLACE) * size_t(static_leaves_.capacity) +
                      size_t(template_of(s).leaf_first);
    runtime_.read(leaves_, at * sizeof(int32_t),
                  n * sizeof(int32_t), places.data());
  }
  for (size_t j = 0; j < n; ++j) {
    boreas_leaf& o = out[j];
    const float* r = &records[j * BOREAS_TREE_LEAF_OUT_PLANES];
    for (int a = 0; a < 3; ++a) {
      o.position[a] = r[BOREAS_TREE_LEAF_OUT_POSITION + a];
      o.axis[a] = r[BOREAS_TREE_LEAF_OUT_AXIS + a];
      o.normal[a] = r[BOREAS_TREE_LEAF_OUT_NORMAL + a];
    }
    if (m.packed) {
      o.length = float(m.packed->leaf_length * scale);
      o.width = float(m.packed->leaf_width * scale);
      o.branch = boreas_leaf_unpack(places[j], 0).entry - block_index(0);
    } else {
      o.length = float(m.leaves[j].length * scale);
      o.width = float(m.leaves[j].width * scale);
      o.branch = m.leaves[j].parent;
    }
  }
  return out;
}

}  // namespace boreas::impl
