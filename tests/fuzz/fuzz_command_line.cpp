// boreas fuzzing: the boreas command's arguments (parse_command_line, then for `boreas run`
// resolve_run_settings against the built-in scene: the checks made before anything runs).
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
  const ParseResult parsed = parse_command_line(int(args.size()), argv.data(), nowhere, nowhere);
  if (!parsed.command_line || parsed.command_line->command != CommandLine::Command::kRun) return 0;
  try {
    (void)resolve_run_settings(scene, parsed.command_line->run);
  } catch (const CliError&) {
  }
  return 0;
}
