/* boreas: a view's cull of one tree slot (boreas_world_enqueue_tree_records, the first step
 * of tree_record_offsets.cl, which culls each run of slots before it sums them: one launch
 * for both). A tree is culled where its bounding sphere (about its base, radius
 * BoreasTreeView.radius: nothing of it reaches farther, however it bends) lies wholly
 * outside one of the view's planes; a tree that straddles a plane is drawn. A drawn tree at
 * least the impostor distance from the eye (its base's distance) is an impostor. Otherwise
 * it writes all its branches and some of its leaves: the stochastic simplification a
 * renderer would do per leaf (Cook, Halstead, Planck and Ryu, "Stochastic simplification of
 * aggregate detail"), made per tree — a leaf of the tree's mean area A at distance d covers
 * A / (d footprint_per_m)^2 pixels; below resolved_area pixels the tree keeps that share of
 * its leaves (at least min_keep, at least one), and each kept leaf grows by
 * sqrt(leaves / kept) each way, so the leaves' total area, and so the crown's coverage,
 * stays. Writes the counts of the slot's out-table row. OpenCL C only. */
#ifndef BOREAS_TREE_CULL_H
#define BOREAS_TREE_CULL_H

#include "shared/tree_records.h"

#ifdef __OPENCL_C_VERSION__
inline void boreas_tree_cull_row(__global const BoreasTreeView* t, const BoreasRecordView* view,
                                 __global int* row) {
  int kind = t->live ? BOREAS_TREE_KIND_DRAWN : BOREAS_TREE_KIND_CULLED;
  const float3 c = (float3)(t->base[0], t->base[1], t->base[2]);
  for (int p = 0; p < 6; ++p) {
    const float3 nrm = (float3)(view->planes[4 * p], view->planes[4 * p + 1], view->planes[4 * p + 2]);
    if (dot(nrm, c) + view->planes[4 * p + 3] < -t->radius) kind = BOREAS_TREE_KIND_CULLED;
  }
  const float3 eye = (float3)(view->eye[0], view->eye[1], view->eye[2]);
  const float d = length(c - eye);
  if (kind == BOREAS_TREE_KIND_DRAWN && view->impostor_distance > 0.0f && d >= view->impostor_distance)
    kind = BOREAS_TREE_KIND_IMPOSTOR;
  int kept = t->leaves;
  float factor = 1.0f;
  if (kind == BOREAS_TREE_KIND_DRAWN && view->footprint_per_m > 0.0f && t->leaves > 0) {
    const float footprint = fmax(d, 1e-3f) * view->footprint_per_m;
    const float keep = clamp(t->leaf_area / (footprint * footprint * view->resolved_area), view->min_keep, 1.0f);
    if (keep < 1.0f) {
      kept = clamp((int)ceil(keep * (float)t->leaves), 1, t->leaves);
      factor = sqrt((float)t->leaves / (float)kept);
    }
  }
  const bool drawn = kind == BOREAS_TREE_KIND_DRAWN;
  row[BOREAS_TREE_OUT_KIND] = kind;
  row[BOREAS_TREE_OUT_BRANCHES] = drawn ? t->branches : 0;
  row[BOREAS_TREE_OUT_KEPT] = drawn ? kept : 0;
  row[BOREAS_TREE_OUT_FACTOR] = as_int(factor);
  row[BOREAS_TREE_OUT_LEAVES] = t->leaves;
  row[BOREAS_TREE_OUT_INVERSE] = t->leaf_inverse;
}
#endif

#endif
