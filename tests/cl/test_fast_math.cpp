// boreas tests: error of the polynomial sin/cos/exp2/log2/pow of cl/shared/fast_math.h,
// evaluated on the device, against double precision over each function's whole domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

#include "reference/probe_kernels.h"
#include "runtime/kernel_defines.h"
#include "runtime/launch.h"
#include "support/test_support.h"

namespace boreas::test {
namespace {

enum Which {
  kSin = 0,
  kCos = 1,
  kExp2 = 2,
  kLog2 = 3,
  kPow = 4,
  kSelectedSin = 5,
  kSelectedPow = 9,
  kAtan2 = 12,
  kSelectedAtan2 = 13
};

class FastMath : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    impl::use_probe_kernels();  // fast_math_probe.cl is not part of the library
    runtime_ = new impl::Runtime(nullptr, nullptr);
  }
  static void TearDownTestSuite() {
    delete runtime_;
    runtime_ = nullptr;
  }

  static std::vector<float> eval(impl::Runtime& rt, Which which, const std::vector<float>& a,
                                 const std::vector<float>& b) {
    cl::Kernel k = rt.kernel("fast_math_probe.cl", "boreas_fast_math_probe");
    size_t n = a.size();
    cl::Buffer ba = rt.buffer(CL_MEM_READ_ONLY, n * 4);
    cl::Buffer bb = rt.buffer(CL_MEM_READ_ONLY, n * 4);
    cl::Buffer bo = rt.buffer(CL_MEM_WRITE_ONLY, n * 4);
    rt.queue().enqueueWriteBuffer(ba, CL_TRUE, 0, n * 4, a.data());
    rt.queue().enqueueWriteBuffer(bb, CL_TRUE, 0, n * 4, b.data());
    impl::launch(rt, k, impl::Items(n), ba, bb, bo, static_cast<int>(n), static_cast<int>(which));
    std::vector<float> out(n);
    rt.queue().enqueueReadBuffer(bo, CL_TRUE, 0, n * 4, out.data());
    return out;
  }
  static std::vector<float> eval(Which which, const std::vector<float>& a,
                                 const std::vector<float>& b = {}) {
    return eval(*runtime_, which, a, b.empty() ? a : b);
  }

  // Every width of the wide probe against the scalar probe, for each `which`.
  static void expect_every_width_matches_width_one(impl::Runtime& rt,
                                                   std::initializer_list<int> whiches,
                                                   const std::string& what);

  static impl::Runtime* runtime_;
};
impl::Runtime* FastMath::runtime_ = nullptr;

std::vector<float> uniform(float lo, float hi, size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(lo, hi);
  std::vector<float> v(n);
  for (float& x : v) x = static_cast<float>(d(rng));
  return v;
}

// Bounds below are the measured maxima rounded up, so a regression of the
// polynomials or of the argument reduction shows up.
TEST_F(FastMath, SinAndCosAbsoluteErrorOverWholeDomain) {
  std::vector<float> x = uniform(-1e5f, 1e5f, 1 << 20, 1);
  std::vector<float> near = uniform(-10.0f, 10.0f, 1 << 18, 2);
  x.insert(x.end(), near.begin(), near.end());
  for (float special : {0.0f, -0.0f, 1e-30f, 1.5707964f, 3.1415927f, 1e5f, -1e5f}) x.push_back(special);
  std::vector<float> s = eval(kSin, x);
  std::vector<float> c = eval(kCos, x);
  double max_sin = 0.0, max_cos = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    max_sin = std::max(max_sin, std::fabs(s[i] - std::sin(double(x[i]))));
    max_cos = std::max(max_cos, std::fabs(c[i] - std::cos(double(x[i]))));
  }
  RecordProperty("max_sin_error", testing::PrintToString(max_sin));
  RecordProperty("max_cos_error", testing::PrintToString(max_cos));
  EXPECT_LT(max_sin, 3e-7) << "sin";
  EXPECT_LT(max_cos, 3e-7) << "cos";
}

TEST_F(FastMath, Exp2RelativeErrorOverWholeDomain) {
  std::vector<float> x = uniform(-126.0f, 127.0f, 1 << 20, 3);
  for (float special : {-126.0f, 0.0f, 0.5f, -0.5f, 1.0f, 127.0f}) x.push_back(special);
  std::vector<float> r = eval(kExp2, x);
  double worst = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    double ref = std::exp2(double(x[i]));
    worst = std::max(worst, std::fabs(r[i] - ref) / ref);
  }
  EXPECT_LT(worst, 4e-7);
  // Below the domain the result flushes to zero rather than to garbage.
  std::vector<float> under = eval(kExp2, {-127.5f, -200.0f, -1e30f});
  for (float u : under) EXPECT_EQ(u, 0.0f);
}

