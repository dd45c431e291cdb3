// boreas images: the frames of a run as one animated file beside them (animation.gif,
// .webp or .mp4), so the wind is seen moving without flipping through PNGs.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"

namespace boreas::render {

enum class AnimationFormat { none, gif, webp, mp4 };

// "none", "gif", "webp", "mp4"; the extension (without a dot) for the three files.
const char* animation_format_name(AnimationFormat format);

// Whether this build can write the format: GIF and WebP when OpenImageIO's writer for them
// takes several subimages (Debian's 2.4 writes animated GIF but only still WebP), MP4 when
// an `ffmpeg` command is on PATH. Always true for none.
bool can_write_animation(AnimationFormat format);

// The first of gif, webp and mp4 this build can write, else none.
AnimationFormat best_animation_format();

// Frames wider than this are shrunk by a whole factor for GIF and WebP (a 1280 x 720 GIF
// of 24 frames takes 15 s to quantize and 12 MB; at 640 x 360, 3 s and 3.5 MB). MP4 keeps
// the frames' size: the encoder is fast and the file small at any size.
constexpr int kMaxPaletteAnimationWidth = 800;

// Writes frames as they come. Frames are 8-bit RGB, rows top to bottom, all of the size
// given at the start; the file plays at frames_per_second and loops (GIF, WebP).
// Errors throw ImageWriteError naming the file. A writer destroyed before finish()
// removes its partial file, so no half-written animation passes for a whole one.
class AnimationWriter {
 public:
  // Opens path for frame_count frames of width x height pixels. format is not none.
  AnimationWriter(const std::string& path, AnimationFormat format, int width, int height,
                  int frame_count, double frames_per_second);
  ~AnimationWriter();
  AnimationWriter(const AnimationWriter&) = delete;
  AnimationWriter& operator=(const AnimationWriter&) = delete;

  void add(const std::vector<uint8_t>& rgb);
  // Closes the file after the last frame; throws when fewer frames came than announced.
  void finish();

  // The size frames are written at (shrunk for GIF and WebP, see above).
  int written_width() const { return out_width_; }
  int written_height() const { return out_height_; }

  class Sink;  // one per format

 private:
  std::string path_;
  int width_ = 0, height_ = 0;
  int factor_ = 1;  // shrink
  int out_width_ = 0, out_height_ = 0;
  int frame_count_ = 0;
  int added_ = 0;
  bool finished_ = false;
  std::unique_ptr<Sink> sink_;
};

// rgb (width x height, 8-bit RGB) shrunk by a whole factor: each output pixel the mean of
// a factor x factor block (the right and bottom remainder is dropped).
std::vector<uint8_t> shrink_rgb8(const std::vector<uint8_t>& rgb, int width, int height,
                                 int factor);

}  // namespace boreas::render
