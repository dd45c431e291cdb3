// render tests: `boreas run` end to end: the files it writes, what the frames show (zero
// wind in obstacles, motion over time, stillness when calm) and how it reports progress.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command_runner.h"
#include "image/animation.h"
#include "image/color_map.h"
#include "image/image.h"
#include "png_reader.h"
#include "test_scenes.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_summary(const TempDir& dir, const std::string& out = "out") {
  return nlohmann::json::parse(read_text(dir.path() / out / "summary.json"));
}

// The 8-bit color zero wind is drawn in.
std::vector<uint8_t> zero_color() {
  Image one(1, 1, viridis(0.0f));
  return one.to_rgb8();
}

bool is_zero_color(const Png& png, int x, int y) {
  static const std::vector<uint8_t> zero = zero_color();
  return std::equal(zero.begin(), zero.end(), png.at(x, y));
}

TEST(CliRun, TinySceneWritesFramesSummaryAndContactSheet) {
  TempDir dir;
  dir.write("tiny.json", obstacle_scene());
  CommandResult r = run_boreas("run --view slice tiny.json --out out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  for (const char* name : {"frame_0000.png", "frame_0001.png", "contact_sheet.png"}) {
    EXPECT_TRUE(fs::is_regular_file(dir.path() / "out" / name)) << name;
  }
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "frame_0002.png"));

  nlohmann::json summary = read_summary(dir);
  EXPECT_EQ(summary["scene"], "tiny");
  EXPECT_EQ(summary["frames"], 2);
  EXPECT_EQ(summary["steps_per_frame"], 2);
  EXPECT_EQ(summary["steps"], 4);
  EXPECT_NEAR(summary["sim_time"].get<double>(), 0.2, 1e-5);
  ASSERT_EQ(summary["frame_stats"].size(), 2u);
  EXPECT_EQ(summary["frame_stats"][1]["file"], "frame_0001.png");
  EXPECT_NEAR(summary["frame_stats"][1]["time"].get<double>(), 0.2, 1e-5);
  EXPECT_FALSE(summary["device"]["name"].get<std::string>().empty());
  for (const char* stage : {"world_create", "wind_step", "sampling", "drawing", "image_writing",
                            "contact_sheet", "total"}) {
    EXPECT_GE(summary["timings"][stage].get<double>(), 0.0) << stage;
  }

  Png sheet = read_png((dir.path() / "out" / "contact_sheet.png").string());
  EXPECT_GT(sheet.width, 2 * 64);  // both frames, side by side
}

TEST(CliRun, FramesHaveTheRequestedSize) {
  TempDir dir;
  dir.write("tiny.json", obstacle_scene());
  CommandResult r = run_boreas("run --view slice tiny.json --out out --frames 1 --size 80x48", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Png png = read_png((dir.path() / "out" / "frame_0000.png").string());
  EXPECT_EQ(png.width, 80);
  EXPECT_EQ(png.height, 48);
  EXPECT_EQ(png.channels, 3);
}

TEST(CliRun, ObstacleShowsZeroWindAndTheRestDoesNot) {
  TempDir dir;
  dir.write("tiny.json", obstacle_scene());
  CommandResult r = run_boreas("run --view slice tiny.json --out out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Png png = read_png((dir.path() / "out" / "frame_0001.png").string());
  ASSERT_EQ(png.width, 64);
  ASSERT_EQ(png.height, 64);

  // Inside the box (pixels [24, 40), a margin kept for interpolation at its edges).
  for (int y = 27; y < 37; ++y) {
    for (int x = 27; x < 37; ++x) EXPECT_TRUE(is_zero_color(png, x, y)) << x << "," << y;
  }
  // Outside, the steady 4 m/s wind colors everything.
  int zero_outside = 0;
  int outside = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      if (x >= 20 && x < 44 && y >= 20 && y < 44) continue;
      ++outside;
      zero_outside += is_zero_color(png, x, y) ? 1 : 0;
    }
  }
  EXPECT_EQ(zero_outside, 0) << "of " << outside;
}