TEST_F(FastMath, Log2AbsoluteErrorOverAllNormalFloats) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> e(-126.0, 128.0);
  std::vector<float> x(1 << 20);
  for (float& v : x) v = static_cast<float>(std::min(std::exp2(e(rng)), double(FLT_MAX)));
  for (float special : {FLT_MIN, 1.0f, 2.0f, 0.70710677f, 1.4142135f, FLT_MAX}) x.push_back(special);
  std::vector<float> r = eval(kLog2, x);
  double worst = 0.0;
  for (size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::fabs(r[i] - std::log2(double(x[i]))));
  EXPECT_LT(worst, 2e-5) << "absolute, over |log2 x| up to 128";
  // Near 1 the error must stay relative to the (small) result.
  std::vector<float> near_one = uniform(0.5f, 2.0f, 1 << 18, 5);
  std::vector<float> rn = eval(kLog2, near_one);
  double worst_near = 0.0;
  for (size_t i = 0; i < near_one.size(); ++i)
    worst_near = std::max(worst_near, std::fabs(rn[i] - std::log2(double(near_one[i]))));
  EXPECT_LT(worst_near, 3e-7);
}

TEST_F(FastMath, PowRelativeErrorGrowsOnlyWithTheExponentItProduces) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> ex(-20.0, 20.0);
  std::uniform_real_distribution<double> ey(-6.0, 6.0);
  std::vector<float> x, y;
  while (x.size() < (1u << 20)) {
    float xv = static_cast<float>(std::exp2(ex(rng)));
    float yv = static_cast<float>(ey(rng));
    if (std::fabs(yv * std::log2(double(xv))) > 126.0) continue;
    x.push_back(xv);
    y.push_back(yv);
  }
  std::vector<float> r = eval(*runtime_, kPow, x, y);
  double worst_ratio = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    double ref = std::pow(double(x[i]), double(y[i]));
    double rel = std::fabs(r[i] - ref) / ref;
    // float y*log2(x) alone has a rounding of 6e-8 of itself: the bound scales with it.
    double bound = 5e-7 + 2.5e-7 * std::fabs(double(y[i]) * std::log2(double(x[i])));
    worst_ratio = std::max(worst_ratio, rel / bound);
  }
  EXPECT_LT(worst_ratio, 1.0);
  // The sine sum's uses: base in [0, 1], sharpness k >= 0, including the edges.
  std::vector<float> base = {0.0f, 0.0f, 1.0f, 0.5f, 0.0f};
  std::vector<float> k = {0.0f, 2.0f, 7.0f, 0.0f, 0.5f};
  std::vector<float> e = eval(*runtime_, kPow, base, k);
  EXPECT_EQ(e[0], 1.0f);
  EXPECT_EQ(e[1], 0.0f);
  EXPECT_EQ(e[2], 1.0f);
  EXPECT_EQ(e[3], 1.0f);
  EXPECT_EQ(e[4], 0.0f);
}

// atan2 over every direction (angles on a fine circle at radii from 1e-6 to 1e4, the axes
// and the diagonals exactly), through the polynomial and the per-device selection.
TEST_F(FastMath, Atan2AbsoluteErrorOverEveryDirection) {
  std::vector<float> y, x;
  for (int i = 0; i < 200000; ++i) {
    double angle = -M_PI + 2.0 * M_PI * (i + 0.5) / 200000.0;
    double radius = std::pow(10.0, -6.0 + 10.0 * ((i * 7919) % 200000) / 200000.0);
    y.push_back(float(radius * std::sin(angle)));
    x.push_back(float(radius * std::cos(angle)));
  }
  for (float a : {1.0f, -1.0f, 0.0f}) {
    for (float b : {1.0f, -1.0f, 0.0f}) {
      y.push_back(a);
      x.push_back(b);
    }
  }
  for (Which which : {kAtan2, kSelectedAtan2}) {
    std::vector<float> r = eval(which, y, x);
    double worst = 0.0;
    for (size_t i = 0; i < r.size(); ++i) worst = std::max(worst, std::fabs(r[i] - std::atan2(double(y[i]), double(x[i]))));
    EXPECT_LT(worst, 4e-7) << "which " << which;
  }
}

