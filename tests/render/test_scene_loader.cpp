// render tests: the scene loader on its own: shipped scenes load, absent keys take the
// library's defaults, and each kind of mistake is caught with the file and JSON path.
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "scene/scene_error.h"
#include "scene_error_for.h"

namespace boreas::render {
namespace {

using testing::error_for;

TEST(SceneLoader, DefaultSceneIsBuiltInAndComplete) {
  Scene scene = load_default_scene();
  EXPECT_EQ(scene.name, "default");
  EXPECT_GE(scene.waves.size(), 2u);
  ASSERT_EQ(scene.primitives.size(), 1u);
  EXPECT_EQ(scene.primitives[0].type, BOREAS_FLOW_VORTEX);
  EXPECT_GE(scene.gusts.size(), 2u);
  EXPECT_GE(scene.obstacles.size(), 1u);
  EXPECT_EQ(scene.run.frames, 20);
  EXPECT_FALSE(scene.device.has_value());
  EXPECT_EQ(scene.run.view, ViewMode::scene) << "filmed in 3D";
  EXPECT_GT(scene.view.sun_elevation_deg, 0.0f) << "in daylight";
  EXPECT_TRUE(scene.view.shadows);
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
  EXPECT_EQ(scene.grid.wind_sampling, BOREAS_WIND_SAMPLING_EXACT);
  EXPECT_TRUE(scene.waves.empty());
  EXPECT_EQ(scene.run.frames, RunSettings{}.frames);
  EXPECT_EQ(scene.run.color_max, 0.0f);  // picked from the scene by the command

  Scene one =
      load_scene_text(R"({"wind": {"waves": [{"amplitude": 2}], "gusts": [{}]}})", "s.json");
  ASSERT_EQ(one.waves.size(), 1u);
  EXPECT_EQ(one.waves[0].amplitude, 2.0f);
  EXPECT_EQ(one.waves[0].wavelength, boreas_default_wave().wavelength);
  EXPECT_EQ(one.gusts[0].strength, boreas_default_gust_def().strength);
}

TEST(SceneLoader, ValuesAreRead) {
  Scene scene = load_scene_text(R"({
    "name": "n", "world": {"device": "cpu", "grid": {"origin": [1, 2, 3], "resolution": [4, 5, 6],
                                                   "edge_fade": 3.5, "follow_focus": true,
                                                   "wind_sampling": "interpolated"}},
    "wind": {"primitives": [{"type": "sink", "position": [1, 1, 1], "radius": 3, "strength": -2}],
             "obstacles": [{"min": [0, 0, 0], "max": [1, 2, 3]}]},
    "run": {"frames": 7, "image_size": [100, 50], "slice_height": 4.5, "color_max": 9}
  })",
                                "s.json");
  EXPECT_EQ(scene.device, std::optional<std::string>("cpu"));
  EXPECT_EQ(scene.grid.origin[2], 3.0f);
  EXPECT_EQ(scene.grid.resolution[2], 6);
  EXPECT_EQ(scene.grid.edge_fade, 3.5f);
  EXPECT_EQ(scene.grid.follow_focus, 1);
  EXPECT_EQ(scene.grid.wind_sampling, BOREAS_WIND_SAMPLING_INTERPOLATED);
  EXPECT_EQ(scene.primitives[0].type, BOREAS_FLOW_SINK);
  EXPECT_EQ(scene.primitives[0].strength, -2.0f);
  EXPECT_EQ(scene.obstacles[0].max[2], 3.0f);
  EXPECT_EQ(scene.run.frames, 7);
  EXPECT_EQ(scene.run.image_width, 100);
  EXPECT_EQ(scene.run.image_height, 50);
  EXPECT_EQ(scene.run.slice_height, 4.5f);
  EXPECT_EQ(scene.run.color_max, 9.0f);
}

TEST(SceneLoader, ViewTakesItsDefaultsWhenAbsent) {
  Scene scene = load_scene_text("{}", "s.json");
  SceneView defaults;
  EXPECT_EQ(scene.run.view, ViewMode::scene);
  EXPECT_FALSE(scene.view.eye.has_value()) << "framed by the command";
  EXPECT_FALSE(scene.view.target.has_value());
  EXPECT_EQ(scene.view.fov_deg, defaults.fov_deg);
  EXPECT_EQ(scene.view.sun_elevation_deg, defaults.sun_elevation_deg);
  EXPECT_EQ(scene.view.sun_azimuth_deg, defaults.sun_azimuth_deg);
  EXPECT_EQ(scene.view.turbidity, defaults.turbidity);
  EXPECT_EQ(scene.view.exposure, defaults.exposure);
  EXPECT_EQ(scene.view.shadows, defaults.shadows);
  EXPECT_TRUE(scene.view.thinning);

  Scene empty = load_scene_text(R"({"view": {}, "run": {}})", "s.json");
  EXPECT_EQ(empty.run.view, ViewMode::scene);
  EXPECT_FALSE(empty.view.eye.has_value());
  EXPECT_EQ(empty.view.fov_deg, defaults.fov_deg);
}

