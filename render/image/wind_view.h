// boreas images: one frame of `boreas run`, a horizontal slice of the wind seen from
// above: speed as a color map, direction as arrows, a title and a color bar.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace boreas::render {

struct WindView {
  int width = 0;   // pixels
  int height = 0;  // pixels
  // 3 floats (x, y, z in m/s) per pixel, rows top to bottom. Image +x is world +x and image
  // +y (down) is world +z, a top view looking down -Y.
  const std::vector<float>* wind = nullptr;
  float color_max = 1.0f;           // m/s at the top of the color map
  float pixels_per_meter_x = 1.0f;  // for arrow directions when x and z scales differ
  float pixels_per_meter_z = 1.0f;
  std::string title;  // top-left caption; empty for none
};

// Overlays (title, color bar) are left out below this many pixels on the shorter side, so
// small images show only the field.
constexpr int kMinOverlaySize = 160;

// The field alone: colors and arrows (what contact sheets tile).
Image draw_wind_field(const WindView& view);
// Adds the title and the color bar when the image is large enough for them.
void draw_wind_overlays(Image& image, const WindView& view);
// Both: a whole frame.
Image draw_wind_view(const WindView& view);

// Arrow sites are this many pixels apart in an image of the given size.
int arrow_spacing(int width, int height);

// "0", "7.5", "15", "0.25": a legend label for a speed.
std::string speed_label(float speed);

}  // namespace boreas::render
