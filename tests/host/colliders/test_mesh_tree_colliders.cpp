// boreas tests: colliders against imported trees (cl/shared/mesh_tree_contact.h) — a
// capsule in the crown of a tube tree pushes its branches out of itself, the branches
// spring back once it leaves, the tree pushes a collider back against its motion and the
// harder the deeper it goes, the same bits every run, and trees no collider meets pay
// nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "host/mesh_trees/tube_trees.h"
#include "pose.h"
#include "shared/mesh_tree_types.h"
#include "support/test_support.h"

namespace boreas {
namespace {

using V = std::array<double, 3>;
constexpr float kDt = 1.0f / 30.0f;
constexpr uint64_t kKey = 77;

// The tube tree at the origin, its levels all at 2 Hz (so it settles within seconds).
std::shared_ptr<impl::MeshTreeInstance> tube_tree() {
  static const test::TubeTree tubes = test::make_tube_tree();
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = "tube tree";
  for (boreas_mesh_level_def& l : def.levels) l.frequency = 2.0f;
  auto tree = std::make_shared<impl::MeshTreeInstance>();
  tree->params = impl::checked_mesh_tree_def(def);
  tree->model = tubes.model;
  tree->data = impl::compute_mesh_tree(tree->model, 5);
  tree->noise = impl::make_noise_texture(BOREAS_MESH_TREE_NOISE_SIZE, 2.0, 5);
  tree->key = kKey;
  return tree;
}

// A calm world (no wave, an unforced grid: the tree stands at rest) holding the tube tree.
std::unique_ptr<impl::World> world_with_tree() {
  const boreas_grid_def grid = test::calm_grid();
  auto world = test::make_world(&grid);
  world->mesh_tree_batch().add(tube_tree(), world->time());
  return world;
}

// The tree's first limb (azimuth 0: in the XY plane) at share u of its 3.5 m from its base
// 3 m up the stem.
V on_first_limb(double u) {
  const double e = 0.7;
  return {u * 3.5 * std::cos(e), 3.0 + u * 3.5 * std::sin(e), 0.0};
}

boreas_collider_def capsule_at(V c, float radius, float half_height) {
  boreas_collider_def d = boreas_default_collider_def();
  d.shape = BOREAS_COLLIDER_CAPSULE;
  d.radius = radius;
  d.half_height = half_height;
  for (int a = 0; a < 3; ++a) d.pose.position[a] = float(c[size_t(a)]);
  return d;
}

// The signed distance from p to a still capsule along Y, in double.
double capsule_distance(const boreas_collider_def& d, const float p[3]) {
  const double y =
      std::clamp(double(p[1]) - d.pose.position[1], -double(d.half_height), double(d.half_height));
  const double dx = p[0] - d.pose.position[0], dy = p[1] - d.pose.position[1] - y,
               dz = p[2] - d.pose.position[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz) - d.radius;
}

double deepest(const std::vector<boreas_vertex>& vertices, const boreas_collider_def& d) {
  double least = 1e30;
  for (const boreas_vertex& v : vertices) least = std::min(least, capsule_distance(d, v.position));
  return least;
}

double farthest_move(const std::vector<boreas_vertex>& a, const std::vector<boreas_vertex>& b) {
  double most = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) d2 += std::pow(double(a[i].position[k]) - b[i].position[k], 2);
    most = std::max(most, std::sqrt(d2));
  }
  return most;
}

