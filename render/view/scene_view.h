// boreas views: what the 3D view of a scene draws and from where, shared by `boreas run`
// and the render benchmarks: the trees' and meadows' draw lists, the camera that frames
// the scene, the ground under it, and the renderer's settings from the scene's "view".
#pragma once

#include <vector>

#include "gl/camera.h"
#include "gl/renderer.h"
#include "gl/world_buffers.h"
#include "scene/scene.h"
#include "sky/preetham.h"
#include "view/meadow_frames.h"

namespace boreas::render {

// The scene's trees (ids in the scene's order) with their levels' mesh grids and their leaf
// kinds' layers in the renderer's leaf maps.
std::vector<TreeToDraw> trees_to_draw(const Scene& scene, const std::vector<boreas_tree_id>& ids,
                                      const Renderer& renderer);

// The leaf kinds the scene's trees wear, each once, in the order first met.
std::vector<std::string> scene_leaf_kinds(const Scene& scene);

// Linear albedo and transmittance per component from the slice view's palette (sRGB
// display colors). Green parts pass about as much light as they reflect (thin blades,
// Kusternig's leaf data); petals pass less of theirs.
std::vector<MeadowToDraw> meadows_to_draw(const FrameMeadows& meadows);

// The camera the scene asks for, with what it leaves open chosen to frame everything that
// is drawn: looking at the middle of it from the sun's side (lit faces, shadows falling
// away and aside), 14 degrees above the horizon, far enough to hold its width and its top.
Camera frame_camera(const SceneView& view, const FrameGeometry& geometry, float aspect);

// The ground under and around the scene: a square 40 times the scene's size, so its edge
// lies in the haze, with the meadows' rectangles as sward.
Ground scene_ground(const Scene& scene, const FrameGeometry& geometry);

// The renderer's settings and sky for the scene's view at the run's image size.
RenderSettings render_settings(const Scene& scene, const RunSettings& run);
SkyParams sky_params(const SceneView& view);

}  // namespace boreas::render
