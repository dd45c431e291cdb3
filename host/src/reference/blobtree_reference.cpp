// boreas: the BlobTree field in double, from the definitions (cone distance in the
// (axial, radial) half-plane, Barr's bend, Gascuel's PCM, CSG cuts, negative scars).
#include "reference/blobtree_reference.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <vector>

namespace boreas::impl::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The bend's plane and arc. A negative angle bends the other way: the same arc as |angle|
// towards -bend_direction.
struct Arc {
  glm::dvec3 a, n, b;  // chord axis, towards the bulge, a x n
  double angle, rho, half_sin, half_cos;
  glm::dvec3 centre;
};

Arc make_arc(const BlobPrimitive& prim) {
  Arc arc;
  double sign = prim.bend_angle < 0.0 ? -1.0 : 1.0;
  arc.a = prim.axis;
  arc.n = sign * prim.bend_direction;
  arc.b = glm::cross(arc.a, arc.n);
  arc.angle = std::abs(prim.bend_angle);
  arc.rho = prim.length / arc.angle;
  arc.half_sin = std::sin(0.5 * arc.angle);
  arc.half_cos = std::cos(0.5 * arc.angle);
  // The arc's midpoint bulges by the sagitta towards n, so the centre lies rho cos(angle/2)
  // behind the chord's midpoint.
  arc.centre = prim.base + (arc.rho * arc.half_sin) * arc.a - (arc.rho * arc.half_cos) * arc.n;
  return arc;
}

// Distance from point q to the segment [s0, s1] of the (t, r) plane.
double segment_distance(glm::dvec2 q, glm::dvec2 s0, glm::dvec2 s1) {
  glm::dvec2 e = s1 - s0;
  double len2 = glm::dot(e, e);
  double s = len2 > 0.0 ? std::clamp(glm::dot(q - s0, e) / len2, 0.0, 1.0) : 0.0;
  return glm::length(q - (s0 + s * e));
}

}  // namespace

double blob_chord_length(const BlobPrimitive& prim) {
  if (prim.bend_angle == 0.0) return prim.length;
  double angle = std::abs(prim.bend_angle);
  return 2.0 * (prim.length / angle) * std::sin(0.5 * angle);
}

BlobLocal blob_local(const BlobPrimitive& prim, const glm::dvec3& p) {
  glm::dvec3 q = p - prim.base;
  if (prim.bend_angle == 0.0) {
    return {glm::dot(q, prim.axis), glm::dot(q, prim.u_direction),
            glm::dot(q, glm::cross(prim.axis, prim.u_direction))};
  }
  Arc arc = make_arc(prim);
  // The angle around the centre measured from the arc's midpoint (direction n), positive
  // towards a: the base lies at -angle/2 and the top at +angle/2. Measuring from the
  // midpoint makes the two ends' regions meet on the bisector behind the centre, where
  // both ends are equally far in angle: there the nearer end of a line skeleton is used.
  glm::dvec3 x = p - arc.centre;
  double xa = glm::dot(x, arc.a), xn = glm::dot(x, arc.n);
  double psi = std::atan2(xa, xn);
  double xb = glm::dot(x, arc.b);
  if (std::abs(psi) <= 0.5 * arc.angle) {
    return {arc.rho * (psi + 0.5 * arc.angle), std::hypot(xa, xn) - arc.rho, xb};
  }
  // Beyond an end the frame is rigid: the end's tangent (the derivative of the arc point
  // sin(psi) a + cos(psi) n in psi) and its outward normal.
  bool before = psi < 0.0;
  double end_psi = before ? -0.5 * arc.angle : 0.5 * arc.angle;
  glm::dvec3 tangent = std::cos(end_psi) * arc.a - std::sin(end_psi) * arc.n;
  glm::dvec3 outward = std::sin(end_psi) * arc.a + std::cos(end_psi) * arc.n;
  glm::dvec3 end = arc.centre + arc.rho * outward;
  glm::dvec3 e = p - end;
  double t0 = before ? 0.0 : prim.length;
  return {t0 + glm::dot(e, tangent), glm::dot(e, outward), glm::dot(e, arc.b)};
}

glm::dvec3 blob_skeleton_point(const BlobPrimitive& prim, double s) {
  if (prim.bend_angle == 0.0) return prim.base + s * prim.axis;
  Arc arc = make_arc(prim);
  double psi = s / arc.rho - 0.5 * arc.angle;
  return arc.centre + arc.rho * (std::sin(psi) * arc.a + std::cos(psi) * arc.n);
}

double blob_cone_distance(double t, double r, double length, double cone_radius) {
  // The solid cone of revolution meets the half-plane of the point in the triangle
  // (0, 0), (0, r0), (L, 0); the nearest point of the solid lies in that half-plane.
  bool inside = t >= 0.0 && t <= length && r * length <= cone_radius * (length - t);
  if (inside) return 0.0;
  glm::dvec2 q(t, r), o(0.0, 0.0), rim(0.0, cone_radius), apex(length, 0.0);
  return std::min(
      {segment_distance(q, o, rim), segment_distance(q, rim, apex), segment_distance(q, o, apex)});
}

double blob_falloff(double d, double influence) {
  if (d >= influence) return 0.0;
  double x = 1.0 - (d * d) / (influence * influence);
  return x * x * x;
}

double blob_surface_slope(const BlobPrimitive& prim) {
  // d/dd (1 - d^2/R^2)^3 = -6 d / R^2 (1 - d^2/R^2)^2.
  double d = prim.iso_distance, r2 = prim.influence * prim.influence;
  if (d >= prim.influence) return 0.0;
  double x = 1.0 - d * d / r2;
  return 6.0 * d / r2 * x * x;
}

