// render tests: every way `boreas run` can be handed bad input ends in one line
// "boreas: error: ..." naming the file and where in it, a non-zero exit, and no output.
#include <gtest/gtest.h>

#include <algorithm>

#include "command_runner.h"
#include "test_scenes.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

struct BadScene {
  const char* label;
  std::string json;
  std::string expected;  // part of stderr: file name and JSON path or line
};

// One case per kind of mistake; test_scene_loader.cpp covers the rest of the messages.
TEST(CliErrors, BadScenesFailNamingTheFileAndThePlace) {
  const BadScene cases[] = {
      {"malformed JSON", "{\n  \"name\": \"x\",\n  \"run\": {\"frames\": 2,}\n}\n",
       "scene.json: line 3, column 23: parse error:"},
      {"negative wavelength", scene_json(R"({"waves": [{}, {}, {"wavelength": -1}]})"),
       "scene.json: /wind/waves/2/wavelength: must be > 0 (got -1)"},
      {"zero direction", scene_json(R"({"gusts": [{"direction": [0, 0, 0]}]})"),
       "scene.json: /wind/gusts/0/direction: must not be the zero vector"},
      {"unknown key", scene_json(R"({"waves": [{"wavelenght": 10}]})"),
       "scene.json: /wind/waves/0/wavelenght: unknown key; did you mean \"wavelength\"?"},
      {"wrong type", scene_json(R"({"waves": [{"amplitude": "3"}]})"),
       "scene.json: /wind/waves/0/amplitude: expected a number, got a string (\"3\")"},
  };
  for (const BadScene& c : cases) {
    SCOPED_TRACE(c.label);
    TempDir dir;
    dir.write("scene.json", c.json);
    CommandResult r = run_boreas("run --view slice scene.json --out out", dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(r.err.rfind("boreas: error: scene.json: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    // Nothing was started: no world, no output folder.
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
  }
}

TEST(CliErrors, MissingSceneFile) {
  TempDir dir;
  CommandResult r = run_boreas("run --view slice missing.json", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "boreas: error: missing.json: cannot open: No such file or directory\n");
}

TEST(CliErrors, BadOptionsNameTheOption) {
  TempDir dir;
  struct Case {
    const char* args;
    const char* expected;
  };
  for (const Case& c :
       {Case{"run --frames 0", "--frames: must be in [1, 100000] (got 0)"},
        Case{"run --size 12", "--size: expected WIDTHxHEIGHT"},
        Case{"run --dt -1", "--dt: must be in (0, 3600] (got -1)"},
        Case{"run --height 40", "--height: must be in [0, 32] m"},
        Case{"run --view top", "--view: expected scene, slice, trails or lidar (got 'top')"},
        Case{"run --interop fast",
             "--interop: expected auto, gl_sharing, zero_copy or copy (got 'fast')"},
        Case{"run --view slice --window", "--window: only with the 3D view"},
        Case{"run --view slice --exr", "--exr: only with the 3D view"},
        Case{"run --no-such-option", "--no-such-option"}, Case{"fly", "unknown command 'fly'"},
        Case{"", "a command is required: info, run, export-mesh, export-animation, preprocess or "
                      "blobtree"}}) {
    CommandResult r = run_boreas(c.args, dir);
    EXPECT_EQ(r.exit_code, 1) << c.args;
    EXPECT_EQ(r.err.rfind("boreas: error: ", 0), 0u) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << ": " << r.err;
  }
}

TEST(CliErrors, UnknownDeviceFailsWithExitCode2BeforeWritingAnything) {
  TempDir dir;
  dir.write("calm.json", calm_scene());
  CommandResult r = run_boreas("run --view slice calm.json --out out", dir, "BOREAS_DEVICE=nonexistent");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("boreas: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("'nonexistent' matches no OpenCL device"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));

  r = run_boreas("run --view slice calm.json --out out --device nonexistent", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'nonexistent' matches no OpenCL device"), std::string::npos) << r.err;
}

TEST(CliErrors, UnwritableOutputFolderFailsWithExitCode3) {
  TempDir dir;
  dir.write("calm.json", calm_scene());
  dir.write("file", "not a folder");
  CommandResult r = run_boreas("run --view slice calm.json --out file/out", dir);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("boreas: error: file/out: cannot create the output folder"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace boreas::render::testing
