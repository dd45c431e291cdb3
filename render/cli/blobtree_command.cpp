// boreas command: `boreas blobtree`. The options and the output path are checked before
// anything is built; the library judges the species and the BlobTree's def.
#include "cli/blobtree_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "boreas/boreas.hpp"
#include "cli/cli_error.h"
#include "cli/mesh_output.h"
#include "cli/progress.h"
#include "mesh/tree_mesh.h"

namespace boreas::render {
namespace {

// "12:0.4" -> {12, 0.4}; the option's name and the text in the error.
std::vector<double> numbers_of(const std::string& option, const std::string& text, size_t least,
                               size_t most, const char* form) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ':')) {
    char* end = nullptr;
    double v = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(v))
      throw CliError(kExitBadInput, option + ": '" + text + "' is not " + form);
    values.push_back(v);
  }
  if (values.size() < least || values.size() > most)
    throw CliError(kExitBadInput, option + ": '" + text + "' is not " + form);
  return values;
}

int32_t branch_of(const std::string& option, const std::string& text, double v) {
  if (v < 0.0 || v > 1e9 || v != std::floor(v))
    throw CliError(kExitBadInput,
                   option + ": '" + text + "': the branch must be a whole number >= 0");
  return static_cast<int32_t>(v);
}

}  // namespace

int run_blobtree_command(const BlobTreeCommandOptions& options) {
  MeshFormat format = checked_mesh_format(options.out);
  check_mesh_output_path(options.out);
  if (!(std::isfinite(options.scale) && options.scale > 0.0 && options.scale <= 1000.0))
    throw CliError(kExitBadInput,
                   "--scale: must be in (0, 1000] (got " + cli_number(options.scale) + ")");
  if (options.junctions != "pcm" && options.junctions != "blend")
    throw CliError(kExitBadInput,
                   "--junctions: must be pcm or blend (got '" + options.junctions + "')");

  std::vector<boreas_blobtree_cut> cuts;
  for (const std::string& c : options.cuts) {
    std::vector<double> v = numbers_of("--cut", c, 2, 2, "BRANCH:AT (e.g. 12:0.4)");
    cuts.push_back(boreas_blobtree_cut{branch_of("--cut", c, v[0]), float(v[1])});
  }
  std::vector<boreas_blobtree_scar> scars;
  for (const std::string& s : options.scars) {
    std::vector<double> v =
        numbers_of("--scar", s, 2, 3, "BRANCH:STUB or BRANCH:STUB:DEPTH (e.g. 7:0.1:0.5)");
    scars.push_back(boreas_blobtree_scar{branch_of("--scar", s, v[0]), float(v[1]),
                                         float(v.size() > 2 ? v[2] : 0.5)});
  }

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
  def.cuts = cuts.data();
  def.cut_count = int(cuts.size());
  def.scars = scars.data();
  def.scar_count = int(scars.size());

  boreas_blobtree_id blob{};
  boreas_blobtree_info info{};
  {
    Progress progress(100, !options.quiet, stderr, "%");
    blob = world.add_blobtree(
        tree, def, [&](float fraction, const char*) { progress.update(int(fraction * 100.0f)); });
    info = world.blobtree_info(blob);
    char done[160];
    std::snprintf(done, sizeof done, "polygonized %d primitives on a %dx%dx%d grid (%.3g m cells)",
                  info.primitives, info.grid[0], info.grid[1], info.grid[2], info.cell);
    progress.finish(done);
  }

  boreas::World::Mesh m = world.blobtree_mesh(blob);
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