TEST(CliRun, FramesChangeAsTheWindMoves) {
  TempDir dir;
  dir.write("moving.json", moving_scene());
  CommandResult r = run_boreas("run --view slice moving.json --out out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Png first = read_png((dir.path() / "out" / "frame_0000.png").string());
  Png second = read_png((dir.path() / "out" / "frame_0001.png").string());
  ASSERT_EQ(first.pixels.size(), second.pixels.size());
  EXPECT_NE(first.pixels, second.pixels);
  nlohmann::json stats = read_summary(dir)["frame_stats"];
  EXPECT_NE(stats[0]["mean_speed"].get<double>(), stats[1]["mean_speed"].get<double>());
  EXPECT_GT(stats[0]["max_speed"].get<double>(), 0.0);
}

TEST(CliRun, CalmSceneFramesAreIdenticalAndStill) {
  TempDir dir;
  dir.write("calm.json", calm_scene());
  CommandResult r = run_boreas("run --view slice calm.json --out out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Png first = read_png((dir.path() / "out" / "frame_0000.png").string());
  Png second = read_png((dir.path() / "out" / "frame_0001.png").string());
  ASSERT_EQ(first.width, 64);
  EXPECT_EQ(first.pixels, second.pixels);
  EXPECT_TRUE(is_zero_color(first, 10, 50));
  nlohmann::json summary = read_summary(dir);
  for (const nlohmann::json& frame : summary["frame_stats"]) {
    EXPECT_EQ(frame["max_speed"].get<double>(), 0.0);
  }
}

TEST(CliRun, CommandLineOverridesTheScene) {
  TempDir dir;
  dir.write("tiny.json", calm_scene());
  CommandResult r = run_boreas(
      "run --view slice tiny.json --out o2 --frames 3 --steps-per-frame 1 --dt 0.1 --height 5 --size 32x16 "
      "--color-max 3 --quiet",
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
  nlohmann::json summary = read_summary(dir, "o2");
  EXPECT_EQ(summary["frames"], 3);
  EXPECT_EQ(summary["steps"], 3);
  EXPECT_NEAR(summary["dt"].get<double>(), 0.1, 1e-6);
  EXPECT_NEAR(summary["slice_height"].get<double>(), 5.0, 1e-6);
  EXPECT_EQ(summary["image_size"], nlohmann::json::array({32, 16}));
  EXPECT_NEAR(summary["color_max"].get<double>(), 3.0, 1e-6);
}

TEST(CliRun, DefaultSceneIsBuiltIn) {
  TempDir dir;
  CommandResult r = run_boreas("run --view slice --frames 1 --steps-per-frame 1 --size 32x32 --out out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json summary = read_summary(dir);
  EXPECT_EQ(summary["scene"], "default");
  EXPECT_EQ(summary["scene_source"], "built-in default");
}

TEST(CliRun, ExampleScenesRun) {
  for (const char* name : {"default.json", "gusty.json", "obstacles.json"}) {
    TempDir dir;
    std::string scene = std::string(BOREAS_SCENES_DIR) + "/" + name;
    CommandResult r =
        run_boreas("run --view slice '" + scene + "' --frames 1 --steps-per-frame 1 --size 32x32 -q", dir);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
  }
}

TEST(CliRun, ProgressStaysShortWhenNotATerminal) {
  TempDir dir;
  dir.write("calm.json", calm_scene());
  CommandResult r =
      run_boreas("run --view slice calm.json --out out --frames 60 --steps-per-frame 1 --size 16x16", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int lines = int(std::count(r.err.begin(), r.err.end(), '\n'));
  EXPECT_GE(lines, 1);
  EXPECT_LE(lines, 11) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  EXPECT_NE(r.err.find("60 frames"), std::string::npos) << r.err;
}

TEST(CliRun, RerunRemovesFramesOfALongerEarlierRun) {
  TempDir dir;
  dir.write("calm.json", calm_scene());
  ASSERT_EQ(run_boreas("run --view slice calm.json --out out --frames 3 -q", dir).exit_code, 0);
  ASSERT_EQ(run_boreas("run --view slice calm.json --out out --frames 1 -q", dir).exit_code, 0);
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "frame_0000.png"));
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "frame_0002.png"));
}

TEST(CliRun, AnimationBesideTheFramesHasOneFramePerFrame) {
  TempDir dir;
  dir.write("tiny.json", obstacle_scene());
  CommandResult r =
      run_boreas("run --view slice tiny.json --out out --frames 3 --animation gif -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json summary = read_summary(dir);
  EXPECT_EQ(summary["animation"], "animation.gif");
  EXPECT_GE(summary["timings"]["animation"].get<double>(), 0.0);
  auto in = OIIO::ImageInput::open((dir.path() / "out" / "animation.gif").string());
  ASSERT_TRUE(in) << OIIO::geterror();
  int subimages = 0;
  while (in->seek_subimage(subimages, 0)) ++subimages;
  EXPECT_EQ(subimages, 3);
  Png first = read_png((dir.path() / "out" / "frame_0000.png").string());
  in->seek_subimage(0, 0);
  EXPECT_EQ(in->spec().width, first.width);
  EXPECT_EQ(in->spec().height, first.height);

  // none writes none, and a rerun removes the earlier run's animation.
  r = run_boreas("run --view slice tiny.json --out out --frames 1 --animation none -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "animation.gif"));
  EXPECT_TRUE(read_summary(dir)["animation"].is_null());
}

TEST(CliRun, AnimationFormatsThisBuildCannotWriteAreRefusedBeforeTheRun) {
  TempDir dir;
  dir.write("tiny.json", obstacle_scene());
  CommandResult r = run_boreas("run --view slice tiny.json --out out --animation avi", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--animation: expected auto, none, gif, webp or mp4 (got 'avi')"),
            std::string::npos)
      << r.err;
  // No ffmpeg on this PATH: mp4 is refused, naming what is missing, and nothing is written.
  r = run_boreas("run --view slice tiny.json --out out --animation mp4", dir, "PATH=/nonexistent");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("needs the ffmpeg command"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  if (!can_write_animation(AnimationFormat::webp)) {
    r = run_boreas("run --view slice tiny.json --out out --animation webp", dir);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("writes only still WebP"), std::string::npos) << r.err;
  }
}

// --seed: the same seed makes the same world (the state hash of summary.json), another seed
// another one; without it the scene's own seeds hold, and the summary says which.
TEST(CliRun, ASeedMakesItsOwnReproducibleWorld) {
  TempDir dir;
  dir.write("trees.json", scene_with_trees(gusty_wind(), aspen_in_the_middle()));
  auto hash_of = [&](const std::string& args, const std::string& out) {
    CommandResult r = run_boreas("run --view slice trees.json --frames 1 -q --out " + out + " " + args, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    nlohmann::json summary = read_summary(dir, out);
    EXPECT_EQ(summary["state_hash"].get<std::string>().size(), 16u);
    return std::make_pair(summary["state_hash"].get<std::string>(), summary["seed"]);
  };
  const auto plain = hash_of("", "plain");
  const auto seven = hash_of("--seed 7", "seven");
  const auto seven_again = hash_of("--seed 7", "seven_again");
  const auto eight = hash_of("--seed 8", "eight");
  EXPECT_TRUE(plain.second.is_null());
  EXPECT_EQ(seven.second, 7);
  EXPECT_EQ(seven.first, seven_again.first);
  EXPECT_NE(seven.first, eight.first);
  EXPECT_NE(seven.first, plain.first);
  EXPECT_EQ(plain.first, hash_of("", "plain_again").first);
}

TEST(CliRun, HelpListsTheOptions) {
  TempDir dir;
  CommandResult r = run_boreas("run --help", dir);
  ASSERT_EQ(r.exit_code, 0);
  for (const char* option : {"--out", "--frames", "--steps-per-frame", "--dt", "--height", "--size",
                             "--device", "--seed", "--animation", "--quiet"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
}

}  // namespace
}  // namespace boreas::render::testing
