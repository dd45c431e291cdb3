// boreas command: the checks and folder creation shared by the commands that write a mesh
// file (export-mesh, blobtree), so bad output paths fail before any work is done.
#pragma once

#include <string>

#include "mesh/tree_mesh.h"

namespace boreas::render {

// The format --out asks for by its extension; throws CliError naming it otherwise.
MeshFormat checked_mesh_format(const std::string& path);

// Throws CliError when the file could never be written there (a folder, or a path
// through a file).
void check_mesh_output_path(const std::string& out);

// Creates the file's folder; throws CliError.
void create_mesh_output_folder(const std::string& out);

}  // namespace boreas::render
