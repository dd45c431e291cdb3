// boreas render bench: a scene set up for the 3D view as `boreas run` sets it up
// (render/cli/scene_run.cpp, with the draw lists, camera and ground of render/view), and
// one frame of it split into timed stages.
#pragma once

#include <memory>
#include <vector>

#include "boreas/boreas.hpp"
#include "gl/camera.h"
#include "gl/renderer.h"
#include "gl/world_buffers.h"
#include "interop/gl_context.h"
#include "interop/strategy.h"
#include "scene/scene.h"
#include "scene/scene_world.h"
#include "textures/texture_files.h"
#include "view/meadow_frames.h"

namespace boreas::render::bench {

// The OpenGL context of the whole run (hidden, 1280 x 720), made at the first call and
// current from then on; throws interop::GlError when there is none (no display).
interop::GlContext& gl_context();
// Releases what the benchmarks hold, then the context: GL objects must go first.
void release_gl_context();

// The generated leaf and bark maps (as `boreas run` without --textures), made once.
const TextureSet& bench_textures();

// Wall time of each stage of one frame, in seconds; device times from boreas_step_stats.
struct FrameTimes {
  double wind = 0.0, trees = 0.0, underbrush = 0.0;  // device, summed over the frame's steps
  double step_wall = 0.0;  // the steps (moving the colliders, boreas_world_step)
  double poses = 0.0;      // the trees' and meadows' state read back (the summary's sway, bend)
  double interop = 0.0;    // WorldBuffers::update: record kernels, then hand-over to GL
  double render = 0.0;     // Renderer::draw + glFinish
  double readback = 0.0;   // Renderer::read_rgb8
  double frame = 0.0;      // all of the above and WorldBuffers::end_draw

  FrameTimes& operator+=(const FrameTimes& t);
};

// A scene's world, its render buffers for one strategy, the renderer, camera and ground.
// Needs gl_context() current. The world runs on the scene's device request (or the best
// device; BOREAS_DEVICE is honoured); the renderer uses the scene's view settings at the
// scene's image size (run.image_width x run.image_height).
class FrameScene {
 public:
  FrameScene(const Scene& scene, interop::Strategy strategy);
  FrameScene(const FrameScene&) = delete;
  FrameScene& operator=(const FrameScene&) = delete;

  // One frame as `boreas run` makes it, without writing the image: steps_per_frame steps,
  // the poses read back, the buffers updated, drawn, read back.
  FrameTimes frame();
  // The steps of one frame only.
  void step_frame(FrameTimes& times);

  const Scene& scene() const { return scene_; }
  const SceneIds& ids() const { return ids_; }
  const FrameMeadows& meadows() const { return meadows_; }
  boreas::World& world() { return world_; }
  WorldBuffers& buffers() { return *buffers_; }
  Renderer& renderer() { return *renderer_; }
  const Camera& camera() const { return camera_; }
  const Ground& ground() const { return ground_; }
  // The buffers' geometry with the colliders where they are now, as the command draws it.
  FrameGeometry geometry() const;

 private:
  void read_poses();

  Scene scene_;
  SceneIds ids_;
  boreas::World world_;
  FrameMeadows meadows_;
  std::unique_ptr<WorldBuffers> buffers_;
  std::unique_ptr<Renderer> renderer_;
  Camera camera_;
  Ground ground_;
  // The trees' state, read back each frame as `boreas run` does (its tree_poses).
  std::vector<boreas_branch> branches_;
  std::vector<boreas_leaf> leaves_;
  float bend_ = 0.0f;  // m: the meadows' largest bend, which the command computes per frame
};

}  // namespace boreas::render::bench
