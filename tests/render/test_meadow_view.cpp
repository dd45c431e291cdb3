// render tests: the underbrush's drawing on its own, on hand-made components: strokes from
// above land where the components stand, petals lie over their stalks, a bent component is
// lighter, the stride thins the strokes, and the close-up shows its slab and the balls in it.
#include "image/meadow_view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "image/image.h"

namespace boreas::render {
namespace {

const Rgb kBlack{0.0f, 0.0f, 0.0f};

MeadowComponent component(float x, float z, float height, uint16_t style, bool attached = false,
                          float lean_x = 0.0f) {
  MeadowComponent c;
  c.base[0] = x;
  c.base[1] = 0.0f;
  c.base[2] = z;
  c.center[0] = x + lean_x;
  c.center[1] = 0.5f * height;
  c.center[2] = z;
  c.style = style;
  c.attached = attached ? 1 : 0;
  return c;
}

bool is_black(const Image& image, int x, int y) {
  Rgb p = image.at(x, y);
  return p.r == 0.0f && p.g == 0.0f && p.b == 0.0f;
}

float brightness(Rgb c) { return c.r + c.g + c.b; }

// 10 pixels per meter, origin at (0, 0).
TopProjection ten_per_meter() {
  TopProjection p;
  p.pixels_per_meter_x = 10.0f;
  p.pixels_per_meter_z = 10.0f;
  return p;
}

std::vector<Rgb> palette() {
  return {underbrush_color("meadow_grass", false, 0), underbrush_color("meadow_grass", true, 0),
          underbrush_color("daisy", false, 0), underbrush_color("daisy", true, 0)};
}

TEST(MeadowView, SpeciesHaveTheirColors) {
  Rgb grass = underbrush_color("meadow_grass", false, 0);
  Rgb clover = underbrush_color("clover", false, 0);
  Rgb petal = underbrush_color("daisy", true, 0);
  EXPECT_GT(grass.g, grass.r);
  EXPECT_GT(grass.g, grass.b);
  EXPECT_LT(brightness(clover), brightness(grass)) << "clover is the darker green";
  EXPECT_GT(std::min({petal.r, petal.g, petal.b}), 0.9f) << "daisy petals are white";
  EXPECT_LT(underbrush_color("daisy", false, 0).r, 0.5f) << "on a green stalk";
  // Species files take distinct colors by their index.
  Rgb a = underbrush_color("/x/moss.json", false, 0);
  Rgb b = underbrush_color("/x/reed.json", false, 1);
  EXPECT_GT(std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b), 0.2f);
}

TEST(MeadowView, StrokesLandWhereTheComponentsStand) {
  Image image(40, 40, kBlack);
  // A blade at (1.5, 2.5) m leaning 0.3 m toward +x: its stroke runs from pixel (15, 25)
  // to (21, 25).
  std::vector<MeadowComponent> now = {component(1.5f, 2.5f, 0.2f, 0, false, 0.3f)};
  draw_meadow_from_above(image, ten_per_meter(), now, {}, palette(), 1);
  EXPECT_FALSE(is_black(image, 17, 24));
  EXPECT_FALSE(is_black(image, 20, 24));
  Rgb p = image.at(18, 24);
  EXPECT_GT(p.g, p.r);
  EXPECT_GT(p.g, p.b);
  EXPECT_TRUE(is_black(image, 15, 20));
  EXPECT_TRUE(is_black(image, 30, 24));
  EXPECT_TRUE(is_black(image, 5, 5));
}

TEST(MeadowView, PetalsLieOverTheirStalks) {
  Image image(20, 20, kBlack);
  // The petal comes first in the list but is drawn after the stalk it sits on.
  std::vector<MeadowComponent> now = {component(1.0f, 1.05f, 0.1f, 3, true, 0.3f),
                                      component(1.0f, 1.05f, 0.1f, 2, false, 0.3f)};
  draw_meadow_from_above(image, ten_per_meter(), now, {}, palette(), 1);
  Rgb p = image.at(12, 10);
  EXPECT_GT(p.b, 0.5f) << "white, not green";
}

TEST(MeadowView, BentComponentsAreLighter) {
  std::vector<MeadowComponent> rest = {component(1.0f, 1.05f, 0.4f, 0, false, 0.3f)};
  std::vector<MeadowComponent> bent = rest;
  bent[0].center[0] += 0.3f;  // pushed 0.3 m further along x
  bent[0].center[1] -= 0.1f;
  Image still(20, 20, kBlack);
  Image moved(20, 20, kBlack);
  draw_meadow_from_above(still, ten_per_meter(), rest, rest, palette(), 1);
  draw_meadow_from_above(moved, ten_per_meter(), bent, rest, palette(), 1);
  EXPECT_GT(brightness(moved.at(12, 10)), brightness(still.at(12, 10)) + 0.1f);
}

TEST(MeadowView, StrideThinsTheStrokes) {
  std::vector<MeadowComponent> now;
  for (int i = 0; i < 10; ++i) now.push_back(component(0.25f + 0.4f * float(i), 1.0f, 0.1f, 0));
  auto drawn = [&](int stride) {
    Image image(50, 20, kBlack);
    draw_meadow_from_above(image, ten_per_meter(), now, {}, palette(), stride);
    int count = 0;
    for (int x = 0; x < 50; ++x) count += is_black(image, x, 10) && is_black(image, x, 9) ? 0 : 1;
    return count;
  };
  int all = drawn(1);
  EXPECT_GT(all, 0);
  EXPECT_LT(drawn(2), all);
  EXPECT_GT(drawn(2), 0);
}

TEST(MeadowView, BallsAndRainShowFromAbove) {
  Image image(40, 40, kBlack);
  Ball ball;
  ball.center[0] = 2.0f;
  ball.center[2] = 2.0f;
  ball.radius = 0.3f;  // 3 pixels
  draw_balls_from_above(image, ten_per_meter(), {ball});
  Rgb p = image.at(20, 20);
  EXPECT_GT(p.r, 0.6f);
  EXPECT_LT(p.g, 0.3f) << "red";
  EXPECT_TRUE(is_black(image, 20, 26));
  // A ball smaller than a pixel still shows.
  Image small(40, 40, kBlack);
  ball.radius = 0.01f;
  draw_balls_from_above(small, ten_per_meter(), {ball});
  EXPECT_GT(small.at(20, 20).r, 0.5f);
  // Rain: a ring, the middle left alone.
  Image rain(40, 40, kBlack);
  Ball area;
  area.center[0] = 2.0f;
  area.center[2] = 2.0f;
  area.radius = 1.0f;
  draw_emitters_from_above(rain, ten_per_meter(), {area});
  EXPECT_FALSE(is_black(rain, 30, 20));
  EXPECT_TRUE(is_black(rain, 20, 20));
}

// The shoelace area of an outline, m^2.
double area_of(const std::vector<std::array<float, 2>>& outline) {
  double twice = 0.0;
  for (size_t i = 0; i < outline.size(); ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % outline.size()];
    twice += double(a[0]) * b[1] - double(b[0]) * a[1];
  }
  return 0.5 * std::fabs(twice);
}

