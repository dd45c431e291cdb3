// render tests: the command line parsed in process (parse_command_line): help, version and
// usage errors go to the streams the caller gives, never straight to stdout or stderr, and
// the process is never ended (the fuzzer, tests/fuzz/fuzz_command_line.cpp, relies on both).
#include "cli/command_line.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_error.h"
#include "cli/mesh_command_checks.h"

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
      {}, {"fly"}, {"run", "--frames", "x"}, {"export-mesh", "--out", "t.obj", "--seed", "-1"},
      {"run", "--seed", "-1"}, {"run", "--seed", "18446744073709551616"}, {"run", "--seed", "1.5"}};
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
  EXPECT_FALSE(p.result.command_line->run.seed);
  EXPECT_EQ(p.out + p.err + p.stdout_text, "");
}

TEST(CommandLine, ARunSeedTakesTheWholeRangeOf64Bits) {
  Parsed p = parse({"run", "--seed", "18446744073709551615"});
  ASSERT_TRUE(p.result.command_line);
  EXPECT_EQ(p.result.command_line->run.seed, uint64_t(18446744073709551615ull));
  Parsed zero = parse({"run", "--seed", "0"});
  ASSERT_TRUE(zero.result.command_line);
  EXPECT_EQ(zero.result.command_line->run.seed, uint64_t(0));
}

// One parser for many command lines (the fuzzer's way) gives what a fresh parser gives
// each time: no option, flag, positional or subcommand carries over to the next parse.
TEST(CommandLine, AReusedParserCarriesNothingOver) {
  const std::vector<std::vector<std::string>> lines = {
      {"run", "scene.json", "--frames", "5", "--exr", "--size", "64x48", "--view", "slice"},
      {"run"},
      {"blobtree", "--out", "t.ply", "--cut", "3:0.5", "--cut", "4:0.2", "--no-offsets"},
      {"blobtree", "--out", "u.obj"},
      {"export-mesh", "--out", "a.glb", "--seed", "9", "--time", "2"},
      {"export-mesh", "--out", "b.glb"},
      {"run", "--frames", "x"},
      {"info", "--device", "cpu"},
      {"info"},
      {"nonsense"},
      {"run", "--quiet"},
      {"run", "--seed", "12"},
      {"run"},
  };
  CommandLineParser reused;
  for (const std::vector<std::string>& line : lines) {
    std::vector<std::string> args = line;
    args.insert(args.begin(), "boreas");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::ostringstream out, err;
    const ParseResult again = reused.parse(int(args.size()), argv.data(), out, err);
    const Parsed fresh = parse(line);
    std::string joined;
    for (const std::string& a : line) joined += a + " ";
    SCOPED_TRACE(joined);
    EXPECT_EQ(again.exit_code, fresh.result.exit_code);
    EXPECT_EQ(err.str(), fresh.err);
    ASSERT_EQ(bool(again.command_line), bool(fresh.result.command_line));
    if (!again.command_line) continue;
    const CommandLine& a = *again.command_line;
    const CommandLine& b = *fresh.result.command_line;
    EXPECT_EQ(a.command, b.command);
    EXPECT_EQ(a.run.scene_path, b.run.scene_path);
    EXPECT_EQ(a.run.frames, b.run.frames);
    EXPECT_EQ(a.run.size, b.run.size);
    EXPECT_EQ(a.run.view, b.run.view);
    EXPECT_EQ(a.run.exr, b.run.exr);
    EXPECT_EQ(a.run.quiet, b.run.quiet);
    EXPECT_EQ(a.run.seed, b.run.seed);
    EXPECT_EQ(a.blobtree.out, b.blobtree.out);
    EXPECT_EQ(a.blobtree.cuts, b.blobtree.cuts);
    EXPECT_EQ(a.blobtree.no_offsets, b.blobtree.no_offsets);
    EXPECT_EQ(a.export_mesh.out, b.export_mesh.out);
    EXPECT_EQ(a.export_mesh.seed, b.export_mesh.seed);
    EXPECT_EQ(a.export_mesh.time, b.export_mesh.time);
    EXPECT_EQ(a.info.device, b.info.device);
  }
}

// export-mesh's and blobtree's checks, made before a world exists (and fuzzed): what they
// take, and that each refusal is a CliError naming the option.
TEST(CommandLine, BlobTreeCutsAndScarsAreReadOrRefusedByName) {
  BlobTreeCommandOptions o;
  o.out = "tree.glb";
  o.cuts = {"12:0.4"};
  o.scars = {"7:0.1", "3:0.2:0.75"};
  BlobTreeInputs in = check_blobtree_options(o);
  EXPECT_EQ(in.format, MeshFormat::kGlb);
  ASSERT_EQ(in.cuts.size(), 1u);
  EXPECT_EQ(in.cuts[0].branch, 12);
  EXPECT_FLOAT_EQ(in.cuts[0].at, 0.4f);
  ASSERT_EQ(in.scars.size(), 2u);
  EXPECT_EQ(in.scars[0].branch, 7);
  EXPECT_FLOAT_EQ(in.scars[0].depth, 0.5f) << "the documented default depth";
  EXPECT_FLOAT_EQ(in.scars[1].depth, 0.75f);
  auto refused = [&](BlobTreeCommandOptions bad, const std::string& option) {
    try {
      check_blobtree_options(bad);
      ADD_FAILURE() << option << " was accepted";
    } catch (const CliError& e) {
      EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
      EXPECT_EQ(e.exit_code(), kExitBadInput);
    }
  };
  for (const char* cut : {"x:0.4", "-1:0.4", "1.5:0.4", "1", "1:0.4:2", "1:nan", "1:inf", ":"}) {
    BlobTreeCommandOptions bad = o;
    bad.cuts = {cut};
    refused(bad, "--cut");
  }
  for (const char* scar : {"2", "2:0.1:0.5:1", "2e10:0.1", "2:x"}) {
    BlobTreeCommandOptions bad = o;
    bad.scars = {scar};
    refused(bad, "--scar");
  }
  BlobTreeCommandOptions bad = o;
  bad.junctions = "smooth";
  refused(bad, "--junctions");
  bad = o;
  bad.scale = std::numeric_limits<double>::quiet_NaN();
  refused(bad, "--scale");
  bad = o;
  bad.out = "tree.stl";
  refused(bad, "--out");
}

TEST(CommandLine, ExportMeshNumbersAreCheckedByName) {
  ExportOptions o;
  o.out = "tree.ply";
  EXPECT_EQ(check_export_options(o), MeshFormat::kPly);
  o.time = kMaxExportTime;
  EXPECT_EQ(check_export_options(o), MeshFormat::kPly);
  for (double t : {-1.0, kMaxExportTime * 2.0, std::nan("")}) {
    ExportOptions bad = o;
    bad.time = t;
    EXPECT_THROW(check_export_options(bad), CliError) << t;
  }
  for (double s : {0.0, -2.0, 1001.0, std::numeric_limits<double>::infinity()}) {
    ExportOptions bad = o;
    bad.scale = s;
    try {
      check_export_options(bad);
      ADD_FAILURE() << "scale " << s << " was accepted";
    } catch (const CliError& e) {
      EXPECT_NE(std::string(e.what()).find("--scale"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace boreas::render
