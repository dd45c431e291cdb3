// boreas: a tree's skin (tree_skin.h). Frames in double from the branch's control points
// and orientation by the same formulas as the deformer (eq. 8, the blended handles of the
// de Casteljau sweep), then made orthonormal, since a joint is a rigid transform.
#include "trees/tree_skin.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "trees/tree_templates.h"

#define BOREAS_FAST_MATH 1
#include "shared/tree_math.h"

namespace boreas::impl {
namespace {

struct V {
  double x = 0, y = 0, z = 0;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(V a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V unit(V a) {
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? a * (1.0 / n) : V{};
}
V point(const float* p) { return {p[0], p[1], p[2]}; }

struct Curve {
  V p[4];
  explicit Curve(const boreas_branch& b) {
    for (int i = 0; i < 4; ++i) p[i] = point(b.control_points[i]);
  }
  V at(double u) const {
    const double w = 1 - u;
    return p[0] * (w * w * w) + p[1] * (3 * u * w * w) + p[2] * (3 * u * u * w) + p[3] * (u * u * u);
  }
  V tangent(double u) const {
    const double w = 1 - u;
    return (p[1] - p[0]) * (3 * w * w) + (p[2] - p[1]) * (6 * u * w) + (p[3] - p[2]) * (3 * u * u);
  }
};

// The joint's axes at u: y the tangent, x the Sloan handle S(u) made perpendicular to it.
void joint_axes(const boreas_branch& b, double u, V* x, V* y, V* z) {
  const Curve c(b);
  const V l0 = unit(c.p[1] - c.p[0]), l1 = unit(c.p[2] - c.p[1]), l2 = unit(c.p[3] - c.p[2]);
  const V s0 = unit(cross(l0, point(b.orientation)));
  const V t1 = unit(cross(s0, l1));
  const V s1 = cross(l1, t1);
  const V t2 = unit(cross(s1, l2));
  const V s2 = cross(l2, t2);
  const double w = 1 - u;
  const V s = s0 * (w * w) + s1 * (2 * u * w) + s2 * (u * u);
  V tangent = c.tangent(u);
  if (dot(tangent, tangent) == 0) tangent = c.p[3] - c.p[0];
  *y = unit(tangent);
  *x = unit(s - *y * dot(s, *y));
  *z = cross(*x, *y);
}

// The unit quaternion (x, y, z, w) of the rotation whose columns are a, b, c.
void to_quaternion(V a, V b, V c, float q[4]) {
  const double m[3][3] = {{a.x, b.x, c.x}, {a.y, b.y, c.y}, {a.z, b.z, c.z}};
  const double trace = m[0][0] + m[1][1] + m[2][2];
  double x, y, z, w;
  if (trace > 0) {
    const double s = 2 * std::sqrt(1 + trace);
    w = s / 4, x = (m[2][1] - m[1][2]) / s, y = (m[0][2] - m[2][0]) / s, z = (m[1][0] - m[0][1]) / s;
  } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
    const double s = 2 * std::sqrt(1 + m[0][0] - m[1][1] - m[2][2]);
    w = (m[2][1] - m[1][2]) / s, x = s / 4, y = (m[0][1] + m[1][0]) / s, z = (m[0][2] + m[2][0]) / s;
  } else if (m[1][1] > m[2][2]) {
    const double s = 2 * std::sqrt(1 + m[1][1] - m[0][0] - m[2][2]);
    w = (m[0][2] - m[2][0]) / s, x = (m[0][1] + m[1][0]) / s, y = s / 4, z = (m[1][2] + m[2][1]) / s;
  } else {
    const double s = 2 * std::sqrt(1 + m[2][2] - m[0][0] - m[1][1]);
    w = (m[1][0] - m[0][1]) / s, x = (m[0][2] + m[2][0]) / s, y = (m[1][2] + m[2][1]) / s, z = s / 4;
  }
  const double n = std::sqrt(x * x + y * y + z * z + w * w);
  q[0] = float(x / n), q[1] = float(y / n), q[2] = float(z / n), q[3] = float(w / n);
}

// Each branch's first joint, -1 for branches finer than max_level.
std::vector<int> first_joints(const std::vector<boreas_branch>& branches, const SkinParams& p) {
  std::vector<int> first(branches.size(), -1);
  int next = 0;
  for (size_t b = 0; b < branches.size(); ++b)
    if (branches[b].level <= p.max_level) first[b] = next, next += p.segments + 1;
  return first;
}

// The joints around place u of a skinned branch: linear in u between its two neighbours.
boreas_skin_weight weight_at(int first, double u, const SkinParams& p) {
  const double s = std::clamp(u, 0.0, 1.0) * p.segments;
  const int k = std::min(int(std::floor(s)), p.segments - 1);
  const double t = s - k;
  boreas_skin_weight w{};
  const int near = t <= 0.5 ? k : k + 1, far = t <= 0.5 ? k + 1 : k;
  w.joints[0] = first + near;
  w.joints[1] = first + far;
  w.weights[0] = float(t <= 0.5 ? 1 - t : t);
  w.weights[1] = 1.0f - w.weights[0];
  return w;
}

// Branch b's place u, or for a finer branch its ancestor's at max_level and the place it
// is carried from there.
boreas_skin_weight carried_weight(const std::vector<boreas_branch>& branches,
                                  const std::vector<int>& first, int b, double u,
                                  const SkinParams& p) {
  while (first[size_t(b)] < 0) {
    u = branches[size_t(b)].parent_v;
    b = branches[size_t(b)].parent;
  }
  return weight_at(first[size_t(b)], u, p);
}

// The curve's parameter nearest to q: a coarse scan, then golden sections around it.
double nearest_u(const Curve& c, V q) {
  auto d2 = [&](double u) {
    const V d = c.at(u) - q;
    return dot(d, d);
  };
  const int n = 64;
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (d2(double(i) / n) < d2(double(best) / n)) best = i;
  double a = std::max(0.0, double(best - 1) / n), b = std::min(1.0, double(best + 1) / n);
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (int i = 0; i < 40; ++i) {
    const double m1 = b - g * (b - a), m2 = a + g * (b - a);
    if (d2(m1) < d2(m2))
      b = m2;
    else
      a = m1;
  }
  return 0.5 * (a + b);
}

}  // namespace

SkinParams checked_skin_def(const boreas_skin_def* def) {
  const boreas_skin_def d = def ? *def : boreas_default_skin_def();
  if (d.max_level < 0 || d.max_level > 3)
    fail_argument("boreas_skin_def.max_level must be 0..3 (got " + std::to_string(d.max_level) +
                  ")");
  if (d.segments < 1 || d.segments > BOREAS_SKIN_MAX_SEGMENTS)
    fail_argument("boreas_skin_def.segments must be 1..BOREAS_SKIN_MAX_SEGMENTS (" +
                  std::to_string(BOREAS_SKIN_MAX_SEGMENTS) + ") (got " +
                  std::to_string(d.segments) + ")");
  return {d.max_level, d.segments};
}

std::vector<boreas_joint> skin_joints(const std::vector<boreas_branch>& branches,
                                      const SkinParams& p) {
  const std::vector<int> first = first_joints(branches, p);
  std::vector<boreas_joint> joints;
  for (size_t b = 0; b < branches.size(); ++b) {
    if (first[b] < 0) continue;
    const boreas_branch& br = branches[b];
    const Curve c(br);
    for (int k = 0; k <= p.segments; ++k) {
      const double u = double(k) / p.segments;
      boreas_joint j{};
      const V o = c.at(u);
      j.position[0] = float(o.x), j.position[1] = float(o.y), j.position[2] = float(o.z);
      V x, y, z;
      joint_axes(br, u, &x, &y, &z);
      to_quaternion(x, y, z, j.rotation);
      j.branch = int32_t(b);
      j.u = float(u);
      if (k > 0)
        j.parent = first[b] + k - 1;
      else if (br.parent < 0)
        j.parent = -1;
      else  // the parent's joint at or below parent_v (parents have joints: levels in order)
        j.parent = first[size_t(br.parent)] +
                   std::min(int(std::floor(double(br.parent_v) * p.segments)), p.segments);
      joints.push_back(j);
    }
  }
  return joints;
}

std::vector<float> skin_tip_caps(const std::shared_ptr<const TreeModel>& model) {
  // A packed model keeps no caps; only a level of nTaper over 1 has any (set_taper), so a
  // species without one is not grown again for its zeros.
  if (model->packed) {
    const Species& s = *model->packed->species;
    bool capped = false;
    for (int l = 0; l < s.levels; ++l) capped = capped || s.level[size_t(l)].taper > 1.0;
    if (!capped) return std::vector<float>(model->packed->branches.size(), 0.0f);
  }
  const std::shared_ptr<const TreeModel> whole = whole_model(model);
  std::vector<float> caps;
  caps.reserve(whole->branches.size());
  for (const BranchModel& b : whole->branches) caps.push_back(float(b.tip_cap));  // as uploaded
  return caps;
}

std::vector<boreas_skin_weight> skin_vertex_weights(const std::vector<boreas_branch>& branches,
                                                    const std::vector<float>& tip_caps,
                                                    const LevelGrids& grids, const SkinParams& p) {
  if (tip_caps.size() != branches.size())
    fail(BOREAS_ERROR_INTERNAL, "skin_vertex_weights: " + std::to_string(tip_caps.size()) +
                                    " tip caps for " + std::to_string(branches.size()) +
                                    " branches");
  const std::vector<int> first = first_joints(branches, p);
  std::vector<boreas_skin_weight> out;
  // Levels in order, each branch a grid of (rings + 1) x (sides + 1), ring-major: ring r
  // lies at the deformer's v, boreas_ring_v (r / rings, but for the last rings of a capped
  // piece, which go round its tip's hemisphere), in the same float.
  for (size_t b = 0; b < branches.size(); ++b) {
    const MeshGrid g = grids[size_t(branches[b].level)];
    for (int r = 0; r <= g.rings; ++r) {
      const double v = boreas_ring_v(float(r), g.rings, tip_caps[b]);
      const boreas_skin_weight w = carried_weight(branches, first, int(b), v, p);
      out.insert(out.end(), size_t(g.sides + 1), w);
    }
  }
  return out;
}

std::vector<boreas_skin_weight> skin_leaf_weights(const std::vector<boreas_branch>& branches,
                                                  const std::vector<boreas_leaf>& leaves,
                                                  const SkinParams& p) {
  const std::vector<int> first = first_joints(branches, p);
  std::vector<boreas_skin_weight> out;
  out.reserve(leaves.size());
  for (const boreas_leaf& leaf : leaves) {
    const int b = leaf.branch;
    // The place matters only on a branch with joints of its own.
    const double u = first[size_t(b)] >= 0
                         ? nearest_u(Curve(branches[size_t(b)]), point(leaf.position))
                         : 0.0;
    out.push_back(carried_weight(branches, first, b, u, p));
  }
  return out;
}

}  // namespace boreas::impl
