// boreas command: frame file names and the output folder.
#include "cli/frame_files.h"

#include <algorithm>
#include <regex>

#include "cli/cli_error.h"

namespace boreas::render {

namespace fs = std::filesystem;

std::string frame_file(int index, int frame_count, const std::string& extension) {
  std::string number = std::to_string(index);
  size_t digits = std::max<size_t>(4, std::to_string(frame_count - 1).size());
  return "frame_" + std::string(digits - std::min(digits, number.size()), '0') + number + extension;
}

void prepare_output(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    throw CliError(kExitFailure, dir.string() + ": cannot create the output folder" +
                                     (error ? ": " + error.message() : ""));
  }
  static const std::regex kFrameName("frame_[0-9]+\\.(png|exr)");
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kFrameName)) {
      fs::remove(entry.path());
    }
  }
}

}  // namespace boreas::render
