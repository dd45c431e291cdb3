// boreas render: impostor records, placements and the hemi-octahedral map (impostor_math.h).
#include "gl/impostor_math.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace boreas::render {

glm::mat4 tree_placement(const glm::vec3& position, float rotation, float scale) {
  // Columns of R_y(rotation) * scale: x -> (c, 0, -s), z -> (s, 0, c) (tree_layout.cpp).
  const float c = std::cos(rotation), s = std::sin(rotation);
  glm::mat4 m(0.0f);
  m[0] = glm::vec4(c * scale, 0.0f, -s * scale, 0.0f);
  m[1] = glm::vec4(0.0f, scale, 0.0f, 0.0f);
  m[2] = glm::vec4(s * scale, 0.0f, c * scale, 0.0f);
  m[3] = glm::vec4(position, 1.0f);
  return m;
}

glm::mat4 tree_placement_inverse(const glm::vec3& position, float rotation, float scale) {
  // (R S)^-1 = S^-1 R^T; the translation follows.
  const float c = std::cos(rotation), s = std::sin(rotation), k = 1.0f / scale;
  glm::mat4 m(0.0f);
  m[0] = glm::vec4(c * k, 0.0f, s * k, 0.0f);
  m[1] = glm::vec4(0.0f, k, 0.0f, 0.0f);
  m[2] = glm::vec4(-s * k, 0.0f, c * k, 0.0f);
  m[3] = glm::vec4(-glm::vec3(m * glm::vec4(position, 0.0f)), 1.0f);
  return m;
}

glm::mat4 impostor_matrix(const ImpostorRecord& r, float tip_height) {
  glm::mat4 m = tree_placement(glm::vec3(r.position[0], r.position[1], r.position[2]),
                               r.rotation, r.scale);
  // The shear: template y moves the point by sway / tip_height per metre of height.
  const float per_m = tip_height > 0.0f ? 1.0f / tip_height : 0.0f;
  m[1] += glm::vec4(r.sway[0] * per_m, r.sway[1] * per_m, r.sway[2] * per_m, 0.0f);
  return m;
}

glm::vec2 hemi_octahedral_uv(const glm::vec3& direction) {
  glm::vec3 d(direction.x, std::max(direction.y, 0.0f), direction.z);
  const float l1 = std::abs(d.x) + d.y + std::abs(d.z);
  if (l1 <= 0.0f) return glm::vec2(0.5f);
  const float x = d.x / l1, z = d.z / l1;
  return glm::vec2(0.5f + 0.5f * (x + z), 0.5f + 0.5f * (x - z));
}

glm::vec3 hemi_octahedral_direction(const glm::vec2& uv) {
  const float a = 2.0f * uv.x - 1.0f, b = 2.0f * uv.y - 1.0f;
  const float x = 0.5f * (a + b), z = 0.5f * (a - b);
  const float y = 1.0f - std::abs(x) - std::abs(z);
  return glm::normalize(glm::vec3(x, std::max(y, 0.0f), z));
}

glm::vec3 impostor_frame_direction(int i, int j) {
  return hemi_octahedral_direction(glm::vec2((float(i) + 0.5f) / float(kImpostorFrames),
                                             (float(j) + 0.5f) / float(kImpostorFrames)));
}

glm::mat4 impostor_frame_view_projection(const glm::vec3& direction, const glm::vec3& center,
                                         float radius) {
  const glm::vec3 up = std::abs(direction.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f)
                                                      : glm::vec3(0.0f, 1.0f, 0.0f);
  glm::mat4 view = glm::lookAt(center + direction * (2.0f * radius), center, up);
  return glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius) * view;
}

}  // namespace boreas::render
