// boreas images: anti-aliased segments, triangles, discs, rings, dots and arrows. Coverage
// comes from the distance of each pixel center to the shape, which is cheap at these sizes.
#include "image/draw.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace boreas::render {

namespace {

float distance_to_segment(Point p, Point a, Point b) {
  float dx = b.x - a.x;
  float dy = b.y - a.y;
  float len2 = dx * dx + dy * dy;
  float t =
      len2 > 0.0f ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0f, 1.0f) : 0.0f;
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// Signed distance from p to the line through a and b, positive on the right of a->b.
float side(Point p, Point a, Point b) {
  float dx = b.x - a.x;
  float dy = b.y - a.y;
  float len = std::hypot(dx, dy);
  return len > 0.0f ? ((p.x - a.x) * dy - (p.y - a.y) * dx) / len : 0.0f;
}

}  // namespace

void draw_segment(Image& image, Point a, Point b, float width, Rgb color, float alpha) {
  float reach = width * 0.5f + 1.0f;
  int x0 = int(std::floor(std::min(a.x, b.x) - reach));
  int x1 = int(std::ceil(std::max(a.x, b.x) + reach));
  int y0 = int(std::floor(std::min(a.y, b.y) - reach));
  int y1 = int(std::ceil(std::max(a.y, b.y) + reach));
  for (int y = std::max(y0, 0); y <= std::min(y1, image.height() - 1); ++y) {
    for (int x = std::max(x0, 0); x <= std::min(x1, image.width() - 1); ++x) {
      float d = distance_to_segment({float(x) + 0.5f, float(y) + 0.5f}, a, b);
      float coverage = std::clamp(width * 0.5f + 0.5f - d, 0.0f, 1.0f);
      image.blend(x, y, color, coverage * alpha);
    }
  }
}

void fill_triangle(Image& image, Point a, Point b, Point c, Rgb color, float alpha) {
  // Orient clockwise on screen so "inside" is where every side() is negative.
  if (side(c, a, b) > 0.0f) std::swap(b, c);
  int x0 = int(std::floor(std::min({a.x, b.x, c.x}))) - 1;
  int x1 = int(std::ceil(std::max({a.x, b.x, c.x}))) + 1;
  int y0 = int(std::floor(std::min({a.y, b.y, c.y}))) - 1;
  int y1 = int(std::ceil(std::max({a.y, b.y, c.y}))) + 1;
  for (int y = std::max(y0, 0); y <= std::min(y1, image.height() - 1); ++y) {
    for (int x = std::max(x0, 0); x <= std::min(x1, image.width() - 1); ++x) {
      Point p{float(x) + 0.5f, float(y) + 0.5f};
      float outside = std::max({side(p, a, b), side(p, b, c), side(p, c, a)});
      image.blend(x, y, color, std::clamp(0.5f - outside, 0.0f, 1.0f) * alpha);
    }
  }
}

void fill_convex(Image& image, std::vector<Point> polygon, Rgb color, float alpha) {
  const size_t n = polygon.size();
  if (n < 3) return;
  // Orient so "inside" is where every side() is negative (as fill_triangle).
  float area = 0.0f;
  for (size_t i = 0; i < n; ++i)
    area += polygon[i].x * polygon[(i + 1) % n].y - polygon[(i + 1) % n].x * polygon[i].y;
  if (area < 0.0f) std::reverse(polygon.begin(), polygon.end());
  float lo_x = polygon[0].x, hi_x = lo_x, lo_y = polygon[0].y, hi_y = lo_y;
  for (const Point& p : polygon) {
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  }
  const int x0 = std::max(int(std::floor(lo_x)) - 1, 0);
  const int x1 = std::min(int(std::ceil(hi_x)) + 1, image.width() - 1);
  const int y0 = std::max(int(std::floor(lo_y)) - 1, 0);
  const int y1 = std::min(int(std::ceil(hi_y)) + 1, image.height() - 1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      Point p{float(x) + 0.5f, float(y) + 0.5f};
      float outside = -1e30f;
      for (size_t i = 0; i < n; ++i) outside = std::max(outside, side(p, polygon[i], polygon[(i + 1) % n]));
      image.blend(x, y, color, std::clamp(0.5f - outside, 0.0f, 1.0f) * alpha);
    }
  }
}

