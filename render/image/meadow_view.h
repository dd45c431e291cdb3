// boreas images: the underbrush on the frames of `boreas run`, until the real renderer
// (issue 5) draws its triangle strips. Each component is one stroke from its base through
// its center of mass X to base + 2 (X - base), a proxy for its tip (X lies about halfway
// up a blade), never longer than at rest. From above, over the wind slice, the strokes
// are a pixel or less at the usual scales, so a component is lightened by how far X
// stands from its rest pose: wind waves run over the meadow as light bands and a ball
// leaves a light wake. A close-up side view (a column of the side-view panel) shows the
// bending itself, over the rest poses in faint grey.
#pragma once

#include <cstdint>
#include <string>
#include <array>
#include <vector>

#include "image/image.h"
#include "image/tree_view.h"

namespace boreas::render {

// One component as the frames draw it (world space, m).
struct MeadowComponent {
  float base[3] = {};
  float center[3] = {};  // center of mass X
  uint16_t style = 0;    // index into the palette the drawing functions are given
  uint8_t attached = 0;  // 1: fixed to another component (petals, leaflets); drawn on top
  uint8_t broken = 0;    // 1: broken, hanging for good; drawn as straw
};

// The color of a species' components: ground parts (blades, stalks, fronds) and attached
// ones (daisy petals white, clover leaflets, fern pinnae). Built-in species have their own
// colors; other species (files) take palette_index-th of a fixed set.
Rgb underbrush_color(const std::string& species, bool attached, int palette_index);

// A collider (a sphere, or a capsule or box given its half extents and axes: the box of
// half extents `half` along `axes` grown by `radius`) or the disk an emitter's events fall in.
struct Ball {
  float center[3] = {};  // m
  float radius = 0.0f;   // m: the sphere's or capsule's (0 for a box)
  float half[3] = {};    // m: a capsule's (0, half_height, 0), a box's half extents
  float axes[3][3] = {{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};  // unit, world

  bool round() const { return half[0] == 0.0f && half[1] == 0.0f && half[2] == 0.0f; }
};

// The outline of a ball's shape seen along a world axis, as a convex polygon in the two
// other world axes u, v (0 x, 1 y, 2 z): for a capsule its stadium, for a box the hull of
// its corners. m.
std::vector<std::array<float, 2>> ball_outline(const Ball& ball, int u, int v);

// Every stride-th component (stride >= 1; the caller keeps a frame's strokes bounded) from
// above: ground components first, attached ones over them. rest holds the same components
// at rest (same order), for the lightening; it may be empty (no lightening).
void draw_meadow_from_above(Image& image, const TopProjection& projection,
                            const std::vector<MeadowComponent>& now,
                            const std::vector<MeadowComponent>& rest,
                            const std::vector<Rgb>& palette, int stride);

// Colliders from above: a red disc with a dark rim, at least 3 pixels across so that a
// small ball still shows; a capsule or a box as its footprint (ball_outline), filled red
// with a dark rim.
void draw_balls_from_above(Image& image, const TopProjection& projection,
                           const std::vector<Ball>& balls);

// Emitters from above: a faint light-blue ring around the disk their events fall in.
void draw_emitters_from_above(Image& image, const TopProjection& projection,
                              const std::vector<Ball>& areas);

// The close-up: a slab of the meadow seen from +z like the trees' panel (image right is
// world +x, up is +y), at a scale where blades are tens of pixels tall. It shows the
// components whose base lies within depth / 2 of the focus along z and inside the window
// along x, farther ones fainter, over their rest poses in faint grey, with the balls among
// them in depth order. Laid out once from the rest poses, so the scale stays put.
struct MeadowCloseUp {
  int width = 0;       // pixels
  int height = 0;      // pixels
  int ground_row = 0;  // pixel row of the ground line
  float pixels_per_meter = 1.0f;
  float depth = 0.5f;  // m: the slab's thickness along z
  float window() const { return float(width) / pixels_per_meter; }  // m along x
};

// The close-up's scale: the tall components (the 95th percentile of the rest tips' heights
// above their bases) reach half the room above the ground line, or less where that would
// make the window narrower than 1.5 m; the slab is as deep as it takes to hold about 400
// components at components_per_m2 (0.2 to 2 m).
MeadowCloseUp layout_meadow_close_up(const std::vector<MeadowComponent>& rest, int width,
                                     int height, float components_per_m2);

// The close-up centered on (focus_x, focus_z), its ground line at the mean base height of
// the ground components shown (focus_y when none is).
Image draw_meadow_close_up(const MeadowCloseUp& view, float focus_x, float focus_y, float focus_z,
                           const std::vector<MeadowComponent>& now,
                           const std::vector<MeadowComponent>& rest,
                           const std::vector<Rgb>& palette, const std::vector<Ball>& balls);

// "MEADOW 1.2 M" under the close-up's ground line, onto a frame whose close-up has its
// top-left corner at (left, top).
void draw_meadow_close_up_label(Image& frame, int left, int top, const MeadowCloseUp& view);

}  // namespace boreas::render
