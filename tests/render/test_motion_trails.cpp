// render tests: the trails view's parts (render/view/motion_trails.h) without OpenGL:
// projection against a hand-worked camera, which tips are chosen (in view, spaced, the
// finest branches first, blades near the eye, no attached parts), the paths recorded, and
// the drawing: pixels change along a path and not away from it.
#include "view/motion_trails.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace boreas::render {
namespace {

constexpr int kW = 200, kH = 100;

// From (0, 1, 10) toward -Z, 60 degrees high, 2:1.
glm::mat4 view_proj() {
  return glm::perspective(glm::radians(60.0f), 2.0f, 0.1f, 500.0f) *
         glm::lookAt(glm::vec3(0, 1, 10), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));
}

TreeCurve branch_to(glm::vec3 tip, int level) {
  TreeCurve c;
  c.level = level;
  for (int k = 0; k < 4; ++k) {
    glm::vec3 p = tip * (float(k) / 3.0f);
    c.points[k][0] = p.x;
    c.points[k][1] = p.y;
    c.points[k][2] = p.z;
  }
  return c;
}

MeadowComponent blade(glm::vec3 base, float height, bool attached = false) {
  MeadowComponent c;
  c.base[0] = base.x, c.base[1] = base.y, c.base[2] = base.z;
  c.center[0] = base.x, c.center[1] = base.y + 0.5f * height, c.center[2] = base.z;
  c.attached = attached ? 1 : 0;
  return c;
}

TEST(MotionTrails, ProjectsThroughTheCamera) {
  float x = 0.0f, y = 0.0f;
  // The target is the image's center.
  ASSERT_TRUE(project_to_image(view_proj(), kW, kH, glm::vec3(0, 1, 0), x, y));
  EXPECT_NEAR(x, 100.0f, 1e-3f);
  EXPECT_NEAR(y, 50.0f, 1e-3f);
  // 10 m away the half-height is tan(30 deg) * 10 = 5.774 m: a point that high is at the top.
  ASSERT_TRUE(project_to_image(view_proj(), kW, kH, glm::vec3(0, 1 + 5.7735f, 0), x, y));
  EXPECT_NEAR(y, 0.0f, 1e-2f);
  // Half-width 11.547 m at 2:1: the right edge.
  ASSERT_TRUE(project_to_image(view_proj(), kW, kH, glm::vec3(11.547f, 1, 0), x, y));
  EXPECT_NEAR(x, 200.0f, 2e-2f);
  EXPECT_FALSE(project_to_image(view_proj(), kW, kH, glm::vec3(0, 1, 20), x, y)) << "behind";
}

TEST(MotionTrails, BladeTipIsTwiceTheCenterOfMassFromTheBase) {
  glm::vec3 tip = blade_tip(blade({1, 0, 2}, 0.4f));
  EXPECT_FLOAT_EQ(tip.x, 1.0f);
  EXPECT_FLOAT_EQ(tip.y, 0.4f);
  EXPECT_FLOAT_EQ(tip.z, 2.0f);
}

TEST(MotionTrails, ChoosesVisibleSpacedTipsFinestFirst) {
  std::vector<TreePose> poses(2);
  // Tree 0: level-3 tips in view, spread 1 m apart (about 8.7 px at 10 m), a level-2 tip in
  // view, and a level-3 tip far out of view.
  for (int i = 0; i < 5; ++i)
    poses[0].branches.push_back(branch_to({-4.0f + 2.0f * i, 2.0f, 0.0f}, 3));
  poses[0].branches.push_back(branch_to({0.0f, 4.0f, 0.0f}, 2));
  poses[0].branches.push_back(branch_to({80.0f, 2.0f, 0.0f}, 3));
  // Tree 1 is not traced.
  poses[1].branches.push_back(branch_to({0.0f, -1.0f, 0.0f}, 3));
  FrameMeadows meadows;
  meadows.now = {blade({0, 0, 5}, 0.5f), blade({3, 0, 5}, 0.5f, true), blade({0, 0, -30}, 0.5f),
                 blade({-3, 0, 5}, 0.5f)};
  TrailChoice choice;
  choice.per_tree = 4;
  choice.spacing = 12.0f;
  choice.margin = 4.0f;
  choice.blade_distance = 12.0f;
  std::vector<MotionTrail> trails =
      choose_trails(poses, {0}, meadows, glm::vec3(0, 1, 10), view_proj(), kW, kH, choice);
  std::vector<size_t> branches, blades;
  for (const MotionTrail& t : trails) {
    if (t.kind == MotionTrail::Kind::branch) {
      EXPECT_EQ(t.tree, 0u);
      branches.push_back(t.branch);
    } else {
      blades.push_back(t.component);
    }
  }
  // Tips 2 m apart are 17 px apart (>= 12): the five level-3 tips qualify, four are taken,
  // none of them the level-2 one or the one out of view.
  ASSERT_EQ(branches.size(), 4u);
  for (size_t b : branches) {
    EXPECT_LT(b, 5u) << "only in-view level-3 tips";
  }
  // Blades: within 12 m of the eye and not attached: components 0 and 3.
  std::sort(blades.begin(), blades.end());
  EXPECT_EQ(blades, (std::vector<size_t>{0, 3}));

  // Wider spacing keeps tips apart: at 40 px no two chosen tips are closer.
  choice.spacing = 40.0f;
  trails = choose_trails(poses, {0}, meadows, glm::vec3(0, 1, 10), view_proj(), kW, kH, choice);
  std::vector<Point> at;
  for (const MotionTrail& t : trails) {
    glm::vec3 p = t.kind == MotionTrail::Kind::branch
                      ? glm::vec3(poses[0].branches[t.branch].points[3][0],
                                  poses[0].branches[t.branch].points[3][1],
                                  poses[0].branches[t.branch].points[3][2])
                      : blade_tip(meadows.now[t.component]);
    Point q;
    ASSERT_TRUE(project_to_image(view_proj(), kW, kH, p, q.x, q.y));
    for (const Point& o : at) EXPECT_GE(std::hypot(o.x - q.x, o.y - q.y), 40.0f);
    at.push_back(q);
  }
  EXPECT_GE(at.size(), 2u);
}

