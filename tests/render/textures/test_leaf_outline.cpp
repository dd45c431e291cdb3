// Leaf outline tests: the float outline of cl/shared/leaf_outline.h (what the rays test)
// against the renderer's double twin (render/textures/leaf_shape.h, what the textures draw),
// each kind's area, the oak's sinuses, and the quad mapping's round trip.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/leaf_outline.h"
#include "textures/leaf_shape.h"

namespace boreas::render {
namespace {

LeafShape shape_of(int outline) {
  LeafShape s;
  s.outline = outline;
  return s;
}

// Whether the double outline's answer is the same within `margin` texture units each way:
// a point that far from the margin has one answer whatever float rounding does.
bool far_from_margin(const LeafShape& s, double u, double v, double margin) {
  const bool in = inside_leaf(s, u, v);
  for (double du : {-margin, 0.0, margin})
    for (double dv : {-margin, 0.0, margin})
      if (inside_leaf(s, u + du, v + dv) != in) return false;
  return true;
}

TEST(LeafOutline, FloatAgreesWithDoubleAwayFromTheMargin) {
  // 1e-4 texture units is hundreds of float ulps at these magnitudes, and the polynomials'
  // relative error (~1e-7) moves the margin by far less.
  const int n = 301;
  for (int k = 0; k < BOREAS_LEAF_OUTLINE_COUNT; ++k) {
    const LeafShape s = shape_of(k);
    int compared = 0, differ = 0;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const double u = (i + 0.37) / n, v = (j + 0.61) / n;
        if (!far_from_margin(s, u, v, 1e-4)) continue;
        ++compared;
        differ += boreas_leaf_outline_inside(k, float(u), float(v)) != int(inside_leaf(s, u, v));
      }
    }
    EXPECT_GT(compared, n * n * 9 / 10) << "kind " << k;
    EXPECT_EQ(differ, 0) << "kind " << k;
  }
}

double area_fraction(int outline, bool use_float, int n) {
  const LeafShape s = shape_of(outline);
  long in = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      in += use_float ? boreas_leaf_outline_inside(outline, float(u), float(v))
                      : inside_leaf(s, u, v);
    }
  return double(in) / (double(n) * n);
}

TEST(LeafOutline, AreaOfEachKindMatchesTheDoubleOutline) {
  // Measured on a 600 x 600 grid; the two may differ only at points within float error of
  // the margin (measured: at most a dozen of the 360000, where a tooth's drop or the tip
  // turns a float rounding of t into a step of the half-width). The areas themselves order as the
  // kinds' shapes do: the round aspen covers most, the deeply lobed oak least.
  double area[BOREAS_LEAF_OUTLINE_COUNT];
  for (int k = 0; k < BOREAS_LEAF_OUTLINE_COUNT; ++k) {
    area[k] = area_fraction(k, true, 600);
    EXPECT_NEAR(area[k], area_fraction(k, false, 600), 1e-4) << "kind " << k;
    EXPECT_GT(area[k], 0.15) << "kind " << k;
    EXPECT_LT(area[k], 0.5) << "kind " << k;
  }
  for (int k = 0; k < BOREAS_LEAF_OUTLINE_COUNT; ++k) {
    if (k != BOREAS_LEAF_OUTLINE_ASPEN) {
      EXPECT_GT(area[BOREAS_LEAF_OUTLINE_ASPEN], area[k]);
    }
    if (k != BOREAS_LEAF_OUTLINE_OAK) {
      EXPECT_LT(area[BOREAS_LEAF_OUTLINE_OAK], area[k]);
    }
  }
}

// The oak's sinuses sit at blade parameter t = k / lobes; its lobes' tips halfway between.
float oak_v(double t) {
  return float(BOREAS_LEAF_BLADE_BASE_V + t * (BOREAS_LEAF_BLADE_TIP_V - BOREAS_LEAF_BLADE_BASE_V));
}

TEST(LeafOutline, OakSinusesAreOutsideAndItsLobesInside) {
  const BoreasLeafOutline& oak = boreas_leaf_outlines[BOREAS_LEAF_OUTLINE_OAK];
  ASSERT_GT(oak.lobes, 0.0f);
  for (int k = 1; k <= 3; ++k) {
    const double sinus = k / double(oak.lobes), lobe = (k - 0.5) / double(oak.lobes);
    for (float side : {-1.0f, 1.0f}) {
      // Two thirds of the way out: past a sinus's bottom (45% of the half-width deep) but
      // within the lobes on either side of it.
      const float x = side * 0.6f * BOREAS_LEAF_BLADE_HALF_WIDTH *
                      float(std::pow(lobe, 0.8) * std::pow(1.0 - lobe, 0.8) / 0.25);
      EXPECT_FALSE(boreas_leaf_outline_inside(BOREAS_LEAF_OUTLINE_OAK, 0.5f + x, oak_v(sinus)))
          << "sinus " << k << " side " << side;
      EXPECT_TRUE(boreas_leaf_outline_inside(BOREAS_LEAF_OUTLINE_OAK, 0.5f + x, oak_v(lobe)))
          << "lobe " << k << " side " << side;
    }
  }
}

TEST(LeafOutline, PetioleAndBladeInsideCornersOutside) {
  for (int k = 0; k < BOREAS_LEAF_OUTLINE_COUNT; ++k) {
    EXPECT_TRUE(boreas_leaf_outline_inside(k, 0.5f, 0.08f)) << "petiole, kind " << k;
    EXPECT_TRUE(boreas_leaf_outline_inside(k, 0.5f, 0.5f)) << "midrib, kind " << k;
    EXPECT_FALSE(boreas_leaf_outline_inside(k, 0.51f, 0.015f)) << "below the stem, kind " << k;
    for (float u : {0.0f, 1.0f})
      for (float v : {0.0f, 1.0f}) EXPECT_FALSE(boreas_leaf_outline_inside(k, u, v));
  }
}

TEST(LeafOutline, UvAndOffsetsRoundTripTheRenderersQuad) {
  // boreas_leaf_offsets is leaf.vert's placement; boreas_leaf_uv inverts it.
  const float length = 0.09f, width = 0.05f;
  float along = 0.0f, across = 0.0f;
  boreas_leaf_offsets(0.5f, BOREAS_LEAF_BLADE_BASE_V, length, width, &along, &across);
  EXPECT_FLOAT_EQ(along, 0.0f);  // the record's base is the blade's base
  EXPECT_FLOAT_EQ(across, 0.0f);
  boreas_leaf_offsets(0.5f + BOREAS_LEAF_BLADE_HALF_WIDTH, BOREAS_LEAF_BLADE_TIP_V, length, width,
                      &along, &across);
  EXPECT_FLOAT_EQ(along, length);         // the blade's tip is the leaf's length away
  EXPECT_FLOAT_EQ(across, 0.5f * width);  // its widest point half its width aside
  for (float u : {0.0f, 0.3f, 1.0f})
    for (float v : {0.0f, 0.7f, 1.0f}) {
      boreas_leaf_offsets(u, v, length, width, &along, &across);
      float u2 = 0.0f, v2 = 0.0f;
      boreas_leaf_uv(along, across, length, width, &u2, &v2);
      EXPECT_NEAR(u2, u, 1e-6f);
      EXPECT_NEAR(v2, v, 1e-6f);
    }
}

}  // namespace
}  // namespace boreas::render
