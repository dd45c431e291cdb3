// boreas command: `boreas info`, the OpenCL devices boreas can use and the one it picks.
#pragma once

#include <optional>
#include <string>

namespace boreas::render {

struct InfoOptions {
  std::optional<std::string> device;  // --device: show what this request picks
};

// Prints to stdout; throws CliError or boreas::Error when there is no device to pick.
int run_info_command(const InfoOptions& options);

}  // namespace boreas::render
