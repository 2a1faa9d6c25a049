#include "util/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace hexgait {

bool ProgressBar::Enabled() {
  static const bool enabled = ::isatty(STDERR_FILENO) != 0;
  return enabled;
}

ProgressBar::ProgressBar(std::string label) : label_(std::move(label)) {}

void ProgressBar::Show(std::string_view stage, long long done, long long total,
                       const std::string& detail) {
  if (!Enabled()) return;
  const double fraction = std::clamp(
      total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0.0, 0.0, 1.0);
  const auto now = Clock::now();
  const bool same_stage = stage == stage_;
  if (drawn_ && same_stage && fraction < 1.0 && now - last_draw_ < std::chrono::milliseconds(100)) {
    return;
  }
  if (!same_stage) stage_ = stage;
  last_draw_ = now;
  const char* const comma = detail.empty() ? "" : ", ";
  if (total <= 0) {  // not known in advance: the count alone
    std::fprintf(stderr, "\r%s %lld %s%s%s\033[K", label_.c_str(), done, stage_.c_str(), comma,
                 detail.c_str());
  } else {
    constexpr int kWidth = 30;
    std::string bar(static_cast<size_t>(fraction * kWidth), '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r%s [%s] %3.0f%% %lld/%lld %s%s%s\033[K", label_.c_str(), bar.c_str(),
                 100.0 * fraction, done, total, stage_.c_str(), comma, detail.c_str());
  }
  std::fflush(stderr);
  drawn_ = true;
}

Progress ProgressBar::Hook() {
  return
      [this](std::string_view stage, long long done, long long total) { Show(stage, done, total); };
}

void ProgressBar::Clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace hexgait
