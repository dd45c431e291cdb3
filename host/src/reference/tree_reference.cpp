// boreas: double-precision references of the tree kernels (see tree_reference.h).
#include "reference/tree_reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "trees/tree_batch.h"
#include "trees/tree_params.h"
#include "trees/wind_load.h"

namespace boreas::impl::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Unit vector, or zero for a zero vector (as the kernels' floor does).
dvec3 unit(const dvec3& a) {
  double l = glm::length(a);
  return l > 0.0 ? a / l : dvec3(0.0);
}

}  // namespace

// ---- Bezier ----------------------------------------------------------------------------

dvec3 bezier_point(const Bezier& c, double u) {
  // de Casteljau, a different route than the Bernstein sum of the kernels.
  dvec3 a = glm::mix(c.p[0], c.p[1], u), b = glm::mix(c.p[1], c.p[2], u),
        d = glm::mix(c.p[2], c.p[3], u);
  dvec3 ab = glm::mix(a, b, u), bd = glm::mix(b, d, u);
  return glm::mix(ab, bd, u);
}

dvec3 bezier_derivative(const Bezier& c, double u) {
  // 3 x the quadratic Bezier of the control point differences.
  dvec3 d0 = c.p[1] - c.p[0], d1 = c.p[2] - c.p[1], d2 = c.p[3] - c.p[2];
  dvec3 a = glm::mix(d0, d1, u), b = glm::mix(d1, d2, u);
  return 3.0 * glm::mix(a, b, u);
}

// ---- Sloan frame -----------------------------------------------------------------------

SloanFrame sloan_frame(const Bezier& c, const dvec3& o) {
  dvec3 l0 = unit(c.p[1] - c.p[0]), l1 = unit(c.p[2] - c.p[1]), l2 = unit(c.p[3] - c.p[2]);
  SloanFrame f;
  f.s[0] = unit(glm::cross(l0, o));
  f.t[0] = glm::cross(f.s[0], l0);
  f.t[1] = unit(glm::cross(f.s[0], l1));
  f.s[1] = glm::cross(l1, f.t[1]);
  f.t[2] = unit(glm::cross(f.s[1], l2));
  f.s[2] = glm::cross(l2, f.t[2]);
  return f;
}

void frame_handles(const SloanFrame& f, double u, dvec3* s, dvec3* t, dvec3* ds, dvec3* dt) {
  double w = 1.0 - u;
  double q0 = w * w, q1 = 2.0 * u * w, q2 = u * u;
  // d/du of the Bernstein weights: -2(1-u), 2(1-u) - 2u, 2u.
  double d0 = -2.0 * w, d1 = 2.0 * w - 2.0 * u, d2 = 2.0 * u;
  if (s) *s = q0 * f.s[0] + q1 * f.s[1] + q2 * f.s[2];
  if (t) *t = q0 * f.t[0] + q1 * f.t[1] + q2 * f.t[2];
  if (ds) *ds = d0 * f.s[0] + d1 * f.s[1] + d2 * f.s[2];
  if (dt) *dt = d0 * f.t[0] + d1 * f.t[1] + d2 * f.t[2];
}

// ---- Attachment ------------------------------------------------------------------------

AttachFrame attach(const Branch& parent, double v, double theta, double alpha) {
  SloanFrame f = sloan_frame(parent.curve, parent.o);
  dvec3 s, t;
  frame_handles(f, v, &s, &t);
  dvec3 u = unit(bezier_derivative(parent.curve, v));
  dvec3 radial = std::sin(theta) * s + std::cos(theta) * t;
  dvec3 e2 = unit(radial - glm::dot(radial, u) * u);
  double ca = std::cos(alpha), sa = std::sin(alpha);
  AttachFrame a;
  a.origin = bezier_point(parent.curve, v);
  a.x = ca * u + sa * e2;
  a.y = ca * e2 - sa * u;
  a.z = glm::cross(u, e2);
  return a;
}

dvec3 attach_place(const AttachFrame& a, const dvec3& local) {
  return a.origin + local.x * a.x + local.y * a.y + local.z * a.z;
}

// ---- Bending ---------------------------------------------------------------------------

