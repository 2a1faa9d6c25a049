// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <string>

#include "util/clock.h"

namespace hexgait {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar() { Clear(); }
  void Update(double fraction, const std::string& detail = "");
  // Shows `done` of `total` UNIT ("123/456 frames"): what a command draws from a library's
  // (done, total) hook, such as a movie's frame progress.
  void Count(long long done, long long total, const std::string& unit);
  void Clear();  // erases the bar so ordinary output can follow
  static bool Enabled();

 private:
  std::string label_;
  bool drawn_ = false;
  Clock::time_point last_draw_{};
};

}  // namespace hexgait
