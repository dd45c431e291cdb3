// boreas command: wall-clock time spent in each stage of a run, in seconds, so the
// summary shows where the time goes (simulation versus sampling versus PNG encoding).
#pragma once

#include <chrono>
#include <ctime>
#include <utility>

namespace boreas::render {

struct StageTimes {
  double world_create = 0.0;     // device, kernels (cached on disk after the first run), scene
  double wind_step = 0.0;        // boreas_world_step, all steps: the wind, trees and underbrush
  double sampling = 0.0;         // boreas_wind_sample, one call per frame
  double tree_readback = 0.0;    // boreas_tree_get_branches and _leaves, once per frame
  double drawing = 0.0;          // color map, arrows and overlays
  double tree_drawing = 0.0;     // trees from above and the side-view panel
  double meadow_readback = 0.0;  // boreas_meadow_get_components: at planting and once per frame
  double meadow_drawing = 0.0;   // meadows, balls and rain from above, and the close-up
  double image_writing = 0.0;    // PNG (and EXR) encoding and file output of the frames
  double sensors = 0.0;          // the sensors read (depth captures cast then) and written
  // The 3D view (render/gl):
  double textures = 0.0;  // generating or loading the leaf and bark maps, uploading them
  double impostors = 0.0;  // baking the trees' impostors, once at rest (OpenGL, to glFinish)
  double wind = 0.0;        // device time of the steps' wind stages (boreas_step_stats)
  double trees = 0.0;       // device time of the steps' tree stages
  double underbrush = 0.0;  // device time of the steps' underbrush stages
  double interop = 0.0;     // the kernels writing the render buffers and handing them to GL
  double render = 0.0;      // OpenGL: shadow map, scene, sky, tone mapping (to glFinish)
  // The process's CPU seconds over the render stage: on llvmpipe the rendering's own work,
  // which the machine's load stretches far less than the wall time.
  double render_cpu = 0.0;
  double readback = 0.0;    // reading the frames back from OpenGL
  double contact_sheet = 0.0;    // shrinking, tiling and writing the sheet
  double animation = 0.0;        // encoding and writing the animated file (GIF, WebP, MP4)
  double total = 0.0;            // the whole command
};

// Runs body and adds its wall time to seconds.
template <typename Body>
decltype(auto) timed(double& seconds, Body&& body) {
  struct Add {
    double& seconds;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    ~Add() {
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } add{seconds};
  return std::forward<Body>(body)();
}

// Runs body and adds the process's CPU time over it to seconds.
template <typename Body>
decltype(auto) cpu_timed(double& seconds, Body&& body) {
  struct Add {
    double& seconds;
    double start = process_cpu_seconds();
    static double process_cpu_seconds() {
      timespec t{};
      clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
      return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
    }
    ~Add() { seconds += process_cpu_seconds() - start; }
  } add{seconds};
  return std::forward<Body>(body)();
}

}  // namespace boreas::render
