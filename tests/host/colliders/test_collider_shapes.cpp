// boreas tests: colliders' shapes and sweeps (cl/shared/collider_math.h, run here at width 1
// as the kernels run it) against double-precision references, their poses over steps, and
// their defs refused field by field.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>

#include "boreas/boreas.h"
#include "colliders/collider.h"
// The host build of the kernels' math, as the native twins take it.
#define BOREAS_FAST_MATH 1
#include "shared/collider_math.h"

namespace {

using boreas::impl::Collider;
using V = std::array<double, 3>;

V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double len(V a) { return std::sqrt(dot(a, a)); }

// A unit quaternion from an axis and angle, as floats.
void set_rotation(boreas_pose& p, V axis, double angle) {
  const double n = len(axis);
  for (int i = 0; i < 3; ++i) p.orientation[i] = float(axis[size_t(i)] / n * std::sin(angle / 2));
  p.orientation[3] = float(std::cos(angle / 2));
}

// The collider's local axes in double, from its float quaternion (normalized).
std::array<V, 3> axes_of(const boreas_pose& p) {
  boreas::impl::Pose pose;
  double n = 0.0;
  for (int i = 0; i < 4; ++i) n += double(p.orientation[i]) * p.orientation[i];
  for (int i = 0; i < 4; ++i) pose.rotation[size_t(i)] = p.orientation[i] / std::sqrt(n);
  return {pose.turn({1, 0, 0}), pose.turn({0, 1, 0}), pose.turn({0, 0, 1})};
}

// The exact signed distance from p to the still shape, in double: the box of half extents h
// grown by r (a sphere, capsule or box), by the closest point, not by the kernel's formula.
double reference_distance(const boreas_collider_def& d, V p) {
  const auto axes = axes_of(d.pose);
  const V c = {d.pose.position[0], d.pose.position[1], d.pose.position[2]};
  V h{}, q{};
  double r = 0.0;
  if (d.shape == BOREAS_COLLIDER_SPHERE) r = d.radius;
  if (d.shape == BOREAS_COLLIDER_CAPSULE) r = d.radius, h = {0.0, d.half_height, 0.0};
  if (d.shape == BOREAS_COLLIDER_BOX) h = {d.half_extents[0], d.half_extents[1], d.half_extents[2]};
  for (size_t i = 0; i < 3; ++i) q[i] = dot(sub(p, c), axes[i]);
  V nearest{};
  bool inside = true;
  for (size_t i = 0; i < 3; ++i) {
    nearest[i] = std::clamp(q[i], -h[i], h[i]);
    inside = inside && std::fabs(q[i]) <= h[i];
  }
  if (!inside) return len(sub(q, nearest)) - r;
  double to_face = 1e300;  // inside the box: the nearest face
  for (size_t i = 0; i < 3; ++i) to_face = std::min(to_face, h[i] - std::fabs(q[i]));
  return -to_face - r;
}

boreas_collider_def shape_def(boreas_collider_shape shape) {
  boreas_collider_def d = boreas_default_collider_def();
  d.shape = shape;
  d.pose.position[0] = 1.0f, d.pose.position[1] = 0.5f, d.pose.position[2] = -2.0f;
  set_rotation(d.pose, {0.3, 1.0, -0.4}, 0.9);
  d.radius = 0.3f;
  d.half_height = 0.6f;
  d.half_extents[0] = 2.0f, d.half_extents[1] = 0.7f, d.half_extents[2] = 0.9f;
  return d;
}

BoreasColliderDistance kernel_distance(const BoreasGpuCollider& g, V p) {
  return boreas_collider_distance(boreas_v3(float(p[0]), float(p[1]), float(p[2])), &g);
}

V random_point(std::mt19937& rng, V around, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread);
  return {around[0] + u(rng), around[1] + u(rng), around[2] + u(rng)};
}

std::string shape_name(boreas_collider_shape s) {
  return s == BOREAS_COLLIDER_SPHERE ? "Sphere" : s == BOREAS_COLLIDER_CAPSULE ? "Capsule" : "Box";
}

class ColliderShape : public ::testing::TestWithParam<boreas_collider_shape> {};

