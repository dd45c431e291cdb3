// boreas render: the view a frame's generated trees are made for (boreas_world_enqueue_
// tree_records, boreas_cl.h), from the camera. One call a frame serves both passes: the
// shadow map is drawn from the camera's records, so the planes are widened toward the sun
// by as far as the tallest tree's shadow reaches (a tree outside the camera's frustum whose
// shadow falls inside it is still made); the scene pass skips those again per tree
// (shaders/tree_ranges.comp). A second call with the sun's view would make a second set of
// records (twice the interop and the device's time) for trees that are, but for that
// margin, the same ones.
#pragma once

#include <array>

#include <glm/mat4x4.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "boreas/boreas_cl.h"
#include "gl/camera.h"

namespace boreas::render {

// What a frame's tree view is made from besides the camera.
struct TreeViewInputs {
  float aspect = 16.0f / 9.0f;  // width / height
  int image_height = 720;       // pixels
  bool thinning = true;         // RenderSettings::thinning: leaves thinned by distance
  float impostor_distance = 0;  // m: trees at least this far are impostors; 0: none
  // The sun's shadows: toward_sun (unit) with y above 0.01, and the height of the tallest
  // caster above the ground (m); a sun at or below the horizon widens nothing.
  glm::vec3 toward_sun{0.0f, 1.0f, 0.0f};
  float shadow_height = 0.0f;
};

// The least share of a tree's leaves the call keeps for the renderer. Per tree it keeps a
// fixed subset, each leaf grown to keep the coverage; leaf.vert thins further per leaf by
// its own distance. The thinning test's crown at 50 m (tests/render/gl/test_renderer.cpp)
// measured the change of the frame against every leaf drawn, in luminance: 8.7 % with no
// thinning by the call, 17 % keeping down to the default 5 %, 13.3 % at 20 %, 11.5 % at
// 35 %: a few leaves grown large shade coarser than the many they stand for.
constexpr float kRecordsMinKeep = 0.3f;

// The records' view for the camera (boreas_set_tree_view_camera, the library's one frustum
// from a camera): its eye, its frustum's planes each moved outward by
// the distance a caster's shadow can travel across it, a pixel's angle (vertically, at
// the image's centre: frame.glsl's u_pixel_angle), kRecordsMinKeep and the impostor
// distance.
boreas_tree_view_def camera_tree_view(const Camera& camera, const TreeViewInputs& in);

}  // namespace boreas::render
