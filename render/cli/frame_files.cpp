// boreas command: frame file names and the output folder.
#include "cli/frame_files.h"

#include <algorithm>
#include <regex>

#include "cli/cli_error.h"
#include "image/png_io.h"

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
  static const std::regex kFrameName("frame_[0-9]+\\.(png|exr)|animation\\.(gif|webp|mp4)");
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kFrameName)) {
      fs::remove(entry.path());
    }
  }
}

std::string animation_file(AnimationFormat format) {
  return std::string("animation.") + animation_format_name(format);
}

std::unique_ptr<AnimationWriter> open_animation(const fs::path& dir, AnimationFormat format,
                                                int width, int height, int frame_count,
                                                double seconds_per_frame) {
  if (format == AnimationFormat::none) return nullptr;
  try {
    return std::make_unique<AnimationWriter>((dir / animation_file(format)).string(), format, width,
                                             height, frame_count, 1.0 / seconds_per_frame);
  } catch (const ImageWriteError& e) {
    throw CliError(kExitFailure, e.what());
  }
}

void add_frame(AnimationWriter& animation, const std::vector<uint8_t>& rgb) {
  try {
    animation.add(rgb);
  } catch (const ImageWriteError& e) {
    throw CliError(kExitFailure, e.what());
  }
}

void finish(AnimationWriter& animation) {
  try {
    animation.finish();
  } catch (const ImageWriteError& e) {
    throw CliError(kExitFailure, e.what());
  }
}

}  // namespace boreas::render
