// render tests: the animated file beside a run's frames: GIF read back through OpenImageIO
// frame by frame against what was written, MP4 through a stand-in `ffmpeg` that records
// what it was given, and no partial file left behind by a failed or unfinished writer.
#include "image/animation.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "command_runner.h"
#include "image/png_io.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

// Frame i of a small test film: a horizontal gradient whose phase moves with i, so every
// frame differs from the last in most pixels and some stay the same.
std::vector<uint8_t> test_frame(int width, int height, int i) {
  std::vector<uint8_t> rgb(size_t(width) * size_t(height) * 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      uint8_t* p = &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
      p[0] = uint8_t((x * 255) / (width - 1));
      p[1] = uint8_t(((x + 7 * i) % width) * 255 / (width - 1));
      p[2] = uint8_t(y < height / 2 ? 40 : 200);
    }
  }
  return rgb;
}

// A GIF's frames as a viewer shows them: each subimage drawn over the ones before, its
// transparent pixels (left unchanged by the encoder) showing what was there.
std::vector<std::vector<uint8_t>> read_gif_frames(const std::string& path, int* width, int* height,
                                                  double* fps) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << OIIO::geterror();
  std::vector<std::vector<uint8_t>> frames;
  if (!in) return frames;
  std::vector<uint8_t> shown;
  for (int s = 0; in->seek_subimage(s, 0); ++s) {
    const OIIO::ImageSpec& spec = in->spec();
    *width = spec.width;
    *height = spec.height;
    int r[2] = {0, 1};
    if (spec.getattribute("FramesPerSecond", OIIO::TypeRational, r)) *fps = double(r[0]) / r[1];
    std::vector<uint8_t> rgba(size_t(spec.width) * size_t(spec.height) * 4);
    EXPECT_TRUE(in->read_image(s, 0, 0, 4, OIIO::TypeDesc::UINT8, rgba.data())) << in->geterror();
    if (shown.empty()) shown.assign(size_t(spec.width) * size_t(spec.height) * 3, 0);
    for (size_t p = 0; p < shown.size() / 3; ++p) {
      if (spec.nchannels == 4 && rgba[p * 4 + 3] == 0) continue;
      for (int c = 0; c < 3; ++c) shown[p * 3 + size_t(c)] = rgba[p * 4 + size_t(c)];
    }
    frames.push_back(shown);
  }
  return frames;
}

double mean_abs_difference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += std::fabs(double(a[i]) - double(b[i]));
  return sum / double(a.size());
}

TEST(Animation, ShrinkAveragesWholeBlocks) {
  // 5 x 3 pixels shrunk by 2: two output pixels, the last column and row dropped.
  std::vector<uint8_t> rgb(5 * 3 * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t((i * 37) % 251);
  std::vector<uint8_t> small = shrink_rgb8(rgb, 5, 3, 2);
  ASSERT_EQ(small.size(), 2u * 1u * 3u);
  for (int x = 0; x < 2; ++x) {
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          sum += rgb[(size_t(dy) * 5 + size_t(2 * x + dx)) * 3 + size_t(c)];
      EXPECT_EQ(small[size_t(x) * 3 + size_t(c)], uint8_t(std::lround(sum / 4.0))) << x << " " << c;
    }
  }
}

