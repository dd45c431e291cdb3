// render tests: meadows in `boreas run`: drawn where they grow (and nowhere else), still when
// calm, bent around a rolling ball that shows from above and in the close-up under the
// slice; a bad meadow image stops the run naming the meadow.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "command_runner.h"
#include "image/color_map.h"
#include "image/image.h"
#include "png_reader.h"
#include "test_scenes.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 64;         // the slice, in pixels: one per meter, x and z in [-32, 32]
constexpr int kPanelHeight = 48;  // side_panel_height(64, 64)

bool is_calm_color(const Png& png, int x, int y) {
  static const std::vector<uint8_t> zero = Image(1, 1, viridis(0.0f)).to_rgb8();
  return std::equal(zero.begin(), zero.end(), png.at(x, y));
}

struct MeadowRun {
  Png first;
  Png second;
  nlohmann::json summary;
};

MeadowRun run_meadow_scene(const std::string& members) {
  TempDir dir;
  dir.write("meadow.json", scene_with("{}", members));
  CommandResult r = run_boreas("run --view slice meadow.json --out out", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  MeadowRun run;
  run.first = read_png((dir.path() / "out" / "frame_0000.png").string());
  run.second = read_png((dir.path() / "out" / "frame_0001.png").string());
  if (r.exit_code == 0) {
    run.summary = nlohmann::json::parse(read_text(dir.path() / "out" / "summary.json"));
  }
  return run;
}

// Pixels of rows [top, bottom) that differ between two frames.
int pixels_differing(const Png& a, const Png& b, int top, int bottom) {
  int differing = 0;
  for (int y = top; y < bottom; ++y) {
    for (int x = 0; x < a.width; ++x) {
      differing += !std::equal(a.at(x, y), a.at(x, y) + a.channels, b.at(x, y)) ? 1 : 0;
    }
  }
  return differing;
}

TEST(CliMeadow, MeadowIsDrawnWhereItGrowsAndStaysStillWhenCalm) {
  MeadowRun run = run_meadow_scene(middle_meadow());
  ASSERT_EQ(run.first.width, kSize);
  ASSERT_EQ(run.first.height, kSize + kPanelHeight) << "the close-up under the slice";
  // Inside the meadow (pixels [24, 40), a margin left for its ragged edge) the calm air's
  // color is mostly covered by plants, green ones.
  int covered = 0;
  int green = 0;
  int inside = 0;
  for (int y = 27; y < 37; ++y) {
    for (int x = 27; x < 37; ++x) {
      ++inside;
      if (is_calm_color(run.first, x, y)) continue;
      ++covered;
      const uint8_t* p = run.first.at(x, y);
      green += p[1] > p[0] && p[1] > p[2] ? 1 : 0;
    }
  }
  EXPECT_GT(covered, inside * 6 / 10);
  EXPECT_GT(green, covered / 2);
  // Outside it, nothing but calm air.
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      bool near = x >= 22 && x < 42 && y >= 22 && y < 42;
      if (!near) {
        EXPECT_TRUE(is_calm_color(run.first, x, y)) << x << ", " << y;
      }
    }
  }
  // The close-up holds plants: pixels that are neither sky nor ground.
  const uint8_t* sky = run.first.at(1, kSize + 1);
  const uint8_t* ground = run.first.at(1, run.first.height - 1);
  int plant = 0;
  for (int y = kSize; y < run.first.height; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const uint8_t* p = run.first.at(x, y);
      plant += std::equal(p, p + 3, sky) || std::equal(p, p + 3, ground) ? 0 : 1;
    }
  }
  EXPECT_GT(plant, 40);
  // Calm: nothing moves.
  EXPECT_EQ(pixels_differing(run.first, run.second, 0, run.first.height), 0);

  const nlohmann::json& s = run.summary;
  const nlohmann::json& u = s["underbrush"];
  ASSERT_EQ(u["meadows"].size(), 1u);
  EXPECT_EQ(u["meadows"][0]["species"], nlohmann::json::array({"meadow_grass", "clover", "daisy"}));
  EXPECT_GT(u["components"].get<int>(), 1000);
  EXPECT_EQ(u["components"], u["meadows"][0]["components"]);
  EXPECT_EQ(u["top_view_stride"], 1);
  EXPECT_TRUE(u["colliders"].empty());
  for (const nlohmann::json& frame : s["frame_stats"]) {
    EXPECT_LT(frame["max_bend"].get<double>(), 1e-3);
  }
  EXPECT_GT(s["timings"]["meadow_readback"].get<double>(), 0.0);
  EXPECT_GT(s["timings"]["meadow_drawing"].get<double>(), 0.0);
}

TEST(CliMeadow, RollingBallBendsTheMeadowFromAboveAndInTheCloseUp) {
  MeadowRun run = run_meadow_scene(middle_meadow() + ",\n  " + rolling_ball());
  ASSERT_EQ(run.first.height, kSize + kPanelHeight);
  const nlohmann::json& s = run.summary;
  ASSERT_EQ(s["underbrush"]["colliders"].size(), 1u);
  const nlohmann::json& ball = s["underbrush"]["colliders"][0];
  double end_x = -6.0 + 4.0 * s["sim_time"].get<double>();
  EXPECT_NEAR(ball["end"][0].get<double>(), end_x, 1e-4);
  EXPECT_EQ(ball["end"][1].get<double>(), 0.5);
  // The ball shows red where it is in each frame: x = -6 + 4 t m, pixel 32 + x.
  for (const Png* png : {&run.first, &run.second}) {
    int frame = png == &run.first ? 0 : 1;
    double t = s["frame_stats"][frame]["time"].get<double>();
    int x = int(std::floor(32.0 - 6.0 + 4.0 * t));
    const uint8_t* p = png->at(x, 32);
    EXPECT_GT(p[0], 150) << "frame " << frame;
    EXPECT_LT(p[1], 100) << "frame " << frame;
  }
  // The ball moved and bent the grass it met: both views change.
  EXPECT_GT(pixels_differing(run.first, run.second, 0, kSize), 10);
  EXPECT_GT(pixels_differing(run.first, run.second, kSize, run.first.height), 10);
  EXPECT_GT(s["frame_stats"][1]["max_bend"].get<double>(), 0.005) << "calm, it would be 0";
}

TEST(CliMeadow, MissingMeadowImageStopsTheRunNamingTheMeadow) {
  TempDir dir;
  fs::create_directories(dir.path() / "scenes");
  // Relative to the scene's folder, not to where boreas runs.
  dir.write("scenes/m.json",
            scene_with("{}", R"("meadows": [{"size": [2, 2], "terrain_image": "hills.png"}])"));
  CommandResult r = run_boreas("run --view slice scenes/m.json --out out", dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("boreas: error: scenes/m.json: /meadows/0/terrain_image: ", 0), 0u)
      << r.err;
  EXPECT_NE(r.err.find("scenes/hills.png"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace
}  // namespace boreas::render::testing