dvec3 bend_point(const dvec3& bent_prev, const dvec3& seg, const dvec3& bend) {
  return bent_prev + glm::length(seg) * unit(seg + bend);
}

// ---- Response --------------------------------------------------------------------------

Response response_step(double omega, double zeta, double dt) {
  if (omega <= 0.0) return Response{};
  // M = A dt, scaled by 2^-k until its norm is below 1/4, exp by Taylor, squared k times.
  double m[4] = {0.0, dt, -omega * omega * dt, -2.0 * zeta * omega * dt};
  double norm = std::abs(m[0]) + std::abs(m[1]) + std::abs(m[2]) + std::abs(m[3]);
  int k = 0;
  while (norm > 0.25) {
    norm *= 0.5;
    ++k;
  }
  double scale = std::ldexp(1.0, -k);
  for (double& x : m) x *= scale;
  double e[4] = {1.0, 0.0, 0.0, 1.0}, term[4] = {1.0, 0.0, 0.0, 1.0};
  for (int n = 1; n <= 24; ++n) {
    double next[4] = {(term[0] * m[0] + term[1] * m[2]) / n, (term[0] * m[1] + term[1] * m[3]) / n,
                      (term[2] * m[0] + term[3] * m[2]) / n, (term[2] * m[1] + term[3] * m[3]) / n};
    for (int i = 0; i < 4; ++i) {
      term[i] = next[i];
      e[i] += term[i];
    }
  }
  for (int i = 0; i < k; ++i) {
    double sq[4] = {e[0] * e[0] + e[1] * e[2], e[0] * e[1] + e[1] * e[3], e[2] * e[0] + e[3] * e[2],
                    e[2] * e[1] + e[3] * e[3]};
    for (int j = 0; j < 4; ++j) e[j] = sq[j];
  }
  return Response{e[0], e[1], e[2], e[3]};
}

// ---- Per-branch step --------------------------------------------------------------------

Branch place_branch(const Branch& parent, const BranchShape& shape) {
  AttachFrame a = attach(parent, shape.v, shape.theta, shape.alpha);
  Branch b;
  // local[0] is 0 but for a trunk standing apart from its tree's base (0BranchDist).
  for (int k = 0; k <= 3; ++k) b.curve.p[k] = attach_place(a, shape.local[k]);
  b.o = a.y;
  return b;
}

Branch branch_step(const Branch& parent, const BranchShape& shape, const dvec3& wind_at_tip,
                   const Response& r, Motion* motion, double dt, double reach_scale) {
  Branch placed = place_branch(parent, shape);
  auto vogel = [&](double speed) {
    return speed > shape.vogel_speed ? std::pow(speed / shape.vogel_speed, shape.vogel_b) : 1.0;
  };
  const double speed = glm::length(wind_at_tip);
  const dvec3 target = (shape.compliance + shape.drag * speed * vogel(speed)) * wind_at_tip;
  dvec3 x = motion->f - target, u = motion->df;
  if (shape.drag > 0.0 && shape.omega > 0.0 && speed > 0.0) {
    // The drag on the wind relative to the tip, linearized in the tip's rate, is extra
    // damping: 2 alpha_air = omega^2 (1 + w2) drag |u| R, times 2 + b' along the wind
    // (cl/shared/tree_math.h, boreas_damped_step). Each direction steps exactly, here by
    // response_step's matrix exponential (the kernel takes closed forms).
    const double across = 0.5 * shape.omega * (1.0 + shape.w2) * shape.drag * speed * vogel(speed);
    const double along = across * (2.0 + (speed > shape.vogel_speed ? shape.vogel_b : 0.0));
    const dvec3 e = wind_at_tip / speed;
    const dvec3 xa = glm::dot(x, e) * e, ua = glm::dot(u, e) * e;
    const Response ra = response_step(shape.omega, shape.zeta + along, dt);
    const Response rc = response_step(shape.omega, shape.zeta + across, dt);
    motion->f = target + ra.a * xa + ra.b * ua + rc.a * (x - xa) + rc.b * (u - ua);
    motion->df = ra.c * xa + ra.d * ua + rc.c * (x - xa) + rc.d * (u - ua);
  } else {
    // x = F - F*, u = dF/dt, advanced exactly over the step with F* held.
    motion->f = target + r.a * x + r.b * u;
    motion->df = r.c * x + r.d * u;
  }
  if (glm::length(motion->f) > shape.break_bend) motion->broken = true;
  Branch out = placed;
  if (motion->broken) {
    // Hanging along drag plus weight, at rest; the first segment turns too.
    const double s = glm::length(wind_at_tip);
    const dvec3 load = shape.hang * s * vogel(s) * wind_at_tip - dvec3(0.0, 1.0, 0.0);
    motion->f = kHangReach * reach_scale * glm::normalize(load);
    motion->df = dvec3(0.0);
    out.curve.p[1] = bend_point(placed.curve.p[0], placed.curve.p[1] - placed.curve.p[0], motion->f);
    // O made perpendicular to the turned segment, with 1e-3 of the attachment frame's z
    // (x0 cross O) mixed in, so that a segment turned along O still leaves a direction.
    const dvec3 x0 = glm::normalize(placed.curve.p[1] - placed.curve.p[0]);
    const dvec3 z = glm::cross(x0, placed.o);
    const dvec3 x1 = glm::normalize(out.curve.p[1] - out.curve.p[0]);
    const dvec3 o = placed.o + 1e-3 * z;
    out.o = glm::normalize(o - glm::dot(o, x1) * x1);
  }
  const dvec3 f = motion->f;
  out.curve.p[2] =
      bend_point(out.curve.p[1], placed.curve.p[2] - placed.curve.p[1], shape.w2 * f);
  out.curve.p[3] = bend_point(out.curve.p[2], placed.curve.p[3] - placed.curve.p[2], f);
  return out;
}

