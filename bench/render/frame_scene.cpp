// boreas render bench: the scene set-up and the frame of frame_scene.h, step for step as
// render/cli/scene_run.cpp makes them, so that the bench draws what `boreas run` draws.
#include "frame_scene.h"

#include <epoxy/gl.h>

#include <chrono>
#include <optional>
#include <stdexcept>

#include "cli/stage_times.h"
#include "textures/leaf_kinds.h"
#include "view/scene_view.h"

namespace boreas::render::bench {

namespace {

std::optional<interop::GlContext>& context_slot() {
  static std::optional<interop::GlContext> context;
  return context;
}

}  // namespace

interop::GlContext& gl_context() {
  std::optional<interop::GlContext>& context = context_slot();
  if (!context) context.emplace(interop::GlContextDef{1280, 720, false, "boreas bench", false});
  context->make_current();
  return *context;
}

void release_gl_context() { context_slot().reset(); }

const TextureSet& bench_textures() {
  static const TextureSet textures = [] {
    TextureSet set = generate_texture_set();
    add_leaf_kinds(set, leaf_kind_names());  // every kind, for whichever scene
    return set;
  }();
  return textures;
}

FrameTimes& FrameTimes::operator+=(const FrameTimes& t) {
  wind += t.wind;
  trees += t.trees;
  underbrush += t.underbrush;
  step_wall += t.step_wall;
  poses += t.poses;
  interop += t.interop;
  render += t.render;
  readback += t.readback;
  frame += t.frame;
  return *this;
}

FrameScene::FrameScene(const Scene& scene, interop::Strategy strategy)
    : scene_(scene),
      world_(make_world(scene, std::nullopt, &ids_)),
      meadows_(plant_frame_meadows(world_, scene_, ids_.meadows)) {
  if (strategy == interop::Strategy::gl_sharing) {
    // The world would have to be made from the GL context (scene_run.cpp's
    // make_shared_world); PoCL has no cl_khr_gl_sharing, so the bench leaves it out.
    throw std::invalid_argument("the render bench measures zero_copy and copy only");
  }
  renderer_ = std::make_unique<Renderer>(render_settings(scene_, scene_.run), bench_textures(),
                                         sky_params(scene_.view));
  buffers_ = std::make_unique<WorldBuffers>(world_.handle(), strategy,
                                            trees_to_draw(scene_, ids_.trees, *renderer_),
                                            meadows_to_draw(meadows_), ids_.mesh_trees);
  const float aspect = float(scene_.run.image_width) / float(scene_.run.image_height);
  camera_ = frame_camera(scene_.view, buffers_->geometry(), aspect);
  ground_ = scene_ground(scene_, buffers_->geometry());
}

void FrameScene::step_frame(FrameTimes& times) {
  const RunSettings& run = scene_.run;
  boreas_step_stats s =
      timed(times.step_wall, [&] { return step_scene(world_, scene_, run.steps_per_frame, run.dt); });
  times.wind += s.wind;
  times.trees += s.trees;
  times.underbrush += s.underbrush;
}

// What `boreas run` reads after each frame's steps for the summary's sway and bend: every
// tree's branches and leaves (read_tree_pose, which render/cli keeps to itself, so the
// calls are made here without its copy into a TreePose) and every meadow's components.
void FrameScene::read_poses() {
  boreas_world w = world_.handle();
  for (boreas_tree_id tree : ids_.trees) {
    int n = 0;
    boreas::check(boreas_tree_get_branches(w, tree, nullptr, 0, &n));
    branches_.resize(size_t(n));
    boreas::check(boreas_tree_get_branches(w, tree, branches_.data(), n, &n));
    boreas::check(boreas_tree_get_leaves(w, tree, nullptr, 0, &n));
    leaves_.resize(size_t(n));
    boreas::check(boreas_tree_get_leaves(w, tree, leaves_.data(), n, &n));
  }
  if (!meadows_.empty()) {
    read_meadows(world_, meadows_);
    bend_ = max_bend(meadows_);
  }
}

FrameGeometry FrameScene::geometry() const {
  FrameGeometry geometry = buffers_->geometry();
  for (const Ball& b : colliders_at(scene_, world_.get_time())) {
    geometry.balls.emplace_back(b.center[0], b.center[1], b.center[2], b.radius);
  }
  return geometry;
}

FrameTimes FrameScene::frame() {
  FrameTimes t;
  timed(t.frame, [&] {
    step_frame(t);
    timed(t.poses, [&] { read_poses(); });
    timed(t.interop, [&] { buffers_->update(camera_.eye, renderer_->tree_view(camera_, buffers_->geometry())); });
    timed(t.render, [&] {
      renderer_->draw(camera_, geometry(), ground_);
      glFinish();
    });
    timed(t.readback, [&] {
      std::vector<uint8_t> rgb = renderer_->read_rgb8();
      if (rgb.empty()) throw std::runtime_error("read_rgb8 returned no pixels");
    });
    buffers_->end_draw();
  });
  return t;
}

}  // namespace boreas::render::bench
