// render tests: the drawing pieces on their own: color map, shapes, text, the wind frame
// and contact sheets.
#include "image/image.h"

#include <gtest/gtest.h>

#include <cmath>

#include "image/bitmap_font.h"
#include "image/color_map.h"
#include "image/contact_sheet.h"
#include "image/draw.h"
#include "image/wind_view.h"

namespace boreas::render {
namespace {

bool same(Rgb a, Rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

TEST(ColorMap, ViridisRunsFromDarkPurpleToYellowAndClamps) {
  Rgb low = viridis(0.0f);
  Rgb high = viridis(1.0f);
  EXPECT_NEAR(low.r, 68.0f / 255.0f, 1e-6f);
  EXPECT_NEAR(low.b, 84.0f / 255.0f, 1e-6f);
  EXPECT_NEAR(high.r, 253.0f / 255.0f, 1e-6f);
  EXPECT_NEAR(high.g, 231.0f / 255.0f, 1e-6f);
  EXPECT_TRUE(same(viridis(-1.0f), low));
  EXPECT_TRUE(same(viridis(std::nanf("")), low));
  EXPECT_TRUE(same(viridis(7.0f), high));
  EXPECT_TRUE(same(speed_color(30.0f, 15.0f), high));
  // Lightness grows along the map, so speed reads in grayscale too.
  float previous = -1.0f;
  for (int i = 0; i <= 20; ++i) {
    Rgb c = viridis(float(i) / 20.0f);
    float luma = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
    EXPECT_GT(luma, previous) << i;
    previous = luma;
  }
}

TEST(Draw, ArrowCoversItsShaftAndTipOnly) {
  Image image(40, 20);
  draw_arrow(image, {5.0f, 10.0f}, {35.0f, 10.0f}, 2.0f, {1, 1, 1}, {0, 0, 0});
  EXPECT_GT(image.at(10, 9).r, 0.9f);             // shaft
  EXPECT_GT(image.at(33, 9).r, 0.5f);             // head
  EXPECT_TRUE(same(image.at(20, 2), {0, 0, 0}));  // far above the shaft
  EXPECT_TRUE(same(image.at(1, 10), {0, 0, 0}));  // behind the tail
}

TEST(Draw, ShapesOffTheEdgeAreClipped) {
  Image image(8, 8);
  draw_segment(image, {-20.0f, -20.0f}, {30.0f, 30.0f}, 3.0f, {1, 0, 0});
  fill_triangle(image, {-5.0f, 0.0f}, {20.0f, 0.0f}, {0.0f, 20.0f}, {0, 1, 0}, 0.5f);
  EXPECT_GT(image.at(4, 4).r + image.at(4, 4).g, 0.5f);
}

TEST(BitmapFont, TextStaysInsideItsBox) {
  Image image(100, 20);
  std::string text = "T=1.25 S m/s";
  draw_text(image, 3, 4, text, 1, {1, 1, 1});
  int right = 3 + text_width(text, 1);
  int lit = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      if (image.at(x, y).r == 0.0f) continue;
      ++lit;
      EXPECT_TRUE(x >= 3 && x < right && y >= 4 && y < 4 + kGlyphHeight) << x << "," << y;
    }
  }
  EXPECT_GT(lit, 40);
  EXPECT_EQ(text_width("AB", 2), (2 * kGlyphAdvance - 1) * 2);
}

TEST(WindView, CalmFieldIsTheZeroColorWithoutArrows) {
  std::vector<float> wind(32 * 24 * 3, 0.0f);
  WindView view;
  view.width = 32;
  view.height = 24;
  view.wind = &wind;
  view.color_max = 5.0f;
  Image image = draw_wind_view(view);
  for (int y = 0; y < 24; ++y) {
    for (int x = 0; x < 32; ++x) EXPECT_TRUE(same(image.at(x, y), viridis(0.0f)));
  }
}

TEST(WindView, ArrowsPointAlongTheWind) {
  // A steady wind along +z (image down) at the top of the scale: arrows are vertical.
  const int size = 64;
  std::vector<float> wind(size * size * 3, 0.0f);
  for (size_t i = 0; i < wind.size(); i += 3) wind[i + 2] = 4.0f;
  WindView view;
  view.width = size;
  view.height = size;
  view.wind = &wind;
  view.color_max = 4.0f;
  Image image = draw_wind_field(view);
  int spacing = arrow_spacing(size, size);
  int site = (size - (size / spacing - 1) * spacing) / 2;
  Rgb field = viridis(1.0f);
  EXPECT_GT(image.at(site, site + spacing / 4).r, 0.95f);        // white shaft below the site
  EXPECT_TRUE(same(image.at(site + spacing / 2, site), field));  // nothing beside it
}

TEST(WindView, SpeedLabels) {
  EXPECT_EQ(speed_label(0.0f), "0");
  EXPECT_EQ(speed_label(15.0f), "15");
  EXPECT_EQ(speed_label(7.5f), "7.5");
  EXPECT_EQ(speed_label(0.25f), "0.25");
}

TEST(ContactSheet, PicksEvenlySpacedFramesWithFirstAndLast) {
  EXPECT_EQ(contact_sheet_frames(24, 8), (std::vector<int>{0, 3, 6, 9, 13, 16, 19, 23}));
  EXPECT_EQ(contact_sheet_frames(2, 8), (std::vector<int>{0, 1}));
  EXPECT_EQ(contact_sheet_frames(1, 8), (std::vector<int>{0}));
}

TEST(ContactSheet, TilesShrunkFramesInRows) {
  Image red(100, 50, {1, 0, 0});
  Image blue(100, 50, {0, 0, 1});
  std::vector<SheetTile> tiles = {{&red, ""}, {&blue, ""}, {&red, ""}};
  Image sheet = make_contact_sheet(tiles, 2, 40, "");
  // Two columns of 40x20 tiles, two rows, 4-pixel gaps.
  EXPECT_EQ(sheet.width(), 4 + 2 * (40 + 4));
  EXPECT_EQ(sheet.height(), 4 + 2 * (20 + 4));
  EXPECT_NEAR(sheet.at(4 + 20, 4 + 10).r, 1.0f, 1e-3f);
  EXPECT_NEAR(sheet.at(48 + 20, 4 + 10).b, 1.0f, 1e-3f);
  EXPECT_NEAR(sheet.at(4 + 20, 28 + 10).r, 1.0f, 1e-3f);
}

}  // namespace
}  // namespace boreas::render
