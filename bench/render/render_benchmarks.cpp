// boreas render bench: frames of the default scene at 1280 x 720 through the OpenGL
// renderer, as `boreas run` makes them, timed by stage (issue 5).
//
//   BM_FrameStages/<strategy>    one frame per iteration: the world's steps_per_frame steps,
//                                the poses read back, WorldBuffers::update, Renderer::draw +
//                                glFinish, read_rgb8 (no image written)
//   BM_InteropUpdate/<strategy>  WorldBuffers::update + glFinish alone, the world stepped
//                                once, zero_copy and copy on the same world
//   BM_RenderOnly/shadows_<on|off>  Renderer::draw + glFinish alone, the same geometry
//
// Every row uses real time (the work runs on PoCL's and llvmpipe's threads). Counters are
// per frame (or per update), in milliseconds where named _ms; device times come from
// boreas_world_get_step_stats (OpenCL profiling between the step's stages). A world,
// its buffers and renderer are made once per row (shared by the rows of one family where
// said) and warmed up before timing (kWarmFrames frames, or one update or draw): PoCL
// compiles work-group functions and llvmpipe its shaders at their first use.
#include "render_benchmarks.h"

#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <string>

#include "bench_fixture.h"
#include "frame_scene.h"
#include "scene/scene_loader.h"
#include "view/scene_view.h"

namespace boreas::render::bench {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kWidth = 1280, kHeight = 720;  // pixels: issue 5's frame
// Iterations per row: a frame takes 1-2 s on llvmpipe, so a handful keeps the whole run
// within about 3 minutes on two cores.
constexpr int kFrameIterations = 5;
constexpr int kInteropIterations = 20;
constexpr int kRenderIterations = 5;
// Frames drawn before BM_FrameStages times any: one compiles the kernels' work-group
// functions and llvmpipe's shader variants; with only one, the first row of a run often
// drew slower than the second, whichever strategy it was.
constexpr int kWarmFrames = 3;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The embedded default scene, filmed at issue 5's frame size.
const Scene& default_scene() {
  static const Scene scene = [] {
    Scene s = load_default_scene();
    s.run.image_width = kWidth;
    s.run.image_height = kHeight;
    return s;
  }();
  return scene;
}

using bench_support::fixture;
using bench_support::Fixture;

// ---- BM_FrameStages ----

struct FrameFixture : Fixture {
  std::unique_ptr<FrameScene> scene;
};

void frame_stages(benchmark::State& state, interop::Strategy strategy) {
  gl_context();
  FrameFixture& f = fixture<FrameFixture>(
      std::string("frames/") + interop::strategy_name(strategy), [&] {
        auto x = std::make_unique<FrameFixture>();
        x->scene = std::make_unique<FrameScene>(default_scene(), strategy);
        for (int i = 0; i < kWarmFrames; ++i) x->scene->frame();
        return x;
      });
  FrameTimes sum;
  for (auto _ : state) sum += f.scene->frame();

  const double n = double(state.iterations());
  auto ms = [&](double seconds) { return 1e3 * seconds / n; };
  state.counters["wind_ms"] = ms(sum.wind);
  state.counters["trees_ms"] = ms(sum.trees);
  state.counters["underbrush_ms"] = ms(sum.underbrush);
  state.counters["step_wall_ms"] = ms(sum.step_wall);
  state.counters["poses_ms"] = ms(sum.poses);
  state.counters["interop_ms"] = ms(sum.interop);
  state.counters["render_ms"] = ms(sum.render);
  state.counters["readback_ms"] = ms(sum.readback);
  state.counters["frame_ms"] = ms(sum.frame);
  state.counters["physics_share"] = sum.frame > 0 ? sum.step_wall / sum.frame : 0.0;
  state.counters["steps"] = double(default_scene().run.steps_per_frame);
  state.counters["in_place"] = f.scene->buffers().maps_in_place() ? 1.0 : 0.0;
  // What is drawn: branch records, leaves, underbrush components.
  const FrameGeometry& g = f.scene->buffers().geometry();
  double branches = 0.0;
  for (const BranchDraw& d : g.branch_draws) branches += d.count;
  state.counters["branches"] = branches;
  state.counters["leaves"] = g.leaf_count;
  state.counters["components"] = g.meadow_components;
}

// ---- BM_InteropUpdate ----

// One world stepped once, with a zero_copy and a copy set of the same buffers.
struct InteropFixture : Fixture {
  std::unique_ptr<FrameScene> scene;  // zero_copy
  std::unique_ptr<WorldBuffers> copy;
  boreas_tree_view_def view{};  // the records' view from the scene's camera

