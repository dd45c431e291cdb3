// boreas render tests: far trees' impostors (render/gl/impostor_math.h, Renderer::
// bake_impostors). A template baked from one tree covers, from the same direction, what the
// full tree covers, for the tree it was baked from and for another tree of the same model
// standing elsewhere, turned and scaled (which checks the shaders' placement of a record
// against the library's); a tree nearer than the impostor distance is drawn as before.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <optional>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "gl/renderer.h"
#include "gl/world_buffers.h"
#include "image/image.h"
#include "image/png_io.h"
#include "interop/gl_context.h"
#include "small_textures.h"
#include "support/small_world.h"
#include "textures/texture_files.h"

namespace boreas::render {
namespace {

constexpr int kWidth = 320, kHeight = 240;

class ImpostorTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    gl_ = new interop::GlContext(interop::GlContextDef{64, 64, false, "boreas impostor test", false});
    textures_ = new TextureSet(small_texture_set(128, 64));
  }
  static void TearDownTestSuite() {
    delete textures_;
    delete gl_;
  }
  void SetUp() override {
    ASSERT_EQ(test::create_small_windy_world(&world_, 0.0f), BOREAS_OK) << boreas_last_error();
    // Two aspens of one model: the first at the origin as grown, the second elsewhere,
    // turned and larger.
    const glm::vec3 at[2] = {glm::vec3(0.0f), glm::vec3(24.0f, 0.0f, 6.0f)};
    const float turn[2] = {0.0f, 1.1f}, scale[2] = {1.0f, 1.15f};
    std::vector<TreeToDraw> draw;
    for (int i = 0; i < 2; ++i) {
      boreas_tree_def def = boreas_default_tree_def();
      std::copy(&at[i].x, &at[i].x + 3, def.position);
      def.rotation = turn[i];
      def.scale = scale[i];
      ASSERT_EQ(boreas_world_add_tree(world_, &def, &trees_[i]), BOREAS_OK) << boreas_last_error();
      TreeToDraw t;
      t.id = trees_[i];
      std::copy(def.levels, def.levels + 4, t.levels);
      t.model = "aspen";
      t.position = at[i];
      t.rotation = turn[i];
      t.scale = scale[i];
      draw.push_back(t);
    }
    buffers_.emplace(world_, interop::Strategy::copy, draw, std::vector<MeadowToDraw>{});
    draw_ = draw;
  }
  void TearDown() override {
    for (const std::string& m : gl_->take_messages()) ADD_FAILURE() << "OpenGL: " << m;
    buffers_.reset();
    if (world_) boreas_world_destroy(world_);
  }

  // The tree's leaves' box.
  void crown(int tree, glm::vec3& lo, glm::vec3& hi) const {
    int n = 0;
    boreas_tree_get_leaves(world_, trees_[tree], nullptr, 0, &n);
    std::vector<boreas_leaf> leaves(static_cast<size_t>(n));
    boreas_tree_get_leaves(world_, trees_[tree], leaves.data(), n, &n);
    lo = glm::vec3(1e30f);
    hi = glm::vec3(-1e30f);
    for (const boreas_leaf& l : leaves) {
      lo = glm::min(lo, glm::vec3(l.position[0], l.position[1], l.position[2]));
      hi = glm::max(hi, glm::vec3(l.position[0], l.position[1], l.position[2]));
    }
  }
  Camera facing(int tree, glm::vec3 direction, float heights) const {
    glm::vec3 lo, hi;
    crown(tree, lo, hi);
    Camera camera;
    camera.target = 0.5f * (lo + hi);
    camera.eye = camera.target + glm::normalize(direction) * (heights * hi.y);
    return camera;
  }

