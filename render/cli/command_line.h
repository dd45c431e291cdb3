// boreas command: the command line, parsed with CLI11 into the options of one subcommand.
// Options not given stay unset, so the scene's own values apply.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "cli/animation_command.h"
#include "cli/blobtree_command.h"
#include "cli/export_command.h"
#include "cli/info_command.h"
#include "cli/preprocess_command.h"
#include "cli/run_options.h"

namespace boreas::render {

struct CommandLine {
  enum class Command { kInfo, kRun, kExportMesh, kPreprocess, kBlobTree, kExportAnimation };
  Command command = Command::kRun;
  InfoOptions info;
  RunOptions run;
  ExportOptions export_mesh;
  PreprocessOptions preprocess;
  BlobTreeCommandOptions blobtree;
  AnimationOptions export_animation;
};

// The parsed command line, or the exit code to stop with when there is nothing to run:
// 0 after --help or --version (printed on out), 1 after a usage error (reported on err as
// "boreas: error: ..."). Nothing else is printed, and the process is never ended here.
struct ParseResult {
  std::optional<CommandLine> command_line;
  int exit_code = 0;
};

// Parses command lines with one CLI11 definition, built when the parser is made: building
// it (five commands, about fifty options) is nearly all of a parse's cost, which matters
// to a caller that parses many (the fuzzer). Every parse starts from the defaults, so one
// leaves nothing for the next. One parse at a time per parser.
class CommandLineParser {
 public:
  CommandLineParser();
  ~CommandLineParser();
  CommandLineParser(const CommandLineParser&) = delete;
  CommandLineParser& operator=(const CommandLineParser&) = delete;
  ParseResult parse(int argc, char** argv, std::ostream& out, std::ostream& err);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One parse with a parser made for it.
ParseResult parse_command_line(int argc, char** argv, std::ostream& out, std::ostream& err);
// The same on stdout and stderr, as the command runs.
ParseResult parse_command_line(int argc, char** argv);

// "42" -> 42: a seed of run, export-mesh, preprocess or blobtree; false unless text is a whole number in [0, 2^64 - 1].
bool parse_seed(const std::string& text, uint64_t& seed);

}  // namespace boreas::render