// The trunk's vertices end outside a capsule set down across the first limb, within a
// stated tolerance: the limb's vertices start up to 0.16 m inside it.
TEST(MeshTreeColliders, BranchesEndOutsideAStillCapsule) {
  auto world = world_with_tree();
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  const std::vector<boreas_vertex> rest = batch.trunk_vertices(kKey);
  const boreas_collider_def capsule = capsule_at(on_first_limb(0.6), 0.3f, 0.5f);
  ASSERT_LT(deepest(rest, capsule), -0.15) << "the capsule must start deep in the limb";
  world->add_collider(capsule);
  for (int s = 0; s < 15; ++s) world->step(kDt);
  const std::vector<boreas_vertex> bent = batch.trunk_vertices(kKey);
  // Tolerance 1 cm: the contact cones hold the vertices at rest; bent, a vertex moves by
  // its own weights, which differ a little from the cone's interpolated ones. Nor is the
  // limb thrown clear: its nearest vertex stays within 10 cm of the capsule.
  EXPECT_GT(deepest(bent, capsule), -0.01);
  EXPECT_LT(deepest(bent, capsule), 0.1);
  EXPECT_GT(farthest_move(bent, rest), 0.25) << "the limb must have moved";
  EXPECT_EQ(batch.trees_in_contact(), 1u);
}

// Once the capsule leaves, the bent branches swing back (damped, at their 2 Hz) and end
// exactly at rest: once they are still the tree's bends are zeroed and it leaves the
// contact launch.
TEST(MeshTreeColliders, BranchesSpringBackOnceTheColliderLeaves) {
  auto world = world_with_tree();
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  const std::vector<boreas_vertex> rest = batch.trunk_vertices(kKey);
  const boreas_collider_id id = world->add_collider(capsule_at(on_first_limb(0.6), 0.3f, 0.5f));
  for (int s = 0; s < 15; ++s) world->step(kDt);
  const double bent = farthest_move(batch.trunk_vertices(kKey), rest);
  world->remove_collider(id);
  // Envelope of a damped spring: exp(-zeta omega t), zeta 0.15, omega 2 pi 2 Hz.
  const double omega = 2.0 * M_PI * 2.0, zeta = 0.15;
  std::vector<double> peaks;
  double peak = 0.0;
  int s = 0;
  for (; s < 60; ++s) {  // two seconds
    world->step(kDt);
    peak = std::max(peak, farthest_move(batch.trunk_vertices(kKey), rest));
    if ((s + 1) % 15 == 0) peaks.push_back(peak), peak = 0.0;
  }
  for (size_t i = 0; i < peaks.size(); ++i) {
    const double t = 0.5 * double(i);  // each window's start, s
    EXPECT_LT(peaks[i], 1.1 * bent * std::exp(-zeta * omega * t)) << "window " << i;
  }
  EXPECT_LT(peaks.back(), 0.1 * bent);
  // At rest (every bend under 0.1 mm at weight 1: BOREAS_MESH_TREE_QUIET_BEND) within
  // ln(bend / 1e-4) / (zeta omega) of the release, about 5 s here; give it 10.
  for (; s * kDt < 10.0 && batch.trees_in_contact() > 0; ++s) world->step(kDt);
  EXPECT_EQ(batch.trees_in_contact(), 0u);
  const std::vector<boreas_vertex> after = batch.trunk_vertices(kKey);
  EXPECT_EQ(std::memcmp(after.data(), rest.data(), rest.size() * sizeof(boreas_vertex)), 0);
}

// A sphere driven into the top of the stem along -x (nothing else within 2 m there) is
// pushed back along +x, the more the deeper it sits.
TEST(MeshTreeColliders, ContactForceOpposesTheMotionAndGrowsWithDepth) {
  double last = 0.0;
  for (double depth : {0.02, 0.05, 0.1}) {
    auto world = world_with_tree();
    boreas_collider_def sphere = boreas_default_collider_def();
    sphere.radius = 0.2f;
    // The stem is about 0.13 m thick at 7.7 m: the sphere starts `depth` into it.
    sphere.pose.position[0] = float(0.13 + 0.2 - depth);
    sphere.pose.position[1] = 7.7f;
    sphere.velocity[0] = -0.5f;
    const boreas_collider_id id = world->add_collider(sphere);
    world->step(kDt);
    const boreas_collider_contact c = world->collider_contact(id);
    EXPECT_GT(c.contacts, 0) << "depth " << depth;
    EXPECT_GT(c.force[0], 0.0f) << "depth " << depth << ": the stem pushes the sphere back";
    EXPECT_GT(c.force[0], last) << "depth " << depth;
    EXPECT_LT(std::hypot(c.force[1], c.force[2]), 0.2f * c.force[0]) << "depth " << depth;
    last = c.force[0];
  }
}

