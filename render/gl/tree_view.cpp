// boreas render: the records' view from the camera (tree_view.h).
#include "gl/tree_view.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace boreas::render {

std::array<glm::dvec4, 6> frustum_planes(const glm::dmat4& m) {
  // Row i of the matrix (glm is column-major: m[column][row]).
  auto row = [&](int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
  const glm::dvec4 w = row(3);
  std::array<glm::dvec4, 6> planes = {w + row(0), w - row(0), w + row(1), w - row(1), w + row(2), w - row(2)};
  for (glm::dvec4& p : planes) p /= glm::length(glm::dvec3(p));
  return planes;
}

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
  view.eye[0] = camera.eye.x;
  view.eye[1] = camera.eye.y;
  view.eye[2] = camera.eye.z;
  const glm::dmat4 projection =
      glm::perspective(glm::radians(double(camera.fov_deg)), double(in.aspect), double(camera.near_m), double(camera.far_m));
  const std::array<glm::dvec4, 6> planes = frustum_planes(projection * glm::dmat4(camera.view()));
  for (int i = 0; i < 6; ++i) {
    const glm::vec3 n(planes[size_t(i)]);
    const float d = float(planes[size_t(i)].w) + shadow_reach(n, in);
    for (int k = 0; k < 3; ++k) view.planes[i][k] = n[k];
    view.planes[i][3] = d;
  }
  view.pixel_angle =
      in.thinning ? 2.0f * std::tan(glm::radians(camera.fov_deg) * 0.5f) / float(std::max(in.image_height, 1)) : 0.0f;
  view.min_keep = kRecordsMinKeep;
  view.impostor_distance = std::max(in.impostor_distance, 0.0f);
  return view;
}

}  // namespace boreas::render