LeafPose leaf_pose(const Branch& parent, const LeafModel& leaf) {
  // The reference attaches by the angles (the model stores their cosines).
  AttachFrame a = attach(parent, leaf.v, leaf.theta(), leaf.alpha());
  LeafPose p;
  p.position = a.origin + leaf.stem * a.x;
  p.axis = a.x;
  p.normal = leaf.cos_roll * a.y + leaf.sin_roll * a.z;
  return p;
}

// ---- Radius and surface ----------------------------------------------------------------

BranchRadius BranchRadius::of(const BranchModel& b) {
  BranchRadius p;
  p.radius = b.radius;
  p.taper_depth = b.taper_depth;
  p.taper_exponent = b.taper_exponent;
  p.flare = b.flare;
  p.bulge_count = b.bulge_count;
  p.bulge_depth = b.bulge_depth;
  p.lobe_count = b.lobe_count;
  p.lobe_depth = b.lobe_depth;
  p.lobe_taper = b.lobe_taper;
  p.tip_cap = b.tip_cap;
  p.bulge_phase = b.bulge_phase;
  return p;
}

namespace {

// The tip's hemisphere: sqrt(w (2 - w)) and its v-derivative (w = (1 - v) / cap inside it).
double cap_factor(double cap, double v, double* d_dv) {
  *d_dv = 0.0;
  if (cap <= 0.0) return 1.0;
  const double w = std::max((1.0 - v) / cap, 0.0);
  if (w >= 1.0) return 1.0;
  const double root = std::sqrt(w * (2.0 - w));
  *d_dv = -(1.0 - w) / (cap * std::max(root, 1e-3));
  return root;
}

// Arbaro's beads: the factor and its v-derivative, x radii from the stem's tip.
double bead_factor(const BranchRadius& p, double v, double* d_dv) {
  *d_dv = 0.0;
  if (p.bulge_depth == 0.0) return 1.0;
  const double x = 2.0 * (p.bulge_count * (1.0 - v) + p.bulge_phase);
  if (x <= 1.0) return 1.0;  // the tip cap's radius
  const double waist = 2.0 * std::floor(0.5 * x + 0.5);
  const double z = std::fabs(x - waist);
  const double root = std::sqrt(z * (2.0 - z));
  const double dz_dv = (x > waist ? -2.0 : 2.0) * p.bulge_count;
  const double held = std::max(root, 0.05);  // the crease's mean at a waist: boreas_beads
  *d_dv = p.bulge_depth * (1.0 - z) * root / (held * held) * dz_dv;
  return 1.0 - p.bulge_depth + p.bulge_depth * root;
}

}  // namespace

