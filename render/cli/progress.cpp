// boreas command: the progress bar.
#include "cli/progress.h"

#include <unistd.h>

#include <cstdint>
#include <utility>

namespace boreas::render {

namespace {

constexpr int kBarWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);

}  // namespace

Progress::Progress(int total, bool enabled, std::FILE* stream, std::string unit)
    : total_(total > 0 ? total : 1),
      unit_(std::move(unit)),
      enabled_(enabled),
      terminal_(isatty(fileno(stream)) != 0),
      stream_(stream),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_ - kRedrawInterval) {}

Progress::~Progress() {
  if (bar_open_) std::fputc('\n', stream_);
}

void Progress::draw_bar(int done) {
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  int filled = done * kBarWidth / total_;
  std::string bar(size_t(filled), '#');
  bar.append(size_t(kBarWidth - filled), '-');
  if (unit_ == "%")
    std::fprintf(stream_, "\r[%s] %3d%%  %.1f s", bar.c_str(), int(int64_t(done) * 100 / total_), seconds);
  else
    std::fprintf(stream_, "\r[%s] %d/%d %ss  %.1f s", bar.c_str(), done, total_, unit_.c_str(), seconds);
  std::fflush(stream_);
  bar_open_ = true;
}

void Progress::update(int done) {
  if (!enabled_) return;
  if (terminal_) {
    auto now = std::chrono::steady_clock::now();
    if (now - last_draw_ < kRedrawInterval && done < total_) return;
    last_draw_ = now;
    draw_bar(done);
    return;
  }
  // One line each time another 1/kLogLines of the run is done.
  int bucket = done * kLogLines / total_;
  if (bucket == last_bucket_ || done == total_) return;  // the last one is finish()'s line
  last_bucket_ = bucket;
  if (bucket == 0) return;
  if (unit_ == "%")
    std::fprintf(stream_, "boreas: %d%%\n", int(int64_t(done) * 100 / total_));
  else
    std::fprintf(stream_, "boreas: %s %d/%d (%d%%)\n", unit_.c_str(), done, total_,
                 int(int64_t(done) * 100 / total_));
  std::fflush(stream_);
}

void Progress::finish(const std::string& message) {
  if (!enabled_) return;
  if (terminal_) {
    draw_bar(total_);
    std::fputc('\n', stream_);
    bar_open_ = false;
  }
  std::fprintf(stream_, "boreas: %s\n", message.c_str());
  std::fflush(stream_);
}

}  // namespace boreas::render
