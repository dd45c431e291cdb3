// boreas command: checking and preparing a mesh file's path (see mesh_output.h).
#include "cli/mesh_output.h"

#include <filesystem>
#include <optional>

#include "cli/cli_error.h"

namespace boreas::render {

MeshFormat checked_mesh_format(const std::string& path) {
  std::optional<MeshFormat> format = mesh_format_for(path);
  if (format) return *format;
  std::string extension = std::filesystem::path(path).extension().string();
  throw CliError(kExitBadInput,
                 "--out: " + path + ": " +
                     (extension.empty() ? std::string("no file extension")
                                        : "unknown mesh format '" + extension + "'") +
                     " (expected .obj, .ply or .glb)");
}

void check_mesh_output_path(const std::string& out) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(out, error)) {
    throw CliError(kExitFailure, out + ": cannot write: it is a folder");
  }
  fs::path folder = fs::path(out).parent_path();
  while (!folder.empty() && !fs::exists(folder, error)) folder = folder.parent_path();
  if (!folder.empty() && !fs::is_directory(folder, error)) {
    throw CliError(kExitFailure, out + ": cannot write: " + folder.string() + " is not a folder");
  }
}

void create_mesh_output_folder(const std::string& out) {
  namespace fs = std::filesystem;
  fs::path folder = fs::path(out).parent_path();
  if (folder.empty()) return;
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder)) {
    throw CliError(kExitFailure, folder.string() + ": cannot create the output folder" +
                                     (error ? ": " + error.message() : ""));
  }
}

}  // namespace boreas::render
