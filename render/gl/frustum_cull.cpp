// boreas render: box against frustum (frustum_cull.h).
#include "gl/frustum_cull.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/vec4.hpp>
#include <initializer_list>

namespace boreas::render {

bool box_outside_frustum(const glm::mat4& view_proj, const glm::vec3& lo, const glm::vec3& hi) {
  glm::vec4 corners[8];
  for (int i = 0; i < 8; ++i) {
    glm::vec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    corners[i] = view_proj * glm::vec4(p, 1.0f);
  }
  // Planes: x >= -w, x <= w, y >= -w, y <= w, z >= -w, z <= w.
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      bool all_out = true;
      for (const glm::vec4& c : corners) {
        if (sign * c[axis] <= c.w) {
          all_out = false;
          break;
        }
      }
      if (all_out) return true;
    }
  }
  return false;
}

bool shadow_outside_frustum(const glm::mat4& view_proj, const glm::vec3& lo, const glm::vec3& hi,
                            const glm::vec3& toward_sun, float ground_y) {
  if (toward_sun.y <= 0.01f) return false;
  glm::vec3 swept_lo = lo, swept_hi = hi;
  for (int i = 0; i < 8; ++i) {
    glm::vec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    // Along -toward_sun until y = ground_y (points below the ground stay where they are).
    float t = std::max(p.y - ground_y, 0.0f) / toward_sun.y;
    glm::vec3 q = p - toward_sun * t;
    swept_lo = glm::min(swept_lo, q);
    swept_hi = glm::max(swept_hi, q);
  }
  return box_outside_frustum(view_proj, swept_lo, swept_hi);
}

}  // namespace boreas::render
