// boreas command: `boreas export-mesh`. Everything that can be checked without a world is
// checked first (the format, the numbers, the scene), so bad input fails at once; the
// species is the library's to judge, when the tree is grown.
#include "cli/export_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "boreas/boreas.hpp"
#include "cli/cli_error.h"
#include "cli/mesh_command_checks.h"
#include "cli/mesh_output.h"
#include "cli/progress.h"
#include "mesh/tree_mesh.h"
#include "scene/scene_loader.h"
#include "scene/scene_world.h"

namespace boreas::render {

namespace {

// The tree stands at the world's origin on the grid's floor when the grid covers the
// origin horizontally, else at the middle of the grid's floor.
void tree_position(const boreas_grid_def& grid, float position[3]) {
  float extent_x = grid.cell_size * float(grid.resolution[0]);
  float extent_z = grid.cell_size * float(grid.resolution[2]);
  bool covers_origin = grid.origin[0] <= 0.0f && grid.origin[0] + extent_x >= 0.0f &&
                       grid.origin[2] <= 0.0f && grid.origin[2] + extent_z >= 0.0f;
  position[0] = covers_origin ? 0.0f : grid.origin[0] + 0.5f * extent_x;
  position[1] = grid.origin[1];
  position[2] = covers_origin ? 0.0f : grid.origin[2] + 0.5f * extent_z;
}

}  // namespace

int run_export_command(const ExportOptions& options) {
  const MeshFormat mesh_format = check_export_options(options);
  Scene scene = options.scene_path ? load_scene_file(*options.scene_path) : load_default_scene();
  scene.trees.clear();  // the one tree exported is the only one grown
  // Only the wind matters to a tree: the underbrush would only cost time to plant.
  scene.meadows.clear();
  scene.colliders.clear();
  scene.emitters.clear();

  boreas::World world = make_world(scene, options.device);
  boreas_tree_def def = boreas_default_tree_def();
  def.species = options.species.c_str();
  def.seed = options.seed;
  def.scale = float(options.scale);
  tree_position(world.wind_get_grid(), def.position);
  boreas_tree_id tree = world.add_tree(def);

  // Whole steps of kExportStep, then one shorter step for what is left.
  long long whole = (long long)std::floor(options.time / kExportStep + 1e-9);
  double rest = options.time - double(whole) * kExportStep;
  bool partial = rest > 1e-7;
  long long steps = whole + (partial ? 1 : 0);
  {
    Progress progress(int(steps), !options.quiet && steps > 0, stderr, "step");
    for (long long i = 0; i < whole; ++i) {
      world.step(float(kExportStep));
      progress.update(int(i + 1));
    }
    if (partial) world.step(float(rest));
    progress.update(int(steps));
    char done[128];
    std::snprintf(done, sizeof done, "%lld steps, %.3f s simulated", steps, world.get_time());
    progress.finish(done);
  }

  boreas::World::Mesh branches = world.tree_get_mesh(tree);
  TreeMesh mesh;
  mesh.branches = branch_mesh(branches.vertices, branches.indices);
  mesh.leaves = leaf_mesh(world.tree_get_leaves(tree));
  std::ostringstream description;
  description << "species " << options.species << ", seed " << options.seed << ", scale "
              << options.scale << ", t = " << world.get_time() << " s, at (" << def.position[0]
              << ", " << def.position[1] << ", " << def.position[2] << ") in scene " << scene.name;
  mesh.description = description.str();
  create_mesh_output_folder(options.out);
  write_tree_mesh(options.out, mesh_format, mesh);

  if (!options.quiet) {
    std::cout << "wrote " << options.out << ": " << options.species << " seed " << options.seed
              << " at t = " << world.get_time() << " s: branches " << mesh.branches.vertex_count()
              << " vertices, " << mesh.branches.triangle_count() << " triangles; leaves "
              << mesh.leaves.vertex_count() / 4 << " quads\n";
  }
  return kExitOk;
}

}  // namespace boreas::render
