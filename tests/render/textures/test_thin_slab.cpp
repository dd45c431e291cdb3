// Texture generator tests: the Kubelka-Munk thin slab against its closed-form limits, the
// textbook hyperbolic form and its inversion, and the default leaf constants.
#include "textures/thin_slab.h"

#include <gtest/gtest.h>

#include <cmath>

#include "textures/texture_error.h"

namespace boreas::render {
namespace {

// Kubelka-Munk as usually printed: T = b / (a sinh(bSd) + b cosh(bSd)), R = sinh(bSd) / (...).
struct TextbookRt {
  double r;
  double t;
};
TextbookRt textbook(double k, double s, double d) {
  double a = 1.0 + k / s;
  double b = std::sqrt(a * a - 1.0);
  double denominator = a * std::sinh(b * s * d) + b * std::cosh(b * s * d);
  return {std::sinh(b * s * d) / denominator, b / denominator};
}

TEST(ThinSlab, VanishingScatteringThicknessTransmitsEverythingWithoutAbsorption) {
  KubelkaMunkSlab slab({0.0, 3.0});
  EXPECT_DOUBLE_EQ(slab.transmittance(0.0), 1.0);
  EXPECT_DOUBLE_EQ(slab.reflectance(0.0), 0.0);
  for (double d : {1e-3, 1e-6, 1e-9}) {
    EXPECT_NEAR(slab.transmittance(d), 1.0, 4.0 * d) << d;
    EXPECT_GT(slab.transmittance(d), slab.transmittance(10.0 * d)) << d;
  }
  KubelkaMunkSlab empty({0.0, 0.0});
  EXPECT_DOUBLE_EQ(empty.transmittance(5.0), 1.0);
}

TEST(ThinSlab, ConservativeSlabTransmitsOneOverOnePlusSd) {
  for (double s : {0.5, 3.0, 40.0}) {
    KubelkaMunkSlab slab({0.0, s});
    for (double d : {0.01, 0.2, 1.0, 7.0}) {
      EXPECT_NEAR(slab.transmittance(d), 1.0 / (1.0 + s * d), 1e-14) << s << " " << d;
      EXPECT_NEAR(slab.reflectance(d), s * d / (1.0 + s * d), 1e-14) << s << " " << d;
    }
  }
}

TEST(ThinSlab, PureAbsorberFollowsBeerLambert) {
  KubelkaMunkSlab slab({5.0, 0.0});
  for (double d : {1e-5, 0.01, 0.2, 2.0}) {
    EXPECT_NEAR(slab.transmittance(d), std::exp(-5.0 * d), 1e-14) << d;
    EXPECT_DOUBLE_EQ(slab.reflectance(d), 0.0);
  }
}

TEST(ThinSlab, AgreesWithTheTextbookHyperbolicForm) {
  // Both branches: y = beta d below and above 1e-3.
  for (double k : {0.01, 1.0, 7.4, 17.5}) {
    for (double s : {0.3, 3.15, 20.0}) {
      KubelkaMunkSlab slab({k, s});
      for (double d : {1e-6, 1e-4, 0.05, 0.2, 0.5, 1.5}) {
        TextbookRt expected = textbook(k, s, d);
        EXPECT_NEAR(slab.transmittance(d), expected.t, 1e-12 * expected.t)
            << k << " " << s << " " << d;
        EXPECT_NEAR(slab.reflectance(d), expected.r, 1e-12) << k << " " << s << " " << d;
      }
    }
  }
}

TEST(ThinSlab, ThickerLeafTransmitsLessAndNoLightIsMade) {
  LeafOptics optics = default_leaf_optics();
  for (int c = 0; c < 3; ++c) {
    KubelkaMunkSlab slab(optics.rgb[c]);
    double previous_t = 2.0, previous_r = -1.0;
    for (int i = 0; i <= 200; ++i) {
      double d = 0.01 * i;
      double t = slab.transmittance(d), r = slab.reflectance(d);
      EXPECT_LT(t, previous_t) << c << " " << d;
      // Reflectance saturates beyond about 1 mm, to within rounding.
      EXPECT_GE(r, previous_r - 1e-15) << c << " " << d;
      EXPECT_LT(r + t, 1.0 + 1e-15) << c << " " << d;
      previous_t = t;
      previous_r = r;
    }
    EXPECT_LT(slab.transmittance(0.5), 0.1 * slab.transmittance(0.2)) << c;
  }
}

TEST(ThinSlab, InversionRecoversKAndS) {
  for (SlabOptics optics : {SlabOptics{0.5, 4.0}, SlabOptics{7.4, 3.15}, SlabOptics{30.0, 1.0}}) {
    KubelkaMunkSlab slab(optics);
    for (double d : {0.1, 0.2, 0.6}) {
      SlabOptics back = slab_optics_from_measurement(slab.reflectance(d), slab.transmittance(d), d);
      EXPECT_NEAR(back.absorption_per_mm, optics.absorption_per_mm,
                  1e-9 * optics.absorption_per_mm);
      EXPECT_NEAR(back.scattering_per_mm, optics.scattering_per_mm,
                  1e-9 * optics.scattering_per_mm);
    }
  }
}

TEST(ThinSlab, DefaultLeafOpticsReproduceTheReferenceLamina) {
  LeafOptics optics = default_leaf_optics();
  EXPECT_EQ(optics.coefficient_channel, 1);
  for (int c = 0; c < 3; ++c) {
    KubelkaMunkSlab slab(optics.rgb[c]);
    // The constants are written with 6 decimals.
    EXPECT_NEAR(slab.reflectance(kReferenceLaminaMm), kReferenceReflectance[c], 2e-6) << c;
    EXPECT_NEAR(slab.transmittance(kReferenceLaminaMm), kReferenceTransmittance[c], 2e-6) << c;
  }
  // A green leaf: green passes and reflects most, blue least.
  KubelkaMunkSlab r(optics.rgb[0]), g(optics.rgb[1]), b(optics.rgb[2]);
  EXPECT_GT(g.transmittance(0.2), r.transmittance(0.2));
  EXPECT_GT(r.transmittance(0.2), b.transmittance(0.2));
}

TEST(ThinSlab, RejectsImpossibleInput) {
  EXPECT_THROW(slab_optics_from_measurement(0.6, 0.4, 0.2), TextureError);
  EXPECT_THROW(slab_optics_from_measurement(0.0, 0.4, 0.2), TextureError);
  EXPECT_THROW(slab_optics_from_measurement(0.1, 0.4, 0.0), TextureError);
  EXPECT_THROW(KubelkaMunkSlab({-1.0, 1.0}), TextureError);
  EXPECT_THROW(KubelkaMunkSlab({1.0, std::nan("")}), TextureError);
}

}  // namespace
}  // namespace boreas::render