// The largest move of tube t's vertices (the tube tree's own numbering: 0 the stem, 1 the
// first limb, 2 its first twig).
double tube_move(const std::vector<boreas_vertex>& a, const std::vector<boreas_vertex>& b, int t) {
  static const test::TubeTree tubes = test::make_tube_tree();
  const test::Tube& tube = tubes.tubes[size_t(t)];
  const std::vector<boreas_vertex> from(a.begin() + tube.first_vertex,
                                        a.begin() + tube.first_vertex + tube.vertex_count);
  const std::vector<boreas_vertex> to(b.begin() + tube.first_vertex,
                                      b.begin() + tube.first_vertex + tube.vertex_count);
  return farthest_move(from, to);
}

// A ball pressing on a twig bends the twig most, and through it its limb and, least, the
// stem: the load passes to the parents, each giving way by its compliance.
TEST(MeshTreeColliders, ALoadOnATwigPassesToItsParents) {
  auto world = world_with_tree();
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  const std::vector<boreas_vertex> rest = batch.trunk_vertices(kKey);
  // The first limb's first twig: from 0.4 of the limb, azimuth 0.9, elevation 0.5, 1.5 m;
  // a 0.1 m ball 0.09 m over its axis at 0.8 of its length (about 3 cm into it).
  const V base = on_first_limb(0.4);
  const V dir = {std::cos(0.5) * std::cos(0.9), std::sin(0.5), std::cos(0.5) * std::sin(0.9)};
  boreas_collider_def ball = boreas_default_collider_def();
  ball.radius = 0.1f;
  for (int a = 0; a < 3; ++a)
    ball.pose.position[a] = float(base[size_t(a)] + 1.2 * dir[size_t(a)] + (a == 1 ? 0.09 : 0.0));
  world->add_collider(ball);
  world->step(kDt);
  const std::vector<boreas_vertex> bent = batch.trunk_vertices(kKey);
  const double twig = tube_move(rest, bent, 2), limb = tube_move(rest, bent, 1),
               stem = tube_move(rest, bent, 0);
  EXPECT_GT(twig, 0.02) << "the twig gives way";
  EXPECT_GT(limb, 0.0) << "its limb takes part of the load";
  EXPECT_GT(stem, 0.0) << "and the stem a little";
  EXPECT_LT(limb, 0.5 * twig);
  EXPECT_LT(stem, limb);
  // Pressed from above, the twig goes down.
  const test::Tube& t = test::make_tube_tree().tubes[2];
  double dy = 0.0;
  for (uint32_t v = t.first_vertex; v < t.first_vertex + t.vertex_count; ++v)
    dy += double(bent[v].position[1]) - rest[v].position[1];
  EXPECT_LT(dy, 0.0);
}

// A tree removed while a collider bends it, and the trees that stay packed on: the batch
// keeps no contact of the tree gone, and the others go on bending.
TEST(MeshTreeColliders, TreesComeAndGoWhileInContact) {
  const boreas_grid_def grid = test::calm_grid();
  auto world = test::make_world(&grid);
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  std::vector<uint64_t> keys;
  for (int n = 0; n < 4; ++n) {
    auto tree = tube_tree();
    tree->key = 100 + uint64_t(n);
    auto params = tree->params;
    params.position[0] = 20.0f * float(n);
    tree->params = params;
    batch.add(tree, world->time());
    keys.push_back(tree->key);
  }
  // A capsule in each tree's first limb.
  for (int n = 0; n < 4; ++n) {
    V at = on_first_limb(0.6);
    at[0] += 20.0 * n;
    world->add_collider(capsule_at(at, 0.3f, 0.5f));
  }
  for (int s = 0; s < 3; ++s) world->step(kDt);
  EXPECT_EQ(batch.trees_in_contact(), 4u);
  batch.remove(keys[0], world->time());
  batch.remove(keys[1], world->time());  // half the trees gone: holes, or a packed batch
  for (int s = 0; s < 3; ++s) world->step(kDt);
  EXPECT_EQ(batch.trees_in_contact(), 2u);
  boreas_collider_def probe =
      capsule_at({60.0 + on_first_limb(0.6)[0], on_first_limb(0.6)[1], 0.0}, 0.3f, 0.5f);
  const auto bent = batch.trunk_vertices(keys[3]);
  EXPECT_GT(deepest(bent, probe), -0.01) << "the last tree still holds out of its capsule";
}

