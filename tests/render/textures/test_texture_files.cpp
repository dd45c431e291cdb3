// Texture generator tests: the texture set's folder: a save and load round trip within the
// files' quantization, upright images, clear errors for missing, unreadable and mis-sized
// files, and the same bytes for the same seed.
#include "textures/texture_files.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

namespace boreas::render {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system's temporary folder, removed with everything in it.
class TempFolder {
 public:
  TempFolder() {
    static int count = 0;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / ("boreas_textures_" + std::to_string(::getpid()) + "_" +
                                         info->name() + "_" + std::to_string(count++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }
  fs::path operator/(const char* name) const { return path_ / name; }

 private:
  fs::path path_;
};

// A small set, not square, so rows and columns cannot be swapped unnoticed.
TextureSet small_set(uint32_t seed = 1, int leaf_width = 96, int leaf_height = 128) {
  LeafTextureParams leaf;
  leaf.width = leaf_width;
  leaf.height = leaf_height;
  leaf.seed = seed;
  BarkTextureParams bark;
  bark.width = 48;
  bark.height = 64;
  bark.seed = seed;
  return generate_texture_set(leaf, bark);
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The message of the TextureError that loading folder throws, or "" when none is thrown.
std::string load_error(const fs::path& folder) {
  try {
    load_texture_set(folder);
  } catch (const TextureError& e) {
    return e.what();
  }
  return "";
}

void expect_near_all(const std::vector<float>& got, const std::vector<float>& want,
                     double tolerance, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  double worst = 0.0;
  size_t where = 0;
  for (size_t i = 0; i < got.size(); ++i) {
    double e = std::abs(double(got[i]) - want[i]);
    if (e > worst) worst = e, where = i;
  }
  EXPECT_LE(worst, tolerance) << what << " at value " << where;
}

const char* const kAllFiles[] = {kLeafAlbedoFile, kLeafNormalFile,       kLeafThicknessFile,
                                 kLeafHl2File,    kLeafTranslucencyFile, kBarkAlbedoFile,
                                 kBarkNormalFile};

TEST(TextureFiles, RoundTripIsExactUpToTheFilesQuantization) {
  TempFolder folder;
  TextureSet saved = small_set();
  save_texture_set(saved, folder.path());
  TextureSet loaded = load_texture_set(folder.path());
  ASSERT_EQ(loaded.leaf.width, 96);
  ASSERT_EQ(loaded.leaf.height, 128);
  ASSERT_EQ(loaded.bark.width, 48);
  ASSERT_EQ(loaded.bark.height, 64);
  // 8-bit sRGB: half a code is at most 0.0047 in linear (at 1.0, where the curve is steepest).
  expect_near_all(loaded.leaf.albedo, saved.leaf.albedo, 0.0047, "leaf albedo");
  expect_near_all(loaded.leaf.translucency, saved.leaf.translucency, 0.0047, "leaf translucency");
  expect_near_all(loaded.bark.albedo, saved.bark.albedo, 0.0047, "bark albedo");
  // 0.5 + 0.5 n in 8 bits: a component is off by at most 1/255, and renormalizing adds
  // about as much again.
  expect_near_all(loaded.leaf.normal, saved.leaf.normal, 2.5 / 255.0, "leaf normal");
  expect_near_all(loaded.bark.normal, saved.bark.normal, 2.5 / 255.0, "bark normal");
  // Half a 16-bit code of 0.1 micrometre.
  expect_near_all(loaded.leaf.thickness_mm, saved.leaf.thickness_mm, 0.5e-4 + 1e-6, "thickness");
  // 32-bit float EXR: exact.
  EXPECT_EQ(loaded.leaf.hl2, saved.leaf.hl2);
  // Alpha is stored linearly: half a code.
  for (size_t i = 0; i < saved.leaf.thickness_mm.size(); ++i) {
    ASSERT_NEAR(loaded.leaf.albedo[i * 4 + 3], saved.leaf.albedo[i * 4 + 3], 0.5 / 255.0 + 1e-6);
  }
}

TEST(TextureFiles, ImagesAreStoredUprightWithTheTipAtTheTop) {
  TempFolder folder;
  save_texture_set(small_set(), folder.path());
  auto in = OIIO::ImageInput::open((folder / kLeafAlbedoFile).string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  ASSERT_EQ(spec.nchannels, 4);
  ASSERT_EQ(spec.format, OIIO::TypeDesc::UINT8);
  std::vector<uint8_t> pixels(size_t(spec.width) * spec.height * 4);
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, pixels.data()));
  auto alpha = [&](int file_row) {
    return pixels[(size_t(file_row) * spec.width + spec.width / 2) * 4 + 3];
  };
  // v = 0.1 is the petiole, v = 0.99 is beyond the tip: in the file the petiole is near the
  // bottom row and the space beyond the tip near the top.
  int petiole_row = spec.height - 1 - int(0.1 * spec.height);
  int beyond_tip_row = spec.height - 1 - int(0.99 * spec.height);
  EXPECT_GT(alpha(petiole_row), 128);
  EXPECT_EQ(alpha(beyond_tip_row), 0);
  // The tip side is where v grows: the normal map's green channel points up the picture.
  auto hl2 = OIIO::ImageInput::open((folder / kLeafHl2File).string());
  ASSERT_TRUE(hl2);
  EXPECT_EQ(hl2->spec().format, OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(hl2->spec().nchannels, 3);
  auto thickness = OIIO::ImageInput::open((folder / kLeafThicknessFile).string());
  ASSERT_TRUE(thickness);
  EXPECT_EQ(thickness->spec().format, OIIO::TypeDesc::UINT16);
}

TEST(TextureFiles, SaveWritesExactlyTheSevenFilesAndReplacesOldOnes) {
  TempFolder folder;
  fs::path nested = folder.path() / "a" / "b";
  save_texture_set(small_set(1), nested);
  save_texture_set(small_set(2), nested);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(nested)) {
    ++files;
    bool known = false;
    for (const char* name : kAllFiles) known |= entry.path().filename() == name;
    EXPECT_TRUE(known) << entry.path();
  }
  EXPECT_EQ(files, 7);
  EXPECT_EQ(load_texture_set(nested).leaf.hl2, small_set(2).leaf.hl2);
}

TEST(TextureFiles, MissingFileIsNamed) {
  TempFolder folder;
  save_texture_set(small_set(), folder.path());
  for (const char* name : kAllFiles) {
    fs::path kept = folder.path() / "kept";
    fs::rename(folder / name, kept);
    std::string message = load_error(folder.path());
    EXPECT_NE(message.find((folder / name).string() + ": missing"), std::string::npos) << message;
    fs::rename(kept, folder / name);
  }
  EXPECT_EQ(load_error(folder.path()), "");
  EXPECT_NE(load_error(folder / "nowhere").find("leaf_albedo.png: missing"), std::string::npos);
}

TEST(TextureFiles, FileOfAnotherSizeIsNamedWithBothSizes) {
  TempFolder big, small;
  save_texture_set(small_set(1, 96, 128), big.path());
  save_texture_set(small_set(1, 64, 80), small.path());
  fs::copy_file(small / kLeafNormalFile, big / kLeafNormalFile,
                fs::copy_options::overwrite_existing);
  std::string message = load_error(big.path());
  EXPECT_NE(message.find((big / kLeafNormalFile).string() +
                         ": is 64 x 80, but leaf_albedo.png is 96 x 128"),
            std::string::npos)
      << message;
  // The bark images are checked against each other.
  save_texture_set(small_set(1, 96, 128), big.path());
  TextureSet other = small_set();
  BarkTextureParams bark;
  bark.width = 32;
  bark.height = 32;
  other.bark = generate_bark_textures(bark);
  save_texture_set(other, small.path());
  fs::copy_file(small / kBarkNormalFile, big / kBarkNormalFile,
                fs::copy_options::overwrite_existing);
  message = load_error(big.path());
  EXPECT_NE(message.find("bark_normal.png: is 32 x 32, but bark_albedo.png is 48 x 64"),
            std::string::npos)
      << message;
}

TEST(TextureFiles, WrongChannelCountAndUnreadableFilesAreNamed) {
  TempFolder folder;
  save_texture_set(small_set(), folder.path());
  fs::copy_file(folder / kLeafTranslucencyFile, folder / kLeafAlbedoFile,
                fs::copy_options::overwrite_existing);
  std::string message = load_error(folder.path());
  EXPECT_NE(message.find((folder / kLeafAlbedoFile).string() + ": has 3 channels, expected 4"),
            std::string::npos)
      << message;

  save_texture_set(small_set(), folder.path());
  std::ofstream(folder / kLeafHl2File, std::ios::trunc) << "not an image";
  message = load_error(folder.path());
  EXPECT_NE(message.find((folder / kLeafHl2File).string() + ": unreadable"), std::string::npos)
      << message;
}

TEST(TextureFiles, SaveRejectsASetWhoseArraysDisagreeWithItsSize) {
  TempFolder folder;
  TextureSet set = small_set();
  set.leaf.hl2.pop_back();
  try {
    save_texture_set(set, folder.path());
    FAIL() << "saved an inconsistent set";
  } catch (const TextureError& e) {
    EXPECT_NE(std::string(e.what()).find("leaf hl2"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(folder.path()));
}

TEST(TextureFiles, SameSeedWritesTheSameBytes) {
  TempFolder first, second, third;
  save_texture_set(small_set(7), first.path());
  save_texture_set(small_set(7), second.path());
  save_texture_set(small_set(8), third.path());
  for (const char* name : kAllFiles) {
    std::string a = bytes_of(first / name);
    ASSERT_FALSE(a.empty()) << name;
    // Compared as booleans: gtest would print the bytes.
    EXPECT_TRUE(a == bytes_of(second / name)) << name;
    EXPECT_FALSE(a == bytes_of(third / name)) << name;
  }
}

}  // namespace
}  // namespace boreas::render
