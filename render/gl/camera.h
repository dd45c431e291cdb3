// boreas render: a perspective camera looking from an eye at a target, Y up, and the orbit
// that `boreas run --window` moves it along.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace boreas::render {

struct Camera {
  glm::vec3 eye{0.0f, 2.0f, 10.0f};  // m
  glm::vec3 target{0.0f};            // m
  float fov_deg = 50.0f;             // vertical
  float near_m = 0.1f;
  float far_m = 3000.0f;

  glm::vec3 up() const;  // the view's up: +Y, or -Z looking straight up or down
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  glm::mat4 view_projection(float aspect) const { return projection(aspect) * view(); }
};

// Spherical coordinates about the target: yaw from +X toward +Z, pitch above the horizon.
struct Orbit {
  glm::vec3 target{0.0f};
  float distance = 10.0f;  // m
  float yaw_deg = 0.0f;
  float pitch_deg = 15.0f;

  static Orbit around(const Camera& camera);
  // Keeps the pitch within (-5, 89) degrees and the distance within [0.5, 5000] m.
  void turn(float d_yaw_deg, float d_pitch_deg);
  void zoom(float factor);
  glm::vec3 eye() const;
};

}  // namespace boreas::render