// A still collider: the kernel's float distance is the exact one within float rounding,
// and its normal points the way the distance grows fastest (a central difference of the
// double reference), wherever the gradient is defined.
TEST_P(ColliderShape, StillShapeDistanceAndNormalMatchTheDoubleReference) {
  Collider c;
  c.def = boreas::impl::checked_collider_def(shape_def(GetParam()), "def");
  const BoreasGpuCollider g = c.gpu(1.0 / 60.0);
  std::mt19937 rng(7);
  const V center = {1.0, 0.5, -2.0};
  int inside = 0, outside = 0;
  for (int k = 0; k < 4000; ++k) {
    const V p = random_point(rng, center, k % 2 ? 3.0 : 0.8);
    const double want = reference_distance(c.def, p);
    const BoreasColliderDistance got = kernel_distance(g, p);
    ASSERT_NEAR(got.distance, want, 2e-5 * (1.0 + std::fabs(want))) << k;
    (want < 0 ? inside : outside)++;
    const double e = 1e-4;
    V grad{};
    for (size_t a = 0; a < 3; ++a) {
      V lo = p, hi = p;
      lo[a] -= e, hi[a] += e;
      grad[a] = (reference_distance(c.def, hi) - reference_distance(c.def, lo)) / (2 * e);
    }
    if (std::fabs(len(grad) - 1.0) > 1e-3) continue;  // an edge or a medial plane: no gradient
    const V n = {got.normal.x, got.normal.y, got.normal.z};
    EXPECT_NEAR(len(n), 1.0, 1e-5) << k;
    EXPECT_GT(dot(n, grad), 0.999) << k << " at distance " << want;
  }
  EXPECT_GT(inside, 20);
  EXPECT_GT(outside, 1000);
}

