// boreas scenes: scene to world. Waves go into the world's definition; primitives, gusts
// and obstacles are added after it exists, all at time 0.
#include "scene/scene_world.h"

namespace boreas::render {

boreas::World make_world(const Scene& scene, const std::optional<std::string>& device) {
  std::optional<std::string> request = device ? device : scene.device;
  boreas_world_def def = boreas_default_world_def();
  def.device = request ? request->c_str() : nullptr;
  def.grid = scene.grid;
  def.waves = scene.waves.empty() ? nullptr : scene.waves.data();
  def.wave_count = static_cast<int>(scene.waves.size());
  boreas::World world(def);
  for (const boreas_flow_primitive& p : scene.primitives) (void)world.add_primitive(p);
  for (const boreas_gust& g : scene.gusts) (void)world.add_gust(g);
  for (const SolidBox& box : scene.obstacles) {
    world.add_solid_box({box.min[0], box.min[1], box.min[2]}, {box.max[0], box.max[1], box.max[2]});
  }
  return world;
}

}  // namespace boreas::render
