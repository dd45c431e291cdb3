// boreas trees: what area a leaf has, one rule for the light (leaf_occlusion.h) and the
// wind (wind_load.h): its length times its width times the fill of its outline, the share
// of the length x width box its blade covers.
//
// The outline is cl/shared/leaf_outline.h's, the one the renderer draws and the rays hit,
// so the area is the drawn blade's, petiole left out (a stalk, not foliage). An elliptic
// blade fills pi/4 of its box; boreas's outlines 0.5-0.75 (an oak's sinuses take a share).
#pragma once

#include "shared/leaf_outline.h"

namespace boreas::impl {

// The blade's area over length x width for an outline row (any row, not only the table's):
// the blade's texture-space area, sampled on a kLeafAreaSamples^2 midpoint grid over the
// quad, times the quad's scale (cl/shared/leaf_outline.h's mapping). Smooth outlines
// converge fast: the ellipse (p = q = 0.5, no teeth) comes out within 1e-4 of pi/4.
inline constexpr int kLeafAreaSamples = 1024;
double outline_fill(const BoreasLeafOutline& outline);

// outline_fill of kind 0..BOREAS_LEAF_OUTLINE_COUNT - 1 of the table, computed once.
double leaf_fill(int outline);

// A leaf's one-sided area, m^2: length and width in m, its outline kind.
inline double leaf_area(double length, double width, int outline) {
  return length * width * leaf_fill(outline);
}

}  // namespace boreas::impl
