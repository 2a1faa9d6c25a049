#include "motor/batch_controller.h"

#include "motor/rest_transition.h"

namespace hexgait {

BatchMotorController::BatchMotorController(const CreatureModel& model, const MotorProgram& program,
                                           std::vector<RestLengthTable> tables, double dt,
                                           int lane_pitch)
    : model_(model),
      lanes_(static_cast<int>(tables.size())),
      events_(program.expanded),
      cycle_period_(program.cycle_period),
      dt_(dt),
      transition_steps_(StepAtTime(program.transition_time, dt)),
      from_(static_cast<size_t>(lane_pitch > 0 ? lane_pitch : model.num_springs()) * lanes_, 0.0),
      change_(from_.size(), 0.0),
      creature_major_(lane_pitch > 0),
      lane_pitch_(lane_pitch),
      start_(creature_major_ ? lane_pitch : 0, 0.0),
      fraction_(start_.size(), 0.0),
      transition_(model.legs.size()) {
  const size_t cells = tables.front().length.size();
  targets_.resize(cells * lanes_);
  for (int lane = 0; lane < lanes_; ++lane) {
    for (size_t j = 0; j < cells; ++j) targets_[j * lanes_ + lane] = tables[lane].length[j];
  }
  for (const Leg& leg : model.legs) {
    std::vector<std::pair<int, int>>& runs = spring_runs_.emplace_back();
    for (int s : leg.springs) {
      if (!runs.empty() && runs.back().first + runs.back().second == s) {
        ++runs.back().second;
      } else {
        runs.emplace_back(s, 1);
      }
    }
  }
  cursor_.Reset(events_, dt_);
}

// As MotorController::Start, for every lane.
template <class T>
void BatchMotorController::Start(long long step, T* rest_length) {
  const int w = lanes_;
  const int ns = model_.num_springs();
  if (creature_major_ && !primed_) {
    // Move recomputes every spring from (from, change, fraction): start each at its value
    // (padding too, which stays 0).
    for (int s = 0; s < lane_pitch_; ++s) {
      for (int l = 0; l < w; ++l) from_[Cell(s, l)] = rest_length[Out(s, l)];
    }
    primed_ = true;
  }
  const Instruction& in = events_[cursor_.next_event];
  Transition& t = transition_[in.leg];
  const double* target = targets_.data() + static_cast<size_t>(in.position) * ns * w;
  for (int s : model_.legs[in.leg].springs) {
    if (creature_major_) start_[s] = static_cast<double>(step);
    for (int l = 0; l < w; ++l) {
      const size_t e = Cell(s, l);
      const double to = target[static_cast<size_t>(s) * w + l];
      T& out = rest_length[Out(s, l)];
      from_[e] = out;
      change_[e] = to - from_[e];  // as MotorController::Move's (to - from)
      if (transition_steps_ == 0) {
        out = static_cast<T>(to);
        from_[e] = to, change_[e] = 0;  // what Move recomputes stays `to`
      }
    }
  }
  if (transition_steps_ > 0) {
    if (!t.moving) ++num_moving_;
    t.moving = true;
    t.start = step;
  }
  cursor_.Advance(events_, cycle_period_, dt_);
}

// As MotorController::Move: the fraction f is shared, the interpolation is per lane.
template <class T>
void BatchMotorController::Move(long long step, T* rest_length) {
  const int w = lanes_;
  LaneInterpolateFnT<T> interpolate;
  SpanInterpolateFnT<T> interpolate_span;
  if constexpr (sizeof(T) == sizeof(float)) {
    interpolate = kernels_.interpolate_float;
    interpolate_span = kernels_.interpolate_span_float;
  } else {
    interpolate = kernels_.interpolate;
    interpolate_span = kernels_.interpolate_span;
  }
  const double* __restrict from = from_.data();
  const double* __restrict change = change_.data();
  for (size_t leg = 0; leg < transition_.size(); ++leg) {
    Transition& t = transition_[leg];
    if (!t.moving) continue;
    const long long elapsed = step - t.start + 1;
    const bool done = elapsed >= transition_steps_;
    if (!creature_major_) {
      const double f =
          StepFraction(static_cast<double>(elapsed), static_cast<double>(transition_steps_));
      for (const auto& [first, count] : spring_runs_[leg]) {
        const size_t e = static_cast<size_t>(first) * w;
        const int n = count * w;
        if (n < 8) {  // too few values for a vector call to pay
          for (int v = 0; v < n; ++v) {
            rest_length[e + v] = Interpolate<T>(from[e + v], f, change[e + v]);
          }
        } else {
          interpolate(from + e, change + e, f, rest_length + e, n);
        }
      }
    }
    if (done) {
      t.moving = false;
      --num_moving_;
    }
  }
  if (creature_major_) {
    // Every spring of every creature, padding included, as whole vectors (the kernel then
    // loads whole stores). A spring not in transition gets the value it already has: its
    // change is 0, or its fraction has stayed 1 since it finished.
    kernels_.transition_fractions(start_.data(), static_cast<double>(step),
                                  static_cast<double>(transition_steps_), fraction_.data(),
                                  lane_pitch_);
    for (int l = 0; l < w; ++l) {
      interpolate_span(from + Cell(0, l), change + Cell(0, l), fraction_.data(),
                       rest_length + Out(0, l), lane_pitch_);
    }
  }
}

template void BatchMotorController::Start<double>(long long, double*);
template void BatchMotorController::Move<double>(long long, double*);
template void BatchMotorController::Start<float>(long long, float*);
template void BatchMotorController::Move<float>(long long, float*);

}  // namespace hexgait
