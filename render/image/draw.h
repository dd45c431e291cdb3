// boreas images: anti-aliased shapes for drawing wind arrows onto frames. Coordinates are
// in pixels with (0, 0) the top-left corner of the top-left pixel.
#pragma once

#include "image/image.h"

namespace boreas::render {

struct Point {
  float x = 0.0f;
  float y = 0.0f;
};

// A line of the given width (pixels) with round ends.
void draw_segment(Image& image, Point a, Point b, float width, Rgb color, float alpha = 1.0f);

// A filled triangle.
void fill_triangle(Image& image, Point a, Point b, Point c, Rgb color, float alpha = 1.0f);

// An arrow from tail to tip: a shaft and a triangular head, over a darker halo so it reads
// on both ends of the color map.
void draw_arrow(Image& image, Point tail, Point tip, float width, Rgb color, Rgb halo);

}  // namespace boreas::render
