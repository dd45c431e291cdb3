// boreas images: anti-aliased shapes for drawing arrows, plants and balls onto frames. Coordinates
// are in pixels with (0, 0) the top-left corner of the top-left pixel.
#pragma once

#include <vector>

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

// A filled convex polygon (either winding), without the seams a fan of triangles leaves.
void fill_convex(Image& image, std::vector<Point> polygon, Rgb color, float alpha = 1.0f);

// A filled disc of the given radius (pixels).
void fill_disc(Image& image, Point center, float radius, Rgb color, float alpha = 1.0f);

// A circle of the given radius (pixels) drawn as a line of the given width.
void draw_ring(Image& image, Point center, float radius, float width, Rgb color,
               float alpha = 1.0f);

// A dot of the given opacity at p, spread bilinearly over the four nearest pixels, so a
// dot that moves a fraction of a pixel still changes the image.
void splat(Image& image, Point p, Rgb color, float alpha);

// An arrow from tail to tip: a shaft and a triangular head, over a darker halo so it reads
// on both ends of the color map.
void draw_arrow(Image& image, Point tail, Point tip, float width, Rgb color, Rgb halo);

}  // namespace boreas::render