  // Renders the two trees (or none) with impostors from this distance on (0: never).
  std::vector<uint8_t> render(const Camera& camera, float impostor_distance, bool trees = true) {
    RenderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.shadow_map_size = 0;
    settings.bloom = 0.0f;
    settings.light_shafts = 0.0f;
    settings.impostor_distance = impostor_distance;
    Renderer renderer(settings, *textures_, SkyParams{});
    FrameGeometry geometry;
    if (trees) {
      if (impostor_distance > 0.0f) {
        buffers_->update_at_rest();
        renderer.bake_impostors(buffers_->rest_geometry());
      }
      buffers_->update(camera.eye, renderer.tree_view(camera, buffers_->geometry()));
      geometry = buffers_->geometry();
    }
    renderer.draw(camera, geometry, Ground{});
    std::vector<uint8_t> rgb = renderer.read_rgb8();
    if (trees) buffers_->end_draw();
    save(rgb);
    return rgb;
  }
  static void save(const std::vector<uint8_t>& rgb) {
    static int count = 0;
    const char* dir = std::getenv("BOREAS_TEST_FRAMES");
    if (!dir) return;
    Image image(kWidth, kHeight);
    for (size_t i = 0; i < rgb.size(); ++i) image.data()[i] = float(rgb[i]) / 255.0f;
    write_png(std::string(dir) + "/impostor_" + std::to_string(count++) + ".png", image);
  }

  // Pixels where the trees changed the frame from the empty one.
  static std::vector<bool> coverage(const std::vector<uint8_t>& frame, const std::vector<uint8_t>& empty) {
    std::vector<bool> out(size_t(kWidth) * kHeight);
    for (size_t i = 0; i < out.size(); ++i) {
      int d = 0;
      for (int c = 0; c < 3; ++c) d += std::abs(int(frame[3 * i + c]) - int(empty[3 * i + c]));
      out[i] = d > 24;
    }
    return out;
  }

  static interop::GlContext* gl_;
  static TextureSet* textures_;
  boreas_world world_ = nullptr;
  boreas_tree_id trees_[2]{};
  std::vector<TreeToDraw> draw_;
  std::optional<WorldBuffers> buffers_;
};

interop::GlContext* ImpostorTest::gl_ = nullptr;
TextureSet* ImpostorTest::textures_ = nullptr;

// The coverage of the impostor against the tree's, from the same camera: how many pixels
// each covers, and how much of the two overlaps (intersection over union).
struct Overlap {
  size_t full = 0, impostor = 0, both = 0, either = 0;
  double area_error() const { return std::abs(double(impostor) - double(full)) / double(full); }
  double iou() const { return double(both) / double(either); }
};

TEST_F(ImpostorTest, ABakedTemplateCoversWhatItsTreesCoverFromTheSameDirection) {
  struct View {
    int tree;
    glm::vec3 direction;
  };
  // Each tree from the side at two azimuths, and from above (35 degrees).
  const View views[] = {{0, {1.0f, 0.05f, 0.3f}}, {0, {-0.4f, 0.05f, 1.0f}}, {0, {0.5f, 0.7f, 0.6f}},
                        {1, {1.0f, 0.05f, 0.3f}}, {1, {-0.7f, 0.1f, -0.6f}}, {1, {-0.3f, 0.7f, 0.6f}}};
  for (const View& v : views) {
    const Camera camera = facing(v.tree, v.direction, 3.0f);
    const std::vector<uint8_t> empty = render(camera, 0.0f, false);
    const std::vector<bool> full = coverage(render(camera, 0.0f), empty);
    // Every tree farther than 1 m: impostors only.
    const std::vector<bool> impostor = coverage(render(camera, 1.0f), empty);
    Overlap o;
    for (size_t i = 0; i < full.size(); ++i) {
      o.full += full[i];
      o.impostor += impostor[i];
      o.both += full[i] && impostor[i];
      o.either += full[i] || impostor[i];
    }
    ASSERT_GT(o.full, size_t(kWidth * kHeight / 50)) << "the tree is in view";
    std::printf("tree %d from (%.1f, %.1f, %.1f): full %zu px, impostor %zu px (%+.1f %%), IoU %.2f\n", v.tree,
                v.direction.x, v.direction.y, v.direction.z, o.full, o.impostor,
                100.0 * (double(o.impostor) / double(o.full) - 1.0), o.iou());
    EXPECT_LT(o.area_error(), 0.2) << "tree " << v.tree << ": full " << o.full << " px, impostor " << o.impostor;
    EXPECT_GT(o.iou(), 0.6) << "tree " << v.tree << ": full " << o.full << " px, impostor " << o.impostor
                            << ", both " << o.both;
  }
}