TEST(SceneLoader, ViewValuesAreRead) {
  Scene scene = load_scene_text(R"({
    "view": {"eye": [1, 2.5, -3], "target": [4, 0, 6], "fov_deg": 35, "sun_elevation_deg": -5,
             "sun_azimuth_deg": 725, "turbidity": 1.7, "exposure": 1000, "shadows": false,
             "thinning": false, "bloom": 0.5, "light_shafts": 2, "impostor_distance": 30},
    "run": {"view": "slice"}
  })",
                                "s.json");
  EXPECT_EQ(scene.run.view, ViewMode::slice);
  ASSERT_TRUE(scene.view.eye.has_value());
  ASSERT_TRUE(scene.view.target.has_value());
  EXPECT_EQ(*scene.view.eye, (std::array<float, 3>{1.0f, 2.5f, -3.0f}));
  EXPECT_EQ(*scene.view.target, (std::array<float, 3>{4.0f, 0.0f, 6.0f}));
  EXPECT_EQ(scene.view.fov_deg, 35.0f);
  EXPECT_EQ(scene.view.sun_elevation_deg, -5.0f);
  EXPECT_EQ(scene.view.sun_azimuth_deg, 725.0f) << "any finite azimuth";
  EXPECT_EQ(scene.view.turbidity, 1.7f);
  EXPECT_EQ(scene.view.exposure, 1000.0f);
  EXPECT_FALSE(scene.view.shadows);
  EXPECT_FALSE(scene.view.thinning);
  EXPECT_EQ(scene.view.bloom, 0.5f);
  EXPECT_EQ(scene.view.light_shafts, 2.0f);
  EXPECT_EQ(scene.view.impostor_distance, 30.0f);
  EXPECT_EQ(load_scene_text(R"({"run": {"view": "scene"}})", "s.json").run.view, ViewMode::scene);
  EXPECT_TRUE(load_scene_text(R"({"view": {"shadows": true}})", "s.json").view.shadows);
}

