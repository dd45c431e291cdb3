// boreas: double-precision host references of the tree kernels (cl/tree_step.cl,
// cl/tree_leaves.cl, cl/tree_deform.cl). Tests compare the float32 kernels against these.
//
// Written independently of cl/shared/tree_math.h (which the kernels and the host share):
// glm::dvec3 and the equations of Skjermo 2007 sec. 3 and 4.2-4.3 as read in
// shared/seeds/README.md, with the conventions documented at the top of tree_math.h:
//  - a branch's unpositioned control points have P0 at the origin and P1 on +x;
//  - Sloan frame (eq. 8) with normalized handles: S0 = L0 x O, T0 = S0 x L0,
//    T1 = S0 x L1, S1 = L1 x T1, T2 = S1 x L2, S2 = L2 x T2;
//  - the handles are blended with the quadratic Bernstein weights (eq. 9), so the surface
//    is X(v, th) = C(v) + r(v, th) (sin th S(v) + cos th T(v));
//  - attachment: U = C'(v) / |C'(v)|, V = the radial direction at (v, theta) made
//    perpendicular to U, the frame (U, V, U x V) turned down by alpha about U x V;
//  - bend factors b_2 = w2 F, b_3 = F with w2 = (2/3)^gamma; the bend of eq. 17 keeps
//    every segment's length; P0 and P1 do not move.
// Nothing here is approximated: libm in double, no polynomial math, no float.
#pragma once

#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "boreas/boreas.h"
#include "trees/tree_model.h"

namespace boreas::impl {
struct TreeInstance;
}

