// boreas render: camera matrices (glm) and the orbit.
#include "gl/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace boreas::render {

glm::vec3 Camera::up() const {
  const glm::vec3 forward = target - eye;
  // Looking straight up or down, +Y cannot be the up vector: tilt it toward -Z.
  const float horizontal = std::hypot(forward.x, forward.z);
  if (horizontal < 1e-4f * glm::length(forward)) return glm::vec3(0.0f, 0.0f, -1.0f);
  return glm::vec3(0.0f, 1.0f, 0.0f);
}

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, up()); }

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(glm::radians(fov_deg), aspect, near_m, far_m);
}

Orbit Orbit::around(const Camera& camera) {
  Orbit o;
  o.target = camera.target;
  glm::vec3 d = camera.eye - camera.target;
  o.distance = std::max(glm::length(d), 0.5f);
  o.yaw_deg = glm::degrees(std::atan2(d.z, d.x));
  o.pitch_deg = glm::degrees(std::asin(std::clamp(d.y / o.distance, -1.0f, 1.0f)));
  o.turn(0.0f, 0.0f);
  return o;
}

void Orbit::turn(float d_yaw_deg, float d_pitch_deg) {
  yaw_deg = std::fmod(yaw_deg + d_yaw_deg, 360.0f);
  pitch_deg = std::clamp(pitch_deg + d_pitch_deg, -5.0f, 89.0f);
}

void Orbit::zoom(float factor) { distance = std::clamp(distance * factor, 0.5f, 5000.0f); }

glm::vec3 Orbit::eye() const {
  float yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
  return target + distance * glm::vec3(std::cos(pitch) * std::cos(yaw), std::sin(pitch),
                                       std::cos(pitch) * std::sin(yaw));
}

}  // namespace boreas::render
