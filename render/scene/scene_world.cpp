// boreas scenes: scene to world. Waves go into the world's definition; primitives, gusts,
// obstacles and trees are added after it exists, all at time 0.
#include "scene/scene_world.h"

namespace boreas::render {

boreas::World make_world(const Scene& scene, const std::optional<std::string>& device,
                         std::vector<boreas_id>* tree_ids) {
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
  if (tree_ids) tree_ids->clear();
  for (size_t i = 0; i < scene.trees.size(); ++i) {
    boreas_tree_def tree = scene.trees[i].def;
    tree.species = scene.trees[i].species.c_str();
    boreas_id id{};
    boreas_status status = boreas_world_add_tree(world.handle(), &tree, &id);
    if (status != BOREAS_OK) {
      // Species files are only read here, once a world exists: say which tree it was.
      std::string source = scene.source.empty() ? "scene" : scene.source;
      throw boreas::Error(status, source + ": /trees/" + std::to_string(i) + ": " +
                                      boreas_last_error());
    }
    if (tree_ids) tree_ids->push_back(id);
  }
  return world;
}

}  // namespace boreas::render
