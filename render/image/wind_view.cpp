// boreas images: the wind frame. Colors come first, then arrows on a regular lattice,
// then the overlays, so text stays readable over everything.
#include "image/wind_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "image/bitmap_font.h"
#include "image/color_map.h"
#include "image/draw.h"

namespace boreas::render {

namespace {

const Rgb kWhite{1.0f, 1.0f, 1.0f};
const Rgb kBlack{0.0f, 0.0f, 0.0f};
constexpr float kPanelAlpha = 0.75f;

float speed_at(const std::vector<float>& wind, size_t pixel) {
  const float* w = &wind[pixel * 3];
  return std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

void draw_colors(Image& image, const WindView& view) {
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      size_t pixel = size_t(y) * size_t(view.width) + size_t(x);
      image.set(x, y, speed_color(speed_at(*view.wind, pixel), view.color_max));
    }
  }
}

void draw_arrows(Image& image, const WindView& view) {
  int spacing = arrow_spacing(view.width, view.height);
  float width = std::max(1.0f, float(spacing) / 14.0f);
  // Center the lattice so the margins on both sides match.
  int x_start = (view.width - (view.width / spacing - 1) * spacing) / 2;
  int y_start = (view.height - (view.height / spacing - 1) * spacing) / 2;
  for (int y = y_start; y < view.height; y += spacing) {
    for (int x = x_start; x < view.width; x += spacing) {
      const float* w = &(*view.wind)[(size_t(y) * size_t(view.width) + size_t(x)) * 3];
      float horizontal = std::hypot(w[0], w[2]);
      float length = std::min(horizontal / view.color_max, 1.0f) * float(spacing) * 0.9f;
      if (!(length >= 2.0f)) continue;
      float dx = w[0] * view.pixels_per_meter_x;
      float dy = w[2] * view.pixels_per_meter_z;
      float norm = std::hypot(dx, dy);
      dx *= length / norm;
      dy *= length / norm;
      Point center{float(x) + 0.5f, float(y) + 0.5f};
      draw_arrow(image, {center.x - dx * 0.5f, center.y - dy * 0.5f},
                 {center.x + dx * 0.5f, center.y + dy * 0.5f}, width, kWhite, kBlack);
    }
  }
}

int overlay_scale(const WindView& view) { return std::min(view.width, view.height) >= 640 ? 2 : 1; }

void draw_title(Image& image, const WindView& view) {
  if (view.title.empty()) return;
  int s = overlay_scale(view);
  int pad = 4 * s;
  int w = std::min(text_width(view.title, s) + 2 * pad, view.width);
  image.fill_rect(0, 0, w, kGlyphHeight * s + 2 * pad, kBlack, kPanelAlpha);
  draw_text(image, pad, pad, view.title, s, kWhite);
}

void draw_color_bar(Image& image, const WindView& view) {
  int s = overlay_scale(view);
  int pad = 5 * s;
  int bar_width = std::clamp(view.width * 2 / 5, 80, 400);
  int bar_height = 8 * s;
  int line = kGlyphHeight * s;
  int panel_width = bar_width + 2 * pad;
  int panel_height = line + bar_height + line + 4 * pad;
  int left = 0;
  int top = view.height - panel_height;
  image.fill_rect(left, top, left + panel_width, view.height, kBlack, kPanelAlpha);

  int y = top + pad;
  draw_text(image, left + pad, y, "WIND SPEED (M/S)", s, kWhite);
  y += line + pad;
  for (int x = 0; x < bar_width; ++x) {
    Rgb c = viridis(float(x) / float(bar_width - 1));
    image.fill_rect(left + pad + x, y, left + pad + x + 1, y + bar_height, c);
  }
  y += bar_height + pad;
  // Labels at 0, the middle and the top; each tick sits under its label's position.
  for (int i = 0; i <= 2; ++i) {
    std::string label = speed_label(view.color_max * float(i) * 0.5f);
    int tick = left + pad + (bar_width - 1) * i / 2;
    int x = std::clamp(tick - text_width(label, s) / 2, left + pad,
                       left + pad + bar_width - text_width(label, s));
    image.fill_rect(tick, y - pad, tick + s, y - pad / 2, kWhite);
    draw_text(image, x, y, label, s, kWhite);
  }
}

}  // namespace

int arrow_spacing(int width, int height) { return std::clamp(std::min(width, height) / 16, 8, 64); }

std::string speed_label(float speed) {
  char text[32];
  if (std::fabs(speed - std::round(speed)) < 1e-3f) {
    std::snprintf(text, sizeof text, "%.0f", double(speed));
  } else if (std::fabs(speed * 10.0f - std::round(speed * 10.0f)) < 1e-2f) {
    std::snprintf(text, sizeof text, "%.1f", double(speed));
  } else {
    std::snprintf(text, sizeof text, "%.2f", double(speed));
  }
  return text;
}

Image draw_wind_field(const WindView& view) {
  if (!view.wind || view.wind->size() != size_t(view.width) * size_t(view.height) * 3) {
    throw std::invalid_argument("wind view: the wind must hold 3 floats per pixel");
  }
  if (!(view.color_max > 0.0f)) throw std::invalid_argument("wind view: color_max must be > 0");
  Image image(view.width, view.height);
  draw_colors(image, view);
  draw_arrows(image, view);
  return image;
}

void draw_wind_overlays(Image& image, const WindView& view) {
  if (std::min(view.width, view.height) < kMinOverlaySize) return;
  draw_title(image, view);
  draw_color_bar(image, view);
}

Image draw_wind_view(const WindView& view) {
  Image image = draw_wind_field(view);
  draw_wind_overlays(image, view);
  return image;
}

}  // namespace boreas::render
