// render tests: `boreas run` in its main view, the 3D scene through OpenGL (run under
// xvfb-run where there is no display): frames, contact sheet and summary written; the
// interop strategy chosen, reported and overridable, with the same frames either way;
// EXR output; the window; and clear failures for a strategy the device lacks, a missing
// texture folder and a missing display.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "command_runner.h"
#include "png_reader.h"
#include "test_scenes.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

std::string windy_grove() {
  return scene_with(gusty_wind(),
                    R"("trees": [{"species": "quaking_aspen", "position": [0, 0, 0], "seed": 4}],
  )" + middle_meadow() + ",\n  " + rolling_ball(),
                    3, 64);
}

nlohmann::json summary_of(const TempDir& dir, const std::string& out = "out") {
  return nlohmann::json::parse(read_text(dir.path() / out / "summary.json"));
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(CliSceneView, FilmsTheSceneWithPerStageTimings) {
  TempDir dir;
  dir.write("grove.json", windy_grove());
  CommandResult r = run_boreas("run grove.json --size 160x96 --out out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"frame_0000.png", "frame_0001.png", "frame_0002.png", "contact_sheet.png"}) {
    EXPECT_TRUE(fs::exists(dir.path() / "out" / name)) << name;
  }
  Png first = read_png((dir.path() / "out" / "frame_0000.png").string());
  EXPECT_EQ(first.width, 160);
  EXPECT_EQ(first.height, 96);
  // Gusts move the aspen and the grass: the last frame is not the first.
  EXPECT_NE(bytes_of(dir.path() / "out" / "frame_0000.png"), bytes_of(dir.path() / "out" / "frame_0002.png"));

  nlohmann::json s = summary_of(dir);
  EXPECT_EQ(s["view"], "scene");
  const nlohmann::json& interop = s["render"]["interop"];
  EXPECT_EQ(interop["choice"], "auto");
  // The automatic choice: a CPU device (PoCL) draws in place, a GPU shares or copies.
  if (s["device"]["type"] == "CPU") {
    EXPECT_EQ(interop["strategy"], "zero_copy");
    EXPECT_EQ(interop["in_place"], true);
  }
  EXPECT_GT(interop["mb_per_frame"].get<double>(), 0.0);
  for (const char* stage : {"wind", "trees", "underbrush", "interop", "render"}) {
    EXPECT_GT(s["timings"][stage].get<double>(), 0.0) << stage;
  }
  EXPECT_NE(r.out.find("stages: wind"), std::string::npos) << r.out;
  EXPECT_EQ(s["frame_stats"].size(), 3u);
  EXPECT_GT(s["frame_stats"][2]["max_sway"].get<double>(), 0.0);
  EXPECT_GT(s["frame_stats"][2]["max_bend"].get<double>(), 0.0);
  EXPECT_FALSE(s["frame_stats"][0].contains("max_speed")) << "no slice is sampled in 3D";
}

// A tree written by `boreas export-mesh` comes back as an imported tree: drawn, swaying in
// the gusts, its preprocessing summarized and kept beside the model for the next run.
TEST(CliSceneView, ExportedTreeImportedIntoASceneSwaysAndIsSummarized) {
  TempDir dir;
  fs::create_directories(dir.path() / "models");
  CommandResult exported = run_boreas("export-mesh --species quaking_aspen --seed 4 --out models/aspen.glb -q", dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  dir.write("imported.json", scene_with(gusty_wind(), R"("mesh_trees": [{"model": "models/aspen.glb"}])", 3, 64));
  CommandResult r = run_boreas("run imported.json --size 160x96 --out out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Png first = read_png((dir.path() / "out" / "frame_0000.png").string());
  Png last = read_png((dir.path() / "out" / "frame_0002.png").string());
  // The camera frames what is drawn, so the tree fills the frame, and the gusts move it.
  EXPECT_NE(first.pixels, last.pixels) << "the imported tree did not move";
  nlohmann::json s = summary_of(dir);
  ASSERT_EQ(s["mesh_trees"].size(), 1u);
  const nlohmann::json& t = s["mesh_trees"][0];
  EXPECT_NE(t["model"].get<std::string>().find("aspen.glb"), std::string::npos);
  EXPECT_GT(t["branches"].get<int>(), 100);
  EXPECT_GT(t["leaves"].get<int>(), 1000);
  EXPECT_GT(t["levels"].get<int>(), 1);
  EXPECT_EQ(t["from_cache"], false);
  EXPECT_TRUE(fs::exists(dir.path() / "models" / "aspen.glb.boreas.glb"));
  CommandResult again = run_boreas("run imported.json --size 160x96 --frames 1 --out out2", dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(summary_of(dir, "out2")["mesh_trees"][0]["from_cache"], true);
  EXPECT_EQ(summary_of(dir, "out2")["mesh_trees"][0]["branches"], t["branches"]);
}

TEST(CliSceneView, CopyAndZeroCopyWriteTheSameFramesAndExr) {
  TempDir dir;
  dir.write("grove.json", windy_grove());
  CommandResult copy = run_boreas("run grove.json --size 96x64 --frames 2 --interop copy --exr -q --out copy", dir);
  ASSERT_EQ(copy.exit_code, 0) << copy.err;
  CommandResult zero = run_boreas("run grove.json --size 96x64 --frames 2 --interop zero_copy -q --out zero", dir);
  ASSERT_EQ(zero.exit_code, 0) << zero.err;
  EXPECT_EQ(summary_of(dir, "copy")["render"]["interop"]["strategy"], "copy");
  EXPECT_EQ(summary_of(dir, "copy")["render"]["interop"]["choice"], "requested");
  EXPECT_EQ(summary_of(dir, "zero")["render"]["interop"]["strategy"], "zero_copy");
  for (const char* name : {"frame_0000.png", "frame_0001.png"}) {
    EXPECT_EQ(bytes_of(dir.path() / "copy" / name), bytes_of(dir.path() / "zero" / name)) << name;
  }
  EXPECT_GT(fs::file_size(dir.path() / "copy" / "frame_0001.exr"), 1000u);
  EXPECT_FALSE(fs::exists(dir.path() / "zero" / "frame_0001.exr"));
}

TEST(CliSceneView, WindowRunsTheGivenFrames) {
  TempDir dir;
  dir.write("grove.json", windy_grove());
  CommandResult r = run_boreas("run grove.json --size 96x64 --window --frames 2", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("2 frames"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));  // a window writes no frames
}

// --view trails: one picture, the first frame with tip paths drawn on it. The same scene's
// first frame in the scene view is the same render (same seed, device and steps), so the
// two differ only where paths and the legend are drawn.
TEST(CliSceneView, TrailsDrawTipPathsOverTheFirstFrame) {
  TempDir dir;
  dir.write("grove.json", windy_grove());
  CommandResult r = run_boreas("run grove.json --view trails --size 320x192 --out trails", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.path() / "trails" / "trails.png"));
  for (const char* absent : {"frame_0000.png", "contact_sheet.png", "animation.gif"}) {
    EXPECT_FALSE(fs::exists(dir.path() / "trails" / absent)) << absent;
  }
  nlohmann::json s = summary_of(dir, "trails");
  EXPECT_EQ(s["view"], "trails");
  EXPECT_EQ(s["trails"]["file"], "trails.png");
  EXPECT_GT(s["trails"]["branch_tips"].get<int>(), 0);
  EXPECT_GT(s["trails"]["blade_tips"].get<int>(), 0);
  ASSERT_EQ(s["frame_stats"].size(), 3u) << "every frame stepped";
  EXPECT_TRUE(s["frame_stats"][0]["file"].is_null());
  EXPECT_GT(s["timings"]["render"].get<double>(), 0.0);

  ASSERT_EQ(
      run_boreas("run grove.json --frames 1 --size 320x192 --animation none --out one -q", dir)
          .exit_code,
      0);
  Png trails = read_png((dir.path() / "trails" / "trails.png").string());
  Png first = read_png((dir.path() / "one" / "frame_0000.png").string());
  ASSERT_EQ(trails.pixels.size(), first.pixels.size());
  // The legend takes the bottom rows; above them, only the paths and their dots.
  const int legend_rows = 20;
  int above = 0, all = 0;
  for (int y = 0; y < trails.height; ++y) {
    for (int x = 0; x < trails.width; ++x) {
      const uint8_t *a = trails.at(x, y), *b = first.at(x, y);
      bool differs = a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
      all += differs;
      above += differs && y < trails.height - legend_rows;
    }
  }
  EXPECT_GT(above, 100) << "no paths drawn";
  EXPECT_LT(all, trails.width * trails.height / 4) << "the frame itself changed";
}

TEST(CliSceneView, TrailsRefuseWhatWritesFrames) {
  TempDir dir;
  dir.write("grove.json", windy_grove());
  for (const char* extra : {"--animation gif", "--window", "--exr"}) {
    CommandResult r =
        run_boreas(std::string("run grove.json --view trails --out out ") + extra, dir);
    EXPECT_EQ(r.exit_code, 1) << extra;
    EXPECT_NE(r.err.find("trails"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out")) << extra;
  }
}

TEST(CliSceneView, FailuresNameTheCauseAndWriteNothing) {
  TempDir dir;
  dir.write("grove.json", windy_grove());
  CommandResult r = run_boreas("run grove.json --textures nowhere --out out", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--textures"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nowhere"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));

  r = run_boreas("run grove.json --out out", dir, "DISPLAY=");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("OpenGL 4.5"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--view slice"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));

  r = run_boreas("run grove.json --interop gl_sharing --out out", dir);
  if (r.exit_code == 0) {
    // A GPU driver with cl_khr_gl_sharing: the requested strategy ran.
    EXPECT_EQ(summary_of(dir)["render"]["interop"]["strategy"], "gl_sharing");
  } else {
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--interop gl_sharing"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
  }
}

}  // namespace
}  // namespace boreas::render::testing