double branch_radius(const BranchRadius& p, double v, double theta, double* dr_dv,
                     double* dr_dtheta) {
  const double t = p.taper_exponent;
  double taper = 1.0 - p.taper_depth * std::pow(v, t);
  double d_taper =
      v > 0.0 ? -p.taper_depth * t * std::pow(v, t - 1.0) : (t == 1.0 ? -p.taper_depth : 0.0);
  double e = 1.0 - 8.0 * v;
  double flare = 1.0, d_flare = 0.0;
  if (e > 0.0) {
    double p100 = std::pow(100.0, e);
    flare = 1.0 + p.flare * (p100 - 1.0) / 100.0;
    d_flare = p.flare / 100.0 * p100 * std::log(100.0) * -8.0;
  }
  double d_bulges = 0.0;
  const double bulges = bead_factor(p, v, &d_bulges);
  double fade = 1.0 - v * p.lobe_taper;
  double lobe_sin = std::sin(p.lobe_count * theta);
  double lobes = 1.0 + p.lobe_depth * lobe_sin * fade;
  double d_lobes_dv = -p.lobe_depth * lobe_sin * p.lobe_taper;
  double d_lobes_dtheta = p.lobe_depth * p.lobe_count * std::cos(p.lobe_count * theta) * fade;
  double d_cap = 0.0;
  const double cap = cap_factor(p.tip_cap, v, &d_cap);
  const double open = p.radius * taper * flare * bulges * lobes;
  if (dr_dv)
    *dr_dv = p.radius * (d_taper * flare * bulges * lobes + taper * d_flare * bulges * lobes +
                         taper * flare * d_bulges * lobes + taper * flare * bulges * d_lobes_dv) *
                 cap +
             open * d_cap;
  if (dr_dtheta) *dr_dtheta = p.radius * taper * flare * bulges * d_lobes_dtheta * cap;
  return open * cap;
}

dvec3 surface_position(const Branch& b, const BranchRadius& p, double v, double theta) {
  SloanFrame f = sloan_frame(b.curve, b.o);
  dvec3 s, t;
  frame_handles(f, v, &s, &t);
  return bezier_point(b.curve, v) +
         branch_radius(p, v, theta) * (std::sin(theta) * s + std::cos(theta) * t);
}

SurfacePoint branch_surface(const Branch& b, const BranchRadius& p, double v, double theta) {
  SloanFrame f = sloan_frame(b.curve, b.o);
  dvec3 s, t, ds, dt;
  frame_handles(f, v, &s, &t, &ds, &dt);
  double dr_dv = 0.0, dr_dtheta = 0.0;
  double r = branch_radius(p, v, theta, &dr_dv, &dr_dtheta);
  double st = std::sin(theta), ct = std::cos(theta);
  dvec3 dir = st * s + ct * t;
  SurfacePoint out;
  out.position = bezier_point(b.curve, v) + r * dir;
  dvec3 x_v = bezier_derivative(b.curve, v) + dr_dv * dir + r * (st * ds + ct * dt);
  dvec3 x_theta = dr_dtheta * dir + r * (ct * s - st * t);
  out.normal = unit(glm::cross(x_theta, x_v));
  return out;
}

// ---- Whole tree --------------------------------------------------------------------------

TreeReference::TreeReference(const TreeModel& model, const dvec3& position,
                             std::vector<BranchShape> shapes, double rotation)
    : model_(model), shapes_(std::move(shapes)) {
  if (shapes_.size() != model_.branches.size())
    throw std::invalid_argument("TreeReference: one shape per branch");
  root_.curve.p = {position, position + dvec3(0.0, 1.0 / 3.0, 0.0),
                   position + dvec3(0.0, 2.0 / 3.0, 0.0), position + dvec3(0.0, 1.0, 0.0)};
  root_.o = dvec3(std::cos(rotation), 0.0, -std::sin(rotation));
  state_.resize(model_.branches.size());
  for (size_t b = 0; b < state_.size(); ++b) {
    if (model_.branches[b].parent >= static_cast<int>(b))
      throw std::invalid_argument("TreeReference: parents must come before their children");
    state_[b] = place_branch(parent_of(state_, static_cast<int>(b)), shapes_[b]);
  }
  rest_ = state_;
  motion_.assign(state_.size(), Motion{});
}

