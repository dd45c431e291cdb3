// boreas command: what export-mesh and blobtree check before anything is built (the
// output's format and path, the numbers, blobtree's cuts and scars), apart from the
// commands, so a bad option fails at once and the fuzzer can reach every check without
// growing a tree.
#pragma once

#include <vector>

#include "boreas/boreas.h"
#include "cli/blobtree_command.h"
#include "cli/export_command.h"
#include "mesh/tree_mesh.h"

namespace boreas::render {

// The mesh format export-mesh writes; throws CliError naming the option that is wrong.
MeshFormat check_export_options(const ExportOptions& options);

struct BlobTreeInputs {
  MeshFormat format = MeshFormat::kObj;
  std::vector<boreas_blobtree_cut> cuts;
  std::vector<boreas_blobtree_scar> scars;
};

// blobtree's format, cuts and scars; throws CliError naming the option that is wrong. The
// BlobTree's own numbers (resolution, ridge, ...) are the library's to judge.
BlobTreeInputs check_blobtree_options(const BlobTreeCommandOptions& options);

}  // namespace boreas::render
