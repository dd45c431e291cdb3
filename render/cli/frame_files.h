// boreas command: where `boreas run` writes its frames: numbered file names and an output
// folder cleared of an earlier run's frames.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "image/animation.h"

namespace boreas::render {

// "frame_0007.png" for index 7 of fewer than 10000 frames; more digits for longer runs.
std::string frame_file(int index, int frame_count, const std::string& extension = ".png");

// Creates dir if needed and removes frame_*.png, frame_*.exr and animation.* left by an
// earlier run (they would pass for this run's). Throws CliError (exit 3) naming the folder.
void prepare_output(const std::filesystem::path& dir);

// "animation.gif" (.webp, .mp4) for a format other than none.
std::string animation_file(AnimationFormat format);

// The animation of a run beside its frames, playing at the simulation's rate (one frame
// per seconds_per_frame of simulated time); nullptr for none. Throws CliError (exit 3).
std::unique_ptr<AnimationWriter> open_animation(const std::filesystem::path& dir,
                                                AnimationFormat format, int width, int height,
                                                int frame_count, double seconds_per_frame);

// AnimationWriter::add and ::finish with their errors as CliError (exit 3).
void add_frame(AnimationWriter& animation, const std::vector<uint8_t>& rgb);
void finish(AnimationWriter& animation);

}  // namespace boreas::render
