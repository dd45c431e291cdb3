// boreas: the encoders of a component's packed index words (frame_pack.h). Each rounds in
// double and then tries the codes on either side, keeping the one whose float decoding
// (the shared one the kernels use) is nearest: the "precise" variant of the octahedral
// encoding in Cigolle et al., "A Survey of Efficient Representations for Independent Unit
// Vectors" (JCGT 2014).
#include "underbrush/frame_pack.h"

#include <cmath>
#include <string>

#include "errors.h"

namespace boreas::impl {
namespace {

constexpr int kCodeMax = 0xffff;

double dot(BoreasV3 a, const double b[3]) {
  return double(a.x) * b[0] + double(a.y) * b[1] + double(a.z) * b[2];
}

// The cosine of the angle between the float a (unit within float rounding) and the unit
// b: with a's length divided out, since near the nearest codes 1 - cos is ~1e-11, far
// below a float's rounding of the length (~6e-8).
double cosine(BoreasV3 a, const double b[3]) {
  return dot(a, b) / std::sqrt(double(a.x) * a.x + double(a.y) * a.y + double(a.z) * a.z);
}

int clamp_code(double q, int hi) { return int(std::fmin(std::fmax(q, 0.0), double(hi))); }

}  // namespace

int32_t pack_link(int part, int back, const char* where) {
  if (part < 0 || part > BOREAS_UB_LINK_PART_MASK)
    fail_argument(std::string(where) + ": part " + std::to_string(part) + " past the " +
                  std::to_string(BOREAS_UB_LINK_PART_MASK + 1) + " a meadow can index");
  if (back < 0 || back > BOREAS_UB_LINK_PART_MASK)
    fail_argument(std::string(where) + ": parent " + std::to_string(back) +
                  " components back; at most " + std::to_string(BOREAS_UB_LINK_PART_MASK));
  return int32_t(uint32_t(part) | (uint32_t(back) << BOREAS_UB_LINK_PART_BITS));
}

int32_t pack_axis(const double axis[3]) {
  // The octahedron's square: x and z over the L1 norm, the lower half folded out.
  const double l1 = std::fabs(axis[0]) + std::fabs(axis[1]) + std::fabs(axis[2]);
  double u = axis[0] / l1, v = axis[2] / l1;
  if (axis[1] < 0.0) {
    const double fu = (1.0 - std::fabs(v)) * (u < 0.0 ? -1.0 : 1.0);
    v = (1.0 - std::fabs(u)) * (v < 0.0 ? -1.0 : 1.0);
    u = fu;
  }
  const double qu = (u + 1.0) * BOREAS_UB_OCT_HALF, qv = (v + 1.0) * BOREAS_UB_OCT_HALF;
  int32_t best = 0;
  double best_dot = -2.0;
  for (int du = 0; du < 2; ++du)
    for (int dv = 0; dv < 2; ++dv) {
      const int a = clamp_code(std::floor(qu) + du, 2 * BOREAS_UB_OCT_HALF);
      const int b = clamp_code(std::floor(qv) + dv, 2 * BOREAS_UB_OCT_HALF);
      const int32_t word = int32_t(uint32_t(a) | (uint32_t(b) << 16));
      const double d = cosine(boreas_ub_unpack_axis(word), axis);
      if (d > best_dot) best_dot = d, best = word;
    }
  return best;
}

namespace {

// The diamond code (low 16 bits of TURN) nearest the unit (c, s) in e_u's basis.
int turn_code(BoreasV3 e_u, const double side[3]) {
  BoreasV3 b1, b2;
  boreas_ub_basis(e_u, &b1, &b2);
  const double c = dot(b1, side), s = dot(b2, side);
  const double l1 = std::fabs(c) + std::fabs(s);
  const double d = (1.0 - c / l1) * (s < 0.0 ? -1.0 : 1.0);  // in [-2, 2]
  const double q = (d + 2.0) / double(BOREAS_UB_TURN_STEP);
  const double r = std::sqrt(c * c + s * s);  // (not hypot: slow, and c, s are near 1)
  const double want[2] = {c / r, s / r};
  int best = 0;
  double best_dot = -2.0;
  for (int dq = 0; dq < 2; ++dq) {
    const int code = (int(std::floor(q)) + dq) & kCodeMax;  // d = 2 is d = -2
    float cc, ss;
    boreas_ub_turn(code, &cc, &ss);
    const double dd = (double(cc) * want[0] + double(ss) * want[1]) /
                      std::sqrt(double(cc) * cc + double(ss) * ss);
    if (dd > best_dot) best_dot = dd, best = code;
  }
  return best;
}

// The positive normal half nearest `scale`.
int half_code(double scale) {
  const int h0 = (boreas_host_as_int(float(scale)) >> 13) - BOREAS_UB_HALF_REBIAS;
  int best = h0;
  for (int h = h0; h <= h0 + 1; ++h) {
    const double e = std::fabs(double(boreas_ub_unpack_scale(h << 16)) - scale);
    if (e < std::fabs(double(boreas_ub_unpack_scale(best << 16)) - scale)) best = h;
  }
  return best;
}

}  // namespace

int32_t pack_turn(int32_t axis_word, const double side[3], double scale, const char* where) {
  if (!(scale >= BOREAS_UB_SCALE_MIN && scale <= BOREAS_UB_SCALE_MAX))
    fail_argument(std::string(where) + ": scale " + std::to_string(scale) +
                  " outside the half-float range " + std::to_string(BOREAS_UB_SCALE_MIN) + ".." +
                  std::to_string(BOREAS_UB_SCALE_MAX));
  const int code = turn_code(boreas_ub_unpack_axis(axis_word), side);
  return int32_t(uint32_t(code) | (uint32_t(half_code(scale)) << 16));
}

UnpackedFrame unpack_frame(const int32_t* index, int n, int c) {
  UnpackedFrame f;
  f.axis = boreas_ub_unpack_axis(index[BOREAS_UB_INDEX_AXIS * n + c]);
  const int32_t turn = index[BOREAS_UB_INDEX_TURN * n + c];
  f.side = boreas_ub_unpack_side(f.axis, turn);
  f.scale = boreas_ub_unpack_scale(turn);
  return f;
}

}  // namespace boreas::impl