// A fast collider does not tunnel: every point its shape passes over in a step is inside
// the swept shape the kernels see (distance <= 0), and a point no position of the step
// holds is outside. The sweep's reference: the least distance over 2001 positions.
TEST_P(ColliderShape, FastColliderTouchesAllItSweepsOverAndNothingElse) {
  Collider c;
  boreas_collider_def d = shape_def(GetParam());
  d.velocity[0] = 20.0f, d.velocity[1] = 3.0f, d.velocity[2] = -12.0f;  // 0.39 m a step
  d.radius = 0.05f;  // thinner than the step's move
  d.half_height = 0.3f;
  d.half_extents[1] = 0.04f;
  c.def = boreas::impl::checked_collider_def(d, "def");
  const double dt = 1.0 / 60.0;
  const BoreasGpuCollider g = c.gpu(dt);
  // The same shape still, moved along the step (orientation: the step's middle, as gpu()).
  std::mt19937 rng(11);
  const double move = dt * len({d.velocity[0], d.velocity[1], d.velocity[2]});
  int swept = 0, missed = 0, clear = 0;
  for (int k = 0; k < 3000; ++k) {
    // Half the points where some position of the shape may hold them, half around it.
    V p = random_point(rng, {1.0 + 0.17, 0.5 + 0.025, -2.0 - 0.1}, 1.0);
    if (k % 2 == 0) {
      std::uniform_real_distribution<double> u(-1.0, 1.0), s01(0.0, 1.0);
      const auto axes = axes_of(c.def.pose);
      const double s = s01(rng);
      const V half = {g.hx + g.radius, g.hy + g.radius, g.hz + g.radius};
      for (size_t a = 0; a < 3; ++a) {
        p[a] = c.def.pose.position[a] + s * d.velocity[a] * dt;
        for (size_t i = 0; i < 3; ++i) p[a] += axes[i][a] * half[i] * u(rng);
      }
    }
    double least = 1e300;
    for (int i = 0; i <= 2000; ++i) {
      const double s = i / 2000.0;
      boreas_collider_def at = c.def;
      for (int a = 0; a < 3; ++a) at.pose.position[a] = float(c.def.pose.position[a] + s * d.velocity[a] * dt);
      least = std::min(least, reference_distance(at, p));
    }
    const float got = kernel_distance(g, p).distance;
    if (least < -1e-4) {
      ++swept;
      if (!(got <= 1e-5f)) ++missed;
    } else if (least > 1e-3) {
      ++clear;
      EXPECT_GT(got, -1e-5f) << k << ": outside every position of the step";
      // Never farther than the least distance over the step by more than the step's move
      // (collider_math.h): the shape at s* is at most |d| from the nearest position.
      EXPECT_LE(got, least + move + 1e-5) << k;
    }
  }
  EXPECT_GT(swept, 30);
  EXPECT_GT(clear, 1000);
  if (GetParam() == BOREAS_COLLIDER_BOX) {
    EXPECT_EQ(missed, 0) << "a box finds every point it swept over";
  } else {
    // Spheres and capsules: exact but for their rounded ends (collider_math.h).
    EXPECT_LE(missed, swept / 20) << missed << " of " << swept;
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, ColliderShape,
                         ::testing::Values(BOREAS_COLLIDER_SPHERE, BOREAS_COLLIDER_CAPSULE,
                                           BOREAS_COLLIDER_BOX),
                         [](const auto& info) { return shape_name(info.param); });

// The world moves a collider by its velocities: 60 steps of 1/60 s at 5 m/s and a quarter
// turn a second about +Y leave it 5 m on and turned by pi/2, against the closed form.
TEST(ColliderPose, StepsMoveItByItsVelocities) {
  boreas_world world = nullptr;
  boreas_world_def wd = boreas_default_world_def();
  ASSERT_EQ(boreas_world_create(&wd, &world), BOREAS_OK) << boreas_last_error();
  boreas_collider_def d = boreas_default_collider_def();
  d.shape = BOREAS_COLLIDER_BOX;
  d.velocity[0] = 5.0f;
  d.angular_velocity[1] = float(M_PI / 2);
  boreas_collider_id id{};
  ASSERT_EQ(boreas_world_add_collider(world, &d, &id), BOREAS_OK) << boreas_last_error();
  for (int s = 0; s < 60; ++s) ASSERT_EQ(boreas_world_step(world, 1.0f / 60.0f), BOREAS_OK);
  boreas_pose p{};
  ASSERT_EQ(boreas_collider_get_pose(world, id, &p), BOREAS_OK);
  EXPECT_NEAR(p.position[0], 5.0, 1e-4);
  EXPECT_NEAR(p.position[1], d.pose.position[1], 1e-6);
  EXPECT_NEAR(p.orientation[1], std::sin(M_PI / 4), 1e-5);
  EXPECT_NEAR(p.orientation[3], std::cos(M_PI / 4), 1e-5);
  // A pose set by the caller overrides; NULL velocities keep what was there.
  boreas_pose at = boreas_default_pose();
  at.position[2] = 3.0f;
  ASSERT_EQ(boreas_collider_set_pose(world, id, &at), BOREAS_OK);
  const float stop[3] = {0.0f, 0.0f, 0.0f};
  ASSERT_EQ(boreas_collider_set_velocity(world, id, stop, nullptr), BOREAS_OK);
  ASSERT_EQ(boreas_world_step(world, 0.5f), BOREAS_OK);
  ASSERT_EQ(boreas_collider_get_pose(world, id, &p), BOREAS_OK);
  EXPECT_EQ(p.position[0], 0.0f);
  EXPECT_EQ(p.position[2], 3.0f);
  EXPECT_NEAR(p.orientation[1], std::sin(M_PI / 8), 1e-5) << "still turning";
  boreas_world_destroy(world);
}

// Bad defs are refused naming the field, and nothing is added or changed.
TEST(ColliderPose, BadDefsAreRefusedNamingTheField) {
  boreas_world world = nullptr;
  boreas_world_def wd = boreas_default_world_def();
  ASSERT_EQ(boreas_world_create(&wd, &world), BOREAS_OK) << boreas_last_error();
  struct Case {
    const char* field;
    void (*spoil)(boreas_collider_def&);
  };
  const Case cases[] = {
      {"collider_def.pose.orientation", [](boreas_collider_def& d) { d.pose.orientation[3] = 0.5f; }},
      {"collider_def.pose.orientation[1]", [](boreas_collider_def& d) { d.pose.orientation[1] = NAN; }},
      {"collider_def.velocity[2]", [](boreas_collider_def& d) { d.velocity[2] = NAN; }},
      {"collider_def.angular_velocity[0]", [](boreas_collider_def& d) { d.angular_velocity[0] = INFINITY; }},
      {"collider_def.half_extents[1]",
       [](boreas_collider_def& d) { d.shape = BOREAS_COLLIDER_BOX, d.half_extents[1] = -1.0f; }},
      {"collider_def.radius", [](boreas_collider_def& d) { d.shape = BOREAS_COLLIDER_CAPSULE, d.radius = 0.0f; }},
      {"collider_def.half_height",
       [](boreas_collider_def& d) { d.shape = BOREAS_COLLIDER_CAPSULE, d.half_height = -0.1f; }},
      {"collider_def.shape", [](boreas_collider_def& d) { d.shape = (boreas_collider_shape)7; }},
  };
  for (const Case& c : cases) {
    boreas_collider_def d = boreas_default_collider_def();
    c.spoil(d);
    boreas_collider_id id{};
    EXPECT_EQ(boreas_world_add_collider(world, &d, &id), BOREAS_ERROR_INVALID_ARGUMENT) << c.field;
    EXPECT_NE(std::string(boreas_last_error()).find(c.field), std::string::npos)
        << boreas_last_error();
  }
  boreas_collider_def d = boreas_default_collider_def();
  boreas_collider_id id{};
  ASSERT_EQ(boreas_world_add_collider(world, &d, &id), BOREAS_OK);
  boreas_pose bad = boreas_default_pose();
  bad.orientation[0] = 1.0f;  // |q| = sqrt(2)
  EXPECT_EQ(boreas_collider_set_pose(world, id, &bad), BOREAS_ERROR_INVALID_ARGUMENT);
  const float nan_velocity[3] = {0.0f, NAN, 0.0f};
  EXPECT_EQ(boreas_collider_set_velocity(world, id, nan_velocity, nullptr),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("velocity[1]"), std::string::npos);
  boreas_pose p{};
  ASSERT_EQ(boreas_collider_get_pose(world, id, &p), BOREAS_OK);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(p.position[a], d.pose.position[a]) << "unchanged";
  EXPECT_EQ(p.orientation[3], 1.0f);
  boreas_world_destroy(world);
}

}  // namespace
