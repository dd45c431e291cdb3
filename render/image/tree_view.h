// boreas images: trees on the frames of `boreas run`. Each branch is a cubic Bezier curve,
// drawn as a polyline (thicker and darker for lower levels), each leaf a small dot. Trees
// are drawn twice: from above over the wind slice, where they stand in the field, and in a
// side-view panel under it, one column per tree, where their sway shows best: the wind
// bends trees sideways, which a top view sees end-on (a tip moving 0.3 m is a pixel there).
// The side view is drawn over the tree's rest pose in faint grey, so the bend reads even in
// one frame.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "image/draw.h"
#include "image/image.h"

namespace boreas::render {

// One branch: its Bezier control points (world space, m), level (0 trunk .. 3) and base
// radius (m).
struct TreeCurve {
  float points[4][3] = {};
  int level = 0;
  float radius = 0.0f;
  bool broken = false;  // broken in a storm (boreas_branch.broken): it hangs from its base
};

// A tree as of one step: its branches and its leaves' centers (m).
struct TreePose {
  std::vector<TreeCurve> branches;
  std::vector<std::array<float, 3>> leaves;
};

// The point of a cubic Bezier curve at t in [0, 1].
std::array<float, 3> bezier_point(const float points[4][3], float t);

// How the slice maps to pixels: x = (world x - origin_x) * pixels_per_meter_x, and image y
// = (world z - origin_z) * pixels_per_meter_z (a top view looking down -Y).
struct TopProjection {
  float origin_x = 0.0f;
  float origin_z = 0.0f;
  float pixels_per_meter_x = 1.0f;
  float pixels_per_meter_z = 1.0f;

  // The pixel of ground point (x, z), and a length on the ground in pixels (the smaller
  // scale, so round things stay round).
  Point pixel(float x, float z) const {
    return Point{(x - origin_x) * pixels_per_meter_x, (z - origin_z) * pixels_per_meter_z};
  }
  float pixels(float meters) const { return meters * std::min(pixels_per_meter_x, pixels_per_meter_z); }
};

// Draws the trees over a frame of the slice; what falls outside the image is clipped.
void draw_trees_from_above(Image& image, const TopProjection& projection,
                           const std::vector<const TreePose*>& trees);

// The side-view panel: one column per tree (as many as fit, in scene order), every tree at
// the same scale so their sizes compare. Seen from +z (the bottom edge of the slice)
// looking toward -z: image right is world +x, image up is world +y. Laid out once from the
// rest poses so that the scale stays put while the trees move.
struct SidePanel {
  struct Column {
    int left = 0;            // pixels
    int width = 0;           // pixels
    float center_x = 0.0f;   // m: the trunk's base, drawn at the column's middle
    float base_y = 0.0f;     // m: the trunk's base, drawn on the ground line
    std::string label;       // species name, under the ground line
  };
  int width = 0;                // pixels
  int height = 0;               // pixels
  int ground_row = 0;           // pixel row of the ground line
  float pixels_per_meter = 1.0f;
  std::vector<Column> columns;  // columns[i] shows tree i
  int hidden = 0;               // trees left out for lack of room
};

// The panel's height under a width x height slice: half the slice, at least 48 pixels.
int side_panel_height(int width, int height);

// Columns for the trees (rest poses) with their labels, in a width x height panel. Trees
// beyond width / kMinSideColumn are left out (SidePanel::hidden counts them).
constexpr int kMinSideColumn = 48;
SidePanel layout_side_panel(const std::vector<const TreePose*>& rest,
                            const std::vector<std::string>& labels, int width, int height);

// The panel with the trees as they are now over their rest poses (same order as the
// layout); no text.
Image draw_side_panel(const SidePanel& panel, const std::vector<const TreePose*>& rest,
                      const std::vector<const TreePose*>& now);

// The species labels under the ground line (and "+N MORE" when trees were left out), onto a
// frame whose panel starts at row top.
void draw_side_panel_labels(Image& frame, int top, const SidePanel& panel);

}  // namespace boreas::render
