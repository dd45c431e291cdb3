// boreas trees: a leaf's area from its outline (leaf_area.h).
#include "trees/leaf_area.h"

#include <array>
#include <cmath>
#include <mutex>

#include "errors.h"

namespace boreas::impl {

double outline_fill(const BoreasLeafOutline& o) {
  // The blade is {|x| < h(t)} with t measured from the notch's start at |x| (leaf_outline.h);
  // both halves alike, so the half x >= 0 is sampled and doubled.
  const int n = kLeafAreaSamples;
  const double du = 0.5 / n, dv = 1.0 / n;
  long inside = 0;
  for (int i = 0; i < n; ++i) {
    const float ax = float((i + 0.5) * du);
    const float start = boreas_leaf_blade_start_v(&o, ax);
    for (int j = 0; j < n; ++j) {
      const float v = float((j + 0.5) * dv);
      const float t = (v - start) / (BOREAS_LEAF_BLADE_TIP_V - start);
      if (ax < boreas_leaf_half_width(&o, t)) ++inside;
    }
  }
  const double texture_area = 2.0 * double(inside) * du * dv;
  // A quad's texture unit is length / (tip_v - base_v) along and width / (2 half_width)
  // across (boreas_leaf_offsets).
  return texture_area / (double(BOREAS_LEAF_BLADE_TIP_V - BOREAS_LEAF_BLADE_BASE_V) *
                         2.0 * double(BOREAS_LEAF_BLADE_HALF_WIDTH));
}

double leaf_fill(int outline) {
  if (outline < 0 || outline >= BOREAS_LEAF_OUTLINE_COUNT)
    fail_argument("leaf outline kind " + std::to_string(outline) + " is not 0.." +
                  std::to_string(BOREAS_LEAF_OUTLINE_COUNT - 1));
  static std::array<double, BOREAS_LEAF_OUTLINE_COUNT> fill{};
  static std::once_flag once;
  std::call_once(once, [] {
    for (int k = 0; k < BOREAS_LEAF_OUTLINE_COUNT; ++k) fill[size_t(k)] = outline_fill(boreas_leaf_outlines[k]);
  });
  return fill[size_t(outline)];
}

}  // namespace boreas::impl
