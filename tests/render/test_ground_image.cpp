// render tests: a meadow's terrain and nutrient images, read through OpenImageIO into the
// pixel arrays the library takes (scene/ground_image.h): values, orientation, the errors
// that name the file, and a scene whose terrain image the planted meadow stands on.
#include "scene/ground_image.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "command_runner.h"
#include "scene/scene_loader.h"
#include "scene/scene_world.h"

namespace boreas::render {
namespace {

using testing::TempDir;

void write_image(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type,
                 const std::vector<float>& pixels) {
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out) << OIIO::geterror();
  OIIO::ImageSpec spec(width, height, channels, type);
  ASSERT_TRUE(out->open(path, spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

// A 16-bit ramp comes back as 0..1 floats, row 0 the file's top row, channel fastest.
TEST(GroundImage, SixteenBitRampReadsAsUnitFloatsTopRowFirst) {
  TempDir dir;
  const std::string path = (dir.path() / "ramp.png").string();
  const int w = 5, h = 3;
  std::vector<float> pixels;
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) pixels.push_back(0.5f * (col / 4.0f + row / 2.0f));
  }
  write_image(path, w, h, 1, OIIO::TypeDesc::UINT16, pixels);
  const GroundImage image = read_ground_image(path);
  ASSERT_EQ(image.width, w);
  ASSERT_EQ(image.height, h);
  ASSERT_EQ(image.channels, 1);
  ASSERT_EQ(image.pixels.size(), pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) EXPECT_NEAR(image.pixels[i], pixels[i], 1.0 / 65535);
  const boreas_image view = image.view();
  EXPECT_EQ(view.pixels, image.pixels.data());
  EXPECT_EQ(view.width * view.height * view.channels, int(pixels.size()));

  // RGB keeps its channels in order.
  const std::string rgb = (dir.path() / "rgb.png").string();
  const std::vector<float> two = {0.0f, 0.2f, 0.4f, 0.6f, 0.8f, 1.0f};  // multiples of 51/255
  write_image(rgb, 2, 1, 3, OIIO::TypeDesc::UINT8, two);
  const GroundImage color = read_ground_image(rgb);
  ASSERT_EQ(color.channels, 3);
  for (size_t i = 0; i < two.size(); ++i) EXPECT_NEAR(color.pixels[i], two[i], 1e-6);
}

TEST(GroundImage, MissingOrNonImageFileIsIoErrorNamingThePath) {
  TempDir dir;
  const std::string missing = (dir.path() / "no_such_height.png").string();
  const std::string text = (dir.path() / "notes.png").string();
  std::ofstream(text) << "this is a text file, not a PNG\n";
  for (const std::string& path : {missing, text}) {
    try {
      (void)read_ground_image(path);
      ADD_FAILURE() << path << " was read";
    } catch (const boreas::Error& e) {
      EXPECT_EQ(e.status(), BOREAS_ERROR_IO);
      EXPECT_NE(std::string(e.what()).find("cannot read image '" + path + "'"), std::string::npos)
          << e.what();
    }
  }
}

// The scene's terrain image is the ground the meadow is planted on: a ramp rising along x
// by terrain_relief.
TEST(GroundImage, SceneMeadowStandsOnItsTerrainImage) {
  TempDir dir;
  write_image((dir.path() / "ramp.png").string(), 2, 2, 1, OIIO::TypeDesc::UINT8,
              {0.0f, 1.0f, 0.0f, 1.0f});
  const std::string text = R"({
    "world": {"grid": {"origin": [-4, 0, -4], "cell_size": 1, "resolution": [8, 4, 8]}},
    "meadows": [{"species": [{"species": "meadow_grass"}], "size": [4, 4], "density": 60,
                 "terrain_image": ")" +
                           (dir.path() / "ramp.png").string() + R"(", "terrain_relief": 2}]
  })";
  const Scene scene = load_scene_text(text, (dir.path() / "s.json").string());
  SceneIds ids;
  boreas::World world = make_world(scene, std::nullopt, &ids);
  ASSERT_EQ(ids.meadows.size(), 1u);
  int n = 0;
  ASSERT_EQ(boreas_meadow_get_components(world.handle(), ids.meadows[0], nullptr, 0, &n),
            BOREAS_OK);
  std::vector<boreas_component> c(static_cast<size_t>(n));
  ASSERT_EQ(boreas_meadow_get_components(world.handle(), ids.meadows[0], c.data(), n, &n),
            BOREAS_OK);
  // Each base within the ramp's slope (0.5) times a plant's spread (a few cm) of it.
  int checked = 0;
  for (const boreas_component& x : c) {
    if (x.parent >= 0) continue;
    EXPECT_NEAR(x.base[1], 2.0 * (x.base[0] + 2.0) / 4.0, 0.03) << "at x " << x.base[0];
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

}  // namespace
}  // namespace boreas::render