// The renderer draws what the records' one call wrote for the camera's view, no more and no
// less: its commands' instances sum to the call's counts (the shadow pass draws every tree
// the call made; the scene pass those in the camera's frustum), a tree behind the camera is
// neither made nor drawn, and far trees are the call's impostors alone.
TEST_F(ImpostorTest, TheDrawsCountWhatTheRecordsCallWroteAndCulledTreesAreNotDrawn) {
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.shadow_map_size = 512;
  settings.impostor_distance = 60.0f;
  // Every leaf the call writes is drawn (the passes' own strides, tree_ranges.comp, thin
  // what they cannot resolve: tested by the thinning test of test_renderer.cpp).
  settings.thinning = false;
  Renderer renderer(settings, *textures_, SkyParams{});
  buffers_->update_at_rest();
  renderer.bake_impostors(buffers_->rest_geometry());
  buffers_->end_draw();
  int branches0 = 0;
  ASSERT_EQ(boreas_tree_get_branches(world_, trees_[0], nullptr, 0, &branches0), BOREAS_OK);
  auto frame = [&](const Camera& camera) {
    buffers_->update(camera.eye, renderer.tree_view(camera, buffers_->geometry()));
    renderer.draw(camera, buffers_->geometry(), Ground{});
    glFinish();
    buffers_->end_draw();
  };
  // Both trees in view, 50-60 m off (short of the handover): both passes draw every record
  // the call wrote.
  Camera side;
  side.target = glm::vec3(12.0f, 4.0f, 3.0f);
  side.eye = glm::vec3(12.0f, 6.0f, 52.0f);
  frame(side);
  const uint32_t* c = buffers_->tree_counts();
  ASSERT_EQ(c[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 2u);
  EXPECT_EQ(c[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1], 0u);
  Renderer::TreeDrawCounts scene = renderer.tree_draw_counts(false), shadow = renderer.tree_draw_counts(true);
  EXPECT_EQ(scene.branches, c[BOREAS_TREE_INDIRECT_BRANCH_COMMAND + 1]);
  EXPECT_EQ(scene.leaves, c[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1]);
  EXPECT_GT(scene.leaves, 0);
  EXPECT_EQ(shadow.branches, c[BOREAS_TREE_INDIRECT_BRANCH_COMMAND + 1]);
  EXPECT_EQ(shadow.leaves, c[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1]);
  EXPECT_EQ(scene.handover_impostors + shadow.handover_impostors, 0);
  // Near tree 0, looking away from tree 1 (at x = 24 m): the scene pass draws tree 0 alone,
  // whatever the call made for the shadows.
  Camera near;
  near.eye = glm::vec3(6.0f, 2.0f, 1.0f);
  near.target = glm::vec3(-10.0f, 3.0f, -1.0f);
  frame(near);
  c = buffers_->tree_counts();
  ASSERT_GE(c[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 1u);
  scene = renderer.tree_draw_counts(false);
  EXPECT_EQ(scene.branches, branches0);
  EXPECT_GT(scene.leaves, 0);
  EXPECT_LE(scene.leaves, c[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1]);
  // Without shadows the view is the camera's own: looking away from both trees (60 m and
  // more behind), neither is made nor drawn.
  {
    RenderSettings unshadowed = settings;
    unshadowed.shadow_map_size = 0;
    Renderer flat(unshadowed, *textures_, SkyParams{});
    Camera away;
    away.eye = glm::vec3(-60.0f, 2.0f, 0.0f);
    away.target = glm::vec3(-100.0f, 3.0f, 0.0f);
    buffers_->update(away.eye, flat.tree_view(away, buffers_->geometry()));
    flat.draw(away, buffers_->geometry(), Ground{});
    glFinish();
    buffers_->end_draw();
    EXPECT_EQ(buffers_->tree_counts()[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 0u);
    EXPECT_EQ(buffers_->tree_counts()[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1], 0u);
    for (bool pass : {false, true}) {
      const Renderer::TreeDrawCounts d = flat.tree_draw_counts(pass);
      EXPECT_EQ(d.branches + d.leaves + d.handover_impostors, 0) << "shadow " << pass;
    }
  }
  // From 200 m both trees are past the handover: two impostor records, nothing else drawn.
  Camera far;
  far.target = glm::vec3(12.0f, 4.0f, 3.0f);
  far.eye = far.target + glm::vec3(0.0f, 20.0f, 200.0f);
  frame(far);
  c = buffers_->tree_counts();
  EXPECT_EQ(c[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 0u);
  EXPECT_EQ(c[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1], 2u);
  for (bool shadow : {false, true}) {
    const Renderer::TreeDrawCounts d = renderer.tree_draw_counts(shadow);
    EXPECT_EQ(d.branches + d.leaves + d.handover_impostors, 0) << "shadow " << shadow;
  }
  // 70 m from tree 0: within the handover (60 to 75 m), it is made in full and handed over.
  Camera handover;
  handover.target = glm::vec3(0.0f, 4.0f, 0.0f);
  handover.eye = glm::vec3(-70.0f, 4.0f, 0.0f);
  frame(handover);
  c = buffers_->tree_counts();
  EXPECT_GE(c[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 1u);
  EXPECT_EQ(renderer.tree_draw_counts(false).handover_impostors, 1);
}

TEST_F(ImpostorTest, TreesNearerThanTheImpostorDistanceAreDrawnAsBefore) {
  const Camera camera = facing(0, {1.0f, 0.1f, 0.3f}, 2.0f);
  // Both trees within 200 m: the baked impostors are never used.
  EXPECT_EQ(render(camera, 200.0f), render(camera, 0.0f));
}


// A frame reads nothing back with a wait (render/gl/world_buffers.h): with the records'
// buffers started small, as a large forest's are, the first frame sizes them with the one
// blocking read; later ones grow them from needed counts read without a wait, a frame
// late. In the frame a view first needs more, the call writes what fits and its commands
// count that alone (the rest is not drawn that frame; nothing is written past a buffer);
// the frame after draws it all.
TEST_F(ImpostorTest, RecordBuffersGrowAFrameLateWithoutAWait) {
  buffers_.reset();
  buffers_.emplace(world_, interop::Strategy::copy, draw_, std::vector<MeadowToDraw>{},
                   std::vector<boreas_mesh_tree_id>{}, 0);
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.shadow_map_size = 0;
  settings.impostor_distance = 60.0f;
  settings.thinning = false;
  Renderer renderer(settings, *textures_, SkyParams{});
  buffers_->update_at_rest();
  renderer.bake_impostors(buffers_->rest_geometry());
  buffers_->end_draw();
  boreas_cl_objects cl{};
  ASSERT_EQ(boreas_world_get_cl(world_, &cl), BOREAS_OK);
  auto frame = [&](const Camera& camera) {
    buffers_->update(camera.eye, renderer.tree_view(camera, buffers_->geometry()));
    renderer.draw(camera, buffers_->geometry(), Ground{});
    glFinish();
    buffers_->end_draw();
    clFinish(cl.queue);  // a frame later: the needed counts' read has landed
  };
  Camera far, side;
  far.target = side.target = glm::vec3(12.0f, 4.0f, 3.0f);
  far.eye = far.target + glm::vec3(0.0f, 20.0f, 200.0f);  // both trees impostors
  side.eye = glm::vec3(12.0f, 6.0f, 52.0f);               // both in full
  frame(far);
  EXPECT_EQ(buffers_->blocking_reads(), 1);
  const uint32_t* c = buffers_->tree_counts();
  EXPECT_EQ(c[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1], 2u);
  frame(side);
  c = buffers_->tree_counts();
  const uint32_t needed_branches = c[BOREAS_TREE_INDIRECT_NEEDED + 0], needed_leaves = c[BOREAS_TREE_INDIRECT_NEEDED + 1];
  ASSERT_GT(needed_branches, 0u);
  EXPECT_LT(c[BOREAS_TREE_INDIRECT_BRANCH_COMMAND + 1], needed_branches) << "the frame that first needs more";
  EXPECT_LT(c[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1], needed_leaves);
  frame(side);
  c = buffers_->tree_counts();
  EXPECT_EQ(c[BOREAS_TREE_INDIRECT_BRANCH_COMMAND + 1], needed_branches) << "grown a frame late";
  EXPECT_EQ(c[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1], needed_leaves);
  EXPECT_EQ(c[BOREAS_TREE_INDIRECT_RANGES_WRITTEN], 2u);
  for (int k = 0; k < 3; ++k) frame(k % 2 ? far : side);
  EXPECT_EQ(buffers_->blocking_reads(), 1) << "only the first frame waited";
  EXPECT_EQ(buffers_->needed_reads(), 6) << "a read after every frame's call but the first far one's";
}

// Pixels where two frames differ by more than a rounding's worth.
size_t pixels_apart(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  size_t n = 0;
  for (size_t i = 0; i + 2 < a.size(); i += 3) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d += std::abs(int(a[i + c]) - int(b[i + c]));
    n += d > 24;
  }
  return n;
}

// Trees of one template share one copy of their leaves' static data (issue 39), each reading
// it at its own scale. Without the crown's occlusion (which the copy takes from the
// template's first tree) the leaves' sizes are all it holds: the turned, larger tree drawn
// from the first one's copy covers what it covers from a copy of its own (another
// transmittance keeps it from sharing: nothing else reads that without occlusion and
// impostors), and its scale is the library's.
TEST_F(ImpostorTest, TreesOfOneTemplateShareTheirLeavesStaticDataAtTheirOwnScale) {
  std::vector<TreeToDraw> draw = draw_;
  for (TreeToDraw& t : draw) t.crown_occlusion = false;
  const Camera camera = facing(1, {0.3f, 0.1f, 1.0f}, 2.0f);
  buffers_.reset();
  buffers_.emplace(world_, interop::Strategy::copy, draw, std::vector<MeadowToDraw>{});
  std::vector<LeafDraw> d = buffers_->geometry().leaf_draws;
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[1].first_static, d[0].first_static);
  EXPECT_EQ(d[0].static_scale, 1.0f);
  EXPECT_NEAR(d[1].static_scale, 1.15f, 1e-4f) << "the second tree's def scale over the first's";
  const std::vector<uint8_t> shared = render(camera, 0.0f);
  draw[1].leaf_transmittance.x += 0.01f;
  buffers_.reset();
  buffers_.emplace(world_, interop::Strategy::copy, draw, std::vector<MeadowToDraw>{});
  d = buffers_->geometry().leaf_draws;
  EXPECT_EQ(d[1].first_static, d[0].first_static + d[0].count);
  EXPECT_EQ(d[1].static_scale, 1.0f);
  const std::vector<uint8_t> own = render(camera, 0.0f);
  const std::vector<uint8_t> empty = render(camera, 0.0f, false);
  const size_t tree = pixels_apart(own, empty), apart = pixels_apart(shared, own);
  std::printf("the tree covers %zu px; its frames from a shared and its own copy differ at %zu\n", tree, apart);
  ASSERT_GT(tree, size_t(kWidth * kHeight / 50)) << "the tree is in view";
  EXPECT_LT(apart, tree / 200) << "of " << tree;
}

// The bake reads the templates' trees alone: update_at_rest makes room for those, one after
// the other, and a template whose tree is not the first (here a third tree, of another
// seed, after the two aspens) is baked from its records where they lie: its impostor
// covers what the tree covers.
TEST_F(ImpostorTest, TheBakesRecordsHoldTheTemplatesTreesAlone) {
  boreas_tree_def def = boreas_default_tree_def();
  def.seed = 5;
  def.position[0] = -80.0f;
  def.position[2] = -20.0f;
  boreas_tree_id third{};
  ASSERT_EQ(boreas_world_add_tree(world_, &def, &third), BOREAS_OK) << boreas_last_error();
  std::vector<TreeToDraw> draw = draw_;
  TreeToDraw t = draw_[0];
  t.id = third;
  t.model = "aspen seed 5";
  t.position = glm::vec3(-80.0f, 0.0f, -20.0f);
  t.rotation = 0.0f;
  t.scale = 1.0f;
  draw.push_back(t);
  buffers_.reset();
  buffers_.emplace(world_, interop::Strategy::copy, draw, std::vector<MeadowToDraw>{});
  int branches[3] = {}, leaves[3] = {};
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(boreas_tree_get_branches(world_, draw[size_t(i)].id, nullptr, 0, &branches[i]), BOREAS_OK);
    ASSERT_EQ(boreas_tree_get_leaves(world_, draw[size_t(i)].id, nullptr, 0, &leaves[i]), BOREAS_OK);
  }
  const size_t before = buffers_->bytes_per_frame();
  buffers_->update_at_rest();
  const size_t rest = buffers_->bytes_per_frame() - before;
  EXPECT_EQ(rest, (size_t(branches[0] + branches[2]) * BOREAS_BRANCH_RECORD_FLOATS +
                   size_t(leaves[0] + leaves[2]) * BOREAS_LEAF_RECORD_FLOATS) * sizeof(float));
  const std::vector<ImpostorTemplate>& m = buffers_->rest_geometry().impostor_templates;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].rest_branch_shift, 0);
  EXPECT_EQ(m[1].tree, 2);
  EXPECT_EQ(m[1].rest_branch_shift, branches[1]) << "after the first aspen's, not both";
  EXPECT_EQ(m[1].rest_leaf_shift, leaves[1]);
  buffers_->end_draw();
  // The third tree from its side, the aspens behind the camera.
  int n = 0;
  boreas_tree_get_leaves(world_, third, nullptr, 0, &n);
  std::vector<boreas_leaf> l(static_cast<size_t>(n));
  boreas_tree_get_leaves(world_, third, l.data(), n, &n);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const boreas_leaf& leaf : l) {
    lo = glm::min(lo, glm::vec3(leaf.position[0], leaf.position[1], leaf.position[2]));
    hi = glm::max(hi, glm::vec3(leaf.position[0], leaf.position[1], leaf.position[2]));
  }
  Camera camera;
  camera.target = 0.5f * (lo + hi);
  camera.eye = camera.target + glm::normalize(glm::vec3(1.0f, 0.05f, 0.3f)) * (3.0f * hi.y);
  const std::vector<uint8_t> empty = render(camera, 0.0f, false);
  const std::vector<bool> full = coverage(render(camera, 0.0f), empty);
  const std::vector<bool> impostor = coverage(render(camera, 1.0f), empty);
  Overlap o;
  for (size_t i = 0; i < full.size(); ++i) {
    o.full += full[i];
    o.impostor += impostor[i];
    o.both += full[i] && impostor[i];
    o.either += full[i] || impostor[i];
  }
  ASSERT_GT(o.full, size_t(kWidth * kHeight / 50)) << "the tree is in view";
  EXPECT_LT(o.area_error(), 0.2) << "full " << o.full << " px, impostor " << o.impostor;
  EXPECT_GT(o.iou(), 0.6) << "full " << o.full << " px, impostor " << o.impostor << ", both " << o.both;
}

}  // namespace
}  // namespace boreas::render
