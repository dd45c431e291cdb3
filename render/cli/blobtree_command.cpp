// boreas command: `boreas blobtree`. The options and the output path are checked before
// anything is built; the library judges the species and the BlobTree's def.
#include "cli/blobtree_command.h"

#include <cstdio>
#include <iostream>
#include <sstream>

#include "boreas/boreas.hpp"
#include "cli/cli_error.h"
#include "cli/mesh_command_checks.h"
#include "cli/mesh_output.h"
#include "cli/progress.h"
#include "mesh/tree_mesh.h"

namespace boreas::render {

int run_blobtree_command(const BlobTreeCommandOptions& options) {
  BlobTreeInputs inputs = check_blobtree_options(options);
  const MeshFormat format = inputs.format;

  boreas_world_def world_def = boreas_default_world_def();
  if (options.device) world_def.device = options.device->c_str();
  boreas::World world(world_def);
  boreas_tree_def tree_def = boreas_default_tree_def();
  tree_def.species = options.species.c_str();
  tree_def.seed = options.seed;
  tree_def.scale = float(options.scale);
  boreas_tree_id tree = world.add_tree(tree_def);

  boreas_blobtree_def def = boreas_default_blobtree_def();
  def.resolution = options.resolution;
  def.max_level = options.max_level;
  def.min_radius = float(options.min_radius);
  def.junctions = options.junctions == "pcm" ? BOREAS_BLOBTREE_PCM : BOREAS_BLOBTREE_BLEND;
  def.offsets = options.no_offsets ? 0 : 1;
  def.ridge = float(options.ridge);
  def.ridge_width = float(options.ridge_width);
  def.bend = float(options.bend);
  def.cuts = inputs.cuts.data();
  def.cut_count = int(inputs.cuts.size());
  def.scars = inputs.scars.data();
  def.scar_count = int(inputs.scars.size());

  boreas_blobtree_id blob{};
  boreas_blobtree_info info{};
  {
    Progress progress(100, !options.quiet, stderr, "%");
    blob = world.add_blobtree(
        tree, def, [&](float fraction, const char*) { progress.update(int(fraction * 100.0f)); });
    info = world.blobtree_get_info(blob);
    char done[160];
    std::snprintf(done, sizeof done, "polygonized %d primitives on a %dx%dx%d grid (%.3g m cells)",
                  info.primitives, info.grid[0], info.grid[1], info.grid[2], info.cell);
    progress.finish(done);
  }

  boreas::World::Mesh m = world.blobtree_get_mesh(blob);
  TreeMesh mesh;
  mesh.branches = branch_mesh(m.vertices, m.indices);
  mesh.branches.name = "bark";  // what `mesh_trees` in a scene takes as the trunk part
  std::ostringstream description;
  description << "BlobTree of species " << options.species << ", seed " << options.seed
              << ", scale " << options.scale << ", resolution " << options.resolution
              << ", junctions " << options.junctions;
  mesh.description = description.str();
  create_mesh_output_folder(options.out);
  write_tree_mesh(options.out, format, mesh);
  if (!options.quiet) {
    std::cout << "wrote " << options.out << ": " << options.species << " seed " << options.seed
              << ": " << info.vertices << " vertices, " << info.triangles << " triangles, "
              << info.branches << " branches (thinner than " << info.min_radius << " m left out)\n";
  }
  return kExitOk;
}

}  // namespace boreas::render