TEST(Animation, GifHoldsEveryFrameAtTheRunsRate) {
  if (!can_write_animation(AnimationFormat::gif))
    GTEST_SKIP() << "this OpenImageIO writes no animated GIF";
  TempDir dir;
  const std::string path = (dir.path() / "animation.gif").string();
  const int w = 96, h = 40, frames = 5;
  {
    AnimationWriter writer(path, AnimationFormat::gif, w, h, frames, 6.0);
    EXPECT_EQ(writer.written_width(), w);
    for (int i = 0; i < frames; ++i) writer.add(test_frame(w, h, i));
    writer.finish();
  }
  int rw = 0, rh = 0;
  double fps = 0.0;
  std::vector<std::vector<uint8_t>> read = read_gif_frames(path, &rw, &rh, &fps);
  ASSERT_EQ(int(read.size()), frames);
  EXPECT_EQ(rw, w);
  EXPECT_EQ(rh, h);
  // GIF keeps whole hundredths of a second per frame: 1/6 s is 17 (or 16) of them.
  EXPECT_NEAR(fps, 6.0, 0.4);
  for (int i = 0; i < frames; ++i) {
    // A 256-color palette per frame: a few levels of error on average, not a wrong frame
    // (the next frame's gradient is shifted by 7 pixels, about 19 levels on average).
    EXPECT_LT(mean_abs_difference(read[size_t(i)], test_frame(w, h, i)), 4.0) << "frame " << i;
    if (i > 0) {
      EXPECT_GT(mean_abs_difference(read[size_t(i)], test_frame(w, h, i - 1)), 8.0) << i;
    }
  }
}

TEST(Animation, WideFramesAreShrunkForGif) {
  if (!can_write_animation(AnimationFormat::gif))
    GTEST_SKIP() << "this OpenImageIO writes no animated GIF";
  TempDir dir;
  const std::string path = (dir.path() / "animation.gif").string();
  const int w = 2 * kMaxPaletteAnimationWidth + 2, h = 8;
  AnimationWriter writer(path, AnimationFormat::gif, w, h, 1, 10.0);
  EXPECT_EQ(writer.written_width(), w / 3);
  EXPECT_EQ(writer.written_height(), h / 3);
  EXPECT_LE(writer.written_width(), kMaxPaletteAnimationWidth);
  writer.add(test_frame(w, h, 0));
  writer.finish();
  int rw = 0, rh = 0;
  double fps = 0.0;
  EXPECT_EQ(read_gif_frames(path, &rw, &rh, &fps).size(), 1u);
  EXPECT_EQ(rw, w / 3);
}

TEST(Animation, UnfinishedOrShortAnimationLeavesNoFile) {
  if (!can_write_animation(AnimationFormat::gif))
    GTEST_SKIP() << "this OpenImageIO writes no animated GIF";
  TempDir dir;
  const std::string path = (dir.path() / "animation.gif").string();
  {
    AnimationWriter writer(path, AnimationFormat::gif, 16, 8, 3, 10.0);
    writer.add(test_frame(16, 8, 0));
    try {
      writer.finish();
      ADD_FAILURE() << "finish() accepted 1 of 3 frames";
    } catch (const ImageWriteError& e) {
      EXPECT_NE(std::string(e.what()).find("1 of 3 frames"), std::string::npos) << e.what();
    }
    EXPECT_THROW(writer.add(test_frame(15, 8, 0)), ImageWriteError);  // wrong size
  }
  EXPECT_FALSE(fs::exists(path));
}

// A stand-in for ffmpeg on PATH: records its arguments and copies its standard input to
// the last argument (the output file), or fails with a message when told to.
class FakeFfmpeg {
 public:
  explicit FakeFfmpeg(const TempDir& dir, bool fail = false) : bin_(dir.path() / "bin") {
    fs::create_directories(bin_);
    std::ofstream script(bin_ / "ffmpeg");
    script << "#!/bin/sh\n"
           << "for a in \"$@\"; do echo \"$a\"; done > \"" << (dir.path() / "args.txt").string()
           << "\"\n";
    if (fail) {
      script << "echo 'Unknown encoder' >&2\nexit 1\n";
    } else {
      script << "for last in \"$@\"; do :; done\ncat > \"$last\"\n";
    }
    script.close();
    ::chmod((bin_ / "ffmpeg").c_str(), 0755);
    const char* path = std::getenv("PATH");
    old_path_ = path ? path : "";
    ::setenv("PATH", (bin_.string() + ":" + old_path_).c_str(), 1);
  }
  ~FakeFfmpeg() { ::setenv("PATH", old_path_.c_str(), 1); }

 private:
  fs::path bin_;
  std::string old_path_;
};

