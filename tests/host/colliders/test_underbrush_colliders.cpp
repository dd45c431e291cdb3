// Colliders on underbrush (issue 38): what a collider does to the components it meets
// (pushes, tramples, breaks) and what they push it back with; trampled grass rising over its
// species' recovery_time; broken components held flat while the wind blows; determinism;
// and components no collider reaches stepping exactly as in a world without colliders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

// The fixtures (through meadow.h) choose the host's math before the shared header is read.
#include "host/underbrush/underbrush_fixtures.h"
#include "shared/underbrush_math.h"
#include "underbrush/frame_pack.h"

namespace boreas {
namespace {

using test::meadow_world;
using test::planting_grid;
using test::species_params;

constexpr float kDt = 1.0f / 60.0f;

struct Placed {
  std::unique_ptr<impl::World> world;
  boreas_meadow_id id;
  const impl::Meadow& meadow() { return world->meadow(id).meadow; }
  std::vector<float> state() { return world->underbrush().read_meadow_state(world->meadow(id).key); }
  // The component planes are on the device alone once added (underbrush/meadow.h).
  std::vector<float> frame() { return world->underbrush().read_meadow_frame(world->meadow(id).key); }
  std::vector<int32_t> index() { return world->underbrush().read_meadow_index(world->meadow(id).key); }
  int n() { return meadow().count; }
};

Placed place(float wind, impl::MeadowParams params, int per_side, double spacing) {
  Placed p;
  p.world = meadow_world(wind);
  p.id = p.world->add_meadow(impl::meadow_from_plantings(std::move(params), planting_grid(per_side, spacing)));
  return p;
}

float plane(const std::vector<float>& s, int n, int plane, int i) { return s[size_t(plane) * size_t(n) + size_t(i)]; }

boreas_collider_def box(float cx, float cy, float cz, float hx, float hy, float hz, float vx = 0.0f) {
  boreas_collider_def d = boreas_default_collider_def();
  d.shape = BOREAS_COLLIDER_BOX;
  d.pose.position[0] = cx, d.pose.position[1] = cy, d.pose.position[2] = cz;
  d.half_extents[0] = hx, d.half_extents[1] = hy, d.half_extents[2] = hz;
  d.velocity[0] = vx;
  return d;
}

// Signed distance (double) from p to an axis-aligned box (center c, half extents h).
double box_distance(const double p[3], const double c[3], const double h[3], double normal[3]) {
  double q[3], o2 = 0.0, deepest = -1e300;
  int face = 0;
  for (int a = 0; a < 3; ++a) {
    q[a] = std::fabs(p[a] - c[a]) - h[a];
    o2 += std::max(q[a], 0.0) * std::max(q[a], 0.0);
    if (q[a] > deepest) deepest = q[a], face = a;
  }
  const double outside = std::sqrt(o2);
  for (int a = 0; a < 3; ++a) {
    const double s = p[a] >= c[a] ? 1.0 : -1.0;
    normal[a] = outside > 0.0 ? s * std::max(q[a], 0.0) / outside : (a == face ? s : 0.0);
  }
  return outside + std::min(deepest, 0.0);
}

// ---- Trampling: a fast box meets every component in its way ----------------------------

// A car-sized box at 20 m/s (33 cm a step, a few blades' spacing) drives through a meadow,
// its bottom 2 cm below the ground. Before each step, every component whose center of mass
// or base lies inside what the box sweeps over that step (a double reference: an
// axis-aligned box moving along x) by more than a millimetre must lie flat after it
// (flatness exactly 1), and none that lay outside it by more than a millimetre in every
// step so far may. With a focus far away (the meadow stepped every 16th step, or not at
// all) as well: tiles a collider reaches are stepped at rate 1.
void expect_no_untouched_blade(bool far_focus) {
  Placed p = place(0.0f, species_params({"meadow_grass"}), 24, 0.1);
  if (far_focus) {
    const float focus[3] = {0.0f, 0.0f, 130.0f};
    p.world->set_focus(focus, 1);
  }
  const double h[3] = {1.0, 0.7, 0.8};
  const double speed = 20.0;
  const boreas_collider_def def = box(-2.4f, float(h[1] - 0.02), 0.1f, float(h[0]), float(h[1]), float(h[2]), float(speed));
  p.world->add_collider(def);
  const int n = p.n();
  std::vector<bool> ever_near(size_t(n), false);
  int inside_total = 0;
  for (int s = 0; s < 16; ++s) {
    const std::vector<float> before = p.state();
    const double x0 = def.pose.position[0] + speed * kDt * s;
    std::vector<int> inside;
    for (int i = 0; i < n; ++i) {
      bool in = false, near = false;
      for (int plane0 : {BOREAS_UB_STATE_X, BOREAS_UB_STATE_BASE}) {
        const double q[3] = {plane(before, n, plane0, i), plane(before, n, plane0 + 1, i),
                             plane(before, n, plane0 + 2, i)};
        // The swept box: x from its start's back to its end's front.
        const double lo[3] = {x0 - h[0], def.pose.position[1] - h[1], def.pose.position[2] - h[2]};
        const double hi[3] = {x0 + speed * kDt + h[0], def.pose.position[1] + h[1], def.pose.position[2] + h[2]};
        double depth = 1e300, gap = 0.0;
        for (int a = 0; a < 3; ++a) {
          depth = std::min({depth, q[a] - lo[a], hi[a] - q[a]});
          gap = std::max({gap, lo[a] - q[a], q[a] - hi[a]});
        }
        in = in || depth > 1e-3;
        near = near || gap < 1e-3;
      }
      if (in) inside.push_back(i);
      if (near) ever_near[size_t(i)] = true;
    }
    p.world->step(kDt);
    const std::vector<float> after = p.state();
    for (int i : inside)
      ASSERT_EQ(plane(after, n, BOREAS_UB_STATE_FLAT, i), 1.0f) << "component " << i << " in the box's way at step " << s;
    for (int i = 0; i < n; ++i)
      if (!ever_near[size_t(i)])
        ASSERT_EQ(plane(after, n, BOREAS_UB_STATE_FLAT, i), 0.0f) << "component " << i << " never near the box";
    inside_total += int(inside.size());
  }
  EXPECT_GT(inside_total, n / 4) << "the box crossed a good part of the meadow";
}

TEST(UnderbrushColliders, FastBoxLeavesNoUntouchedBladeInItsPath) { expect_no_untouched_blade(false); }
TEST(UnderbrushColliders, FastBoxTramplesFarFromTheFocusToo) { expect_no_untouched_blade(true); }

// ---- Reaction: what the components push a collider back with ---------------------------

// A box held still with its bottom `depth` below the highest rest center of mass, for 1 s:
// its contact force and torque, and the same summed in double from the state the last
// step read (minus mass times the push of every component, at the box's surface point).
struct Press {
  boreas_collider_contact got{};
  double want_force[3] = {}, want_torque[3] = {};
  int64_t want_contacts = 0;
};

Press press(double depth) {
  Placed p = place(0.0f, species_params({"meadow_grass"}), 14, 0.1);
  const impl::Meadow& m = p.meadow();
  const std::vector<float> frame = p.frame();
  const std::vector<int32_t> index = p.index();
  const int n = m.count;
  double top = -1e300;
  for (int i = 0; i < n; ++i) top = std::max(top, double(frame[size_t(BOREAS_UB_FRAME_REST + 1) * n + i]));
  const double c[3] = {0.0, top - depth + 0.2, 0.0}, h[3] = {0.4, 0.2, 0.4};
  boreas_collider_id id = p.world->add_collider(box(float(c[0]), float(c[1]), float(c[2]), float(h[0]), float(h[1]), float(h[2])));
  for (int s = 0; s < 59; ++s) p.world->step(kDt);
  const std::vector<float> before = p.state();
  p.world->step(kDt);
  Press out;
  out.got = p.world->collider_contact(id);
  for (int i = 0; i < n; ++i) {
    const BoreasGpuPart& g = m.parts[size_t(impl::part_of(index.data(), int(n), int(i)))].gpu;
    const double reach = double(g.reach) * impl::unpack_frame(index.data(), int(n), int(i)).scale;
    const double x[3] = {plane(before, n, BOREAS_UB_STATE_X, i), plane(before, n, BOREAS_UB_STATE_X + 1, i),
                         plane(before, n, BOREAS_UB_STATE_X + 2, i)};
    double normal[3];
    const double d = box_distance(x, c, h, normal);
    const double k = double(g.collider_push) * std::clamp((reach - d) / reach, 0.0, 1.0);
    if (k <= 0.0) continue;
    ++out.want_contacts;
    double f[3], r[3];
    for (int a = 0; a < 3; ++a) {
      // mass: the part's times the instance's scale (length_variation keeps the cross-section)
      f[a] = -k * normal[a] * impl::unpack_frame(index.data(), int(n), int(i)).scale / double(g.inv_mass);
      r[a] = x[a] - d * normal[a] - c[a];
      out.want_force[a] += f[a];
    }
    out.want_torque[0] += r[1] * f[2] - r[2] * f[1];
    out.want_torque[1] += r[2] * f[0] - r[0] * f[2];
    out.want_torque[2] += r[0] * f[1] - r[1] * f[0];
  }
  return out;
}

TEST(UnderbrushColliders, ContactForceOpposesThePressAndGrowsWithDepth) {
  double last = 0.0;
  for (double depth : {0.01, 0.02, 0.03}) {
    const Press r = press(depth);
    const float* f = r.got.force;
    std::printf("pressed %.0f cm: force %.4g %.4g %.4g N, torque %.3g %.3g %.3g N m, %d contacts\n", depth * 100,
                f[0], f[1], f[2], r.got.torque[0], r.got.torque[1], r.got.torque[2], r.got.contacts);
    EXPECT_GT(f[1], 0.0f) << "the grass pushes the box up, against its press";
    EXPECT_LT(std::hypot(f[0], f[2]), 0.2 * f[1]) << "a square box over an even meadow: mostly up";
    EXPECT_GT(f[1], 1.05 * last) << "deeper presses more components, harder";
    last = f[1];
    // Against the double sum of the same pushes (the kernel's float sums: relative 1e-4).
    EXPECT_EQ(r.got.contacts, r.want_contacts);
    const double scale = std::hypot(r.want_force[0], r.want_force[1], r.want_force[2]);
    const double tscale = std::hypot(r.want_torque[0], r.want_torque[1], r.want_torque[2]) + 1e-3 * scale;
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(f[a], r.want_force[a], 1e-4 * scale) << "force " << a;
      EXPECT_NEAR(r.got.torque[a], r.want_torque[a], 1e-3 * tscale) << "torque " << a;
    }
  }
}

TEST(UnderbrushColliders, DrivingBoxFeelsTheGrassHoldItBack) {
  Placed p = place(0.0f, species_params({"meadow_grass"}), 20, 0.1);
  boreas_collider_id id = p.world->add_collider(box(-1.6f, 0.35f, 0.0f, 0.3f, 0.3f, 0.3f, 2.0f));
  int touching = 0;
  for (int s = 0; s < 60; ++s) {
    p.world->step(kDt);
    const boreas_collider_contact c = p.world->collider_contact(id);
    if (c.contacts == 0) continue;
    ++touching;
    EXPECT_LE(c.force[0], 0.0f) << "step " << s << ": the grass it drives into pushes back";
  }
  EXPECT_GT(touching, 40);
}

// ---- Recovery ------------------------------------------------------------------------

// Trampled by a box that then leaves, grass rises: its flatness is exp(-t / T) (the step's
// loss 1 - exp(-dt / T) compounded: relative 1e-4 over 3 T), and its centers of mass follow
// the equilibrium that flatness sets, rest height + f (flat height - rest height), behind
// it by the critically damped constraint's lag: a follower 1 / (1 + s tau)^2 of a target
// falling as exp(-t / T) settles at 1 / (1 - tau / T)^2 times it, so the centers of mass
// are still that share lower (1.138 f of the fall for tau = 0.25 s, T = 4 s; checked to
// 0.01 of f times the fall from T / 2 on, when the start's transient, e^(-t/tau), is gone).
TEST(UnderbrushColliders, TrampledGrassRisesOverItsRecoveryTime) {
  impl::MeadowParams params = species_params({"meadow_grass"});
  const double T = 4.0;
  params.species[0].tissue.recovery_time = T;
  Placed p = place(0.0f, params, 8, 0.1);
  const int n = p.n();
  const impl::Meadow& m = p.meadow();
  const std::vector<float> frame = p.frame();
  const std::vector<int32_t> index = p.index();
  boreas_collider_id id = p.world->add_collider(box(0.0f, 0.3f - 0.02f, 0.0f, 1.0f, 0.3f, 1.0f));
  p.world->step(kDt);
  p.world->remove_collider(id);
  std::vector<float> s = p.state();
  for (int i = 0; i < n; ++i) ASSERT_EQ(plane(s, n, BOREAS_UB_STATE_FLAT, i), 1.0f) << "all under the box";
  int steps = 0;
  for (double t : {0.5 * T, T, 2.0 * T, 3.0 * T}) {
    for (; steps < int(std::lround(t / kDt)); ++steps) p.world->step(kDt);
    s = p.state();
    const double f_want = std::exp(-steps * double(kDt) / T);
    const double tau = params.species[0].tissue.tau;
    double fall = 0.0, off = 0.0, lag = 0.0;
    for (int i = 0; i < n; ++i) {
      const float f = plane(s, n, BOREAS_UB_STATE_FLAT, i);
      ASSERT_NEAR(f, f_want, 1e-4 * f_want) << "t = " << t;
      const BoreasGpuPart& g = m.parts[size_t(impl::part_of(index.data(), int(n), int(i)))].gpu;
      const double reach = double(g.reach) * impl::unpack_frame(index.data(), int(n), int(i)).scale;
      const double base_y = frame[size_t(BOREAS_UB_FRAME_BASE + 1) * n + i];
      const double rest_y = frame[size_t(BOREAS_UB_FRAME_REST + 1) * n + i];
      const double flat_y = base_y + BOREAS_UB_FLAT_HEIGHT * reach;
      fall += rest_y - flat_y;
      off += plane(s, n, BOREAS_UB_STATE_X + 1, i) - (rest_y + f * (flat_y - rest_y));
      // each instance's own tau: tau s^2 (length_variation), weighted by its fall
      const double scale = impl::unpack_frame(index.data(), int(n), int(i)).scale, tau_i = tau * scale * scale;
      lag += (rest_y - flat_y) * (1.0 / ((1.0 - tau_i / T) * (1.0 - tau_i / T)) - 1.0);
    }
    lag /= fall;
    std::printf("t = %.1f s: flatness %.4f, centers of mass %.4f f of the fall below the "
                "equilibrium (lag law %.4f)\n", t, f_want, -off / (fall * f_want), lag);
    EXPECT_NEAR(-off / (fall * f_want), lag, 0.01) << "t = " << t;
  }
}

// ---- Storms and breaking -----------------------------------------------------------

// A gale breaks weak blades, which lie flat (flatness 1) while it blows; once it falls,
// they rise at their recovery rate and stay broken.
TEST(UnderbrushColliders, BrokenComponentsLieFlatUntilTheWindFalls) {
  impl::MeadowParams params = species_params({"meadow_grass"});
  params.species[0].tissue.break_stress = 2e6;
  params.species[0].tissue.recovery_time = 2.0;
  Placed p = place(45.0f, params, 3, 0.3);
  const int n = p.n();
  for (int s = 0; s < 120; ++s) p.world->step(kDt);
  std::vector<float> s = p.state();
  int broken = 0;
  for (int i = 0; i < n; ++i) {
    const bool b = plane(s, n, BOREAS_UB_STATE_BROKEN, i) > 0.0f;
    broken += b;
    EXPECT_EQ(plane(s, n, BOREAS_UB_STATE_FLAT, i), b ? 1.0f : 0.0f) << "component " << i;
  }
  ASSERT_GT(broken, 0);
  p.world->wind().set_waves(nullptr, 0, 0.0f, p.world->time());
  for (int k = 0; k < 120; ++k) p.world->step(kDt);
  s = p.state();
  const double f_want = std::exp(-2.0 * 1.0 / 2.0);
  for (int i = 0; i < n; ++i)
    if (plane(s, n, BOREAS_UB_STATE_BROKEN, i) > 0.0f)
      EXPECT_NEAR(plane(s, n, BOREAS_UB_STATE_FLAT, i), f_want, 2e-3) << "rising since the wind fell";
}

// A collider's push is in the load that Endo's rule reads: blades weak enough to break under
// the full push (40 g) but not under their own weight break where a box presses them, and
// nowhere else.
TEST(UnderbrushColliders, ColliderPressingHardEnoughBreaksWeakBlades) {
  impl::MeadowParams params = species_params({"meadow_grass"});
  // holds itself, not 40 g (its longest blades, 1.3 times the mean, break at 1/1.3^2 of
  // the mean's load)
  params.species[0].tissue.break_stress = 4e6;
  Placed p = place(0.0f, params, 12, 0.1);
  const int n = p.n();
  std::vector<float> s = p.state();
  for (int i = 0; i < n; ++i) ASSERT_EQ(plane(s, n, BOREAS_UB_STATE_BROKEN, i), 0.0f) << "holds its own weight";
  p.world->add_collider(box(-0.6f, 0.1f, 0.0f, 0.3f, 0.1f, 0.3f));
  for (int k = 0; k < 30; ++k) p.world->step(kDt);
  s = p.state();
  int near_broken = 0, far_broken = 0;
  for (int i = 0; i < n; ++i) {
    const bool b = plane(s, n, BOREAS_UB_STATE_BROKEN, i) > 0.0f;
    const bool far = plane(s, n, BOREAS_UB_STATE_BASE, i) > 0.2f;
    (far ? far_broken : near_broken) += b;
  }
  EXPECT_GT(near_broken, 0);
  EXPECT_EQ(far_broken, 0);
}

// ---- Determinism and cost --------------------------------------------------------------

TEST(UnderbrushColliders, SameInputsGiveTheSameContactBitsAndState) {
  auto run = [] {
    Placed p = place(6.0f, species_params({"meadow_grass", "daisy"}), 12, 0.12);
    std::vector<boreas_collider_id> ids;
    ids.push_back(p.world->add_collider(box(-1.2f, 0.3f, 0.1f, 0.4f, 0.3f, 0.5f, 8.0f)));
    boreas_collider_def walker = boreas_default_collider_def();
    walker.shape = BOREAS_COLLIDER_CAPSULE;
    walker.radius = 0.2f;
    walker.half_height = 0.6f;
    walker.pose.position[1] = 0.8f;
    walker.velocity[2] = 1.4f;
    ids.push_back(p.world->add_collider(walker));
    std::vector<boreas_collider_contact> contacts;
    std::vector<uint64_t> hashes;
    for (int s = 0; s < 30; ++s) {
      p.world->step(kDt);
      for (boreas_collider_id id : ids) contacts.push_back(p.world->collider_contact(id));
      hashes.push_back(p.world->state_hash());
    }
    return std::make_pair(contacts, hashes);
  };
  const auto a = run(), b = run();
  ASSERT_EQ(a.first.size(), b.first.size());
  EXPECT_EQ(std::memcmp(a.first.data(), b.first.data(), a.first.size() * sizeof(boreas_collider_contact)), 0);
  EXPECT_EQ(a.second, b.second);
  int touched = 0;
  for (const boreas_collider_contact& c : a.first) touched += c.contacts > 0;
  EXPECT_GT(touched, 20) << "the colliders did touch the meadow";
}

// Components whose tiles no collider reaches step as in a world without colliders, bit for
// bit, and the tiles the collider reaches are a few.
TEST(UnderbrushColliders, FarComponentsAreBitIdenticalToAWorldWithoutColliders) {
  auto run = [](bool collider) {
    Placed p = place(5.0f, species_params({"meadow_grass", "clover"}), 30, 0.15);
    if (collider) p.world->add_collider(box(-1.5f, 0.3f, -1.5f, 0.3f, 0.3f, 0.3f, 1.0f));
    for (int s = 0; s < 40; ++s) p.world->step(kDt);
    return p;
  };
  Placed with = run(true), without = run(false);
  const std::vector<float> a = with.state(), b = without.state();
  const int n = with.n();
  int far = 0, differ_far = 0, differ_near = 0;
  for (int i = 0; i < n; ++i) {
    const double bx = plane(a, n, BOREAS_UB_STATE_BASE, i) + 1.5, bz = plane(a, n, BOREAS_UB_STATE_BASE + 2, i) + 1.5;
    bool same = true;
    for (int k = 0; k < BOREAS_UB_STATE_PLANES; ++k)
      same = same && std::memcmp(&a[size_t(k) * n + i], &b[size_t(k) * n + i], sizeof(float)) == 0;
    // Beyond the collider's path (x from -1.5 to -0.8), its size and two tiles' worth of room.
    if (std::fabs(bz) > 2.0 || bx > 3.0) {
      ++far;
      differ_far += !same;
    } else {
      differ_near += !same;
    }
  }
  EXPECT_GT(far, n / 3);
  EXPECT_EQ(differ_far, 0);
  EXPECT_GT(differ_near, 0) << "the collider did change the components in its way";
  EXPECT_LT(with.world->underbrush().contact_pairs(), 40u) << "work in proportion to what it reaches";
}

TEST(UnderbrushColliders, RecoveryTimeIsReadFromTheSpeciesFileAndChecked) {
  const std::string good =
      R"({"format": "boreas-underbrush-1", "name": "g", "tissue": {"recovery_time": 7200},
          "parts": [{"name": "blade"}]})";
  EXPECT_EQ(impl::parse_component_species(good, "g.json").tissue.recovery_time, 7200.0);
  EXPECT_EQ(impl::load_component_species("meadow_grass").tissue.recovery_time, 30.0) << "the default";
  std::string bad = good;
  bad.replace(bad.find("7200"), 4, "-1.0");
  try {
    impl::parse_component_species(bad, "g.json");
    FAIL() << "a negative recovery time was taken";
  } catch (const impl::Error& e) {
    EXPECT_NE(std::string(e.what()).find("g.json: tissue.recovery_time"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace boreas
