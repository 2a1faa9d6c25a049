// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <string>
#include <string_view>

#include "util/clock.h"
#include "util/progress.h"

namespace hexgait {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar() { Clear(); }
  // Draws `done` of `total` STAGE ("123/456 frames"), then `detail` if any. A new stage starts
  // a fresh line of the bar.
  void Show(std::string_view stage, long long done, long long total,
            const std::string& detail = "");
  // The hook a library takes (util/progress.h): each call shows.
  Progress Hook();
  void Clear();  // erases the bar so ordinary output can follow
  static bool Enabled();

 private:
  std::string label_;
  std::string stage_;
  bool drawn_ = false;
  Clock::time_point last_draw_{};
};

}  // namespace hexgait