TEST(MotionTrails, RecordsOnePointPerCall) {
  std::vector<TreePose> poses(1);
  poses[0].branches.push_back(branch_to({1, 2, 0}, 3));
  FrameMeadows meadows;
  meadows.now = {blade({0, 0, 5}, 0.5f)};
  std::vector<MotionTrail> trails(2);
  trails[0].kind = MotionTrail::Kind::branch;
  trails[1].kind = MotionTrail::Kind::blade;
  record_trails(trails, poses, meadows);
  poses[0].branches[0].points[3][0] = 1.5f;
  meadows.now[0].center[0] = 0.1f;
  record_trails(trails, poses, meadows);
  ASSERT_EQ(trails[0].path.size(), 2u);
  ASSERT_EQ(trails[1].path.size(), 2u);
  EXPECT_FLOAT_EQ(trails[0].path[0].x, 1.0f);
  EXPECT_FLOAT_EQ(trails[0].path[1].x, 1.5f);
  EXPECT_FLOAT_EQ(trails[1].path[1].x, 0.2f) << "the tip moves twice as far as the center";
}

TEST(MotionTrails, DrawsAlongThePathAndNowhereElseAboveTheLegend) {
  const Rgb grey{0.5f, 0.5f, 0.5f};
  Image image(kW, kH, grey);
  MotionTrail t;
  t.kind = MotionTrail::Kind::blade;
  t.path = {glm::vec3(-2, 1, 0), glm::vec3(0, 1, 0), glm::vec3(2, 1, 0)};  // across the middle row
  draw_trails(image, {t}, view_proj(), 4.0);
  auto changed = [&](int x, int y) {
    Rgb c = image.at(x, y);
    return std::abs(c.r - grey.r) + std::abs(c.g - grey.g) + std::abs(c.b - grey.b) > 0.02f;
  };
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  ASSERT_TRUE(project_to_image(view_proj(), kW, kH, t.path.front(), x0, y0));
  ASSERT_TRUE(project_to_image(view_proj(), kW, kH, t.path.back(), x1, y1));
  // On the path: every column between its ends changed on the row through it.
  for (int x = int(x0) + 1; x < int(x1); ++x) EXPECT_TRUE(changed(x, int(y0))) << x;
  // Away from it (above the legend's band at the bottom), nothing changed.
  for (int y = 0; y < kH - 20; ++y) {
    for (int x = 0; x < kW; ++x) {
      if (std::abs(float(y) + 0.5f - y0) > 5.0f) {
        EXPECT_FALSE(changed(x, y)) << x << "," << y;
      }
    }
  }
  // The legend: the bottom-left corner is darkened.
  EXPECT_TRUE(changed(2, kH - 2));
}

// A broken branch is marked at its base, white, and nowhere else; an unbroken one is not.
TEST(MotionTrails, BrokenBranchesAreMarkedWhereTheyBreakOff) {
  TreePose pose;
  pose.branches.resize(2);
  for (TreeCurve& c : pose.branches) c.points[0][1] = 1.0f;
  pose.branches[0].points[0][0] = -1.0f;  // unbroken
  pose.branches[1].points[0][0] = 1.0f;
  pose.branches[1].broken = true;
  const std::vector<glm::vec3> breaks = break_points({pose});
  ASSERT_EQ(breaks.size(), 1u);
  EXPECT_EQ(breaks[0], glm::vec3(1.0f, 1.0f, 0.0f));
  const Rgb grey{0.5f, 0.5f, 0.5f};
  Image image(kW, kH, grey);
  draw_trails(image, {}, view_proj(), 4.0, breaks);
  float x = 0, y = 0, ux = 0, uy = 0;
  ASSERT_TRUE(project_to_image(view_proj(), kW, kH, breaks[0], x, y));
  ASSERT_TRUE(project_to_image(view_proj(), kW, kH, glm::vec3(-1, 1, 0), ux, uy));
  const Rgb mark = image.at(int(x), int(y));
  EXPECT_GT(mark.r + mark.g + mark.b, 2.7f) << "white at the break";
  const Rgb calm = image.at(int(ux), int(uy));
  EXPECT_EQ(calm.r, grey.r) << "nothing at the unbroken branch";
}

}  // namespace
}  // namespace boreas::render
