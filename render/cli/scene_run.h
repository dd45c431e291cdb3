// boreas command: `boreas run` in its main view: the scene in 3D through the OpenGL renderer
// (render/gl), the kernels writing the render buffers through CL-GL interop.
#pragma once

#include <chrono>

#include "cli/run_options.h"
#include "cli/run_summary.h"
#include "scene/scene.h"

namespace boreas::render {

// Films the scene (summary.run already resolved) into options.out_dir with its animation
// in the given format, or shows it in a window; writes summary.json. Returns the exit
// code; throws CliError.
int run_scene_view(const Scene& scene, const RunOptions& options, AnimationFormat animation,
                   RunSummary& summary, std::chrono::steady_clock::time_point command_start);

}  // namespace boreas::render
