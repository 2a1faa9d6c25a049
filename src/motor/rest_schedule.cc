#include "motor/rest_schedule.h"

#include <algorithm>
#include <cmath>

#include "motor/rest_transition.h"

namespace hexgait {
namespace {

// Fraction of a transition done `elapsed` time units after it started.
double TransitionFraction(double elapsed, double transition_time) {
  if (transition_time <= 0) return 1.0;
  return std::clamp(elapsed / transition_time, 0.0, 1.0);
}

}  // namespace

RestLengthSchedule::RestLengthSchedule(const CreatureModel& model, const MotorProgram& program,
                                       const RestLengthTable& table, std::vector<double> initial,
                                       double duration)
    : model_(model),
      transition_time_(program.transition_time),
      initial_(std::move(initial)),
      segments_(model.legs.size()) {
  // Replays the controller's event order: each instruction starts from the leg's rest lengths
  // at that moment (which may be mid-way through an earlier transition).
  std::vector<double> now(initial_);
  for (long long cycle = 0;; ++cycle) {
    const double base = static_cast<double>(cycle) * program.cycle_period;
    if (base > duration) break;
    for (const Instruction& in : program.expanded) {
      const double t = base + in.time;
      if (t > duration) break;
      const std::vector<int>& springs = model.legs[in.leg].springs;
      Segment seg;
      seg.start = t;
      std::vector<Segment>& leg_segments = segments_[in.leg];
      for (size_t j = 0; j < springs.size(); ++j) {
        double value = initial_[springs[j]];
        if (!leg_segments.empty()) {
          const Segment& last = leg_segments.back();
          const double f = TransitionFraction(t - last.start, transition_time_);
          value = Interpolate<double>(last.from[j], f, last.to[j] - last.from[j]);
        }
        seg.from.push_back(value);
        seg.to.push_back(table.at(in.position, springs[j]));
      }
      leg_segments.push_back(std::move(seg));
      if (t > 0) breakpoints_.push_back(t);
      if (t + transition_time_ < duration) breakpoints_.push_back(t + transition_time_);
    }
  }
  std::sort(breakpoints_.begin(), breakpoints_.end());
  breakpoints_.erase(std::unique(breakpoints_.begin(), breakpoints_.end()), breakpoints_.end());
}

void RestLengthSchedule::At(double t, double* rest_length) const {
  std::copy(initial_.begin(), initial_.end(), rest_length);
  for (size_t leg = 0; leg < segments_.size(); ++leg) {
    const std::vector<Segment>& segs = segments_[leg];
    // Last segment that has started at or before t.
    auto it = std::upper_bound(segs.begin(), segs.end(), t,
                               [](double time, const Segment& s) { return time < s.start; });
    if (it == segs.begin()) continue;
    const Segment& s = *(it - 1);
    const double f = TransitionFraction(t - s.start, transition_time_);
    const std::vector<int>& springs = model_.legs[leg].springs;
    for (size_t j = 0; j < springs.size(); ++j) {
      rest_length[springs[j]] = Interpolate<double>(s.from[j], f, s.to[j] - s.from[j]);
    }
  }
}

}  // namespace hexgait