// A box's footprint is its rectangle, turned with it; a capsule's an upright disc from
// above and a stadium from the side (its 16-sided rings within 3 % of the circle's area).
TEST(MeadowView, CapsulesAndBoxesHaveTheirFootprints) {
  Ball car;
  car.half[0] = 2.25f;
  car.half[1] = 0.75f;
  car.half[2] = 0.9f;
  EXPECT_NEAR(area_of(ball_outline(car, 0, 2)), 4.5 * 1.8, 1e-5);
  EXPECT_NEAR(area_of(ball_outline(car, 0, 1)), 4.5 * 1.5, 1e-5);
  // A quarter turn about +Y: local x along world -z.
  float turned[3][3] = {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}};
  std::copy(&turned[0][0], &turned[0][0] + 9, &car.axes[0][0]);
  float x_max = -1e9f, z_max = -1e9f;
  for (const auto& q : ball_outline(car, 0, 2)) x_max = std::max(x_max, q[0]), z_max = std::max(z_max, q[1]);
  EXPECT_NEAR(x_max, 0.9f, 1e-5f);
  EXPECT_NEAR(z_max, 2.25f, 1e-5f);

  Ball walker;
  walker.radius = 0.25f;
  walker.half[1] = 0.65f;
  const double circle = M_PI * 0.25 * 0.25;
  EXPECT_NEAR(area_of(ball_outline(walker, 0, 2)), circle, 0.03 * circle);
  const double stadium = 0.5 * 1.3 + circle;
  EXPECT_NEAR(area_of(ball_outline(walker, 0, 1)), stadium, 0.03 * circle);

  // Drawn from above: the car's footprint is red across its middle, its corners' outside
  // left alone; a sphere stays the disc it was.
  Image image(80, 40, kBlack);
  Ball level;
  level.center[0] = 4.0f;
  level.center[2] = 2.0f;
  std::copy(car.half, car.half + 3, level.half);
  draw_balls_from_above(image, ten_per_meter(), {level});
  EXPECT_GT(image.at(40 - 20, 20).r, 0.6f) << "inside the 4.5 m length";
  EXPECT_GT(image.at(40, 20 + 7).r, 0.6f) << "inside the 1.8 m width";
  EXPECT_TRUE(is_black(image, 40 - 25, 20));
  EXPECT_TRUE(is_black(image, 40, 20 + 12));
  EXPECT_TRUE(Ball().round());
  EXPECT_FALSE(walker.round());
}

