// boreas images: animated GIF and WebP through OpenImageIO's multi-subimage writers, MP4
// through an `ffmpeg` process fed raw frames on its standard input.
#include "image/animation.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "image/png_io.h"

extern char** environ;

namespace boreas::render {

namespace {

bool oiio_writes_movie(const char* extension) {
  auto out = OIIO::ImageOutput::create(std::string("probe.") + extension);
  return out && out->supports("multiimage") && out->supports("appendsubimage");
}

bool ffmpeg_on_path() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    std::string file = (dir.empty() ? std::string(".") : dir) + "/ffmpeg";
    if (::access(file.c_str(), X_OK) == 0) return true;
  }
  return false;
}

}  // namespace

class AnimationWriter::Sink {
 public:
  virtual ~Sink() = default;
  virtual void write(const std::vector<uint8_t>& rgb) = 0;
  virtual void close() = 0;
};

namespace {

// GIF or WebP: every subimage announced at open (the writers need the count first), then
// appended one by one.
class OiioSink final : public AnimationWriter::Sink {
 public:
  OiioSink(const std::string& path, int width, int height, int frames, double fps) : path_(path) {
    out_ = OIIO::ImageOutput::create(path);
    if (!out_) throw ImageWriteError(path + ": cannot write animations: " + OIIO::geterror());
    spec_ = OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8);
    // The rate as a rational in thousandths: GIF keeps whole hundredths of a second per
    // frame, so finer is lost anyway.
    int rate[2] = {int(std::lround(fps * 1000.0)), 1000};
    spec_.attribute("FramesPerSecond", OIIO::TypeRational, rate);
    spec_.attribute("oiio:Movie", 1);
    spec_.attribute("oiio:LoopCount", 0);  // forever
    std::vector<OIIO::ImageSpec> specs(size_t(frames), spec_);
    if (!out_->open(path, frames, specs.data()))
      throw ImageWriteError(path + ": " + out_->geterror());
  }
  ~OiioSink() override {
    if (out_ && !closed_) out_->close();
  }
  void write(const std::vector<uint8_t>& rgb) override {
    if (written_ > 0 && !out_->open(path_, spec_, OIIO::ImageOutput::AppendSubimage)) {
      throw ImageWriteError(path_ + ": " + out_->geterror());
    }
    if (!out_->write_image(OIIO::TypeDesc::UINT8, rgb.data())) {
      throw ImageWriteError(path_ + ": " + out_->geterror());
    }
    ++written_;
  }
  void close() override {
    closed_ = true;
    if (!out_->close()) throw ImageWriteError(path_ + ": " + out_->geterror());
  }

 private:
  std::string path_;
  std::unique_ptr<OIIO::ImageOutput> out_;
  OIIO::ImageSpec spec_;
  int written_ = 0;
  bool closed_ = false;
};

// MP4: `ffmpeg` reads raw RGB frames from a pipe and encodes them (its default encoder for
// .mp4, 4:2:0 chroma so every player takes it; odd sizes are padded by a pixel). Its
// messages go to a log beside the file, quoted when it fails.
class FfmpegSink final : public AnimationWriter::Sink {
 public:
  FfmpegSink(const std::string& path, int width, int height, double fps)
      : path_(path), log_(path + ".log") {
    int fds[2];
    if (::pipe(fds) != 0)
      throw ImageWriteError(path + ": cannot open a pipe to ffmpeg: " + std::strerror(errno));
    // A dead encoder must surface as a write error, not kill the command with SIGPIPE
    // (restored by the destructor, or below if ffmpeg cannot start).
    old_pipe_handler_ = std::signal(SIGPIPE, SIG_IGN);
    char size[32], rate[32];
    std::snprintf(size, sizeof size, "%dx%d", width, height);
    std::snprintf(rate, sizeof rate, "%ld/1000", std::lround(fps * 1000.0));
    // clang-format off
    std::vector<std::string> args = {
        "ffmpeg", "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
        "-f", "rawvideo", "-pixel_format", "rgb24", "-video_size", size, "-framerate", rate,
        "-i", "pipe:0",
        "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", "-movflags", "+faststart",
        path};
    // clang-format on
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    posix_spawn_file_actions_addopen(&actions, 2, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int spawned = posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (spawned != 0) {
      ::close(fds[1]);
      restore();
      throw ImageWriteError(path + ": cannot run ffmpeg: " + std::strerror(spawned));
    }
    pipe_ = fds[1];
  }
  ~FfmpegSink() override {
    if (pipe_ >= 0) ::close(pipe_);
    if (pid_ > 0) ::waitpid(pid_, nullptr, 0);
    std::error_code ignored;
    std::filesystem::remove(log_, ignored);
    restore();
  }
  void write(const std::vector<uint8_t>& rgb) override {
    size_t at = 0;
    while (at < rgb.size()) {
      ssize_t n = ::write(pipe_, rgb.data() + at, rgb.size() - at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) fail("ffmpeg stopped reading frames");
      at += size_t(n);
    }
  }
  void close() override {
    ::close(pipe_);
    pipe_ = -1;
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail("ffmpeg failed");
    std::error_code ignored;
    std::filesystem::remove(log_, ignored);
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    if (pipe_ >= 0) ::close(pipe_);
    pipe_ = -1;
    if (pid_ > 0) ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
    std::ifstream in(log_);
    std::string line, last;
    while (std::getline(in, line)) {
      if (!line.empty()) last = line;
    }
    throw ImageWriteError(path_ + ": " + what + (last.empty() ? "" : ": " + last));
  }
  void restore() {
    if (old_pipe_handler_ != SIG_ERR) std::signal(SIGPIPE, old_pipe_handler_);
    old_pipe_handler_ = SIG_ERR;
  }

  std::string path_, log_;
  pid_t pid_ = -1;
  int pipe_ = -1;
  void (*old_pipe_handler_)(int) = SIG_ERR;
};

}  // namespace

