// boreas: a world's BlobTree — the public def checked into model options, the model built
// from one of the world's trees and polygonized, kept with its description.
#pragma once

#include "blobtree/blobtree_model.h"
#include "blobtree/polygonizer.h"
#include "boreas/boreas.h"
#include "trees/tree_batch.h"

namespace boreas::impl {

class Runtime;

struct BlobTreeParams {
  BlobTreeOptions options;  // min_radius 0 here means "half a cell"
  int resolution = 128;
  bool cubic = false;
};

// Every field checked; errors name it ("blobtree_def.resolution must be ..."; a cut or
// scar on a branch the tree does not have: "cuts[1].branch: 57 is not a branch ...").
BlobTreeParams checked_blobtree_def(const boreas_blobtree_def& def);

struct BlobTreeInstance {
  BlobMesh mesh;
  boreas_blobtree_info info{};
};

// The model and grid make_blobtree polygonizes: the automatic radii applied (min_radius 0
// means half a cell; every surface at least 0.9 cells from its skeleton). Throws
// boreas::Error (INVALID_ARGUMENT) naming what is wrong.
struct BlobSetup {
  BlobModel model;
  BlobGrid grid;
  double min_radius = 0.0;   // m, as used
  double min_surface = 0.0;  // m
};
BlobSetup blobtree_setup(const TreeModel& tree, const glm::dvec3& position,
                         const BlobTreeParams& params, double rotation = 0.0);

// Builds and polygonizes; throws boreas::Error (nothing is kept on failure).
BlobTreeInstance make_blobtree(Runtime& rt, const TreeInstance& tree, const BlobTreeParams& params,
                               const BlobProgress& progress, BlobScratch* scratch = nullptr);

}  // namespace boreas::impl
