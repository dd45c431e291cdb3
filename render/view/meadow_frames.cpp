// boreas command: meadows for the frames, from boreas_meadow_get_components.
#include "view/meadow_frames.h"

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

#include "scene/scene_world.h"

namespace boreas::render {

namespace {

// The components of one meadow, into out from offset on; palette entries start at
// first_style (2 per species: ground, attached).
void read_one(const boreas::World& world, boreas_meadow_id meadow, int first_style,
              std::vector<MeadowComponent>& out, size_t offset, size_t count) {
  // Kept across frames: the C call fills it without allocating again.
  static thread_local std::vector<boreas_component> buffer;
  int n = 0;
  boreas::check(boreas_meadow_get_components(world.handle(), meadow, nullptr, 0, &n));
  buffer.resize(size_t(n));
  boreas::check(boreas_meadow_get_components(world.handle(), meadow, buffer.data(), n, &n));
  size_t copied = std::min(count, size_t(n));
  for (size_t i = 0; i < copied; ++i) {
    const boreas_component& c = buffer[i];
    MeadowComponent& m = out[offset + i];
    std::copy(c.base, c.base + 3, m.base);
    std::copy(c.center_of_mass, c.center_of_mass + 3, m.center);
    m.attached = c.parent >= 0 ? 1 : 0;
    m.style = uint16_t(first_style + 2 * std::max(c.species, 0) + m.attached);
    m.broken = c.broken != 0 ? 1 : 0;
  }
}

// Appends the meadow's part looks to meadows.looks and, for each of its components, the
// index of its look to meadows.look_of; returns its component count. The parts come
// species by species, each species' parts in order (boreas_meadow_get_parts), so a
// component's look is its species' first part plus its part index.
int read_looks(const boreas::World& world, boreas_meadow_id meadow, FrameMeadows& meadows) {
  int n = 0;
  boreas::check(boreas_meadow_get_parts(world.handle(), meadow, nullptr, 0, &n));
  std::vector<boreas_meadow_part> parts(static_cast<size_t>(n));
  boreas::check(boreas_meadow_get_parts(world.handle(), meadow, parts.data(), n, &n));
  std::vector<uint32_t> first_of_species;  // index into meadows.looks
  for (const boreas_meadow_part& part : parts) {
    if (part.part == 0) first_of_species.push_back(uint32_t(meadows.looks.size()));
    meadows.looks.push_back(part);
  }
  boreas::check(boreas_meadow_get_components(world.handle(), meadow, nullptr, 0, &n));
  std::vector<boreas_component> components(static_cast<size_t>(n));
  boreas::check(boreas_meadow_get_components(world.handle(), meadow, components.data(), n, &n));
  for (const boreas_component& c : components) {
    meadows.look_of.push_back(first_of_species[size_t(c.species)] + uint32_t(c.part));
  }
  return n;
}

}  // namespace

FrameMeadows plant_frame_meadows(const boreas::World& world, const Scene& scene,
                                 std::vector<boreas_meadow_id> ids) {
  FrameMeadows meadows;
  meadows.ids = std::move(ids);
  std::vector<std::string> files;  // species files, in the order they first appear
  for (size_t m = 0; m < meadows.ids.size(); ++m) {
    std::vector<std::string> names;
    if (m < scene.meadows.size()) {
      for (const SceneMeadowSpecies& entry : scene.meadows[m].species)
        names.push_back(entry.species);
    }
    if (names.empty()) names = default_meadow_mix();
    meadows.first_style.push_back(int(meadows.palette.size()));
    for (const std::string& name : names) {
      auto file = std::find(files.begin(), files.end(), name);
      int index = int(file - files.begin());
      if (file == files.end()) files.push_back(name);
      meadows.palette.push_back(underbrush_color(name, false, index));
      meadows.palette.push_back(underbrush_color(name, true, index));
    }
    meadows.species.push_back(std::move(names));
    meadows.counts.push_back(read_looks(world, meadows.ids[m], meadows));
  }
  size_t total = 0;
  for (int n : meadows.counts) total += size_t(n);
  meadows.now.resize(total);
  read_meadows(world, meadows);
  meadows.rest = meadows.now;
  meadows.stride = int((total + kMaxTopStrokes - 1) / kMaxTopStrokes);
  meadows.stride = std::max(meadows.stride, 1);
  return meadows;
}

void read_meadows(const boreas::World& world, FrameMeadows& meadows) {
  size_t offset = 0;
  for (size_t m = 0; m < meadows.ids.size(); ++m) {
    size_t count = size_t(meadows.counts[m]);
    read_one(world, meadows.ids[m], meadows.first_style[m], meadows.now, offset, count);
    offset += count;
  }
}

float max_bend(const FrameMeadows& meadows) {
  float bend = 0.0f;
  size_t n = std::min(meadows.now.size(), meadows.rest.size());
  for (size_t i = 0; i < n; ++i) {
    const float* p = meadows.now[i].center;
    const float* q = meadows.rest[i].center;
    bend = std::max(bend, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  }
  return bend;
}

namespace {

// v turned by the unit quaternion q (x, y, z, w): v + 2 w (u x v) + 2 u x (u x v).
void turn(const float q[4], const float v[3], float out[3]) {
  const float u[3] = {q[0], q[1], q[2]};
  const float t[3] = {2.0f * (u[1] * v[2] - u[2] * v[1]), 2.0f * (u[2] * v[0] - u[0] * v[2]),
                      2.0f * (u[0] * v[1] - u[1] * v[0])};
  out[0] = v[0] + q[3] * t[0] + (u[1] * t[2] - u[2] * t[1]);
  out[1] = v[1] + q[3] * t[1] + (u[2] * t[0] - u[0] * t[2]);
  out[2] = v[2] + q[3] * t[2] + (u[0] * t[1] - u[1] * t[0]);
}

}  // namespace

Ball collider_ball(const SceneCollider& collider, double t) {
  const boreas_collider_def& d = collider.def;
  const boreas_pose pose = collider_pose_at(collider, t);
  Ball ball;
  std::copy(pose.position, pose.position + 3, ball.center);
  switch (d.shape) {
    case BOREAS_COLLIDER_CAPSULE:
      ball.radius = d.radius;
      ball.half[1] = d.half_height;
      break;
    case BOREAS_COLLIDER_BOX:
      std::copy(d.half_extents, d.half_extents + 3, ball.half);
      break;
    default:
      ball.radius = d.radius;
  }
  for (int i = 0; i < 3; ++i) {
    const float unit[3] = {i == 0 ? 1.0f : 0.0f, i == 1 ? 1.0f : 0.0f, i == 2 ? 1.0f : 0.0f};
    turn(pose.orientation, unit, ball.axes[i]);
  }
  return ball;
}

std::vector<glm::vec4> ball_spheres(const Ball& ball) {
  const glm::vec3 c(ball.center[0], ball.center[1], ball.center[2]);
  if (ball.round()) return {glm::vec4(c, ball.radius)};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int a, int b) { return ball.half[a] < ball.half[b]; });
  const int longest = order[2];
  const float radius = ball.radius + ball.half[order[0]];
  const glm::vec3 axis(ball.axes[longest][0], ball.axes[longest][1], ball.axes[longest][2]);
  const float reach = std::max(ball.half[longest] + ball.radius - radius, 0.0f);
  const int count = std::min(16, 1 + int(std::ceil(2.0f * reach / std::max(radius, 1e-3f))));
  std::vector<glm::vec4> spheres;
  for (int i = 0; i < count; ++i) {
    const float u = count == 1 ? 0.0f : -reach + 2.0f * reach * float(i) / float(count - 1);
    spheres.emplace_back(c + u * axis, radius);
  }
  return spheres;
}