namespace boreas::impl::reference {

using glm::dvec3;

// ---- Cubic Bezier ----------------------------------------------------------------------

struct Bezier {
  std::array<dvec3, 4> p{};
};

dvec3 bezier_point(const Bezier& c, double u);
dvec3 bezier_derivative(const Bezier& c, double u);  // dC/du

// ---- Sloan frame (eq. 8) and its blended handles -----------------------------------------

struct SloanFrame {
  std::array<dvec3, 3> s{}, t{};  // S0..S2, T0..T2
};

SloanFrame sloan_frame(const Bezier& c, const dvec3& o);

// S(u), T(u) = (1-u)^2 X0 + 2u(1-u) X1 + u^2 X2, and their u-derivatives (any may be null).
void frame_handles(const SloanFrame& f, double u, dvec3* s, dvec3* t, dvec3* ds = nullptr,
                   dvec3* dt = nullptr);

// ---- A branch's animated state: its world control points and orientation vector O --------

struct Branch {
  Bezier curve;
  dvec3 o{1.0, 0.0, 0.0};
};

// ---- Attachment (sec. 4.2) ---------------------------------------------------------------

struct AttachFrame {
  dvec3 origin{0.0}, x{0.0}, y{0.0}, z{0.0};
};

// theta and alpha in radians.
AttachFrame attach(const Branch& parent, double v, double theta, double alpha);
dvec3 attach_place(const AttachFrame& a, const dvec3& local);

// ---- Bending (sec. 4.3, eq. 17) -----------------------------------------------------------

// P'_i = P'_{i-1} + |seg| normalize(seg + bend), seg = P_i - P_{i-1} unbent.
dvec3 bend_point(const dvec3& bent_prev, const dvec3& seg, const dvec3& bend);

// ---- Per-branch step ----------------------------------------------------------------------

// The exact step over dt of x'' + 2 zeta omega x' + omega^2 x = 0 as (x, x') -> (a x + b x',
// c x + d x'). All zero means quasi-static (F = F* at once).
struct Response {
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;
};

// exp(A dt) for A = [[0, 1], [-omega^2, -2 zeta omega]] by scaling and squaring of its
// Taylor series (independent of the closed forms in tree_params.cpp); omega <= 0 gives
// the quasi-static zero response.
Response response_step(double omega, double zeta, double dt);

// The bend factor F, its rate, and whether the branch is broken.
struct Motion {
  dvec3 f{0.0}, df{0.0};
  bool broken = false;
};

// Everything about one branch that does not change from step to step.
struct BranchShape {
  std::array<dvec3, 4> local{};  // unpositioned control points (local[0]: P0, 0 but for a
                                 // trunk standing apart)
  double v = 0.0, theta = 0.0, alpha = 0.0;
  double compliance = 0.0;         // linear load: bend vector per unit wind, m / (m/s)
  double drag = 0.0;               // drag load: bend per squared wind, m / (m/s)^2
  double w2 = 0.0;                 // bend weight of P2
  double omega = 0.0, zeta = 0.0;  // damped response; omega 0 = quasi-static
  // Storms (drag load, trees/wind_load.h): Vogel's exponent and reference speed (m/s), the
  // bend at which the branch breaks (m; infinite: never), its drag over weight (1/(m/s)^2).
  double vogel_b = 0.0, vogel_speed = 1.0;
  double break_bend = 1e300, hang = 0.0;
};

// How far (m, times the tree's scale in shapes_of) a broken branch's bend reaches along its
// load (cl/shared/tree_types.h's BOREAS_TREE_HANG_REACH).
inline constexpr double kHangReach = 1e4;

// The branch placed unbent on its parent (O = the child's y axis).
Branch place_branch(const Branch& parent, const BranchShape& shape);

// One step of one branch: placed on `parent`, bent by F advanced over dt toward
// F* = compliance u (linear load) or drag |u| u R (drag load; R = (|u| / vogel_speed)^vogel_b
// above vogel_speed, else 1) over one step of `response`; with a drag load and a damped
// response, the drag on the wind relative to the tip (its velocity (1 + w2) dF/dt),
// linearized in that velocity, adds aerodynamic damping and the step is the exact one of
// the oscillator with it (cl/shared/tree_math.h, boreas_damped_step); `motion` is
// updated. Once |F| passes break_bend the branch is broken: F is kHangReach * reach_scale along
// hang R |u| u - y, its rate 0, and its first segment turns too (eq. 17's rule).
// wind_at_tip is the wind at the placed, unbent P3.
Branch branch_step(const Branch& parent, const BranchShape& shape, const dvec3& wind_at_tip,
                   const Response& response, Motion* motion, double dt, double reach_scale = 1.0);

// ---- Leaves --------------------------------------------------------------------------------

struct LeafPose {
  dvec3 position{0.0}, axis{0.0}, normal{0.0};
};

// The leaf attached to its parent as a child branch is; the blade starts stem along x.
LeafPose leaf_pose(const Branch& parent, const LeafModel& leaf);

// ---- Radius functions (eq. 2-5) and the swept surface (eq. 6-9, sec. 3.4) ------------------

struct BranchRadius {
  double radius = 0.0;
  double taper_depth = 1.0, taper_exponent = 1.0;
  double flare = 0.0;
  double bulge_count = 0.0, bulge_depth = 0.0;
  double lobe_count = 0.0, lobe_depth = 0.0, lobe_taper = 1.0;
  double tip_cap = 0.0;
  double bulge_phase = 0.0;
  static BranchRadius of(const BranchModel& b);
};

// r(v, theta) = radius (1 - taper_depth v^taper_exponent) (1 + flare (100^max(0, 1-8v) - 1)
// / 100) beads(v) (1 + lobe_depth sin(lobe_count theta) (1 - v lobe_taper)) sqrt(w (2 - w)),
// w = min(1, (1 - v) / tip_cap) (1 where tip_cap is 0), theta in radians; beads(v) = 1 -
// bulge_depth + bulge_depth sqrt(z (2 - z)), z the distance in radii from the nearest waist,
// the waists 2 radii apart counted from the stem's tip, x = 2 (bulge_count (1 - v) +
// bulge_phase) radii away (Arbaro's periodic taper), 1 within the last radius; with its
// partial derivatives (either may be null). The cap's slope is held finite at the tip as the
// device holds it (its root at least 1e-3: boreas_tip_cap), the beads' falls to 0 at a
// waist as the device's (boreas_beads).
double branch_radius(const BranchRadius& p, double v, double theta, double* dr_dv = nullptr,
                     double* dr_dtheta = nullptr);

struct SurfacePoint {
  dvec3 position{0.0};
  dvec3 normal{0.0};  // unit, outward: normalize(X_theta x X_v); zero where undefined
};

// X(v, theta) = C(v) + r (sin th S(v) + cos th T(v)) and its analytic outward normal.
SurfacePoint branch_surface(const Branch& b, const BranchRadius& p, double v, double theta);
dvec3 surface_position(const Branch& b, const BranchRadius& p, double v, double theta);

// ---- A whole tree --------------------------------------------------------------------------

using WindFn = std::function<dvec3(const dvec3&)>;

// A tree as TreeBatch lays it out: a fixed root (the vertical unit segment at the tree's
// position, O = +x turned by the tree's rotation about +y) that the trunk hangs from, every
// branch placed unbent at rest to start with, zero motion.
class TreeReference {
 public:
  // Branches of `model` with their per-branch constants in `shapes` (same order).
  TreeReference(const TreeModel& model, const dvec3& position, std::vector<BranchShape> shapes,
                double rotation = 0.0);
  // The constants as TreeBatch derives them from the tree's params (drag_compliance or
  // bend_compliance by its load, natural_frequency and the levels' damping ratios, w2 =
  // (2/3)^bend_exponent), for the tree's template at its scale and rotation.
  explicit TreeReference(const TreeInstance& tree);

  // One step: every branch re-attached and bent. Lagged: each branch hangs from its
  // parent's state before this step. Exact: from its parent's state after it (parents
  // first). wind(p) is the wind at p for this step.
  void step(double dt, boreas_tree_mode mode, const WindFn& wind);

  const Branch& root() const { return root_; }
  const std::vector<Branch>& branches() const { return state_; }
  const std::vector<Motion>& motion() const { return motion_; }
  const std::vector<BranchShape>& shapes() const { return shapes_; }
  // The leaves on the current state.
  std::vector<LeafPose> leaves() const;
  // The unbent rest placement (state at construction).
  const std::vector<Branch>& rest() const { return rest_; }
  // The tree's scale (the hang's reach).
  double scale = 1.0;

  static std::vector<BranchShape> shapes_of(const TreeInstance& tree);

 private:
  const Branch& parent_of(const std::vector<Branch>& state, int b) const;

  TreeModel model_;
  Branch root_;
  std::vector<BranchShape> shapes_;
  std::vector<Branch> state_, rest_;
  std::vector<Motion> motion_;
};

}  // namespace boreas::impl::reference
