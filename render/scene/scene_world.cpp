// boreas scenes: scene to world. Waves go into the world's definition; primitives, gusts,
// obstacles, trees, meadows, colliders and emitters are added after it exists, all at
// time 0.
#include "scene/scene_world.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "scene/ground_image.h"
#include "scene/leaf_choice.h"

namespace boreas::render {

namespace {

// Throws boreas::Error with the library's last message, prefixed with the scene and where
// in it the rejected object is.
void check_added(boreas_status status, const Scene& scene, const std::string& where) {
  if (status == BOREAS_OK) return;
  // Species files and images are only read here, once a world exists: say which object.
  std::string source = scene.source.empty() ? "scene" : scene.source;
  throw boreas::Error(status, source + ": " + where + ": " + boreas_last_error());
}

// Every tree in one call (trees of one species and seed grow once; one upload for all).
std::vector<boreas_tree_id> add_trees(boreas::World& world, const Scene& scene) {
  std::vector<boreas_tree_def> trees(scene.trees.size());
  for (size_t i = 0; i < scene.trees.size(); ++i) {
    trees[i] = scene.trees[i].def;
    trees[i].species = scene.trees[i].species.c_str();
    trees[i].leaf_outline = leaf_outline_of_kind(scene.trees[i].leaf_kind);
  }
  std::vector<boreas_tree_id> added(trees.size());
  const boreas_status status =
      trees.empty()
          ? BOREAS_OK
          : boreas_world_add_trees(world.handle(), trees.data(), int(trees.size()), added.data());
  if (status != BOREAS_OK) {
    // The library names the def ("defs[i]: ..."): say which tree of the scene it is.
    std::string message = boreas_last_error();
    std::string where = "/trees";
    if (size_t at = message.find("defs["); at != std::string::npos) {
      const size_t close = message.find("]: ", at);
      if (close != std::string::npos) {
        where += "/" + message.substr(at + 5, close - at - 5);
        message = message.substr(close + 3);
      }
    }
    std::string source = scene.source.empty() ? "scene" : scene.source;
    throw boreas::Error(status, source + ": " + where + ": " + message);
  }
  return added;
}

boreas_mesh_tree_id add_mesh_tree(boreas::World& world, const Scene& scene, size_t i) {
  const SceneMeshTree& m = scene.mesh_trees[i];
  boreas_mesh_tree_def def = m.def;
  def.model = m.model.c_str();
  def.trunk_part = m.trunk_part ? m.trunk_part->c_str() : nullptr;
  def.leaves_part = m.leaves_part ? m.leaves_part->c_str() : nullptr;
  boreas_mesh_tree_id id{};
  check_added(boreas_world_add_mesh_tree(world.handle(), &def, &id), scene,
              "/mesh_trees/" + std::to_string(i));
  return id;
}

// The C++ layer has no underbrush calls yet: the C API, on the world's handle.
boreas_meadow_id add_meadow(boreas::World& world, const Scene& scene, size_t i) {
  const SceneMeadow& meadow = scene.meadows[i];
  std::vector<boreas_meadow_species> mix;
  for (const SceneMeadowSpecies& entry : meadow.species) {
    mix.push_back({entry.species.c_str(), entry.weight});
  }
  boreas_meadow_def def = meadow.def;
  def.species = mix.empty() ? nullptr : mix.data();
  def.species_count = static_cast<int>(mix.size());
  // The library takes pixels: the scene's image files are read here, once a world
  // exists, and named with the key that gave them.
  const std::string where = "/meadows/" + std::to_string(i);
  GroundImage terrain, nutrients;
  const auto read = [&](const std::string& path, const char* key, GroundImage& image) {
    if (path.empty()) return boreas_image{0, 0, 0, nullptr};
    try {
      image = read_ground_image(path);
    } catch (const boreas::Error& e) {
      std::string source = scene.source.empty() ? "scene" : scene.source;
      throw boreas::Error(e.status(), source + ": " + where + "/" + key + ": " + e.what());
    }
    return image.view();
  };
  def.terrain = read(meadow.terrain_image, "terrain_image", terrain);
  def.nutrients = read(meadow.nutrient_image, "nutrient_image", nutrients);
  boreas_meadow_id id{};
  check_added(boreas_world_add_meadow(world.handle(), &def, &id), scene, where);
  return id;
}

// The scene's LiDARs, each at its pose at time 0; a null id for each depth camera, which
// the world does not hold (it is captured on demand).
std::vector<boreas_lidar_id> add_lidars(boreas::World& world, const Scene& scene) {
  std::vector<boreas_lidar_id> ids;
  for (size_t i = 0; i < scene.sensors.size(); ++i) {
    boreas_lidar_id id{};
    const SceneSensor& sensor = scene.sensors[i];
    if (sensor.type == SceneSensor::Type::lidar) {
      boreas_lidar_def def = sensor.lidar_def();
      def.pose = sensor_pose_at(sensor, world.get_time());
      check_added(boreas_world_add_lidar(world.handle(), &def, &id), scene,
                  "/sensors/" + std::to_string(i));
    }
    ids.push_back(id);
  }
  return ids;
}

}  // namespace

boreas::World make_world(const Scene& scene, const std::optional<std::string>& device,
                         SceneIds* ids, const intptr_t* cl_context_properties,
                         const float* focus) {
  std::optional<std::string> request = device ? device : scene.device;
  boreas_world_def def = boreas_default_world_def();
  def.device = request ? request->c_str() : nullptr;
  def.grid = scene.grid;
  def.waves = scene.waves.empty() ? nullptr : scene.waves.data();
  def.wave_count = static_cast<int>(scene.waves.size());
  def.cl_context_properties = cl_context_properties;
  boreas::World world(def);
  // Before the add: a tree settles at add only where the focus is already known.
  if (focus) boreas::check(boreas_world_set_focus(world.handle(), focus, 1));
  for (const boreas_flow_primitive_def& p : scene.primitives) (void)world.wind_add_primitive(p);
  for (const boreas_gust_def& g : scene.gusts) (void)world.wind_add_gust(g);
  for (const SolidBox& box : scene.obstacles) {
    world.wind_add_solid_box({box.min[0], box.min[1], box.min[2]},
                             {box.max[0], box.max[1], box.max[2]});
  }
  SceneIds added;
  added.trees = add_trees(world, scene);
  for (size_t i = 0; i < scene.mesh_trees.size(); ++i)
    added.mesh_trees.push_back(add_mesh_tree(world, scene, i));
  for (size_t i = 0; i < scene.meadows.size(); ++i)
    added.meadows.push_back(add_meadow(world, scene, i));
  for (size_t i = 0; i < scene.colliders.size(); ++i) {
    boreas_collider_id id{};
    // The world moves it by its velocities each step (boreas_collider_def).
    check_added(boreas_world_add_collider(world.handle(), &scene.colliders[i].def, &id), scene,
                "/colliders/" + std::to_string(i));
    added.colliders.push_back(id);
  }
  for (size_t i = 0; i < scene.emitters.size(); ++i) {
    boreas_emitter_id id{};
    check_added(boreas_world_add_emitter(world.handle(), &scene.emitters[i], &id), scene,
                "/emitters/" + std::to_string(i));
    added.emitters.push_back(id);
  }
  added.lidars = add_lidars(world, scene);
  if (ids) *ids = std::move(added);
  return world;
}

void collider_position(const SceneCollider& collider, double t, float out[3]) {
  for (int a = 0; a < 3; ++a) {
    double p = double(collider.def.pose.position[a]) + double(collider.def.velocity[a]) * t;
    out[a] = float(std::clamp(p, -BOREAS_WORLD_MAX_COORDINATE, BOREAS_WORLD_MAX_COORDINATE));
  }
}

boreas_pose collider_pose_at(const SceneCollider& collider, double t) {
  boreas_pose pose = collider.def.pose;
  collider_position(collider, t, pose.position);
  const float* w = collider.def.angular_velocity;
  const double angle = std::sqrt(double(w[0]) * w[0] + double(w[1]) * w[1] + double(w[2]) * w[2]) * t;
  if (angle == 0.0) return pose;
  // r = exp(w t / 2) = (sin(angle / 2) axis, cos(angle / 2)); the pose turns to r q.
  const double s = std::sin(0.5 * angle) / angle * t, c = std::cos(0.5 * angle);
  const double r[3] = {w[0] * s, w[1] * s, w[2] * s};
  const float* q = collider.def.pose.orientation;
  const double out[4] = {c * q[0] + r[0] * q[3] + r[1] * q[2] - r[2] * q[1],
                         c * q[1] + r[1] * q[3] + r[2] * q[0] - r[0] * q[2],
                         c * q[2] + r[2] * q[3] + r[0] * q[1] - r[1] * q[0],
                         c * q[3] - r[0] * q[0] - r[1] * q[1] - r[2] * q[2]};
  const double norm = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
  for (int i = 0; i < 4; ++i) pose.orientation[i] = float(out[i] / norm);
  return pose;
}

void move_lidars(boreas::World& world, const Scene& scene, const std::vector<boreas_lidar_id>& ids,
                 double t) {
  size_t n = std::min(ids.size(), scene.sensors.size());
  for (size_t i = 0; i < n; ++i) {
    const SceneSensor& sensor = scene.sensors[i];
    if (sensor.type != SceneSensor::Type::lidar || sensor.path.empty()) continue;
    boreas_pose pose = sensor_pose_at(sensor, t);
    boreas::check(boreas_lidar_set_pose(world.handle(), ids[i], &pose));
  }
}

boreas_step_stats step_scene(boreas::World& world, const Scene& scene, int steps, float dt,
                             const std::vector<boreas_lidar_id>& lidars) {
  boreas_step_stats sum{};
  for (int i = 0; i < steps; ++i) {
    // A LiDAR takes the pose it reaches at the step's end; its firings interpolate.
    move_lidars(world, scene, lidars, world.get_time() + double(dt));
    world.step(dt);
    boreas_step_stats s = world.get_step_stats();
    sum.wind += s.wind;
    sum.trees += s.trees;
    sum.underbrush += s.underbrush;
    sum.total += s.total;
    sum.branches_broken += s.branches_broken;
  }
  return sum;
}

}  // namespace boreas::render
