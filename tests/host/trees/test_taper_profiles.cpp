// boreas tests: nTaper between 1 and 3 against Arbaro 1.9.9's radius function
// (StemImpl.stemRadius, transcribed below in double): the deformer's radius functions carry a
// stem's taper as a cone, Arbaro's beads (the bulges) and the tip's cap (tree_generator.cpp,
// set_taper); Arbaro's profile ends in a hemisphere (1..2) or is a row of spherical beads
// (2..3). Measured here: the mean radius and the volume (mean r^2) over the stem, the
// profile point by point, in the double reference and in the shared header's float.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#define BOREAS_FAST_MATH 1
#include "reference/tree_reference.h"
#include "boreas/boreas.hpp"
#include "shared/tree_math.h"
#include "support/temp_dir.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace boreas::impl {
namespace {

// Arbaro's stemRadius(h) for a stem of length `length` and base radius `base`, z = h / length
// (no flare, lobes or 0Scale: a plain stem).
double arbaro_radius(double n_taper, double length, double base, double z) {
  double unit_taper = 0.0;
  if (n_taper <= 1.0) {
    unit_taper = n_taper;
  } else if (n_taper <= 2.0) {
    unit_taper = 2.0 - n_taper;
  }
  double radius = base * (1.0 - unit_taper * z);
  if (n_taper > 1.0) {
    const double z2 = (1.0 - z) * length;
    const double depth = (n_taper < 2.0 || z2 < radius) ? 1.0 : n_taper - 2.0;
    const double z3 =
        n_taper < 2.0 ? z2 : std::fabs(z2 - 2.0 * radius * double(int(z2 / 2.0 / radius + 0.5)));
    if (n_taper > 2.0 || z3 < radius)
      radius = (1.0 - depth) * radius +
               depth * std::sqrt(std::max(0.0, radius * radius - (z3 - radius) * (z3 - radius)));
  }
  return radius;
}

// A one-level species: a straight trunk 10 m long of base radius 10 m * ratio.
Species trunk_species(double n_taper, double ratio) {
  Species s;
  s.name = "taper";
  s.levels = 1;
  s.scale = 10.0;
  s.scale_v = 0.0;
  s.ratio = ratio;
  s.flare = 0.0;
  s.lobes = 0;
  s.lobe_depth = 0.0;
  s.leaves = 0;
  s.trunk_scale = 1.0;
  s.trunk_scale_v = 0.0;
  s.level[0].length = 1.0;
  s.level[0].length_v = 0.0;
  s.level[0].branches = 1;
  s.level[0].curve_res = 3;
  s.level[0].taper = n_taper;
  return s;
}

struct Means {
  double radius = 0.0, volume = 0.0;  // mean r and mean r^2 over the stem
};

TEST(TaperProfiles, MeanRadiusAndVolumeFollowArbaroBetweenOneAndThree) {
  constexpr int kSamples = 200000;
  for (double ratio : {0.02, 0.05}) {
    for (double n_taper : {1.03, 1.4, 1.7, 1.9, 2.0, 2.1, 2.5, 2.9}) {
      SCOPED_TRACE(testing::Message() << "nTaper " << n_taper << ", r / L " << ratio);
      const TreeModel t = grow_tree(trunk_species(n_taper, ratio), 1);
      ASSERT_EQ(t.branches.size(), 1u);
      const BranchModel& trunk = t.branches[0];
      const reference::BranchRadius p = reference::BranchRadius::of(trunk);
      const double length = trunk.length, base = length * ratio;
      ASSERT_DOUBLE_EQ(length, 10.0);
      Means ours, arbaro;
      for (int k = 0; k < kSamples; ++k) {
        const double z = (k + 0.5) / kSamples;
        const double r = reference::branch_radius(p, z, 0.0);
        const double a = arbaro_radius(n_taper, length, base, z);
        ours.radius += r / kSamples;
        ours.volume += r * r / kSamples;
        arbaro.radius += a / kSamples;
        arbaro.volume += a * a / kSamples;
        // 1..2: the linear taper is Arbaro's wherever its tip hemisphere has not begun, and
        // the hemisphere Arbaro's to the cone's narrowing over it (its sphere has the local
        // radius, the cap the tip's).
        const double tip = (n_taper - 1.0) * base;
        if (n_taper < 2.0 && (1.0 - z) * length > base) EXPECT_NEAR(r, a, 1e-12 * base) << z;
        if (n_taper < 2.0) EXPECT_NEAR(r, a, (2.0 - n_taper) * base / length * tip + 1e-12) << z;
        // 2..3: Arbaro's beads and its hemisphere, to rounding (which a waist's sqrt turns
        // from 1e-16 into 1e-8).
        if (n_taper >= 2.0) ASSERT_NEAR(r, a, 1e-7 * base) << z;
      }
      std::printf("    nTaper %.2f r/L %.2f: mean radius %+5.2f %%, volume %+5.2f %%\n", n_taper,
                  ratio, 100.0 * (ours.radius / arbaro.radius - 1.0),
                  100.0 * (ours.volume / arbaro.volume - 1.0));
      EXPECT_NEAR(ours.radius / arbaro.radius, 1.0, n_taper < 2.0 ? 1e-3 : 1e-9);
      EXPECT_NEAR(ours.volume / arbaro.volume, 1.0, n_taper < 2.0 ? 1e-3 : 1e-9);
    }
  }
}

// The old approximation (a profile 1 - v^p of the same mean) put up to 11 % more wood in a
// stem of nTaper 1.4 than Arbaro's; now the stem is Arbaro's cone, cut at (nTaper - 1) r
// where its hemisphere begins, one tip radius short of the end, and closed there.
TEST(TaperProfiles, BetweenOneAndTwoTheTipIsTheConesCutClosedByAHemisphere) {
  const TreeModel t = grow_tree(trunk_species(1.4, 0.02), 1);
  const BranchModel& trunk = t.branches[0];
  const reference::BranchRadius p = reference::BranchRadius::of(trunk);
  const double tip = 0.4 * trunk.radius;
  EXPECT_DOUBLE_EQ(trunk.tip_cap, tip / trunk.length);
  EXPECT_NEAR(reference::branch_radius(p, 1.0 - trunk.tip_cap, 0.0),
              trunk.radius * (1.0 - 0.6 * (1.0 - trunk.tip_cap)), 1e-12);
  EXPECT_NEAR(reference::branch_radius(p, 0.5, 0.0), 0.7 * trunk.radius, 1e-12);
  EXPECT_EQ(reference::branch_radius(p, 1.0, 0.0), 0.0);
}

// Near the tip: the shared header's radius and slope (float, as the kernels, the mesh and the
// rays evaluate it) against the double reference, and both against the analytic hemisphere
// of the tip's radius: r = r_tip sqrt(w (2 - w)) times the cone's own widening over the cap,
// 1 + eps w, eps = (2 - nTaper) r / L (its slope), so within eps r_tip of the hemisphere.
TEST(TaperProfiles, TheTipIsAHemisphereInTheHeaderAndTheReference) {
  for (double n_taper : {1.1, 1.5, 1.9}) {
    SCOPED_TRACE(testing::Message() << "nTaper " << n_taper);
    const TreeModel t = grow_tree(trunk_species(n_taper, 0.04), 1);
    const BranchModel& trunk = t.branches[0];
    const reference::BranchRadius p = reference::BranchRadius::of(trunk);
    const double cap = trunk.tip_cap, tip = (n_taper - 1.0) * trunk.radius;
    ASSERT_GT(cap, 0.0);
    BoreasBranchRadius f{};
    f.radius = float(p.radius);
    f.taper_depth = float(p.taper_depth);
    f.taper_exponent = float(p.taper_exponent);
    f.flare = float(p.flare);
    f.lobe_taper = float(p.lobe_taper);
    f.tip_cap = float(cap);
    const double eps = (2.0 - n_taper) * trunk.radius / trunk.length;
    double worst_sphere = 0.0;
    for (int k = 0; k <= 1000; ++k) {
      // v as the float it is drawn at (1 - v is short of digits there).
      const double v = double(float(1.0 - k / 1000.0 * cap)), w = std::min((1.0 - v) / cap, 1.0);
      double dr_ref = 0.0;
      const double r_ref = reference::branch_radius(p, v, 0.0, &dr_ref);
      float r = 0.0f, dr = 0.0f, lobes = 0.0f, d_lobes = 0.0f;
      boreas_branch_radius(f, float(v), 0.0f, &r, &dr, &lobes, &d_lobes);
      ASSERT_NEAR(r, r_ref, 2e-6 * trunk.radius + 1e-5 * tip) << "w " << w;
      // The slope: relative, away from the tip where float's w loses its digits.
      if (w > 0.01) ASSERT_NEAR(dr, dr_ref, 1e-3 * std::fabs(dr_ref) + 1e-5 * trunk.radius) << "w " << w;
      const double sphere = tip * std::sqrt(w * (2.0 - w));
      ASSERT_NEAR(r_ref, sphere, 1.001 * eps * tip) << "w " << w;
      // Going in from the tip, r grows as the circle's, (1 - w) / sqrt(w (2 - w)) per tip
      // radius, and the cone's slope with it: their ratio is 1 + eps (w + w (2 - w) / (1 - w)).
      if (w > 0.01 && w < 0.99) {
        const double circle = (1.0 - w) / std::sqrt(w * (2.0 - w));
        ASSERT_NEAR(-dr_ref / trunk.length / circle, 1.0,
                    1.01 * eps * (w + w * (2.0 - w) / (1.0 - w)) + 1e-9) << "w " << w;
      }
      worst_sphere = std::max(worst_sphere, std::fabs(r_ref - sphere) / tip);
    }
    std::printf("    nTaper %.1f: cap %.4f of the length, worst off the hemisphere %.2g r_tip\n",
                n_taper, cap, worst_sphere);
    EXPECT_EQ(reference::branch_radius(p, 1.0, 0.0), 0.0);
    // Below the cap the radius is the cone's, bit for bit the uncapped function's.
    BoreasBranchRadius open = f;
    open.tip_cap = 0.0f;
    for (double v : {0.0, 0.3, 0.9, 1.0 - 1.01 * cap}) {
      float r0, d0, l0, dl0, r1, d1, l1, dl1;
      boreas_branch_radius(f, float(v), 0.25f, &r0, &d0, &l0, &dl0);
      boreas_branch_radius(open, float(v), 0.25f, &r1, &d1, &l1, &dl1);
      EXPECT_EQ(r0, r1) << v;
      EXPECT_EQ(d0, d1) << v;
    }
  }
}

// nTaper 2..3 in the shared header's float (the kernels, the mesh, the rays) against the double
// reference, which the test above holds to Arbaro's: the radius at every v to the float's
// rounding of the distance from the tip (amplified near a waist, where the bead's sqrt is
// steep), the slope where the bead's circle is not near vertical; and the waists and crests
// where Arbaro puts them: a waist every two radii from the tip, of (3 - nTaper) r.
TEST(TaperProfiles, TheBeadsAreArbarosInTheHeader) {
  for (double n_taper : {2.1, 2.5, 3.0}) {
    SCOPED_TRACE(testing::Message() << "nTaper " << n_taper);
    const TreeModel t = grow_tree(trunk_species(n_taper, 0.04), 1);
    const BranchModel& trunk = t.branches[0];
    const reference::BranchRadius p = reference::BranchRadius::of(trunk);
    const double base = trunk.radius, depth = n_taper - 2.0, length = trunk.length;
    ASSERT_DOUBLE_EQ(trunk.bulge_count, length / (2.0 * base));
    BoreasBranchRadius f{};
    f.radius = float(p.radius);
    f.taper_depth = float(p.taper_depth);
    f.taper_exponent = float(p.taper_exponent);
    f.lobe_taper = float(p.lobe_taper);
    f.bulge_count = float(p.bulge_count);
    f.bulge_depth = float(p.bulge_depth);
    f.bulge_phase = float(p.bulge_phase);
    f.tip_cap = float(p.tip_cap);
    // The float's error in x (radii from the tip, up to L / r = 25) is a few of its ulps.
    const double dx = 8.0 * (length / base) * std::ldexp(1.0, -24);
    for (int k = 0; k <= 20000; ++k) {
      const double v = double(float(k / 20000.0));
      double dr_ref = 0.0;
      const double r_ref = reference::branch_radius(p, v, 0.0, &dr_ref);
      float r = 0.0f, dr = 0.0f, lobes = 0.0f, d_lobes = 0.0f;
      boreas_branch_radius(f, float(v), 0.0f, &r, &dr, &lobes, &d_lobes);
      const double x = (1.0 - v) * length / base, z = std::fabs(x - 2.0 * std::floor(0.5 * x + 0.5));
      const double root = std::sqrt(z * (2.0 - z));
      const double steep = std::min(std::sqrt(2.0 * dx), dx / std::max(root, 1e-12));
      ASSERT_NEAR(r, r_ref, base * (2e-6 + depth * steep)) << "v " << v;
      if (x > 1.0 && root > 0.2)
        ASSERT_NEAR(dr, dr_ref, 1e-3 * std::fabs(dr_ref) + 2e-3 * base) << "v " << v;
    }
    // Waists and crests: x = 2, 4, ... and 3, 5, ... radii from the tip.
    for (double x : {2.0, 3.0, 4.0, 7.0, 10.0}) {
      const double v = 1.0 - x * base / length;
      const double expected = std::fmod(x, 2.0) == 0.0 ? (1.0 - depth) * base : base;
      EXPECT_NEAR(reference::branch_radius(p, v, 0.0), expected, 1e-7 * base) << "x " << x;
      EXPECT_NEAR(arbaro_radius(n_taper, length, base, 1.0 - x * base / length), expected,
                  1e-7 * base) << "x " << x;
    }
    EXPECT_EQ(reference::branch_radius(p, 1.0, 0.0), 0.0);
  }
}

// A split beaded stem: each piece's beads carry their place from the stem's tip (the phase),
// so every piece, clones and continuation alike, is Arbaro's stem over its own stretch.
TEST(TaperProfiles, TheBeadsRunOnAcrossASplitStemsPieces) {
  Species s = trunk_species(2.6, 0.03);
  s.level[0].curve_res = 6;
  s.level[0].seg_splits = 1.0;
  s.level[0].split_angle = 20.0;
  const TreeModel t = grow_tree(s, 3);
  ASSERT_GT(t.branches.size(), 1u);
  const double base = t.branches[0].radius, length = t.branches[0].stem_length;
  int inner = 0;
  for (const BranchModel& b : t.branches) {
    const double end = b.stem_from + b.length / b.stem_length;
    if (end < 1.0 - 1e-9) ++inner;
    EXPECT_NEAR(b.bulge_phase, (1.0 - end) * length / (2.0 * base), 1e-9 * length / base);
    const reference::BranchRadius p = reference::BranchRadius::of(b);
    for (int k = 0; k <= 200; ++k) {
      const double v = k / 200.0, z = b.stem_from + v * b.length / b.stem_length;
      ASSERT_NEAR(reference::branch_radius(p, v, 0.0), arbaro_radius(2.6, length, base, z),
                  1e-7 * base) << "piece from " << b.stem_from << ", v " << v;
    }
  }
  EXPECT_GE(inner, 1);  // a piece that ends at a split, with a phase
}

// Pieces: a split stem carries the cap on the pieces that reach its tip only, in their own v.
TEST(TaperProfiles, TheCapSitsOnTheStemsLastPieces) {
  Species s = trunk_species(1.5, 0.03);
  s.level[0].curve_res = 6;
  s.level[0].seg_splits = 1.0;
  s.level[0].split_angle = 20.0;
  const TreeModel t = grow_tree(s, 3);
  ASSERT_GT(t.branches.size(), 1u);
  int capped = 0;
  for (const BranchModel& b : t.branches) {
    const double end = b.stem_from + b.length / b.stem_length;
    if (end < 1.0 - 1e-9) {
      EXPECT_EQ(b.tip_cap, 0.0);
    } else {
      ++capped;
      // The cap is as long as the tip is thick: the cone's radius where it begins, to the
      // cone's narrowing over it ((2 - nTaper) / (nTaper - 1) times the cap, 1.5 % here).
      const reference::BranchRadius p = reference::BranchRadius::of(b);
      reference::BranchRadius cone = p;
      cone.tip_cap = 0.0;
      const double tip = reference::branch_radius(cone, 1.0 - b.tip_cap, 0.0);
      EXPECT_NEAR(b.tip_cap * b.length, tip, 0.03 * tip);
      EXPECT_EQ(reference::branch_radius(p, 1.0, 0.0), 0.0);
    }
  }
  EXPECT_GE(capped, 2);  // the continuation and at least one clone
}

// The world's mesh and its rays close the tip: a straight pole of 0Taper 1.5 ends in one point
// on its axis (the mesh's last ring, its normals along the axis), and a ray coming down beside
// the axis meets the cone from the last full ring to that point where the mesh's triangle is.
TEST(TaperProfiles, TheMeshAndTheRaysCloseTheTip) {
  test::TempDir dir;
  const std::string path = (dir.path() / "capped_pole.json").string();
  std::ofstream(path) << R"({"format": "boreas-species-1", "name": "capped_pole", "params": {
    "Levels": 1, "Scale": 10, "ScaleV": 0, "Flare": 0, "Lobes": 0, "Leaves": 0, "Ratio": 0.03,
    "0Taper": 1.5, "0Curve": 0, "0CurveV": 0, "0CurveBack": 0, "0SegSplits": 0}})";
  boreas_world_def wd = boreas_default_world_def();
  wd.wave_count = 0;
  World world(wd);
  boreas_tree_def def = boreas_default_tree_def();
  def.species = path.c_str();
  const TreeId tree = world.add_tree(def);
  const std::vector<boreas_branch> branches = world.tree_get_branches(tree);
  ASSERT_EQ(branches.size(), 1u);
  const float* tip = branches[0].control_points[3];
  const int rings = def.levels[0].rings, sides = def.levels[0].sides;
  const std::vector<boreas_vertex> mesh = world.tree_get_mesh(tree).vertices;
  ASSERT_EQ(mesh.size(), size_t((rings + 1) * (sides + 1)));
  const auto vertex = [&](int ring, int side) { return mesh[size_t(ring * (sides + 1) + side)]; };
  for (int k = 0; k <= sides; ++k) {
    const boreas_vertex& a = vertex(rings, k);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.position[c], tip[c], 1e-5f) << k;
    EXPECT_GT(a.normal[1], 0.999f) << k;  // along the axis, +y (the clamp leans it ~1e-3)
  }
  // The last rings go round the hemisphere (boreas_ring_v): every vertex of the cap's m rings
  // and of its rim lies one tip radius from the rim's centre (to the cone's narrowing over
  // the cap, 1.5 % here), at the angles 90 deg j / m from the rim, its normal pointing away from
  // that centre; the rim itself one tip radius short of the tip.
  const int m = BOREAS_CAP_RINGS(rings);
  ASSERT_EQ(m, 3);  // 12 rings
  const double r_tip = 0.5 * 0.03 * 10.0, top = tip[1];
  const double centre[3] = {tip[0], top - r_tip, tip[2]};
  for (int j = 0; j <= m; ++j) {
    const double phi = 0.5 * 3.14159265358979323846 * j / m;
    for (int k = 0; k < sides; ++k) {
      const boreas_vertex& a = vertex(rings - m + j, k);
      double d[3], len = 0.0;
      for (int c = 0; c < 3; ++c) {
        d[c] = a.position[c] - centre[c];
        len += d[c] * d[c];
      }
      len = std::sqrt(len);
      EXPECT_NEAR(len, r_tip, 0.02 * r_tip) << "ring " << rings - m + j << " side " << k;
      EXPECT_NEAR(d[1] / len, std::sin(phi), 0.02) << "ring " << rings - m + j << " side " << k;
      if (j > 0 && j < m) {
        double cosine = 0.0;
        for (int c = 0; c < 3; ++c) cosine += d[c] / len * a.normal[c];
        EXPECT_GT(cosine, 0.999) << "ring " << rings - m + j << " side " << k;
      }
    }
  }
  // Rays down beside the axis, through the middle of each face of the last band.
  const float* apex = vertex(rings, 0).position;
  std::vector<boreas_ray> rays;
  std::vector<double> expected;
  for (int k = 0; k < sides; ++k) {
    const boreas_vertex &a = vertex(rings - 1, k), &b = vertex(rings - 1, k + 1);
    double m[3], e1[3], e2[3];
    for (int c = 0; c < 3; ++c) {
      m[c] = 0.5 * (double(a.position[c]) + b.position[c]) - apex[c];
      e1[c] = double(a.position[c]) - apex[c];
      e2[c] = double(b.position[c]) - apex[c];
    }
    // 0.3 of the way out from the axis toward the face's middle, from 5 m above the tip.
    const double x = apex[0] + 0.3 * m[0], z = apex[2] + 0.3 * m[2], from = 5.0;
    // The face's plane through the apex: n . (p - apex) = 0 at p = (x, y, z).
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    const double y = apex[1] - (n[0] * (x - apex[0]) + n[2] * (z - apex[2])) / n[1];
    rays.push_back({{float(x), float(apex[1] + from), float(z)}, {0.0f, -1.0f, 0.0f}, 100.0f});
    expected.push_back(apex[1] + from - y);
  }
  const std::vector<boreas_hit> hits = world.cast_rays(rays);
  for (size_t i = 0; i < hits.size(); ++i) {
    EXPECT_EQ(hits[i].kind, BOREAS_HIT_BRANCH) << i;
    EXPECT_NEAR(hits[i].distance, expected[i], 1e-5 * 5.0) << i;
    // Below the apex by less than the band: the tip is closed, not cut flat.
    EXPECT_GT(expected[i], 5.0) << i;
  }
}

}  // namespace
}  // namespace boreas::impl
