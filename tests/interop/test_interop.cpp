// boreas interop tests: whatever the strategy, the GL buffers hold exactly what the
// library's host readbacks give, frame after frame (the fences and maps in between), and
// the simulation's state is bit for bit that of the same world never drawn.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "interop/gl_context.h"
#include "interop/shared_buffer.h"
#include "support/small_world.h"

namespace boreas::interop {
namespace {

// One GL context for the whole program (GLFW windows are cheap, but one is enough).
GlContext& context() {
  static GlContext* gl = new GlContext(GlContextDef{64, 64, false, "boreas interop test", false});
  gl->make_current();
  return *gl;
}

std::vector<unsigned char> read_gl(const SharedBuffer& b) {
  std::vector<unsigned char> out(b.bytes());
  glGetNamedBufferSubData(b.gl(), 0, GLsizeiptr(out.size()), out.data());
  return out;
}

// A world with a tree and a small meadow in a steady wind, on the default device.
struct Scene {
  boreas_world world = nullptr;
  boreas_tree_id tree{};
  boreas_meadow_id meadow{};
  int branches = 0, leaves = 0, components = 0;
  boreas_cl_objects cl{};

  Scene() {
    EXPECT_EQ(test::create_small_windy_world(&world), BOREAS_OK) << boreas_last_error();
    boreas_tree_def t = boreas_default_tree_def();
    EXPECT_EQ(boreas_world_add_tree(world, &t, &tree), BOREAS_OK) << boreas_last_error();
    boreas_meadow_def m = boreas_default_meadow_def();
    m.size[0] = m.size[1] = 2.0f;
    EXPECT_EQ(boreas_world_add_meadow(world, &m, &meadow), BOREAS_OK) << boreas_last_error();
    EXPECT_EQ(boreas_tree_get_branches(world, tree, nullptr, 0, &branches), BOREAS_OK);
    EXPECT_EQ(boreas_tree_get_leaves(world, tree, nullptr, 0, &leaves), BOREAS_OK);
    int vertices = 0;
    EXPECT_EQ(boreas_meadow_get_vertices(world, meadow, nullptr, nullptr, 0, &vertices, nullptr), BOREAS_OK);
    components = vertices / BOREAS_MEADOW_VERTEX_STRIDE;
    EXPECT_EQ(boreas_world_get_cl(world, &cl), BOREAS_OK);
  }
  ~Scene() { boreas_world_destroy(world); }

