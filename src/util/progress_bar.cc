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

void ProgressBar::Update(double fraction, const std::string& detail) {
  if (!Enabled()) return;
  const auto now = Clock::now();
  if (drawn_ && fraction < 1.0 && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kWidth);
  std::string bar(filled, '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r%s [%s] %3.0f%% %s\033[K", label_.c_str(), bar.c_str(),
               100.0 * std::clamp(fraction, 0.0, 1.0), detail.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::Count(long long done, long long total, const std::string& unit) {
  Update(total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0,
         std::to_string(done) + "/" + std::to_string(total) + " " + unit);
}

void ProgressBar::Clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace hexgait
