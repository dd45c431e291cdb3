// boreas images: the underbrush from above and in the close-up. Strokes shorter than a
// pixel are splatted as a dot at X (the stroke's middle), spread over four pixels, which
// is both faster and truer than a sub-pixel segment.
#include "image/meadow_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image/bitmap_font.h"
#include "image/draw.h"

namespace boreas::render {

namespace {

// Built-in species: ground parts, attached parts.
struct SpeciesColors {
  const char* name;
  Rgb ground;
  Rgb attached;
};
const SpeciesColors kBuiltinColors[] = {
    {"meadow_grass", {0.40f, 0.66f, 0.18f}, {0.40f, 0.66f, 0.18f}},
    {"clover", {0.16f, 0.40f, 0.14f}, {0.20f, 0.47f, 0.17f}},
    {"daisy", {0.30f, 0.52f, 0.16f}, {0.98f, 0.98f, 0.94f}},
    {"fern", {0.35f, 0.46f, 0.15f}, {0.22f, 0.56f, 0.30f}},
};
// Species files, in the order they appear.
const Rgb kFilePalette[] = {{0.62f, 0.70f, 0.16f}, {0.72f, 0.36f, 0.62f}, {0.90f, 0.74f, 0.18f},
                            {0.30f, 0.62f, 0.58f}, {0.80f, 0.45f, 0.25f}, {0.50f, 0.40f, 0.75f}};
const Rgb kStraw{0.78f, 0.68f, 0.42f};  // broken components
const Rgb kSheen{0.93f, 0.97f, 0.68f};  // what a bent component is lightened toward
constexpr float kMaxSheen = 0.75f;
const Rgb kBall{0.86f, 0.18f, 0.14f};
const Rgb kBallRim{0.22f, 0.04f, 0.03f};
const Rgb kRain{0.70f, 0.86f, 1.0f};
const Rgb kSky{0.91f, 0.94f, 0.97f};
const Rgb kGround{0.45f, 0.38f, 0.30f};
const Rgb kRestPose{0.76f, 0.79f, 0.84f};
const Rgb kLabel{1.0f, 1.0f, 1.0f};
constexpr float kTopAlpha = 0.65f;  // per stroke from above; a dense meadow saturates
constexpr float kMinWindow = 1.5f;  // m: the close-up's least width

// The proxy tip: base + 2 (X - base).
void tip_of(const MeadowComponent& c, float tip[3]) {
  for (int a = 0; a < 3; ++a) tip[a] = 2.0f * c.center[a] - c.base[a];
}

// The same, no longer than at rest: a component does not stretch, but an attached one's X
// can trail its base (the tip of a swaying stalk) by several times its length.
void tip_of(const MeadowComponent& c, const MeadowComponent& rest, float tip[3]) {
  float length =
      std::hypot(c.center[0] - c.base[0], c.center[1] - c.base[1], c.center[2] - c.base[2]);
  float rest_length = std::hypot(rest.center[0] - rest.base[0], rest.center[1] - rest.base[1],
                                 rest.center[2] - rest.base[2]);
  float k = length > rest_length ? 2.0f * rest_length / length : 2.0f;
  for (int a = 0; a < 3; ++a) tip[a] = c.base[a] + k * (c.center[a] - c.base[a]);
}

Rgb color_of(const MeadowComponent& c, const std::vector<Rgb>& palette) {
  if (c.broken) return kStraw;
  return c.style < palette.size() ? palette[c.style] : kFilePalette[0];
}

// How far X stands from its rest pose, in units of the distance from base to X at rest,
// halved: 0 at rest, 1 where X has swung over to the opposite side of its base (a
// component laid flat by the wind is about 0.5, so gusts still show over a bent meadow).
float bend_of(const MeadowComponent& now, const MeadowComponent& rest) {
  float reach =
      std::max(0.01f, std::hypot(rest.center[0] - rest.base[0], rest.center[1] - rest.base[1],
                                 rest.center[2] - rest.base[2]));
  float moved = std::hypot(now.center[0] - rest.center[0], now.center[1] - rest.center[1],
                           now.center[2] - rest.center[2]);
  return std::clamp(0.5f * moved / reach, 0.0f, 1.0f);
}

int label_scale(int width, int height) { return std::min(width, 2 * height) >= 640 ? 2 : 1; }

}  // namespace

Rgb underbrush_color(const std::string& species, bool attached, int palette_index) {
  for (const SpeciesColors& colors : kBuiltinColors) {
    if (species == colors.name) return attached ? colors.attached : colors.ground;
  }
  constexpr int kCount = int(sizeof kFilePalette / sizeof kFilePalette[0]);
  Rgb color = kFilePalette[((palette_index % kCount) + kCount) % kCount];
  return attached ? mix(color, Rgb{1.0f, 1.0f, 1.0f}, 0.35f) : color;
}

void draw_meadow_from_above(Image& image, const TopProjection& projection,
                            const std::vector<MeadowComponent>& now,
                            const std::vector<MeadowComponent>& rest,
                            const std::vector<Rgb>& palette, int stride) {
  stride = std::max(stride, 1);
  bool lighten = rest.size() == now.size();
  auto to_pixel = [&](const float p[3]) { return projection.pixel(p[0], p[2]); };
  // Ground components first: the petals and leaflets they carry lie over them.
  for (uint8_t attached : {uint8_t(0), uint8_t(1)}) {
    for (size_t i = 0; i < now.size(); i += size_t(stride)) {
      const MeadowComponent& c = now[i];
      if (c.attached != attached) continue;
      Rgb color = color_of(c, palette);
      if (lighten && !c.broken) color = mix(color, kSheen, kMaxSheen * bend_of(c, rest[i]));
      float tip[3];
      if (lighten) {
        tip_of(c, rest[i], tip);
      } else {
        tip_of(c, tip);
      }
      Point a = to_pixel(c.base);
      Point b = to_pixel(tip);
      if (std::hypot(b.x - a.x, b.y - a.y) < 1.0f) {
        splat(image, Point{0.5f * (a.x + b.x), 0.5f * (a.y + b.y)}, color, kTopAlpha);
      } else {
        draw_segment(image, a, b, 1.0f, color, kTopAlpha);
      }
    }
  }
}

std::vector<std::array<float, 2>> ball_outline(const Ball& ball, int u, int v) {
  // Each corner of the box (a capsule's two segment ends, repeated), ringed by the radius.
  constexpr int kRing = 16;
  std::vector<std::array<float, 2>> points;
  for (int corner = 0; corner < 8; ++corner) {
    float p[3] = {ball.center[0], ball.center[1], ball.center[2]};
    for (int i = 0; i < 3; ++i) {
      const float sign = (corner >> i) & 1 ? 1.0f : -1.0f;
      for (int a = 0; a < 3; ++a) p[a] += sign * ball.half[i] * ball.axes[i][a];
    }
    for (int k = 0; k < (ball.radius > 0.0f ? kRing : 1); ++k) {
      const float angle = 6.2831853f * float(k) / kRing;
      points.push_back({p[u] + ball.radius * std::cos(angle), p[v] + ball.radius * std::sin(angle)});
    }
  }
  // Andrew's monotone chain: the hull, counter-clockwise.
  std::sort(points.begin(), points.end());
  auto turn = [](const std::array<float, 2>& o, const std::array<float, 2>& a,
                 const std::array<float, 2>& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<std::array<float, 2>> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0f) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0f) --k;
    hull[k++] = points[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

namespace {

// A convex outline (pixels) filled red (alpha: 1 opaque) over a dark rim.
void fill_outline(Image& image, const std::vector<Point>& outline, float rim, float alpha) {
  const size_t n = outline.size();
  for (size_t i = 0; i < n; ++i)
    draw_segment(image, outline[i], outline[(i + 1) % n], 2.0f * rim, kBallRim, 0.9f);
  fill_convex(image, outline, kBall, alpha);
}

}  // namespace

void draw_balls_from_above(Image& image, const TopProjection& projection,
                           const std::vector<Ball>& balls) {
  for (const Ball& ball : balls) {
    if (!ball.round()) {
      std::vector<Point> outline;
      for (const auto& q : ball_outline(ball, 0, 2)) outline.push_back(projection.pixel(q[0], q[1]));
      fill_outline(image, outline, 0.8f, 1.0f);
      continue;
    }
    Point c = projection.pixel(ball.center[0], ball.center[2]);
    float r = std::max(1.5f, projection.pixels(ball.radius));
    fill_disc(image, c, r + 0.8f, kBallRim, 0.9f);
    fill_disc(image, c, r, kBall);
  }
}

void draw_emitters_from_above(Image& image, const TopProjection& projection,
                              const std::vector<Ball>& areas) {
  for (const Ball& area : areas) {
    Point c = projection.pixel(area.center[0], area.center[2]);
    float r = std::max(2.0f, projection.pixels(area.radius));
    draw_ring(image, c, r, 1.0f, kRain, 0.7f);
  }
}

MeadowCloseUp layout_meadow_close_up(const std::vector<MeadowComponent>& rest, int width,
                                     int height, float components_per_m2) {
  MeadowCloseUp view;
  view.width = width;
  view.height = height;
  view.ground_row = height - std::clamp(height / 8, 6, 24);
  int top_pad = std::max(3, height / 24);
  std::vector<float> heights;
  heights.reserve(rest.size());
  for (const MeadowComponent& c : rest) {
    // Attached components ride on their parents, whose tips already count.
    if (c.attached) continue;
    float tip[3];
    tip_of(c, tip);
    heights.push_back(tip[1] - c.base[1]);
  }
  float tall = 0.3f;  // m, when there is nothing to measure
  if (!heights.empty()) {
    size_t k = heights.size() * 95 / 100;
    std::nth_element(heights.begin(), heights.begin() + std::ptrdiff_t(k), heights.end());
    tall = std::max(0.05f, heights[k]);
  }
  // Tall plants reach half the room, but the window spans at least kMinWindow, so that a
  // ball and its wake fit in it.
  view.pixels_per_meter =
      std::min(0.5f * float(view.ground_row - top_pad) / tall, float(width) / kMinWindow);
  float area_for_400 = 400.0f / std::max(components_per_m2, 1e-3f);
  view.depth = std::clamp(area_for_400 / view.window(), 0.2f, 2.0f);
  return view;
}

Image draw_meadow_close_up(const MeadowCloseUp& view, float focus_x, float focus_y, float focus_z,
                           const std::vector<MeadowComponent>& now,
                           const std::vector<MeadowComponent>& rest,
                           const std::vector<Rgb>& palette, const std::vector<Ball>& balls) {
  Image image(view.width, view.height, kSky);
  image.fill_rect(0, view.ground_row, view.width, view.height, kGround);
  float half_window = 0.5f * view.window();
  float half_depth = 0.5f * view.depth;
  // What lies in the slab and the window (with room for a component leaning in), from the
  // rest poses, so a component swaying out of the window does not blink.
  bool has_rest = rest.size() == now.size();
  const std::vector<MeadowComponent>& placed = has_rest ? rest : now;
  std::vector<size_t> shown;
  double ground_sum = 0.0;
  int ground_count = 0;
  float lean = 0.5f * float(view.ground_row) / view.pixels_per_meter;
  for (size_t i = 0; i < placed.size(); ++i) {
    const MeadowComponent& c = placed[i];
    if (std::fabs(c.base[2] - focus_z) > half_depth) continue;
    if (std::fabs(c.base[0] - focus_x) > half_window + lean) continue;
    shown.push_back(i);
    if (!c.attached && std::fabs(c.base[0] - focus_x) <= half_window) {
      ground_sum += c.base[1];
      ++ground_count;
    }
  }
  float ground_y = ground_count > 0 ? float(ground_sum / ground_count) : focus_y;
  float s = view.pixels_per_meter;
  auto to_pixel = [&](const float p[3]) {
    return Point{0.5f * float(view.width) + (p[0] - focus_x) * s,
                 float(view.ground_row) - (p[1] - ground_y) * s};
  };
  // Far (small z) to near: the viewer stands at +z.
  std::sort(shown.begin(), shown.end(),
            [&](size_t a, size_t b) { return placed[a].base[2] < placed[b].base[2]; });
  if (has_rest) {
    for (size_t i : shown) {
      float tip[3];
      tip_of(rest[i], tip);
      draw_segment(image, to_pixel(rest[i].base), to_pixel(tip), 1.0f, kRestPose);
    }
  }
  std::vector<const Ball*> in_slab;
  for (const Ball& ball : balls) {
    // Its reach along z: the radius and its half extents' parts along z.
    float reach = ball.radius;
    for (int i = 0; i < 3; ++i) reach += std::fabs(ball.half[i] * ball.axes[i][2]);
    if (std::fabs(ball.center[2] - focus_z) <= half_depth + reach) in_slab.push_back(&ball);
  }
  std::sort(in_slab.begin(), in_slab.end(),
            [](const Ball* a, const Ball* b) { return a->center[2] < b->center[2]; });
  size_t next_ball = 0;
  auto draw_balls_before = [&](float z) {
    for (; next_ball < in_slab.size() && in_slab[next_ball]->center[2] <= z; ++next_ball) {
      const Ball& ball = *in_slab[next_ball];
      if (!ball.round()) {
        std::vector<Point> outline;
        for (const auto& q : ball_outline(ball, 0, 1)) {
          const float p[3] = {q[0], q[1], 0.0f};
          outline.push_back(to_pixel(p));
        }
        // See-through: a car fills the close-up, and the plants it presses are the point.
        fill_outline(image, outline, 1.0f, 0.3f);
        continue;
      }
      Point c = to_pixel(ball.center);
      float r = std::max(1.5f, ball.radius * s);
      fill_disc(image, c, r + 1.0f, kBallRim);
      fill_disc(image, c, r, kBall);
    }
  };
  float width = std::clamp(s * 0.004f, 1.0f, 3.0f);  // a blade is a few mm wide
  for (size_t i : shown) {
    const MeadowComponent& c = now[i];
    draw_balls_before(placed[i].base[2]);
    // Aerial haze: the far side of the slab fades toward the sky.
    float nearness =
        std::clamp((placed[i].base[2] - (focus_z - half_depth)) / view.depth, 0.0f, 1.0f);
    Rgb color = mix(kSky, color_of(c, palette), 0.45f + 0.55f * nearness);
    float tip[3];
    if (has_rest) {
      tip_of(c, rest[i], tip);
    } else {
      tip_of(c, tip);
    }
    draw_segment(image, to_pixel(c.base), to_pixel(tip), c.attached ? width * 1.5f : width, color);
  }
  draw_balls_before(1e30f);
  // Stems drawn below the ground line (a slope, a leaning stroke) are covered again.
  image.fill_rect(0, view.ground_row, view.width, view.height, kGround);
  return image;
}

void draw_meadow_close_up_label(Image& frame, int left, int top, const MeadowCloseUp& view) {
  int scale = label_scale(view.width, view.height);
  int line = kGlyphHeight * scale;
  if (view.height - view.ground_row < line + 2) return;
  char text[64];
  float window = view.window();
  std::snprintf(text, sizeof text, window < 10.0f ? "MEADOW %.1f M" : "MEADOW %.0f M",
                double(window));
  std::string label = text;
  int fit = (view.width - 4 * scale + scale) / (kGlyphAdvance * scale);
  if (int(label.size()) > fit) label = "MEADOW";
  if (int(label.size()) > fit) return;
  int x = left + (view.width - text_width(label, scale)) / 2;
  int y = top + view.ground_row + (view.height - view.ground_row - line) / 2;
  draw_text(frame, x, y, label, scale, kLabel);
}

}  // namespace boreas::render
