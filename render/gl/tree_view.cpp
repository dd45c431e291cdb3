// boreas render: the records' view from the camera (tree_view.h).
#include "gl/tree_view.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace boreas::render {

namespace {

// How far (m) a shadow can land beyond the plane from a caster outside it: a point h above
// the ground casts along -toward_sun, so its shadow moves by -n . toward_sun * h / y
// toward the inside; the tallest caster's is the most.
float shadow_reach(const glm::vec3& normal, const TreeViewInputs& in) {
  if (in.toward_sun.y <= 0.01f || in.shadow_height <= 0.0f) return 0.0f;
  return std::max(-glm::dot(normal, in.toward_sun), 0.0f) * in.shadow_height / in.toward_sun.y;
}

}  // namespace

boreas_tree_view_def camera_tree_view(const Camera& camera, const TreeViewInputs& in) {
  boreas_tree_view_def view = boreas_default_tree_view_def();
  const glm::vec3 forward = camera.target - camera.eye, up = camera.up();
  // A camera the library refuses (its eye on its target, a window of no width) draws every
  // tree whole rather than none: the default view's planes kept.
  if (boreas_set_tree_view_camera(&view, &camera.eye.x, &forward.x, &up.x, glm::radians(camera.fov_deg),
                                  in.aspect, camera.near_m, camera.far_m, std::max(in.image_height, 1)) != BOREAS_OK) {
    view = boreas_default_tree_view_def();
    for (int a = 0; a < 3; ++a) view.eye[a] = camera.eye[a];
  }
  for (auto& plane : view.planes) plane[3] += shadow_reach(glm::vec3(plane[0], plane[1], plane[2]), in);
  if (!in.thinning) view.pixel_angle = 0.0f;
  view.min_keep = kRecordsMinKeep;
  view.impostor_distance = std::max(in.impostor_distance, 0.0f);
  return view;
}

}  // namespace boreas::render
