// boreas command: `boreas run`, which simulates a scene's wind and films a horizontal
// slice of it: one PNG per frame, a contact sheet and summary.json in the output folder.
#pragma once

#include "cli/run_options.h"

namespace boreas::render {

// Throws SceneError, CliError, boreas::Error or ImageWriteError; main() reports them.
int run_run_command(const RunOptions& options);

}  // namespace boreas::render
