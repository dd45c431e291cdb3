// boreas: one Weber-Penn stem walked segment by segment, as Weber & Penn (1995) and Arbaro
// grow it: curvature, AttractionUp, splits (clones) and the pruning test, in world space at
// rest. The generator (tree_generator.cpp) turns the walk's pieces into one cubic Bezier
// each (Skjermo 2007 sec. 2.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "trees/rest_frame.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace boreas::impl {

// A run of a stem's segments between splits: one branch of the model.
struct StemPiece {
  int depth = 0;       // splits between the stem's base and this piece
  bool clone = false;  // begun as a clone (else the stem itself, or its continuation)
  int parent = -1;     // the piece it grows from (index in StemWalk::pieces); -1: the stem's base
  int first = 0;       // segments [first, end) of the stem's CurveRes
  int end = 0;
  std::vector<Vec3> directions;  // each segment's unit direction, world
};

struct StemWalk {
  std::vector<StemPiece> pieces;  // a piece comes after the piece it grows from
  int outside = -1;  // prune test: the first segment whose end left the envelope, else -1
  size_t segments = 0;  // segments walked, the clones' included
};

// What one walk may still add to its tree: the tree's GrowthLimits less what the tree
// already has (branches) or has walked (segments).
struct StemWalkRoom {
  size_t pieces = 0;
  size_t segments = 0;
  const GrowthLimits* limits = nullptr;  // the tree's, for the error's message
};

struct StemWalkInput {
  const Species* species = nullptr;
  int level = 0;
  int segments = 1;     // the level's CurveRes
  double length = 0.0;  // the stem's length, m
  RestFrame start;      // where it starts; x along its first segment, z the curving axis
  uint64_t seed = 0;    // random streams (seed, stem, purpose)
  uint64_t stem = 0;
  double tree_size = 1.0;  // Weber-Penn's scale_tree, m (the envelope's size)
};

// Walks the stem. split_error is the level's split error (Arbaro carries it from stem to
// stem in growth order, so a level of 0.2 splits per segment splits every fifth segment
// whatever its stems' CurveRes); it is updated. With prune_test the walk stops at the
// first segment whose end leaves the envelope. A walk past its room fails (an exploding
// species: splits, or nCurveRes on too many stems), naming the species, the parameters to
// lower and the limit.
StemWalk walk_stem(const StemWalkInput& in, double* split_error, bool prune_test,
                   const StemWalkRoom& room);

// Whether a point lies inside Weber-Penn's pruning envelope (Shape 8 with PruneWidth,
// PruneWidthPeak, PrunePowerLow/High), as Arbaro tests it: r / scale_tree < PruneWidth
// ShapeRatio8((scale_tree - height) / (scale_tree (1 - BaseSize))), r the distance from
// the trunk's vertical axis.
bool inside_envelope(const Species& s, double tree_size, const Vec3& p);

}  // namespace boreas::impl