double blob_primitive_field(const BlobPrimitive& prim, const glm::dvec3& p, double* distance) {
  BlobLocal l = blob_local(prim, p);
  double d = blob_cone_distance(l.t, std::hypot(l.c0, l.c1), prim.length, prim.cone_radius);
  if (distance) *distance = d;
  return blob_falloff(d, prim.influence);
}

double blob_pcm_expansion(double r, double w, double peak, double slope) {
  if (r < 0.0 || r >= w) return 0.0;
  if (r < 0.5 * w) {
    double c = 4.0 * (w * slope - 4.0 * peak) / (w * w * w);
    double d = 4.0 * (3.0 * peak - w * slope) / (w * w);
    return c * r * r * r + d * r * r + slope * r;
  }
  return 4.0 * peak / (w * w * w) * (r - w) * (r - w) * (4.0 * r - w);
}

double blob_pcm_group_field(const BlobModel& m, int begin, int end, const glm::dvec3& p) {
  int count = end - begin;
  std::vector<double> f(count), r(count);
  for (int i = 0; i < count; ++i) {
    double d;
    f[i] = blob_primitive_field(m.primitives[begin + i], p, &d);
    r[i] = d - m.primitives[begin + i].iso_distance;
  }
  double best = 0.0;
  for (int i = 0; i < count; ++i) {
    const BlobPrimitive& self = m.primitives[begin + i];
    // The others: their largest field, and the nearest surface with its slope (the first
    // one on a tie).
    double other_f = 0.0, other_r = std::numeric_limits<double>::infinity(), other_k = 0.0;
    for (int j = 0; j < count; ++j) {
      if (j == i) continue;
      other_f = std::max(other_f, f[j]);
      if (r[j] < other_r) {
        other_r = r[j];
        other_k = blob_surface_slope(m.primitives[begin + j]);
      }
    }
    double s = 0.0;
    if (other_r < 0.0) {
      s = kBlobIso - other_f;  // interpenetration: compressed to the contact surface
    } else if (other_r < self.pcm_width) {
      // Propagation: the ridge, faded out with this member's own field where it is below
      // half the iso-value (well beyond the ridge).
      double support = std::min(1.0, f[i] / (0.5 * kBlobIso));
      s = blob_pcm_expansion(other_r, self.pcm_width, self.pcm_peak, other_k) * support;
    }
    best = std::max(best, f[i] + s);
  }
  // Where two members overlap, the solid stays solid: the second largest field is above
  // the iso-value exactly there (the deformed fields alone equal it on the contact
  // surface, which would leave a sheet of iso-value inside the wood).
  std::vector<double> sorted = f;
  std::sort(sorted.begin(), sorted.end(), std::greater<double>());
  if (count >= 2) best = std::max(best, sorted[1]);
  return best;
}

double blob_cutter(const BlobCut& cut, const glm::dvec3& p) {
  // Signed depth into the cutter (half-space within the ball), then a linear ramp.
  glm::dvec3 q = p - cut.point;
  double depth = std::min(glm::dot(q, cut.normal), cut.radius - glm::length(q));
  return std::clamp(0.5 + 0.5 * depth / cut.ramp, 0.0, 1.0);
}

double blob_field(const BlobModel& m, const glm::dvec3& p) {
  const std::vector<BlobPrimitive>& prims = m.primitives;
  int n = int(prims.size());
  double total = 0.0;
  for (int i = 0; i < n;) {
    if (!prims[i].pcm) {
      total += prims[i].weight * blob_primitive_field(prims[i], p);
      ++i;
      continue;
    }
    int e = i + 1;
    while (e < n && prims[e].pcm && prims[e].group == prims[i].group) ++e;
    total += blob_pcm_group_field(m, i, e, p);
    i = e;
  }
  if (m.cuts.empty()) return total;
  // CSG difference with the union of the cutters (which also caps F at 1 wherever a model
  // has a cut: only deep inside, where F > 1, so the surface does not move).
  double cutter = 0.0;
  for (const BlobCut& cut : m.cuts) cutter = std::max(cutter, blob_cutter(cut, p));
  return std::min(total, 1.0 - cutter);
}

glm::dvec3 blob_gradient(const BlobModel& m, const glm::dvec3& p, double h) {
  glm::dvec3 g;
  for (int k = 0; k < 3; ++k) {
    glm::dvec3 e(0.0);
    e[k] = h;
    g[k] = (blob_field(m, p + e) - blob_field(m, p - e)) / (2.0 * h);
  }
  return g;
}

glm::dvec2 blob_uv(const BlobModel& m, const glm::dvec3& p) {
  glm::dvec2 sum(0.0);
  double weight = 0.0;
  for (const BlobPrimitive& prim : m.primitives) {
    if (prim.weight <= 0.0) continue;
    double f = blob_primitive_field(prim, p);
    if (f <= 0.0) continue;
    BlobLocal l = blob_local(prim, p);
    double u = std::atan2(l.c1, l.c0) / (2.0 * kPi);
    u -= std::floor(u);
    if (u >= 1.0) u = 0.0;  // a tiny negative angle rounds up to 1
    sum += f * glm::dvec2(u, prim.v0 + prim.v_scale * l.t);
    weight += f;
  }
  return weight > 0.0 ? sum / weight : glm::dvec2(0.0);
}

}  // namespace boreas::impl::reference