// Lanes of the wide probe (fast_math_probe.cl) at each width that differ from the scalar
// probe's, for `which` over inputs that cross every branch (reduction wraps, exp2's clamps,
// log2's mantissa fold, atan2's octants, pow's zero base and zero exponent), with a count
// that leaves a partial last work-item.
void FastMath::expect_every_width_matches_width_one(impl::Runtime& rt,
                                                    std::initializer_list<int> whiches,
                                                    const std::string& what) {
  std::vector<float> a = uniform(-300.0f, 300.0f, 10007, 21);
  std::vector<float> b = uniform(-4.0f, 4.0f, a.size(), 22);
  for (size_t i = 0; i < 64; ++i) {
    a[i] = 0.0f;                           // pow(0, y), atan2(0, x)
    b[i + 64] = 0.0f;                      // pow(x, 0), atan2(y, 0)
    a[i + 128] = float(i) * 0.25f - 8.0f;  // exact multiples of pi/4-ish steps and halves
  }
  std::vector<float> positive(a.size());
  for (size_t i = 0; i < a.size(); ++i)
    positive[i] = std::fabs(a[i]) * (i % 3 == 0 ? 1e-30f : 1.0f);
  std::vector<float> cycles = uniform(-0.5f, 0.5f, a.size(), 23);
  const size_t n = a.size();
  for (int width : {1, 2, 4, 8, 16}) {
    cl::Kernel k =
        rt.kernel("fast_math_probe.cl", "boreas_fast_math_probe_wide", impl::width_define(width));
    for (int which : whiches) {
      // The selection's cases (5..9, 11, 13) take the polynomials' inputs (0..4, 10, 12).
      const int plain =
          which >= 5 && which <= 9 ? which - 5 : (which == 11 || which == 13 ? which - 1 : which);
      const std::vector<float>& x = plain == 3 || plain == 4 ? positive : plain == 10 ? cycles : a;
      std::vector<float> scalar = eval(rt, static_cast<Which>(which), x, b);
      cl::Buffer bx = rt.buffer(CL_MEM_READ_ONLY, n * 4);
      cl::Buffer by = rt.buffer(CL_MEM_READ_ONLY, n * 4);
      cl::Buffer bo = rt.buffer(CL_MEM_WRITE_ONLY, n * 4);
      rt.queue().enqueueWriteBuffer(bx, CL_TRUE, 0, n * 4, x.data());
      rt.queue().enqueueWriteBuffer(by, CL_TRUE, 0, n * 4, b.data());
      impl::launch(rt, k, impl::Items(n).per_work_item(size_t(width)), bx, by, bo,
                   static_cast<int>(n), which);
      std::vector<float> wide(n);
      rt.queue().enqueueReadBuffer(bo, CL_TRUE, 0, n * 4, wide.data());
      size_t differing = 0;
      for (size_t i = 0; i < n; ++i)
        differing += std::memcmp(&wide[i], &scalar[i], sizeof(float)) != 0;
      EXPECT_EQ(differing, 0u) << what << ", width " << width << ", which " << which;
    }
  }
}

// cl/shared/fast_math_width.inc is one body instantiated per SIMD width (simd_width.h): the
// vector instantiations must give width 1's results bit for bit.
TEST_F(FastMath, EveryWidthMatchesWidthOneBitForBit) {
  expect_every_width_matches_width_one(*runtime_, {0, 1, 2, 3, 4, 10, 12}, "polynomials");
}

// What kernels call (boreas_sin, ...) must too, with either BOREAS_FAST_MATH: the builtins
// (GPUs' path, or BOREAS_FAST_MATH=0 with any BOREAS_SIMD_WIDTH) are called lane by lane
// above width 1, since PoCL's vector exp2, atan2 and powr are not its scalar ones bit for
// bit (which made the meadow's width test fail at 8 and 16 with BOREAS_FAST_MATH=0).
TEST_F(FastMath, TheSelectedMathMatchesWidthOneBitForBitWithPolynomialsOrBuiltins) {
  for (const char* fast : {"1", "0"}) {
    ScopedEnv env("BOREAS_FAST_MATH", fast);
    impl::Runtime rt(nullptr, nullptr);
    ASSERT_EQ(rt.device().uses_fast_math(), std::string(fast) == "1");
    expect_every_width_matches_width_one(rt, {5, 6, 7, 8, 9, 11, 13},
                                         std::string("BOREAS_FAST_MATH=") + fast);
  }
}

}  // namespace
}  // namespace boreas::test

namespace boreas::test {
namespace {

// sin(2 pi u) over its whole domain, one cycle, through the polynomial and the builtin path.
TEST(FastMathCycle, SineOfAPhaseInCyclesOverItsDomain) {
  std::vector<float> u;
  for (int i = -500000; i <= 500000; ++i) u.push_back(float(i) * 1e-6f);
  for (float special : {0.25f, -0.25f, 0.5f, -0.5f, 0.2500001f, -0.4999999f}) u.push_back(special);
  std::vector<float> none(u.size(), 0.0f);
  impl::use_probe_kernels();
  for (const char* fast : {"1", "0"}) {
    ScopedEnv env("BOREAS_FAST_MATH", fast);
    impl::Runtime rt(nullptr, nullptr);
    cl::Kernel k = rt.kernel("fast_math_probe.cl", "boreas_fast_math_probe");
    size_t n = u.size();
    cl::Buffer a = rt.buffer(CL_MEM_READ_ONLY, n * 4), o = rt.buffer(CL_MEM_WRITE_ONLY, n * 4);
    rt.queue().enqueueWriteBuffer(a, CL_TRUE, 0, n * 4, u.data());
    impl::launch(rt, k, impl::Items(n), a, a, o, int(n), 11);  // 11: the per-device selection
    std::vector<float> r(n);
    rt.queue().enqueueReadBuffer(o, CL_TRUE, 0, n * 4, r.data());
    double worst = 0.0;
    for (size_t i = 0; i < n; ++i) worst = std::max(worst, std::fabs(r[i] - std::sin(2 * M_PI * double(u[i]))));
    EXPECT_LT(worst, 3e-7) << "BOREAS_FAST_MATH=" << fast;
  }
}

}  // namespace
}  // namespace boreas::test
