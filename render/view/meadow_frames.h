// boreas views: the scene's underbrush as the frames of `boreas run` see it: the
// meadows' components read back through the public API once per frame, their palette,
// and the balls and rain areas drawn with them.
#pragma once

#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "boreas/boreas.hpp"
#include "image/meadow_view.h"
#include "scene/scene.h"

namespace boreas::render {

// At most this many strokes from above per frame; a bigger meadow is drawn every
// stride-th component (stride = ceil(components / kMaxTopStrokes)).
constexpr int kMaxTopStrokes = 200000;

struct FrameMeadows {
  std::vector<boreas_meadow_id> ids;              // the scene's meadows, in order
  std::vector<int> counts;                        // components per meadow
  std::vector<std::vector<std::string>> species;  // per meadow: its species, as planted
  std::vector<Rgb> palette;                       // per meadow, per species: ground, attached
  std::vector<int> first_style;                   // per meadow: its first palette entry
  std::vector<MeadowComponent> rest;              // every meadow's components at time 0, in order
  std::vector<MeadowComponent> now;               // the same as of the last step
  // The 3D view's colors: every meadow's parts as their species files describe them
  // (boreas_meadow_get_parts), and per component (in order) the index of its part there.
  std::vector<boreas_meadow_part> looks;
  std::vector<uint32_t> look_of;
  int stride = 1;                                 // from above: every stride-th component

  bool empty() const { return ids.empty(); }
  int total() const { return int(now.size()); }
};

// Reads the just planted meadows (at rest) and builds their palette: built-in species by
// name, species files in the order they first appear.
FrameMeadows plant_frame_meadows(const boreas::World& world, const Scene& scene,
                                 std::vector<boreas_meadow_id> ids);

// Reads every meadow's components as of the last step into meadows.now.
void read_meadows(const boreas::World& world, FrameMeadows& meadows);

// m: the farthest any component's center of mass stands from its rest pose.
float max_bend(const FrameMeadows& meadows);

// The scene's colliders at time t (s), where `boreas run` has moved them.
std::vector<Ball> colliders_at(const Scene& scene, double t);
// One collider at time t as drawn (its shape, pose and axes).
Ball collider_ball(const SceneCollider& collider, double t);
// For the 3D view, which draws spheres: a sphere as it is; a capsule or a box as a chain of
// spheres (center m, radius m) along its longest axis, as thick as its thinnest (so none
// reaches out of the shape: a car does not sink into the ground).
std::vector<glm::vec4> ball_spheres(const Ball& ball);

// The disks the scene's emitters' events fall in.
std::vector<Ball> emitter_areas(const Scene& scene);

// Where the close-up looks at time t: the first collider (clamped to the first meadow's
// rectangle), or the first meadow's center without colliders. Writes x, y, z (m).
void close_up_focus(const Scene& scene, double t, float out[3]);

}  // namespace boreas::render
