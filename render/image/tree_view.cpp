// boreas images: trees from above and from the side. Branches are sampled along their
// Bezier curves and drawn as anti-aliased segments; leaves are splatted as single dots
// spread bilinearly over four pixels, so a leaf that moves a fraction of a pixel still
// changes the frame.
#include "image/tree_view.h"

#include <algorithm>
#include <cmath>

#include "image/bitmap_font.h"
#include "image/draw.h"

namespace boreas::render {

namespace {

constexpr int kLevels = 4;
// Bark darkens toward the trunk; leaves are green.
const Rgb kBark[kLevels] = {
    {0.20f, 0.12f, 0.06f}, {0.30f, 0.19f, 0.10f}, {0.40f, 0.28f, 0.16f}, {0.48f, 0.36f, 0.22f}};
const Rgb kLeafAbove{0.62f, 0.93f, 0.42f};
const Rgb kLeafSide{0.20f, 0.48f, 0.14f};
const Rgb kRestPose{0.74f, 0.77f, 0.82f};
const Rgb kSky{0.91f, 0.94f, 0.97f};
const Rgb kGround{0.45f, 0.38f, 0.30f};
const Rgb kSeparator{0.70f, 0.73f, 0.78f};
const Rgb kLabel{1.0f, 1.0f, 1.0f};

// Points along a branch: more for the long trunk and boughs than for twigs.
constexpr int kSamples[kLevels] = {8, 8, 6, 4};
// Line widths from above, in pixels at a 384-pixel frame.
constexpr float kTopWidth[kLevels] = {2.2f, 1.5f, 0.9f, 0.6f};
// Opacity from above: twigs faint, so the crown's leaves still show.
constexpr float kTopAlpha[kLevels] = {0.95f, 0.85f, 0.45f, 0.35f};
// The thinnest line per level from the side (wider where the branch is).
constexpr float kSideMinWidth[kLevels] = {1.2f, 0.9f, 0.6f, 0.5f};
// Room beside a tree for its sway, as a fraction of its height.
constexpr float kSwayMargin = 0.12f;

int level_of(const TreeCurve& c) { return std::clamp(c.level, 0, kLevels - 1); }

// Draws one curve mapped to pixels by to_pixel(x, y, z).
template <typename Project>
void draw_curve(Image& image, const TreeCurve& curve, const Project& to_pixel, float width,
                Rgb color, float alpha) {
  int samples = kSamples[level_of(curve)];
  std::array<float, 3> p = bezier_point(curve.points, 0.0f);
  Point previous = to_pixel(p[0], p[1], p[2]);
  for (int i = 1; i < samples; ++i) {
    p = bezier_point(curve.points, float(i) / float(samples - 1));
    Point next = to_pixel(p[0], p[1], p[2]);
    draw_segment(image, previous, next, width, color, alpha);
    previous = next;
  }
}

int label_scale(const SidePanel& panel) {
  return std::min(panel.width, 2 * panel.height) >= 640 ? 2 : 1;
}

}  // namespace

std::array<float, 3> bezier_point(const float points[4][3], float t) {
  float u = 1.0f - t;
  float b0 = u * u * u;
  float b1 = 3.0f * u * u * t;
  float b2 = 3.0f * u * t * t;
  float b3 = t * t * t;
  std::array<float, 3> p{};
  for (int a = 0; a < 3; ++a) {
    p[size_t(a)] = b0 * points[0][a] + b1 * points[1][a] + b2 * points[2][a] + b3 * points[3][a];
  }
  return p;
}

void draw_trees_from_above(Image& image, const TopProjection& projection,
                           const std::vector<const TreePose*>& trees) {
  float k = std::clamp(float(std::min(image.width(), image.height())) / 384.0f, 0.5f, 3.0f);
  auto to_pixel = [&](float x, float, float z) { return projection.pixel(x, z); };
  for (const TreePose* tree : trees) {
    // Leaves first, faint, so the branches show through as the crown's spokes. Their
    // opacity follows how many fall on a pixel of the crown, so a dense crown is a haze
    // rather than a solid disc.
    if (!tree->leaves.empty()) {
      float cx = 0.0f;
      float cz = 0.0f;
      for (const auto& leaf : tree->leaves) {
        cx += leaf[0];
        cz += leaf[2];
      }
      cx /= float(tree->leaves.size());
      cz /= float(tree->leaves.size());
      float spread = 0.0f;  // mean squared distance from the crown's middle, in pixels
      for (const auto& leaf : tree->leaves) {
        float dx = (leaf[0] - cx) * projection.pixels_per_meter_x;
        float dz = (leaf[2] - cz) * projection.pixels_per_meter_z;
        spread += dx * dx + dz * dz;
      }
      spread /= float(tree->leaves.size());
      float per_pixel = float(tree->leaves.size()) / std::max(1.0f, 3.14159f * 2.0f * spread);
      float alpha = std::clamp(2.5f / per_pixel, 0.03f, 0.5f);
      for (const std::array<float, 3>& leaf : tree->leaves) {
        splat(image, to_pixel(leaf[0], leaf[1], leaf[2]), kLeafAbove, alpha);
      }
    }
    // Twigs first, the trunk last: from above the trunk's line is the tree's spine.
    for (int level = kLevels - 1; level >= 0; --level) {
      for (const TreeCurve& curve : tree->branches) {
        if (level_of(curve) != level) continue;
        draw_curve(image, curve, to_pixel, kTopWidth[level] * k, kBark[level], kTopAlpha[level]);
      }
    }
  }
}

int side_panel_height(int width, int height) {
  (void)width;
  return std::max(48, height / 2);
}

SidePanel layout_side_panel(const std::vector<const TreePose*>& rest,
                            const std::vector<std::string>& labels, int width, int height) {
  SidePanel panel;
  panel.width = width;
  panel.height = height;
  int ground = std::clamp(height / 8, 6, 24);
  int top_pad = std::max(3, height / 24);
  panel.ground_row = height - ground;
  int shown = std::min<int>(int(rest.size()), std::max(1, width / kMinSideColumn));
  panel.hidden = int(rest.size()) - shown;
  float scale = 1e30f;
  for (int i = 0; i < shown; ++i) {
    const TreePose& tree = *rest[size_t(i)];
    SidePanel::Column column;
    column.left = width * i / shown;
    column.width = width * (i + 1) / shown - column.left;
    column.label = i < int(labels.size()) ? labels[size_t(i)] : "";
    if (!tree.branches.empty()) {
      column.center_x = tree.branches[0].points[0][0];
      column.base_y = tree.branches[0].points[0][1];
    }
    // The control polygons hold their curves, so their points bound the tree.
    float half_width = 0.0f;
    float tree_height = 0.1f;
    auto grow = [&](float x, float y) {
      half_width = std::max(half_width, std::fabs(x - column.center_x));
      tree_height = std::max(tree_height, y - column.base_y);
    };
    for (const TreeCurve& curve : tree.branches) {
      for (const auto& p : curve.points) grow(p[0], p[1]);
    }
    for (const auto& leaf : tree.leaves) grow(leaf[0], leaf[1]);
    float fit_x = (0.5f * float(column.width) - 2.0f) / (half_width + kSwayMargin * tree_height);
    float fit_y = float(panel.ground_row - top_pad) / (tree_height * 1.02f);
    scale = std::min({scale, fit_x, fit_y});
    panel.columns.push_back(column);
  }
  panel.pixels_per_meter = shown > 0 && scale > 0.0f && scale < 1e29f ? scale : 1.0f;
  return panel;
}

Image draw_side_panel(const SidePanel& panel, const std::vector<const TreePose*>& rest,
                      const std::vector<const TreePose*>& now) {
  Image image(panel.width, panel.height, kSky);
  image.fill_rect(0, panel.ground_row, panel.width, panel.height, kGround);
  float s = panel.pixels_per_meter;
  for (size_t i = 0; i < panel.columns.size(); ++i) {
    const SidePanel::Column& column = panel.columns[i];
    // Each column is drawn on its own canvas, so a tree never spills into its neighbour.
    Image canvas(column.width, panel.height, kSky);
    canvas.fill_rect(0, panel.ground_row, column.width, panel.height, kGround);
    auto to_pixel = [&](float x, float y, float) {
      return Point{0.5f * float(column.width) + (x - column.center_x) * s,
                   float(panel.ground_row) - (y - column.base_y) * s};
    };
    auto width_of = [&](const TreeCurve& curve) {
      int level = level_of(curve);
      return std::clamp(2.0f * curve.radius * s, kSideMinWidth[level],
                        std::max(2.0f, float(column.width) / 12.0f));
    };
    if (i < rest.size()) {
      for (const TreeCurve& curve : rest[i]->branches) {
        draw_curve(canvas, curve, to_pixel, width_of(curve), kRestPose, 1.0f);
      }
    }
    if (i < now.size()) {
      for (const TreeCurve& curve : now[i]->branches) {
        draw_curve(canvas, curve, to_pixel, width_of(curve), kBark[level_of(curve)], 1.0f);
      }
      for (const std::array<float, 3>& leaf : now[i]->leaves) {
        splat(canvas, to_pixel(leaf[0], leaf[1], leaf[2]), kLeafSide, 0.4f);
      }
    }
    if (column.left > 0) canvas.fill_rect(0, 0, 1, panel.ground_row, kSeparator);
    image.paste(canvas, column.left, 0);
  }
  return image;
}

void draw_side_panel_labels(Image& frame, int top, const SidePanel& panel) {
  int scale = label_scale(panel);
  int line = kGlyphHeight * scale;
  if (panel.height - panel.ground_row < line + 2) return;
  int y = top + panel.ground_row + (panel.height - panel.ground_row - line) / 2;
  for (const SidePanel::Column& column : panel.columns) {
    int fit = (column.width - 4 * scale + scale) / (kGlyphAdvance * scale);
    std::string label = column.label;
    if (int(label.size()) > fit) label = label.substr(0, size_t(std::max(fit, 0)));
    if (label.empty()) continue;
    int x = column.left + (column.width - text_width(label, scale)) / 2;
    draw_text(frame, x, y, label, scale, kLabel);
  }
  if (panel.hidden > 0) {
    std::string more = "+" + std::to_string(panel.hidden) + " MORE";
    int w = text_width(more, scale);
    draw_text(frame, panel.width - w - 3 * scale, top + 3 * scale, more, scale, kBark[0]);
  }
}

}  // namespace boreas::render