const char* animation_format_name(AnimationFormat format) {
  switch (format) {
    case AnimationFormat::gif:
      return "gif";
    case AnimationFormat::webp:
      return "webp";
    case AnimationFormat::mp4:
      return "mp4";
    case AnimationFormat::none:
      break;
  }
  return "none";
}

bool can_write_animation(AnimationFormat format) {
  switch (format) {
    case AnimationFormat::gif:
      return oiio_writes_movie("gif");
    case AnimationFormat::webp:
      return oiio_writes_movie("webp");
    case AnimationFormat::mp4:
      return ffmpeg_on_path();
    case AnimationFormat::none:
      break;
  }
  return true;
}

AnimationFormat best_animation_format() {
  for (AnimationFormat f : {AnimationFormat::gif, AnimationFormat::webp, AnimationFormat::mp4}) {
    if (can_write_animation(f)) return f;
  }
  return AnimationFormat::none;
}

std::vector<uint8_t> shrink_rgb8(const std::vector<uint8_t>& rgb, int width, int height,
                                 int factor) {
  const int w = width / factor, h = height / factor, area = factor * factor;
  std::vector<uint8_t> out(size_t(w) * size_t(h) * 3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int dy = 0; dy < factor; ++dy) {
          const uint8_t* row =
              rgb.data() + (size_t(y * factor + dy) * size_t(width) + size_t(x * factor)) * 3;
          for (int dx = 0; dx < factor; ++dx) sum += row[dx * 3 + c];
        }
        out[(size_t(y) * size_t(w) + size_t(x)) * 3 + size_t(c)] = uint8_t((sum + area / 2) / area);
      }
    }
  }
  return out;
}

AnimationWriter::AnimationWriter(const std::string& path, AnimationFormat format, int width,
                                 int height, int frame_count, double frames_per_second)
    : path_(path), width_(width), height_(height), frame_count_(frame_count) {
  if (format == AnimationFormat::none || width < 1 || height < 1 || frame_count < 1 ||
      !(frames_per_second > 0.0)) {
    throw ImageWriteError(path + ": an animation needs a format, a size, frames and a frame rate");
  }
  if (format != AnimationFormat::mp4) {
    while (width / factor_ > kMaxPaletteAnimationWidth) ++factor_;
  }
  out_width_ = std::max(width / factor_, 1);
  out_height_ = std::max(height / factor_, 1);
  if (format == AnimationFormat::mp4) {
    sink_ = std::make_unique<FfmpegSink>(path, out_width_, out_height_, frames_per_second);
  } else {
    sink_ =
        std::make_unique<OiioSink>(path, out_width_, out_height_, frame_count, frames_per_second);
  }
}

AnimationWriter::~AnimationWriter() {
  if (finished_) return;
  sink_.reset();
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

void AnimationWriter::add(const std::vector<uint8_t>& rgb) {
  if (added_ >= frame_count_) throw ImageWriteError(path_ + ": more frames than announced");
  if (rgb.size() != size_t(width_) * size_t(height_) * 3) {
    throw ImageWriteError(path_ + ": a frame of another size than the animation's");
  }
  if (factor_ == 1) {
    sink_->write(rgb);
  } else {
    sink_->write(shrink_rgb8(rgb, width_, height_, factor_));
  }
  ++added_;
}

void AnimationWriter::finish() {
  if (added_ != frame_count_) {
    throw ImageWriteError(path_ + ": " + std::to_string(added_) + " of " +
                          std::to_string(frame_count_) + " frames written");
  }
  sink_->close();
  finished_ = true;
}

}  // namespace boreas::render