void fill_disc(Image& image, Point center, float radius, Rgb color, float alpha) {
  int x0 = int(std::floor(center.x - radius - 1.0f));
  int x1 = int(std::ceil(center.x + radius + 1.0f));
  int y0 = int(std::floor(center.y - radius - 1.0f));
  int y1 = int(std::ceil(center.y + radius + 1.0f));
  for (int y = std::max(y0, 0); y <= std::min(y1, image.height() - 1); ++y) {
    for (int x = std::max(x0, 0); x <= std::min(x1, image.width() - 1); ++x) {
      float d = std::hypot(float(x) + 0.5f - center.x, float(y) + 0.5f - center.y);
      image.blend(x, y, color, std::clamp(radius + 0.5f - d, 0.0f, 1.0f) * alpha);
    }
  }
}

void draw_ring(Image& image, Point center, float radius, float width, Rgb color, float alpha) {
  float reach = radius + width * 0.5f + 1.0f;
  int x0 = int(std::floor(center.x - reach));
  int x1 = int(std::ceil(center.x + reach));
  int y0 = int(std::floor(center.y - reach));
  int y1 = int(std::ceil(center.y + reach));
  for (int y = std::max(y0, 0); y <= std::min(y1, image.height() - 1); ++y) {
    for (int x = std::max(x0, 0); x <= std::min(x1, image.width() - 1); ++x) {
      float d =
          std::fabs(std::hypot(float(x) + 0.5f - center.x, float(y) + 0.5f - center.y) - radius);
      image.blend(x, y, color, std::clamp(width * 0.5f + 0.5f - d, 0.0f, 1.0f) * alpha);
    }
  }
}

void splat(Image& image, Point p, Rgb color, float alpha) {
  float fx = p.x - 0.5f;
  float fy = p.y - 0.5f;
  if (!(fx > -1.0f && fy > -1.0f && fx < float(image.width()) && fy < float(image.height())))
    return;
  int x0 = int(std::floor(fx));
  int y0 = int(std::floor(fy));
  float tx = fx - float(x0);
  float ty = fy - float(y0);
  image.blend(x0, y0, color, alpha * (1.0f - tx) * (1.0f - ty));
  image.blend(x0 + 1, y0, color, alpha * tx * (1.0f - ty));
  image.blend(x0, y0 + 1, color, alpha * (1.0f - tx) * ty);
  image.blend(x0 + 1, y0 + 1, color, alpha * tx * ty);
}

void draw_arrow(Image& image, Point tail, Point tip, float width, Rgb color, Rgb halo) {
  float dx = tip.x - tail.x;
  float dy = tip.y - tail.y;
  float length = std::hypot(dx, dy);
  if (!(length > 0.0f)) return;
  float ux = dx / length;
  float uy = dy / length;
  float head_length = std::min(length * 0.45f, std::max(3.0f * width, 3.0f));
  float head_half = head_length * 0.55f;
  Point base{tip.x - ux * head_length, tip.y - uy * head_length};
  Point left{base.x - uy * head_half, base.y + ux * head_half};
  Point right{base.x + uy * head_half, base.y - ux * head_half};

  draw_segment(image, tail, base, width + 2.0f, halo, 0.45f);
  fill_triangle(image, {tip.x + ux, tip.y + uy}, {left.x - uy, left.y + ux},
                {right.x + uy, right.y - ux}, halo, 0.45f);
  draw_segment(image, tail, base, width, color);
  fill_triangle(image, tip, left, right, color);
}

}  // namespace boreas::render
