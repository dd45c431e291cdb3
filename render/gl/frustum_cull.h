// boreas render: whether a box can be seen through a view-projection, for skipping whole
// trees that lie outside the camera's (or the sun's shadow map's) frustum.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace boreas::render {

// True when every corner of the box [lo, hi] lies outside one and the same clip plane of
// view_proj (OpenGL clip space: -w <= x, y, z <= w). Conservative: a box that straddles
// planes without crossing into the frustum is kept, never the other way round.
bool box_outside_frustum(const glm::mat4& view_proj, const glm::vec3& lo, const glm::vec3& hi);

// True when nothing in the box [lo, hi] can cast a shadow that view_proj sees: the box
// swept away from the sun (toward_sun, unit, pointing up) down to the ground at ground_y,
// bounded by a box, lies outside the frustum. For a sun at or below the horizon nothing is
// culled.
bool shadow_outside_frustum(const glm::mat4& view_proj, const glm::vec3& lo, const glm::vec3& hi,
                            const glm::vec3& toward_sun, float ground_y);

}  // namespace boreas::render
