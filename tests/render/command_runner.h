// render tests: runs the built boreas command in a fresh temporary folder and captures its
// exit code, stdout and stderr, the way a user's shell or a CI job would.
#pragma once

#include <filesystem>
#include <string>

namespace boreas::render::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// A temporary folder named after the running test, emptied first, removed at the end.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Writes text to name inside the folder; returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;

 private:
  std::filesystem::path path_;
};

// Runs "boreas <args>" inside dir; env is prepended as shell assignments ("A=1 B=2").
CommandResult run_boreas(const std::string& args, const TempDir& dir, const std::string& env = "");

std::string read_text(const std::filesystem::path& path);

}  // namespace boreas::render::testing
