// boreas tests: a temporary folder, for tests that need nothing else of test_support.h (no
// runtime, no world).
#pragma once

#include <filesystem>
#include <random>
#include <string>

namespace boreas::test {

// A fresh folder under the system temp dir, removed at the end of its scope.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("boreas-test-" + std::to_string(rd()) + "-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::string str() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace boreas::test