  WorldBuffers& buffers(interop::Strategy s) {
    return s == interop::Strategy::copy ? *copy : scene->buffers();
  }
};

void interop_update(benchmark::State& state, interop::Strategy strategy) {
  gl_context();
  InteropFixture& f = fixture<InteropFixture>("interop", [&] {
    auto x = std::make_unique<InteropFixture>();
    const Scene& scene = default_scene();
    x->scene = std::make_unique<FrameScene>(scene, interop::Strategy::zero_copy);
    FrameTimes ignored;
    x->scene->step_frame(ignored);
    x->copy = std::make_unique<WorldBuffers>(
        x->scene->world().handle(), interop::Strategy::copy,
        trees_to_draw(scene, x->scene->ids().trees, x->scene->renderer()),
        meadows_to_draw(x->scene->meadows()), x->scene->ids().mesh_trees);
    const Camera& camera = x->scene->camera();
    x->view = x->scene->renderer().tree_view(camera, x->scene->buffers().geometry());
    for (WorldBuffers* b : {&x->scene->buffers(), x->copy.get()}) {  // warm-up: grows the records
      b->update(camera.eye, x->view);
      glFinish();
      b->end_draw();
    }
    return x;
  });
  WorldBuffers& buffers = f.buffers(strategy);
  const glm::vec3 eye = f.scene->camera().eye;
  double update = 0.0;
  for (auto _ : state) {
    Clock::time_point start = Clock::now();
    buffers.update(eye, f.view);
    glFinish();  // copy: the upload is done (llvmpipe may defer it)
    update += seconds_since(start);
    buffers.end_draw();
  }
  const double n = double(state.iterations());
  const double bytes = double(buffers.bytes_per_frame());
  state.counters["update_ms"] = 1e3 * update / n;
  state.counters["MB_per_frame"] = bytes / 1e6;
  state.counters["GB/s"] = update > 0 ? bytes * n / update / 1e9 : 0.0;
  state.counters["in_place"] = buffers.maps_in_place() ? 1.0 : 0.0;
}

// ---- BM_RenderOnly ----

// One world stepped once, its zero_copy buffers updated once; a renderer with the
// scene's shadow map (2048^2) and one without.
struct RenderFixture : Fixture {
  std::unique_ptr<FrameScene> scene;
  std::unique_ptr<Renderer> no_shadows;
  FrameGeometry geometry;
};

void render_only(benchmark::State& state, bool shadows) {
  gl_context();
  RenderFixture& f = fixture<RenderFixture>("render", [&] {
    auto x = std::make_unique<RenderFixture>();
    const Scene& scene = default_scene();
    x->scene = std::make_unique<FrameScene>(scene, interop::Strategy::zero_copy);
    FrameTimes ignored;
    x->scene->step_frame(ignored);
    const Camera& camera = x->scene->camera();
    x->scene->buffers().update(camera.eye, x->scene->renderer().tree_view(camera, x->scene->buffers().geometry()));
    x->geometry = x->scene->geometry();
    RenderSettings settings = render_settings(scene, scene.run);
    settings.shadow_map_size = 0;
    x->no_shadows = std::make_unique<Renderer>(settings, bench_textures(), sky_params(scene.view));
    for (Renderer* r : {&x->scene->renderer(), x->no_shadows.get()}) {  // warm-up
      r->draw(x->scene->camera(), x->geometry, x->scene->ground());
      glFinish();
    }
    return x;
  });
  if (shadows && f.scene->renderer().settings().shadow_map_size == 0) {
    state.SkipWithError("the default scene has its shadows off");
    return;
  }
  Renderer& renderer = shadows ? f.scene->renderer() : *f.no_shadows;
  for (auto _ : state) {
    renderer.draw(f.scene->camera(), f.geometry, f.scene->ground());
    glFinish();
  }
  state.counters["shadow_map"] = double(renderer.settings().shadow_map_size);
}

void add(const std::string& name, int iterations, std::function<void(benchmark::State&)> body) {
  // An exception (no display, an OpenCL or GL failure) ends the row with its message
  // instead of the run.
  auto guarded = [body = std::move(body)](benchmark::State& state) {
    try {
      body(state);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
    }
  };
  benchmark::RegisterBenchmark(name.c_str(), std::move(guarded))
      ->UseRealTime()
      ->Unit(benchmark::kMillisecond)
      ->Iterations(iterations);
}

}  // namespace

void register_benchmarks() {
  for (interop::Strategy s : {interop::Strategy::zero_copy, interop::Strategy::copy}) {
    add(std::string("BM_FrameStages/") + interop::strategy_name(s), kFrameIterations,
        [s](benchmark::State& state) { frame_stages(state, s); });
  }
  for (interop::Strategy s : {interop::Strategy::zero_copy, interop::Strategy::copy}) {
    add(std::string("BM_InteropUpdate/") + interop::strategy_name(s), kInteropIterations,
        [s](benchmark::State& state) { interop_update(state, s); });
  }
  for (bool shadows : {true, false}) {
    add(std::string("BM_RenderOnly/shadows_") + (shadows ? "on" : "off"), kRenderIterations,
        [shadows](benchmark::State& state) { render_only(state, shadows); });
  }
}

void release_benchmarks() { bench_support::release_fixture(); }

}  // namespace boreas::render::bench
