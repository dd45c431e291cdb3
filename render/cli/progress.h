// boreas command: progress of a run on stderr. On a terminal, one line redrawn in place;
// elsewhere (CI logs, pipes) at most kLogLines plain lines, so logs stay short.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace boreas::render {

class Progress {
 public:
  static constexpr int kLogLines = 10;

  // total: the number of units (frames, steps: unit names one; "%" shows done / total as
  // a percentage); enabled false prints nothing at all.
  Progress(int total, bool enabled, std::FILE* stream = stderr, std::string unit = "frame");
  // Ends a bar left unfinished (a run that failed), so the error starts on its own line.
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // done units so far.
  void update(int done);
  // Ends the bar with a final line.
  void finish(const std::string& message);

 private:
  void draw_bar(int done);

  int total_;
  std::string unit_;
  bool enabled_;
  bool terminal_;
  std::FILE* stream_;
  int last_bucket_ = -1;
  bool bar_open_ = false;  // a bar is drawn and its line not yet ended
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace boreas::render
