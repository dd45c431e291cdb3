// boreas render: sky light inside a crown (crown_light.h).
#include "gl/crown_light.h"

#include <glm/geometric.hpp>

namespace boreas::render {

float leaf_occlusion(const glm::vec3& p, const Bounds& crown) {
  glm::vec3 center = 0.5f * (crown.min + crown.max);
  glm::vec3 half = glm::max(0.5f * (crown.max - crown.min), glm::vec3(0.1f));
  glm::vec3 d = (p - center) / half;
  float rim = glm::clamp(glm::length(d), 0.0f, 1.0f);
  float top = glm::clamp(0.5f + 0.5f * d.y, 0.0f, 1.0f);
  return glm::clamp(0.3f + 0.5f * rim * rim + 0.2f * top, 0.0f, 1.0f);
}

}  // namespace boreas::render
