// boreas gltf: a mesh's motion over its keys as a few morph targets weighted per key.
//
// Every key's displacement from the (quantized) base is kept as what a viewer draws:
// base + sum_i w_i(k) target_i, with int16 targets. The targets are the motion's principal
// components (the eigenvectors of the keys' Gram matrix, largest first), each quantized
// and then weighted per key by least squares against what is left, so that a target's
// rounding is absorbed by the next; targets are added until every vertex at every key lies
// within the tolerance of boreas's position (or every component is used). A meadow sways
// in a few coherent shapes: far fewer targets than keys. A target whose largest rounding
// at 8 bits stays within an eighth of the tolerance is written as int8.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace boreas::gltf {

struct MorphTargets {
  // targets[i]: 3 per vertex, normalized integers: the displacement in units of the box's
  // extent per axis (the node scales by it) divided by the target's own scale; int8
  // (-127..127) where levels[i] is 127 (a small target, whose rounding the tolerance
  // leaves room for: half the bytes), else int16 (levels[i] 32767).
  std::vector<std::vector<int16_t>> targets;
  std::vector<int> levels;
  std::vector<std::vector<float>> weights;  // weights[k][i]: target i's weight at key k
  double max_error = 0.0;                   // the largest distance left, base space units
};

// residual[k]: 3 floats per vertex, key k's positions minus the dequantized base (base
// space); extent: the quantization box's size per axis; tolerance in base space units.
MorphTargets fit_morph_targets(std::vector<std::vector<float>> residual,
                               const std::array<double, 3>& extent, double tolerance);

// The eigenvectors of the symmetric n x n matrix a (row-major), as columns of the result,
// largest eigenvalue first (cyclic Jacobi; n is at most a few hundred keys).
std::vector<std::vector<double>> symmetric_eigenvectors(std::vector<double> a, size_t n);

}  // namespace boreas::gltf