std::vector<Ball> colliders_at(const Scene& scene, double t) {
  std::vector<Ball> balls;
  for (const SceneCollider& collider : scene.colliders) balls.push_back(collider_ball(collider, t));
  return balls;
}

std::vector<Ball> emitter_areas(const Scene& scene) {
  std::vector<Ball> areas;
  for (const boreas_emitter_def& emitter : scene.emitters) {
    Ball area;
    std::copy(emitter.center, emitter.center + 3, area.center);
    area.radius = emitter.area_radius;
    areas.push_back(area);
  }
  return areas;
}

void close_up_focus(const Scene& scene, double t, float out[3]) {
  if (scene.meadows.empty()) {
    out[0] = out[1] = out[2] = 0.0f;
    return;
  }
  const boreas_meadow_def& meadow = scene.meadows[0].def;
  std::copy(meadow.center, meadow.center + 3, out);
  if (scene.colliders.empty()) return;
  float at[3];
  collider_position(scene.colliders[0], t, at);
  out[0] = std::clamp(at[0], meadow.center[0] - 0.5f * meadow.size[0],
                      meadow.center[0] + 0.5f * meadow.size[0]);
  out[2] = std::clamp(at[2], meadow.center[2] - 0.5f * meadow.size[1],
                      meadow.center[2] + 0.5f * meadow.size[1]);
}

}  // namespace boreas::render
