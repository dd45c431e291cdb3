// render tests: the scene loader on its own: shipped scenes load, absent keys take the
// library's defaults, and each kind of mistake is caught with the file and JSON path.
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "scene/scene_error.h"

namespace boreas::render {
namespace {

// The SceneError load_scene_text throws for text, or a failure when it throws none.
SceneError error_for(const std::string& text) {
  try {
    load_scene_text(text, "s.json");
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << text;
  return SceneError("", "", "");
}

TEST(SceneLoader, DefaultSceneIsBuiltInAndComplete) {
  Scene scene = load_default_scene();
  EXPECT_EQ(scene.name, "default");
  EXPECT_GE(scene.waves.size(), 2u);
  ASSERT_EQ(scene.primitives.size(), 1u);
  EXPECT_EQ(scene.primitives[0].type, BOREAS_FLOW_VORTEX);
  EXPECT_GE(scene.gusts.size(), 2u);
  EXPECT_GE(scene.obstacles.size(), 1u);
  EXPECT_EQ(scene.run.frames, 24);
  EXPECT_FALSE(scene.device.has_value());
}

TEST(SceneLoader, ShippedScenesLoad) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(BOREAS_SCENES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_NO_THROW(load_scene_file(entry.path().string())) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(SceneLoader, EmbeddedDefaultMatchesTheFile) {
  Scene file = load_scene_file(std::string(BOREAS_SCENES_DIR) + "/default.json");
  Scene embedded = load_default_scene();
  EXPECT_EQ(file.name, embedded.name);
  EXPECT_EQ(file.waves.size(), embedded.waves.size());
  EXPECT_EQ(file.obstacles.size(), embedded.obstacles.size());
}

TEST(SceneLoader, AbsentKeysTakeTheLibraryDefaults) {
  Scene scene = load_scene_text("{}", "dir/breeze.json");
  boreas_grid_def grid = boreas_default_grid_def();
  EXPECT_EQ(scene.name, "breeze");
  EXPECT_EQ(scene.grid.cell_size, grid.cell_size);
  EXPECT_EQ(scene.grid.resolution[1], grid.resolution[1]);
  EXPECT_EQ(scene.grid.response_time, grid.response_time);
  EXPECT_TRUE(scene.waves.empty());
  EXPECT_EQ(scene.run.frames, RunSettings{}.frames);
  EXPECT_EQ(scene.run.color_max, 0.0f);  // picked from the scene by the command

  Scene one =
      load_scene_text(R"({"wind": {"waves": [{"amplitude": 2}], "gusts": [{}]}})", "s.json");
  ASSERT_EQ(one.waves.size(), 1u);
  EXPECT_EQ(one.waves[0].amplitude, 2.0f);
  EXPECT_EQ(one.waves[0].wavelength, boreas_default_wave().wavelength);
  EXPECT_EQ(one.gusts[0].strength, boreas_default_gust().strength);
}

TEST(SceneLoader, ValuesAreRead) {
  Scene scene = load_scene_text(R"({
    "name": "n", "world": {"device": "cpu", "grid": {"origin": [1, 2, 3], "resolution": [4, 5, 6]}},
    "wind": {"primitives": [{"type": "sink", "position": [1, 1, 1], "radius": 3, "strength": -2}],
             "obstacles": [{"min": [0, 0, 0], "max": [1, 2, 3]}]},
    "run": {"frames": 7, "image_size": [100, 50], "slice_height": 4.5, "color_max": 9}
  })",
                                "s.json");
  EXPECT_EQ(scene.device, std::optional<std::string>("cpu"));
  EXPECT_EQ(scene.grid.origin[2], 3.0f);
  EXPECT_EQ(scene.grid.resolution[2], 6);
  EXPECT_EQ(scene.primitives[0].type, BOREAS_FLOW_SINK);
  EXPECT_EQ(scene.primitives[0].strength, -2.0f);
  EXPECT_EQ(scene.obstacles[0].max[2], 3.0f);
  EXPECT_EQ(scene.run.frames, 7);
  EXPECT_EQ(scene.run.image_width, 100);
  EXPECT_EQ(scene.run.image_height, 50);
  EXPECT_EQ(scene.run.slice_height, 4.5f);
  EXPECT_EQ(scene.run.color_max, 9.0f);
}

TEST(SceneLoader, SliceDefaultsToTwoMetersAboveTheGridFloor) {
  Scene scene = load_scene_text(R"({"world": {"grid": {"origin": [0, 10, 0]}}})", "s.json");
  EXPECT_EQ(scene.run.slice_height, 12.0f);
}

struct Mistake {
  const char* label;
  const char* json;
  const char* where;
  const char* detail;  // the start of the message after the place
};

TEST(SceneLoader, MistakesAreReportedWithTheirPath) {
  const Mistake cases[] = {
      Mistake{"Malformed", "{\n\"a\": 1,\n\"b\": }", "line 3, column 6",
              "parse error: syntax error"},
      Mistake{"Truncated", "{\"wind\": {", "line 1, column 11", "parse error:"},
      Mistake{"NegativeWavelength", R"({"wind": {"waves": [{}, {}, {"wavelength": -1}]}})",
              "/wind/waves/2/wavelength", "must be > 0 (got -1)"},
      Mistake{"HugeWavelength", R"({"wind": {"waves": [{"wavelength": 2e7}]}})",
              "/wind/waves/0/wavelength", "must be <= 10000000 (got 20000000)"},
      Mistake{"ZeroWaveDirection", R"({"wind": {"waves": [{"direction": [0, 0]}]}})",
              "/wind/waves/0/direction", "must not be the zero vector"},
      Mistake{
          "ZeroVortexAxis",
          R"({"wind": {"primitives": [{"type": "vortex", "radius": 1, "direction": [0, 0, 0]}]}})",
          "/wind/primitives/0/direction", "must not be the zero vector"},
      Mistake{"VortexWithoutRadius", R"({"wind": {"primitives": [{"type": "vortex"}]}})",
              "/wind/primitives/0/radius", "missing: a vortex needs a radius > 0"},
      Mistake{"UnknownType", R"({"wind": {"primitives": [{"type": "twister", "radius": 1}]}})",
              "/wind/primitives/0/type", "must be one of uniform, source, sink, vortex"},
      Mistake{"UnknownKeyWithSuggestion", R"({"wind": {"gusts": [{"strenght": 1}]}})",
              "/wind/gusts/0/strenght", "unknown key; did you mean \"strength\"?"},
      Mistake{"UnknownKeyListsKnownOnes", R"({"run": {"speed": 1}})", "/run/speed",
              "unknown key; known keys: color_max dt frames"},
      Mistake{"UnknownTopLevelKey", R"({"wnd": {}})", "/wnd",
              "unknown key; did you mean \"wind\"?"},
      Mistake{"StringForNumber", R"({"wind": {"waves": [{"amplitude": "3"}]}})",
              "/wind/waves/0/amplitude", "expected a number, got a string (\"3\")"},
      Mistake{"BooleanForNumber", R"({"run": {"dt": true}})", "/run/dt",
              "expected a number, got a boolean (true)"},
      Mistake{"ObjectForArray", R"({"wind": {"waves": {"amplitude": 1}}})", "/wind/waves",
              "expected an array of objects, got an object"},
      Mistake{"NumberForObject", R"({"wind": {"waves": [3]}})", "/wind/waves/0",
              "expected an object, got a number (3)"},
      Mistake{"ShortVector", R"({"world": {"grid": {"origin": [1, 2]}}})", "/world/grid/origin",
              "expected an array of 3 numbers, got an array of 2"},
      Mistake{"FractionalResolution", R"({"world": {"grid": {"resolution": [8, 4.5, 8]}}})",
              "/world/grid/resolution/1", "must be an integer (got 4.5)"},
      Mistake{"TooManyCells", R"({"world": {"grid": {"resolution": [1024, 1024, 1024]}}})",
              "/world/grid/resolution", "must have at most 2^26"},
      Mistake{"ZeroFrames", R"({"run": {"frames": 0}})", "/run/frames", "must be >= 1 (got 0)"},
      Mistake{"TinyImage", R"({"run": {"image_size": [8, 64]}})", "/run/image_size/0",
              "must be >= 16 (got 8)"},
      Mistake{"InvertedBox", R"({"wind": {"obstacles": [{"min": [0, 0, 0], "max": [1, -1, 1]}]}})",
              "/wind/obstacles/0/max/1", "must be >= min/1 = 0 (got -1)"},
      Mistake{"BoxWithoutMax", R"({"wind": {"obstacles": [{"min": [0, 0, 0]}]}})",
              "/wind/obstacles/0/max", "missing: an obstacle needs both min and max"},
      Mistake{"DeviceNotAString", R"({"world": {"device": 1}})", "/world/device",
              "expected a string or null, got a number (1)"},
      Mistake{"DuplicateKey", R"({"wind": {"waves": [{"speed": 1, "speed": 2}]}})",
              "/wind/waves/0/speed", "key given twice in the same object"},
      Mistake{"KeyWithSlash", R"({"a/b": 1})", "/a~1b", "unknown key"},
  };
  for (const Mistake& m : cases) {
    SCOPED_TRACE(m.label);
    SceneError e = error_for(m.json);
    EXPECT_EQ(e.source(), "s.json");
    EXPECT_EQ(e.where(), m.where);
    EXPECT_EQ(e.detail().rfind(m.detail, 0), 0u) << e.detail();
    EXPECT_EQ(std::string(e.what()), "s.json: " + std::string(m.where) + ": " + e.detail());
  }
}

TEST(SceneLoader, MissingFileNamesIt) {
  try {
    load_scene_file("/nonexistent/scene.json");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/nonexistent/scene.json: cannot open: No such file or directory");
  }
}

}  // namespace
}  // namespace boreas::render