  // The host readbacks, laid out as the device records are.
  std::vector<unsigned char> expected_branches() const {
    std::vector<boreas_branch> b(static_cast<size_t>(branches));
    int n = branches;
    EXPECT_EQ(boreas_tree_get_branches(world, tree, b.data(), n, &n), BOREAS_OK);
    std::vector<float> f;
    for (const boreas_branch& br : b) {
      for (int p = 0; p < 4; ++p) f.insert(f.end(), br.control_points[p], br.control_points[p] + 3);
      f.insert(f.end(), br.orientation, br.orientation + 3);
      f.resize(f.size() + 9);  // the radius function: compared separately, below
      f.push_back(float(br.broken));  // then the broken flag, the tip's cap (radius, zeroed
      f.resize(f.size() + 3);         // below too) and zeros to 28 floats
    }
    return bytes_of(f);
  }
  std::vector<unsigned char> expected_leaves() const {
    std::vector<boreas_leaf> l(static_cast<size_t>(leaves));
    int n = leaves;
    EXPECT_EQ(boreas_tree_get_leaves(world, tree, l.data(), n, &n), BOREAS_OK);
    std::vector<float> f;
    for (const boreas_leaf& leaf : l) {
      f.insert(f.end(), leaf.position, leaf.position + 3);
      f.insert(f.end(), leaf.axis, leaf.axis + 3);
      f.insert(f.end(), leaf.normal, leaf.normal + 3);
    }
    return bytes_of(f);
  }
  std::vector<unsigned char> expected_vertices(const float* camera) const {
    int n = components * BOREAS_MEADOW_VERTEX_STRIDE;
    std::vector<boreas_meadow_vertex> v(static_cast<size_t>(n));
    EXPECT_EQ(boreas_meadow_get_vertices(world, meadow, camera, v.data(), n, &n, nullptr), BOREAS_OK);
    std::vector<unsigned char> out(v.size() * sizeof(boreas_meadow_vertex));
    std::memcpy(out.data(), v.data(), out.size());
    return out;
  }
  static std::vector<unsigned char> bytes_of(const std::vector<float>& f) {
    std::vector<unsigned char> out(f.size() * sizeof(float));
    std::memcpy(out.data(), f.data(), out.size());
    return out;
  }
};

// The branch records without their static radius part (zeroed: floats 15..23 and the tip's
// cap, 25), to compare with the host.
std::vector<unsigned char> without_radius(std::vector<unsigned char> records) {
  const size_t R = BOREAS_BRANCH_RECORD_FLOATS * sizeof(float);
  for (size_t at = 0; at + R <= records.size(); at += R) {
    std::memset(&records[at + 15 * sizeof(float)], 0, 9 * sizeof(float));
    std::memset(&records[at + 25 * sizeof(float)], 0, sizeof(float));
  }
  return records;
}

class Interop : public ::testing::TestWithParam<Strategy> {};

TEST_P(Interop, GlBuffersHoldWhatTheReadbacksGiveFrameAfterFrame) {
  context();
  Scene s;
  ASSERT_GT(s.branches, 0);
  ASSERT_GT(s.leaves, 0);
  ASSERT_GT(s.components, 0);
  const Strategy strategy = GetParam();
  SharedBuffer branches(strategy, s.cl.context, s.cl.queue, size_t(s.branches) * BOREAS_BRANCH_RECORD_FLOATS * 4);
  SharedBuffer leaves(strategy, s.cl.context, s.cl.queue, size_t(s.leaves) * BOREAS_LEAF_RECORD_FLOATS * 4);
  SharedBuffer vertices(strategy, s.cl.context, s.cl.queue,
                        size_t(s.components) * BOREAS_MEADOW_VERTEX_STRIDE * sizeof(boreas_meadow_vertex));
  SharedBuffer counts(strategy, s.cl.context, s.cl.queue, size_t(s.components) * sizeof(int32_t));
  const float camera[3] = {1.0f, 1.5f, 1.0f};
  std::vector<unsigned char> first_frame;
  Scene bare;  // the same world, never drawn: its state must not differ by a bit
  for (int frame = 0; frame < 3; ++frame) {
    ASSERT_EQ(boreas_world_step(s.world, 1.0f / 30.0f), BOREAS_OK);
    ASSERT_EQ(boreas_world_step(bare.world, 1.0f / 30.0f), BOREAS_OK);
    for (SharedBuffer* b : {&branches, &leaves, &vertices, &counts}) b->begin_write();
    ASSERT_EQ(boreas_tree_enqueue_branch_records(s.world, s.tree, branches.cl(), 0), BOREAS_OK) << boreas_last_error();
    ASSERT_EQ(boreas_tree_enqueue_leaf_records(s.world, s.tree, leaves.cl(), 0), BOREAS_OK);
    ASSERT_EQ(boreas_meadow_enqueue_vertices(s.world, s.meadow, camera, vertices.cl(), counts.cl(), 0), BOREAS_OK);
    for (SharedBuffer* b : {&branches, &leaves, &vertices, &counts}) b->end_write();
    // Zero-copy is zero copies when OpenCL maps the buffer at GL's own address.
    if (strategy == Strategy::zero_copy) {
      EXPECT_TRUE(branches.maps_in_place());
    }

    std::vector<unsigned char> got = read_gl(branches);
    EXPECT_TRUE(without_radius(got) == s.expected_branches()) << "branches, frame " << frame;
    EXPECT_TRUE(read_gl(leaves) == s.expected_leaves()) << "leaves, frame " << frame;
    EXPECT_TRUE(read_gl(vertices) == s.expected_vertices(camera)) << "vertices, frame " << frame;
    if (frame == 0) first_frame = got;
    if (frame == 2) {
      EXPECT_FALSE(got == first_frame) << "the wind moved nothing: the test would prove little";
    }
    for (SharedBuffer* b : {&branches, &leaves, &vertices, &counts}) b->end_draw();
    uint64_t drawn = 0, undrawn = 0;
    ASSERT_EQ(boreas_world_get_state_hash(s.world, &drawn), BOREAS_OK);
    ASSERT_EQ(boreas_world_get_state_hash(bare.world, &undrawn), BOREAS_OK);
    EXPECT_EQ(drawn, undrawn) << "frame " << frame << ": drawing through "
                              << strategy_name(strategy) << " changed the simulation";
  }
  EXPECT_TRUE(context().take_messages().empty());
}

INSTANTIATE_TEST_SUITE_P(Strategies, Interop,
                         ::testing::Values(Strategy::copy, Strategy::zero_copy),
                         [](const auto& info) { return std::string(strategy_name(info.param)); });

// Where the device shares GL objects (GPU drivers with cl_khr_gl_sharing), the world made
// from the GL context gives the same through clCreateFromGLBuffer.
TEST(GlSharing, WorldMadeFromTheGlContextGivesTheSameBuffers) {
  GlContext& gl = context();
  std::vector<intptr_t> props = gl.cl_sharing_properties();
  ASSERT_FALSE(props.empty());
  boreas_world_def def = boreas_default_world_def();
  def.cl_context_properties = props.data();
  boreas_world world = nullptr;
  if (boreas_world_create(&def, &world) != BOREAS_OK)
    GTEST_SKIP() << "this device does not share with OpenGL: " << boreas_last_error();
  boreas_tree_def t = boreas_default_tree_def();
  boreas_tree_id tree{};
  ASSERT_EQ(boreas_world_add_tree(world, &t, &tree), BOREAS_OK);
  ASSERT_EQ(boreas_world_step(world, 1.0f / 30.0f), BOREAS_OK);
  int n = 0;
  ASSERT_EQ(boreas_tree_get_leaves(world, tree, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_leaf> l(static_cast<size_t>(n));
  ASSERT_EQ(boreas_tree_get_leaves(world, tree, l.data(), n, &n), BOREAS_OK);
  boreas_cl_objects cl{};
  ASSERT_EQ(boreas_world_get_cl(world, &cl), BOREAS_OK);
  {
    SharedBuffer leaves(Strategy::gl_sharing, cl.context, cl.queue, size_t(n) * BOREAS_LEAF_RECORD_FLOATS * 4);
    leaves.begin_write();
    ASSERT_EQ(boreas_tree_enqueue_leaf_records(world, tree, leaves.cl(), 0), BOREAS_OK);
    leaves.end_write();
    std::vector<unsigned char> got = read_gl(leaves);
    std::vector<float> f(got.size() / 4);
    std::memcpy(f.data(), got.data(), got.size());
    for (int j = 0; j < n; ++j)
      for (int a = 0; a < 3; ++a) ASSERT_EQ(f[size_t(j) * 9 + size_t(a)], l[size_t(j)].position[a]);
  }
  boreas_world_destroy(world);
}

TEST(Strategy, NamesRoundTripAndTheChoiceFollowsTheDevice) {
  for (Strategy s : {Strategy::gl_sharing, Strategy::zero_copy, Strategy::copy})
    EXPECT_EQ(parse_strategy(strategy_name(s)), s);
  EXPECT_EQ(parse_strategy("zerocopy"), std::nullopt);
  EXPECT_EQ(choose_strategy({true, false}), Strategy::zero_copy);
  EXPECT_EQ(choose_strategy({false, false}), Strategy::copy);
  EXPECT_EQ(choose_strategy({false, true}), Strategy::gl_sharing);
}

}  // namespace
}  // namespace boreas::interop
