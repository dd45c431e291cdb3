// boreas command: where `boreas run` writes its frames: numbered file names and an output
// folder cleared of an earlier run's frames.
#pragma once

#include <filesystem>
#include <string>

namespace boreas::render {

// "frame_0007.png" for index 7 of fewer than 10000 frames; more digits for longer runs.
std::string frame_file(int index, int frame_count, const std::string& extension = ".png");

// Creates dir if needed and removes frame_*.png and frame_*.exr left by an earlier, longer
// run (they would pass for this run's). Throws CliError (exit 3) naming the folder.
void prepare_output(const std::filesystem::path& dir);

}  // namespace boreas::render