TEST(Animation, Mp4FeedsFfmpegRawFramesAtTheRunsRate) {
  TempDir dir;
  FakeFfmpeg ffmpeg(dir);
  ASSERT_TRUE(can_write_animation(AnimationFormat::mp4));
  const std::string path = (dir.path() / "animation.mp4").string();
  // MP4 keeps the frames' size, however wide.
  const int w = kMaxPaletteAnimationWidth + 33, h = 7, frames = 3;
  AnimationWriter writer(path, AnimationFormat::mp4, w, h, frames, 6.0);
  EXPECT_EQ(writer.written_width(), w);
  std::vector<uint8_t> all;
  for (int i = 0; i < frames; ++i) {
    std::vector<uint8_t> f = test_frame(w, h, i);
    writer.add(f);
    all.insert(all.end(), f.begin(), f.end());
  }
  writer.finish();
  EXPECT_EQ(read_text(path), std::string(all.begin(), all.end()));
  std::string args = read_text(dir.path() / "args.txt");
  EXPECT_NE(args.find("-video_size\n" + std::to_string(w) + "x" + std::to_string(h) + "\n"),
            std::string::npos)
      << args;
  EXPECT_NE(args.find("-framerate\n6000/1000\n"), std::string::npos) << args;
  EXPECT_NE(args.find("-pixel_format\nrgb24\n"), std::string::npos) << args;
  EXPECT_FALSE(fs::exists(path + ".log"));
}

TEST(Animation, FailingFfmpegIsAnErrorNamingTheFileAndLeavesNothing) {
  TempDir dir;
  FakeFfmpeg ffmpeg(dir, true);
  const std::string path = (dir.path() / "animation.mp4").string();
  try {
    AnimationWriter writer(path, AnimationFormat::mp4, 8, 4, 40, 6.0);
    // The stand-in exits at once: writing or closing reports it, whichever comes first.
    for (int i = 0; i < 40; ++i) writer.add(test_frame(8, 4, i));
    writer.finish();
    ADD_FAILURE() << "a failing ffmpeg went unnoticed";
  } catch (const ImageWriteError& e) {
    std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("Unknown encoder"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".log"));
}

// Where ffmpeg is installed (it is optional; CI has none), the file it makes is decoded
// back to raw frames by ffmpeg itself: every frame, close to what was sent (4:2:0 chroma
// and lossy coding: a few levels on a smooth gradient).
TEST(Animation, Mp4FromTheRealFfmpegDecodesToTheFrames) {
  if (!can_write_animation(AnimationFormat::mp4)) GTEST_SKIP() << "no ffmpeg on PATH";
  TempDir dir;
  const fs::path path = dir.path() / "animation.mp4", raw = dir.path() / "decoded.rgb";
  const int w = 96, h = 64, frames = 4;
  AnimationWriter writer(path.string(), AnimationFormat::mp4, w, h, frames, 6.0);
  for (int i = 0; i < frames; ++i) writer.add(test_frame(w, h, i));
  writer.finish();
  std::string decode = "ffmpeg -v error -i '" + path.string() + "' -f rawvideo -pix_fmt rgb24 '" +
                       raw.string() + "'";
  ASSERT_EQ(std::system(decode.c_str()), 0) << decode;
  std::string bytes = read_text(raw);
  const size_t frame_bytes = size_t(w) * size_t(h) * 3;
  ASSERT_EQ(bytes.size(), frames * frame_bytes);
  for (int i = 0; i < frames; ++i) {
    std::vector<uint8_t> frame(bytes.begin() + long(i * frame_bytes),
                               bytes.begin() + long((i + 1) * frame_bytes));
    EXPECT_LT(mean_abs_difference(frame, test_frame(w, h, i)), 8.0) << "frame " << i;
  }
}

TEST(Animation, Mp4NeedsFfmpegOnPath) {
  const char* path = std::getenv("PATH");
  std::string old = path ? path : "";
  ::setenv("PATH", "/nonexistent", 1);
  EXPECT_FALSE(can_write_animation(AnimationFormat::mp4));
  ::setenv("PATH", old.c_str(), 1);
}

}  // namespace
}  // namespace boreas::render::testing
