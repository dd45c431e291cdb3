// boreas: a world's one-call tree records (boreas_world_enqueue_tree_records, boreas_cl.h):
// the view checked and turned into the kernels' form (cl/shared/tree_records.h), then each
// batch's launches (trees/tree_batch_view.cpp), the lagged chunks' counts first.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "errors.h"
#include "validation.h"
#include "world.h"

namespace boreas::impl {

namespace {

static_assert(BOREAS_TREE_IMPOSTOR_RECORD_FLOATS == BOREAS_TREE_IMPOSTOR_WORDS &&
                  BOREAS_TREE_RANGE_RECORD_INTS == BOREAS_TREE_RANGE_WORDS &&
                  BOREAS_TREE_INDIRECT_UINTS == BOREAS_TREE_INDIRECT_WORDS &&
                  BOREAS_TREE_INDIRECT_BRANCH_COMMAND == BOREAS_TREE_INDIRECT_BRANCHES &&
                  BOREAS_TREE_INDIRECT_LEAF_COMMAND == BOREAS_TREE_INDIRECT_LEAVES &&
                  BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND == BOREAS_TREE_INDIRECT_IMPOSTORS &&
                  BOREAS_TREE_INDIRECT_RANGES_WRITTEN == BOREAS_TREE_INDIRECT_RANGES,
              "boreas_cl.h names cl/shared/tree_records.h's layouts");
static_assert(sizeof(BoreasTreeView) == 20 * 4 && sizeof(BoreasRecordView) == 40 * 4,
              "the view structs are 4-byte fields, the same in OpenCL C");

// The view's fields checked, its planes normalized (in double).
BoreasRecordView checked_view(const boreas_tree_view_def& def) {
  BoreasRecordView v{};
  check_position(def.eye, "view->eye");
  for (int a = 0; a < 3; ++a) v.eye[a] = def.eye[a];
  for (int p = 0; p < 6; ++p) {
    for (int c = 0; c < 4; ++c)
      check_finite(def.planes[p][c], "view->planes[" + std::to_string(p) + "][" + std::to_string(c) + "]");
    const double nx = def.planes[p][0], ny = def.planes[p][1], nz = def.planes[p][2];
    const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (length == 0.0) {
      if (def.planes[p][3] < 0.0f)
        fail_argument("view->planes[" + std::to_string(p) +
                      "] has a zero normal and d < 0: it would cull every tree");
      v.planes[4 * p + 3] = 1.0f;  // no plane: every point inside
      continue;
    }
    for (int c = 0; c < 4; ++c) v.planes[4 * p + c] = float(def.planes[p][c] / length);
  }
  check_finite(def.pixel_angle, "view->pixel_angle");
  if (def.pixel_angle < 0.0f || def.pixel_angle >= 1.0f)
    fail_argument("view->pixel_angle must be in [0, 1) rad (got " + num(def.pixel_angle) + ")");
  check_finite(def.resolved_pixels, "view->resolved_pixels");
  if (!(def.resolved_pixels > 0.0f))
    fail_argument("view->resolved_pixels must be > 0 (got " + num(def.resolved_pixels) + ")");
  check_finite(def.min_keep, "view->min_keep");
  if (!(def.min_keep > 0.0f && def.min_keep <= 1.0f))
    fail_argument("view->min_keep must be in (0, 1] (got " + num(def.min_keep) + ")");
  check_finite(def.impostor_distance, "view->impostor_distance");
  if (def.impostor_distance < 0.0f)
    fail_argument("view->impostor_distance must be >= 0 (got " + num(def.impostor_distance) + ")");
  const int vertices[3] = {def.vertices_per_branch, def.vertices_per_leaf, def.vertices_per_impostor};
  const char* names[3] = {"vertices_per_branch", "vertices_per_leaf", "vertices_per_impostor"};
  for (int k = 0; k < 3; ++k) {
    if (vertices[k] < 0)
      fail_argument(std::string("view->") + names[k] + " must be >= 0 (got " + std::to_string(vertices[k]) + ")");
    v.vertices[k] = vertices[k];
  }
  v.footprint_per_m = def.pixel_angle;
  v.resolved_area = def.resolved_pixels;
  v.min_keep = def.min_keep;
  v.impostor_distance = def.impostor_distance;
  return v;
}

// Records of record_bytes a buffer holds (at most 2^31 - 1: the kernels count in int).
int capacity_of(const cl::Buffer& buffer, size_t record_bytes) {
  const size_t bytes = buffer.getInfo<CL_MEM_SIZE>();
  return int(std::min<size_t>(bytes / record_bytes, size_t(std::numeric_limits<int32_t>::max())));
}

}  // namespace

void World::enqueue_tree_records(const boreas_tree_view_def& def,
                                 const TreeBatch::RecordOutputs& out) {
  BoreasRecordView view = checked_view(def);
  const size_t indirect_bytes = out.indirect.getInfo<CL_MEM_SIZE>();
  if (indirect_bytes < BOREAS_TREE_INDIRECT_UINTS * sizeof(uint32_t))
    fail_argument("out->indirect holds " + std::to_string(indirect_bytes) + " bytes, less than the " +
                  std::to_string(BOREAS_TREE_INDIRECT_UINTS * sizeof(uint32_t)) +
                  " of BOREAS_TREE_INDIRECT_UINTS words");
  view.branch_capacity = capacity_of(out.branches, BOREAS_BRANCH_RECORD_FLOATS * sizeof(float));
  view.leaf_capacity = capacity_of(out.leaves, BOREAS_LEAF_RECORD_FLOATS * sizeof(float));
  view.impostor_capacity =
      capacity_of(out.impostors, BOREAS_TREE_IMPOSTOR_RECORD_FLOATS * sizeof(float));
  view.range_capacity = capacity_of(out.ranges, BOREAS_TREE_RANGE_RECORD_INTS * sizeof(int32_t));
  // Every chunk that holds trees, lagged first, the counts continued from one to the next;
  // with no trees at all the first chunk still zeroes them.
  std::vector<TreeBatch*> batches;
  for (TreeBatch* batch : all_tree_batches())
    if (!batch->empty()) batches.push_back(batch);
  if (batches.empty()) batches.push_back(&tree_batch(BOREAS_TREE_LAGGED));
  view.first_batch = 1;
  for (TreeBatch* batch : batches) {
    batch->enqueue_view_records(view, out, output_origin_);
    view.first_batch = 0;
  }
}

int World::tree_template(boreas_tree_id id) {
  const TreeInstance& tree = *trees_.get(id);
  return tree_batch(tree).template_number(tree.key);
}

}  // namespace boreas::impl