TreeReference::TreeReference(const TreeInstance& tree)
    : TreeReference(
          scaled_model(*tree.model, tree.params.scale),
          dvec3(tree.params.position[0], tree.params.position[1], tree.params.position[2]),
          shapes_of(tree), tree.params.rotation) {
  scale = tree.params.scale;
}

std::vector<BranchShape> TreeReference::shapes_of(const TreeInstance& tree) {
  std::vector<BranchShape> shapes;
  const double w2 = std::pow(2.0 / 3.0, tree.params.bend_exponent);
  const bool drag = tree.params.load == BOREAS_TREE_LOAD_DRAG;
  const std::vector<double> drag_k =
      drag ? drag_compliance(*tree.model, tree.params) : std::vector<double>{};
  const bool damped = tree.params.response == BOREAS_TREE_DAMPED;
  const std::vector<double> beam_radius =
      damped ? beam_base_radius(*tree.model) : std::vector<double>{};
  const std::vector<double> share = drag ? reconfiguring_share(*tree.model) : std::vector<double>{};
  const std::vector<double> breaks = drag ? break_bend(*tree.model, tree.params) : std::vector<double>{};
  const std::vector<double> hang = drag ? drag_per_weight(*tree.model) : std::vector<double>{};
  for (size_t b = 0; b < tree.model->branches.size(); ++b) {
    const BranchModel& template_branch = tree.model->branches[b];
    const BranchModel br = scaled_branch(template_branch, tree.params.scale);
    const TreeLevelParams& lp = tree.params.levels[br.level];
    BranchShape s;
    for (int k = 0; k < 4; ++k) s.local[k] = dvec3(br.local[k][0], br.local[k][1], br.local[k][2]);
    s.v = br.v;
    s.theta = br.theta;
    s.alpha = br.alpha;
    if (drag) {
      s.drag = drag_k[b] * tree.params.scale;
      s.vogel_b = share[b] * tree.model->vogel_exponent;
      s.vogel_speed = tree.model->vogel_speed;
      s.break_bend = breaks[b] * tree.params.scale;
      s.hang = hang[b] / tree.params.scale;
    } else
      s.compliance = scaled_compliance(template_branch, lp, tree.params.scale);
    s.w2 = w2;
    if (damped) {
      BranchModel beam = br;
      beam.radius = beam_radius[b] * tree.params.scale;
      s.omega = natural_frequency(beam, lp, tree.model->wood_modulus);
      s.zeta = lp.damping_ratio;
    }
    shapes.push_back(s);
  }
  return shapes;
}

const Branch& TreeReference::parent_of(const std::vector<Branch>& state, int b) const {
  int p = model_.branches[b].parent;
  return p < 0 ? root_ : state[p];
}

void TreeReference::step(double dt, boreas_tree_mode mode, const WindFn& wind) {
  const std::vector<Branch> before = state_;
  const std::vector<Branch>& parents = mode == BOREAS_TREE_LAGGED ? before : state_;
  for (size_t b = 0; b < state_.size(); ++b) {
    const BranchShape& shape = shapes_[b];
    const Branch& parent = parent_of(parents, static_cast<int>(b));
    dvec3 tip = place_branch(parent, shape).curve.p[3];
    Response r = response_step(shape.omega, shape.zeta, dt);
    state_[b] = branch_step(parent, shape, wind(tip), r, &motion_[b], dt, scale);
  }
}

std::vector<LeafPose> TreeReference::leaves() const {
  std::vector<LeafPose> out;
  out.reserve(model_.leaves.size());
  for (const LeafModel& leaf : model_.leaves) out.push_back(leaf_pose(state_[leaf.parent], leaf));
  return out;
}

}  // namespace boreas::impl::reference
