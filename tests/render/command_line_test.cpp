// render tests: the command line parsed in process (parse_command_line): help, version and
// usage errors go to the streams the caller gives, never straight to stdout or stderr, and
// the process is never ended (the fuzzer, tests/fuzz/fuzz_command_line.cpp, relies on both).
#include "cli/command_line.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace boreas::render {
namespace {

struct Parsed {
  ParseResult result;
  std::string out, err, stdout_text;
};

Parsed parse(std::vector<std::string> args) {
  args.insert(args.begin(), "boreas");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::ostringstream out, err;
  Parsed p;
  ::testing::internal::CaptureStdout();
  p.result = parse_command_line(int(args.size()), argv.data(), out, err);
  p.stdout_text = ::testing::internal::GetCapturedStdout();
  p.out = out.str();
  p.err = err.str();
  return p;
}

TEST(CommandLine, HelpAndVersionGoToTheOutStreamGiven) {
  for (const char* flag : {"--help", "--version"}) {
    SCOPED_TRACE(flag);
    Parsed p = parse({flag});
    EXPECT_FALSE(p.result.command_line);
    EXPECT_EQ(p.result.exit_code, 0);
    EXPECT_NE(p.out.find("boreas"), std::string::npos) << p.out;
    EXPECT_EQ(p.err, "");
    EXPECT_EQ(p.stdout_text, "");
  }
}

TEST(CommandLine, UsageErrorsGoToTheErrStreamGiven) {
  const std::vector<std::vector<std::string>> cases = {
      {}, {"fly"}, {"run", "--frames", "x"}, {"export-mesh", "--out", "t.obj", "--seed", "-1"}};
  for (const auto& args : cases) {
    Parsed p = parse(args);
    EXPECT_FALSE(p.result.command_line);
    EXPECT_EQ(p.result.exit_code, 1);
    EXPECT_EQ(p.err.rfind("boreas: error: ", 0), 0u) << p.err;
    EXPECT_EQ(p.out, "");
    EXPECT_EQ(p.stdout_text, "");
  }
}

TEST(CommandLine, ARunIsParsedWithoutPrinting) {
  Parsed p = parse({"run", "--frames", "5", "--size", "64x48", "--view", "slice"});
  ASSERT_TRUE(p.result.command_line);
  EXPECT_EQ(p.result.command_line->command, CommandLine::Command::kRun);
  EXPECT_EQ(p.result.command_line->run.frames, 5);
  EXPECT_EQ(p.result.command_line->run.size, "64x48");
  EXPECT_EQ(p.out + p.err + p.stdout_text, "");
}

}  // namespace
}  // namespace boreas::render
