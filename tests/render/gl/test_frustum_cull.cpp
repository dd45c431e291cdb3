// boreas render tests: box_outside_frustum (render/gl/frustum_cull.h) against a camera
// looking down -Z and an orthographic shadow-map projection: boxes in view, behind the
// camera, beside it, past the far plane, and reaching over an edge.
#include "gl/frustum_cull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace boreas::render {
namespace {

// 90 degrees wide and high, near 0.5 m, far 100 m, from the origin toward -Z.
glm::mat4 camera() {
  return glm::perspective(glm::radians(90.0f), 1.0f, 0.5f, 100.0f) *
         glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

bool outside(const glm::mat4& m, glm::vec3 center, float half) {
  return box_outside_frustum(m, center - glm::vec3(half), center + glm::vec3(half));
}

TEST(FrustumCull, KeepsWhatIsInViewAndDropsWhatIsNot) {
  const glm::mat4 m = camera();
  EXPECT_FALSE(outside(m, {0, 0, -10}, 1));   // straight ahead
  EXPECT_FALSE(outside(m, {8, 0, -10}, 1));   // inside the 45-degree half-angle
  EXPECT_TRUE(outside(m, {0, 0, 10}, 1));     // behind
  EXPECT_TRUE(outside(m, {20, 0, -10}, 1));   // right of the right plane (x = -z)
  EXPECT_TRUE(outside(m, {-20, 0, -10}, 1));  // left
  EXPECT_TRUE(outside(m, {0, 20, -10}, 1));   // above
  EXPECT_TRUE(outside(m, {0, 0, -150}, 1));   // past the far plane
}

TEST(FrustumCull, KeepsABoxThatReachesIntoView) {
  const glm::mat4 m = camera();
  // Centered 1.5 m right of the right plane's trace at z = -10 (x = 10), 2 m half-size:
  // its left side crosses into view.
  EXPECT_FALSE(outside(m, {11.5f, 0, -10}, 2));
  // A box around the camera itself: corners behind it and in front, on every side.
  EXPECT_FALSE(outside(m, {0, 0, 0}, 5));
}

TEST(FrustumCull, WorksForAnOrthographicShadowMap) {
  // The sun straight above, a 40 m square map.
  const glm::mat4 m = glm::ortho(-20.0f, 20.0f, -20.0f, 20.0f, 1.0f, 200.0f) *
                      glm::lookAt(glm::vec3(0, 100, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  EXPECT_FALSE(outside(m, {10, 5, 10}, 2));
  EXPECT_TRUE(outside(m, {30, 5, 0}, 2));
  EXPECT_FALSE(outside(m, {21, 5, 0}, 2));  // reaches over the edge
}

TEST(FrustumCull, ShadowCastersAreKeptWhereTheirShadowIsSeen) {
  // The camera 2 m up looking down -Z and a little down, so the ground ahead is in view.
  const glm::mat4 m = glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 200.0f) *
                      glm::lookAt(glm::vec3(0, 2, 0), glm::vec3(0, 0, -10), glm::vec3(0, 1, 0));
  // The sun low in the west (toward -X), 30 degrees up: shadows fall toward +X.
  const glm::vec3 toward_sun = glm::normalize(glm::vec3(-std::sqrt(3.0f), 1.0f, 0.0f));
  // A tree 30 m west of the view's middle at z = -20, out of the camera's frustum; its 10 m
  // crown's shadow reaches 17 m east of it, short of the view.
  const glm::vec3 lo(-40, 0, -22), hi(-36, 10, -18);
  EXPECT_TRUE(box_outside_frustum(m, lo, hi));
  EXPECT_TRUE(shadow_outside_frustum(m, lo, hi, toward_sun, 0.0f));
  // A 25 m tree there reaches 43 m east: into the view (the frustum is 23 m wide at z = -20).
  const glm::vec3 tall(-36, 25, -18);
  EXPECT_TRUE(box_outside_frustum(m, lo, tall));
  EXPECT_FALSE(shadow_outside_frustum(m, lo, tall, toward_sun, 0.0f));
  // A tree behind the camera, the sun ahead of it: its shadow falls away from the view.
  const glm::vec3 ahead = glm::normalize(glm::vec3(0.0f, 1.0f, -1.0f));
  EXPECT_TRUE(shadow_outside_frustum(m, glm::vec3(-2, 0, 8), glm::vec3(2, 10, 12), ahead, 0.0f));
  // The sun at the horizon: nothing is culled.
  EXPECT_FALSE(shadow_outside_frustum(m, lo, hi, glm::vec3(-1, 0, 0), 0.0f));
}

}  // namespace
}  // namespace boreas::render