// The same calls give the same bits: vertices and contact sums.
TEST(MeshTreeColliders, ContactsAreDeterministic) {
  auto run = [] {
    auto world = world_with_tree();
    boreas_collider_def box = boreas_default_collider_def();
    box.shape = BOREAS_COLLIDER_BOX;
    box.half_extents[0] = box.half_extents[1] = box.half_extents[2] = 0.4f;
    box.pose.position[0] = 4.0f;
    box.pose.position[1] = 5.0f;
    box.velocity[0] = -2.0f;
    box.angular_velocity[1] = 0.5f;
    const boreas_collider_id id = world->add_collider(box);
    std::vector<unsigned char> bytes;
    for (int s = 0; s < 45; ++s) {
      world->step(kDt);
      const boreas_collider_contact c = world->collider_contact(id);
      const auto* p = reinterpret_cast<const unsigned char*>(&c);
      bytes.insert(bytes.end(), p, p + sizeof(c));
    }
    const auto v = world->mesh_tree_batch().trunk_vertices(kKey);
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    bytes.insert(bytes.end(), p, p + v.size() * sizeof(boreas_vertex));
    return bytes;
  };
  EXPECT_EQ(run(), run());
}

// A tree no collider meets stays out of the contact launch, beside one a collider bends:
// its vertices are the same bits as in a world with no collider.
TEST(MeshTreeColliders, TreesNoColliderMeetsPayNothing) {
  const boreas_wave wave = test::windy_wave();
  auto with = test::make_world_with_wave(wave);
  auto without = test::make_world_with_wave(wave);
  for (impl::World* w : {with.get(), without.get()}) {
    w->mesh_tree_batch().add(tube_tree(), w->time());
    auto far = tube_tree();
    far->key = kKey + 1;
    auto params = far->params;
    params.position[0] = 300.0f;  // beyond its reach box at 75 m/s (mesh_tree_contact.h)
    far->params = params;
    w->mesh_tree_batch().add(far, w->time());
  }
  with->add_collider(capsule_at(on_first_limb(0.6), 0.3f, 0.5f));
  boreas_collider_def passing = capsule_at({-300.0, 1.0, 0.0}, 0.4f, 0.5f);
  passing.velocity[2] = 3.0f;
  with->add_collider(passing);
  for (int s = 0; s < 10; ++s) {
    with->step(kDt);
    without->step(kDt);
  }
  EXPECT_EQ(with->mesh_tree_batch().trees_in_contact(), 1u);
  for (auto part : {BOREAS_MESH_TRUNK, BOREAS_MESH_LEAVES}) {
    const auto a = part == BOREAS_MESH_TRUNK ? with->mesh_tree_batch().trunk_vertices(kKey + 1)
                                             : with->mesh_tree_batch().leaf_vertices(kKey + 1);
    const auto b = part == BOREAS_MESH_TRUNK ? without->mesh_tree_batch().trunk_vertices(kKey + 1)
                                             : without->mesh_tree_batch().leaf_vertices(kKey + 1);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(boreas_vertex)), 0);
  }
  // And the bent one's leaves went with its branches.
  const auto bent = with->mesh_tree_batch().leaf_vertices(kKey);
  const auto calm = without->mesh_tree_batch().leaf_vertices(kKey);
  EXPECT_GT(farthest_move(bent, calm), 0.05);
}

}  // namespace
}  // namespace boreas