TEST(MeadowView, CloseUpShowsItsSlabAndTheBall) {
  // Blades 0.3 m tall along x, one in the slab (z = 0) and one 3 m behind it.
  std::vector<MeadowComponent> rest;
  for (int i = -10; i <= 10; ++i) rest.push_back(component(0.1f * float(i), 0.0f, 0.3f, 0));
  rest.push_back(component(0.0f, -3.0f, 1.2f, 2));  // a tall stalk out of the slab
  MeadowCloseUp view = layout_meadow_close_up(rest, 120, 80, 400.0f);
  EXPECT_EQ(view.width, 120);
  EXPECT_GE(view.window(), 1.5f - 1e-4f);
  EXPECT_GE(view.depth, 0.2f);
  EXPECT_LE(view.depth, 2.0f);
  Image calm = draw_meadow_close_up(view, 0.0f, 0.0f, 0.0f, rest, rest, palette(), {});
  ASSERT_EQ(calm.width(), 120);
  ASSERT_EQ(calm.height(), 80);
  // The blade at x = 0 stands in the middle column, up from the ground line.
  float s = view.pixels_per_meter;
  int blade_top = view.ground_row - int(0.3f * s);
  Rgb mid = calm.at(60, (view.ground_row + blade_top) / 2);
  EXPECT_GT(mid.g, mid.b) << "green blade";
  // The tall stalk 3 m behind is not in the slab.
  Rgb above = calm.at(60, std::max(1, view.ground_row - int(0.9f * s)));
  EXPECT_GT(above.b, above.g) << "sky";
  // Bent components over their rest poses: the frame changes, and a ball shows in red.
  std::vector<MeadowComponent> bent = rest;
  for (MeadowComponent& c : bent) c.center[0] += 0.1f;
  Ball ball;  // in front of the blades
  ball.center[0] = 0.4f;
  ball.center[1] = 0.1f;
  ball.center[2] = 0.3f;
  ball.radius = 0.1f;
  Image windy = draw_meadow_close_up(view, 0.0f, 0.0f, 0.0f, bent, rest, palette(), {ball});
  Rgb red = windy.at(int(60.0f + 0.4f * s), int(float(view.ground_row) - 0.1f * s));
  EXPECT_GT(red.r, 0.6f);
  EXPECT_LT(red.g, 0.4f);
  int differing = 0;
  for (int y = 0; y < 80; ++y) {
    for (int x = 0; x < 120; ++x) {
      Rgb a = calm.at(x, y);
      Rgb b = windy.at(x, y);
      differing += std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b) > 0.05f;
    }
  }
  EXPECT_GT(differing, 50);
}

}  // namespace
}  // namespace boreas::render
