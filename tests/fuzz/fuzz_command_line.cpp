// boreas fuzzing: the boreas command's arguments (parse_command_line, then the checks made
// before anything runs: for `boreas run` resolve_run_settings against the built-in scene,
// for export-mesh and blobtree their options' checks; the output path is only looked at).
// The input is split into arguments at each NUL byte or newline, after the program's name.
// What the parser prints (help, usage errors) goes nowhere; a refusal is an exit code or a
// CliError, and nothing else may escape, end the process or print.
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "cli/cli_error.h"
#include "cli/command_line.h"
#include "cli/mesh_command_checks.h"
#include "cli/run_options.h"
#include "scene/scene_loader.h"

namespace {

std::vector<std::string> arguments_of(const uint8_t* data, size_t size) {
  std::vector<std::string> args{"boreas"};
  std::string arg;
  for (size_t i = 0; i < size; ++i) {
    const char c = char(data[i]);
    if (c == '\0' || c == '\n') {
      args.push_back(arg);
      arg.clear();
    } else {
      arg += c;
    }
  }
  if (size > 0) args.push_back(arg);
  return args;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace boreas::render;
  static const Scene scene = load_default_scene();
  std::vector<std::string> args = arguments_of(data, size);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::ostream nowhere(nullptr);  // no buffer: every write is dropped
  // One definition for every input, as a parser promises each parse starts afresh (and
  // CommandLine.AReusedParserCarriesNothingOver checks); building it per input was nearly
  // all of the harness's time.
  static CommandLineParser parser;
  const ParseResult parsed = parser.parse(int(args.size()), argv.data(), nowhere, nowhere);
  if (!parsed.command_line) return 0;
  const CommandLine& line = *parsed.command_line;
  try {
    switch (line.command) {
      case CommandLine::Command::kRun:
        (void)resolve_run_settings(scene, line.run);
        break;
      case CommandLine::Command::kExportMesh:
        (void)check_export_options(line.export_mesh);
        break;
      case CommandLine::Command::kBlobTree:
        (void)check_blobtree_options(line.blobtree);
        break;
      default:
        break;
    }
  } catch (const CliError&) {
  }
  return 0;
}
