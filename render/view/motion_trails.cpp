// boreas views: motion trails (motion_trails.h).
#include "view/motion_trails.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "image/bitmap_font.h"
#include "image/draw.h"

namespace boreas::render {
namespace {

glm::vec3 branch_tip(const TreeCurve& c) {
  return {c.points[3][0], c.points[3][1], c.points[3][2]};
}

// Whether (x, y) keeps `spacing` pixels from every point in taken.
bool spaced(const std::vector<Point>& taken, float x, float y, float spacing) {
  for (const Point& p : taken) {
    if ((p.x - x) * (p.x - x) + (p.y - y) * (p.y - y) < spacing * spacing) return false;
  }
  return true;
}

// An order over n items that spreads them (a multiplicative stride coprime to n), so the
// first ones taken are not all from one end of a list laid out branch by branch.
size_t spread_index(size_t i, size_t n) {
  constexpr size_t kStride = 7919;  // a prime
  size_t stride = kStride % n == 0 ? 1 : kStride;
  return (i * stride) % n;
}

}  // namespace

bool project_to_image(const glm::mat4& view_proj, int width, int height, const glm::vec3& p,
                      float& x, float& y) {
  glm::vec4 c = view_proj * glm::vec4(p, 1.0f);
  if (c.w <= 1e-6f) return false;
  x = (c.x / c.w * 0.5f + 0.5f) * float(width);
  y = (0.5f - c.y / c.w * 0.5f) * float(height);
  return true;
}

glm::vec3 blade_tip(const MeadowComponent& c) {
  glm::vec3 base(c.base[0], c.base[1], c.base[2]), center(c.center[0], c.center[1], c.center[2]);
  return base + 2.0f * (center - base);
}

std::vector<MotionTrail> choose_trails(const std::vector<TreePose>& poses,
                                       const std::vector<size_t>& traced_trees,
                                       const FrameMeadows& meadows, const glm::vec3& eye,
                                       const glm::mat4& view_proj, int width, int height,
                                       const TrailChoice& choice) {
  std::vector<MotionTrail> trails;
  std::vector<Point> taken;
  auto visible = [&](const glm::vec3& p, float& x, float& y) {
    return project_to_image(view_proj, width, height, p, x, y) && x >= choice.margin &&
           y >= choice.margin && x < float(width) - choice.margin &&
           y < float(height) - choice.margin - choice.legend_rows;
  };
  for (size_t tree : traced_trees) {
    if (tree >= poses.size()) continue;
    const std::vector<TreeCurve>& branches = poses[tree].branches;
    if (branches.empty()) continue;
    int finest = 0;
    for (const TreeCurve& c : branches) finest = std::max(finest, c.level);
    int chosen = 0;
    // The finest level first (its tips sway most), then the next coarser.
    for (int level = finest; level >= 1 && chosen < choice.per_tree; --level) {
      for (size_t k = 0; k < branches.size() && chosen < choice.per_tree; ++k) {
        size_t b = spread_index(k, branches.size());
        if (branches[b].level != level) continue;
        float x = 0.0f, y = 0.0f;
        glm::vec3 tip = branch_tip(branches[b]);
        if (!visible(tip, x, y) || !spaced(taken, x, y, choice.spacing)) continue;
        MotionTrail t;
        t.kind = MotionTrail::Kind::branch;
        t.tree = tree;
        t.branch = b;
        trails.push_back(t);
        taken.push_back({x, y});
        ++chosen;
      }
    }
  }
  // Blades: those near enough that a 3 cm move of the tip (a blade sways some centimetres)
  // is a pixel or more, or, where none is, at least half as many pixels as the nearest
  // one's; taken in a spread order so they cover the near ground.
  std::vector<std::pair<float, size_t>> candidates;  // pixels a 3 cm move spans, component
  float most = 0.0f;
  for (size_t i = 0; i < meadows.now.size(); ++i) {
    const MeadowComponent& c = meadows.now[i];
    if (c.attached) continue;  // petals and leaflets ride on their stalks
    const glm::vec3 tip = blade_tip(c);
    if (choice.blade_distance > 0.0f && glm::distance(tip, eye) > choice.blade_distance) continue;
    float x = 0.0f, y = 0.0f, x3 = 0.0f, y3 = 0.0f;
    if (!visible(tip, x, y)) continue;
    if (!project_to_image(view_proj, width, height, tip + glm::vec3(0.0f, 0.03f, 0.0f), x3, y3))
      continue;
    const float pixels = std::hypot(x3 - x, y3 - y);
    candidates.emplace_back(pixels, i);
    most = std::max(most, pixels);
  }
  const float threshold = std::min(1.0f, 0.5f * most);
  std::vector<size_t> near;
  for (const auto& [pixels, i] : candidates) {
    if (pixels >= threshold) near.push_back(i);
  }
  int blades = 0;
  for (size_t k = 0; k < near.size() && blades < choice.blades; ++k) {
    const size_t i = near[spread_index(k, near.size())];
    float x = 0.0f, y = 0.0f;
    project_to_image(view_proj, width, height, blade_tip(meadows.now[i]), x, y);
    if (!spaced(taken, x, y, choice.spacing)) continue;
    MotionTrail t;
    t.kind = MotionTrail::Kind::blade;
    t.component = i;
    trails.push_back(t);
    taken.push_back({x, y});
    ++blades;
  }
  return trails;
}

void record_trails(std::vector<MotionTrail>& trails, const std::vector<TreePose>& poses,
                   const FrameMeadows& meadows) {
  for (MotionTrail& t : trails) {
    if (t.kind == MotionTrail::Kind::branch) {
      if (t.tree < poses.size() && t.branch < poses[t.tree].branches.size())
        t.path.push_back(branch_tip(poses[t.tree].branches[t.branch]));
    } else if (t.component < meadows.now.size()) {
      t.path.push_back(blade_tip(meadows.now[t.component]));
    }
  }
}

std::vector<glm::vec3> break_points(const std::vector<TreePose>& poses) {
  std::vector<glm::vec3> out;
  for (const TreePose& pose : poses)
    for (const TreeCurve& c : pose.branches)
      if (c.broken) out.emplace_back(c.points[0][0], c.points[0][1], c.points[0][2]);
  return out;
}

void draw_trails(Image& image, const std::vector<MotionTrail>& trails, const glm::mat4& view_proj,
                 double seconds, const std::vector<glm::vec3>& breaks) {
  const Rgb halo{0.05f, 0.05f, 0.08f};
  const Rgb branch_start{1.0f, 0.92f, 0.2f}, branch_end{0.95f, 0.15f, 0.1f};
  const Rgb blade_start{0.3f, 0.95f, 1.0f}, blade_end{0.55f, 0.25f, 1.0f};
  // Halos first, for every trail, so no halo covers another trail's line.
  for (int pass = 0; pass < 2; ++pass) {
    for (const MotionTrail& t : trails) {
      const bool branch = t.kind == MotionTrail::Kind::branch;
      const size_t n = t.path.size();
      for (size_t i = 0; i + 1 < n; ++i) {
        Point a, b;
        if (!project_to_image(view_proj, image.width(), image.height(), t.path[i], a.x, a.y) ||
            !project_to_image(view_proj, image.width(), image.height(), t.path[i + 1], b.x, b.y))
          continue;
        if (pass == 0) {
          draw_segment(image, a, b, 3.5f, halo, 0.55f);
        } else {
          float along = n > 2 ? float(i) / float(n - 2) : 0.0f;
          Rgb color =
              branch ? mix(branch_start, branch_end, along) : mix(blade_start, blade_end, along);
          draw_segment(image, a, b, 1.6f, color);
        }
      }
      Point start;
      if (n > 0 &&
          project_to_image(view_proj, image.width(), image.height(), t.path[0], start.x, start.y)) {
        if (pass == 0) {
          fill_disc(image, start, 3.2f, halo, 0.6f);
        } else {
          fill_disc(image, start, 2.0f, branch ? branch_start : blade_start);
        }
      }
    }
  }
  // Breaks: a white cross on a dark halo at each broken branch's base.
  for (int pass = 0; pass < 2; ++pass) {
    for (const glm::vec3& at : breaks) {
      Point c;
      if (!project_to_image(view_proj, image.width(), image.height(), at, c.x, c.y)) continue;
      const float arm = 4.0f;
      for (float s : {-1.0f, 1.0f}) {
        const Point a{c.x - arm, c.y - s * arm}, b{c.x + arm, c.y + s * arm};
        if (pass == 0) {
          draw_segment(image, a, b, 3.5f, halo, 0.6f);
        } else {
          draw_segment(image, a, b, 1.6f, Rgb{1.0f, 1.0f, 1.0f});
        }
      }
    }
  }
  // The legend, bottom left, on a dark band.
  char text[200];
  if (breaks.empty()) {
    std::snprintf(text, sizeof text,
                  "PATHS OVER %.1f S:  BRANCH TIPS YELLOW TO RED,  BLADE TIPS CYAN TO VIOLET",
                  seconds);
  } else {
    std::snprintf(text, sizeof text,
                  "PATHS OVER %.1f S:  BRANCH TIPS YELLOW TO RED,  BLADE TIPS CYAN TO VIOLET,  "
                  "%zu BREAKS WHITE X",
                  seconds, breaks.size());
  }
  const int scale = image.width() >= 960 ? 2 : 1;
  const int w = text_width(text, scale), h = 9 * scale;
  image.fill_rect(0, image.height() - h - 8, w + 16, image.height(), halo, 0.6f);
  draw_text(image, 8, image.height() - h - 4, text, scale, Rgb{0.95f, 0.95f, 0.95f});
}

}  // namespace boreas::render