TEST(SceneLoader, ViewPositionsMayBeNullOrGivenAlone) {
  Scene scene = load_scene_text(R"({"view": {"eye": null, "target": null}})", "s.json");
  EXPECT_FALSE(scene.view.eye.has_value());
  EXPECT_FALSE(scene.view.target.has_value());

  Scene eye_only = load_scene_text(R"({"view": {"eye": [0, 2, 0]}})", "s.json");
  ASSERT_TRUE(eye_only.view.eye.has_value());
  EXPECT_FALSE(eye_only.view.target.has_value());
  Scene target_only = load_scene_text(R"({"view": {"target": [0, 2, 0]}})", "s.json");
  EXPECT_FALSE(target_only.view.eye.has_value());
  ASSERT_TRUE(target_only.view.target.has_value());
  // Just far enough apart.
  EXPECT_NO_THROW(
      load_scene_text(R"({"view": {"eye": [0, 0, 0], "target": [0, 0.0011, 0]}})", "s.json"));
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

// nlohmann stops at a NUL byte as at the end of the input: a file with one is refused there.
TEST(SceneLoader, ANulByteIsAParseErrorAtItsPlace) {
  constexpr char kText[] = "{\"run\": {}}\n\0{\"wnd\": 1}";
  SceneError e = error_for(std::string(kText, sizeof kText - 1));
  EXPECT_EQ(e.where(), "line 2, column 1");
  EXPECT_NE(e.detail().find("NUL byte"), std::string::npos) << e.detail();
}

TEST(SceneLoader, MistakesAreReportedWithTheirPath) {
  const Mistake cases[] = {
      Mistake{"Malformed", "{\n\"a\": 1,\n\"b\": }", "line 3, column 6",
              "parse error: syntax error"},
      Mistake{"Truncated", "{\"wind\": {", "line 1, column 11", "parse error:"},
      // nlohmann throws out_of_range, without a position, for a number past a double's range.
      Mistake{"NumberOverflow", "{\"run\":\n {\"dt\": 1e400}}", "line 2, column 9",
              "parse error: number overflow parsing '1e400'"},
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
      Mistake{"NegativeEdgeFade", R"({"world": {"grid": {"edge_fade": -1}}})",
              "/world/grid/edge_fade", "must be >= 0 (got -1)"},
      Mistake{"FollowNotABoolean", R"({"world": {"grid": {"follow_focus": 1}}})",
              "/world/grid/follow_focus", "expected a boolean"},
      Mistake{"UnknownWindSampling", R"({"world": {"grid": {"wind_sampling": "cubic"}}})",
              "/world/grid/wind_sampling", "must be one of exact, interpolated (got \"cubic\")"},
      Mistake{"WindSamplingNotAString", R"({"world": {"grid": {"wind_sampling": 1}}})",
              "/world/grid/wind_sampling", "expected a string, got a number (1)"},
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
      Mistake{"RunViewUnknown", R"({"run": {"view": "top"}})", "/run/view",
              "must be one of scene, slice, trails, lidar (got \"top\")"},
      Mistake{"RunViewNotAString", R"({"run": {"view": 1}})", "/run/view",
              "expected a string, got a number (1)"},
      Mistake{"ViewNotAnObject", R"({"view": "scene"})", "/view",
              "expected an object, got a string (\"scene\")"},
      Mistake{"ViewUnknownKey", R"({"view": {"sun_elevation": 30}})", "/view/sun_elevation",
              "unknown key; did you mean \"sun_elevation_deg\"?"},
      Mistake{
          "ViewUnknownKeyListsKnownOnes", R"({"view": {"camera": [0, 1, 2]}})", "/view/camera",
          "unknown key; known keys: bloom exposure eye eye_end fov_deg impostor_distance light_shafts msaa"},
      Mistake{"EyeShort", R"({"view": {"eye": [1, 2]}})", "/view/eye",
              "expected an array of 3 numbers or null, got an array of 2"},
      Mistake{"EyeString", R"({"view": {"eye": "above"}})", "/view/eye",
              "expected an array of 3 numbers or null, got a string (\"above\")"},
      Mistake{"EyeFar", R"({"view": {"eye": [0, 2e7, 0]}})", "/view/eye/1",
              "must be <= 10000000 (got 20000000)"},
      Mistake{"TargetNotANumber", R"({"view": {"target": [0, null, 0]}})", "/view/target/1",
              "expected a number, got null"},
      Mistake{"TargetFar", R"({"view": {"target": [-2e7, 0, 0]}})", "/view/target/0",
              "must be >= -10000000 (got -20000000)"},
      Mistake{"TargetOnEye", R"({"view": {"eye": [1, 2, 3], "target": [1, 2, 3.0005]}})",
              "/view/target", "must be at least 0.001 m from eye"},
      Mistake{"NarrowFov", R"({"view": {"fov_deg": 4}})", "/view/fov_deg", "must be >= 5 (got 4)"},
      Mistake{"WideFov", R"({"view": {"fov_deg": 151}})", "/view/fov_deg",
              "must be <= 150 (got 151)"},
      Mistake{"SunAboveZenith", R"({"view": {"sun_elevation_deg": 91}})", "/view/sun_elevation_deg",
              "must be <= 90 (got 91)"},
      Mistake{"SunBelowNadir", R"({"view": {"sun_elevation_deg": -90.5}})",
              "/view/sun_elevation_deg", "must be >= -90 (got -90.5)"},
      Mistake{"AzimuthNotANumber", R"({"view": {"sun_azimuth_deg": "south"}})",
              "/view/sun_azimuth_deg", "expected a number, got a string (\"south\")"},
      Mistake{"AzimuthTooLargeForAFloat", R"({"view": {"sun_azimuth_deg": 1e39}})",
              "/view/sun_azimuth_deg", "is too large for a float"},
      Mistake{"ClearerThanAir", R"({"view": {"turbidity": 1.6}})", "/view/turbidity",
              "must be >= 1.7 (got 1.6)"},
      Mistake{"Murky", R"({"view": {"turbidity": 11}})", "/view/turbidity",
              "must be <= 10 (got 11)"},
      Mistake{"ZeroExposure", R"({"view": {"exposure": 0}})", "/view/exposure",
              "must be > 0 (got 0)"},
      Mistake{"HugeExposure", R"({"view": {"exposure": 1001}})", "/view/exposure",
              "must be <= 1000 (got 1001)"},
      Mistake{"ShadowsAsString", R"({"view": {"shadows": "yes"}})", "/view/shadows",
              "expected a boolean (true or false), got a string (\"yes\")"},
      Mistake{"ShadowsAsNumber", R"({"view": {"shadows": 1}})", "/view/shadows",
              "expected a boolean (true or false), got a number (1)"},
      Mistake{"ShadowsNull", R"({"view": {"shadows": null}})", "/view/shadows",
              "expected a boolean (true or false), got null"},
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
