// boreas command: entry point. Runs the subcommand the command line names and turns every
// error into "boreas: error: ..." on stderr and an exit code (cli_error.h).
#include <filesystem>

#include "boreas/boreas.hpp"
#include "cli/blobtree_command.h"
#include "cli/cli_error.h"
#include "cli/command_line.h"
#include "cli/export_command.h"
#include "cli/info_command.h"
#include "cli/preprocess_command.h"
#include "cli/run_command.h"
#include "image/png_io.h"
#include "mesh/tree_mesh.h"
#include "scene/scene_error.h"

namespace {

using namespace boreas::render;

int exit_code_of(boreas_status status) {
  switch (status) {
    case BOREAS_ERROR_NO_DEVICE:
      return kExitNoDevice;
    case BOREAS_ERROR_INVALID_ARGUMENT:
    case BOREAS_ERROR_IO:  // the library reads species files, meadow images, BOREAS_KERNEL_DIR
      return kExitBadInput;
    default:
      return kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ParseResult parsed = parse_command_line(argc, argv);
  if (!parsed.command_line) return parsed.exit_code;
  const CommandLine& line = *parsed.command_line;
  try {
    switch (line.command) {
      case CommandLine::Command::kInfo:
        return run_info_command(line.info);
      case CommandLine::Command::kRun:
        return run_run_command(line.run);
      case CommandLine::Command::kExportMesh:
        return run_export_command(line.export_mesh);
      case CommandLine::Command::kPreprocess:
        return run_preprocess_command(line.preprocess);
      case CommandLine::Command::kBlobTree:
        return run_blobtree_command(line.blobtree);
      case CommandLine::Command::kExportAnimation:
        return run_animation_command(line.export_animation);
    }
    return kExitOk;
  } catch (const SceneError& e) {
    return report_error(e.what(), kExitBadInput);
  } catch (const CliError& e) {
    return report_error(e.what(), e.exit_code());
  } catch (const boreas::Error& e) {
    return report_error(e.what(), exit_code_of(e.status()));
  } catch (const ImageWriteError& e) {
    return report_error(e.what(), kExitFailure);
  } catch (const MeshWriteError& e) {
    return report_error(e.what(), kExitFailure);
  } catch (const std::filesystem::filesystem_error& e) {
    return report_error(e.what(), kExitFailure);
  } catch (const std::exception& e) {
    return report_error(std::string("unexpected failure: ") + e.what(), kExitFailure);
  }
}
