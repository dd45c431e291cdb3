// boreas command: `boreas preprocess` through the public C API (boreas_preprocess_mesh_tree).
#include "cli/preprocess_command.h"

#include <cstdio>
#include <filesystem>

#include "boreas/boreas.hpp"
#include "cli/cli_error.h"

namespace boreas::render {

int run_preprocess_command(const PreprocessOptions& options) {
  std::filesystem::path out(options.out);
  if (out.extension() != ".glb")
    throw CliError(kExitBadInput,
                   "--out: the preprocessed tree is written as binary glTF: name it *.glb (got '" +
                       options.out + "')");
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = options.model.c_str();
  def.trunk_part = options.trunk_part.empty() ? nullptr : options.trunk_part.c_str();
  def.leaves_part = options.leaves_part.empty() ? nullptr : options.leaves_part.c_str();
  def.seed = options.seed;
  boreas_mesh_tree_info info{};
  boreas::check(boreas_preprocess_mesh_tree(&def, options.out.c_str(), &info));
  if (!options.quiet) {
    std::printf(
        "boreas: %s -> %s: %d branches in %d levels%s, %d leaves; trunk %d vertices / %d "
        "triangles, "
        "leaves %d vertices / %d triangles\n",
        options.model.c_str(), options.out.c_str(), info.branches, info.levels,
        info.levels > 4 ? " (levels past 4 move with their parent)" : "", info.leaves,
        info.trunk_vertices, info.trunk_triangles, info.leaf_vertices, info.leaf_triangles);
    if (info.orphans > 0)
      std::printf(
          "boreas: warning: %d branches touch no thicker branch; each was hung on the nearest "
          "one\n",
          info.orphans);
  }
  return kExitOk;
}

}  // namespace boreas::render
