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

// Every field checked; errors name it ("blobtree_def.cuts[1].at must be ...").
BlobTreeParams checked_blobtree_def(const boreas_blobtree_def& def);

struct BlobTreeInstance {
  BlobMesh mesh;
  boreas_blobtree_info info{};
};

// Builds and polygonizes; throws boreas::Error (nothing is kept on failure).
BlobTreeInstance make_blobtree(Runtime& rt, const TreeInstance& tree, const BlobTreeParams& params,
                               const BlobProgress& progress);

}  // namespace boreas::impl
