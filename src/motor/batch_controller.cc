#include "motor/batch_controller.h"

namespace hexgait {

BatchMotorController::BatchMotorController(const CreatureModel& model, const MotorProgram& program,
                                           std::vector<RestLengthTable> tables, double dt)
    : model_(model),
      lanes_(static_cast<int>(tables.size())),
      events_(program.expanded),
      cycle_period_(program.cycle_period),
      dt_(dt),
      transition_steps_(StepAtTime(program.transition_time, dt)),
      from_(static_cast<size_t>(model.num_springs()) * lanes_, 0.0),
      to_(from_.size(), 0.0),
      transition_(model.legs.size()) {
  const size_t cells = tables.front().length.size();
  targets_.resize(cells * lanes_);
  for (int lane = 0; lane < lanes_; ++lane) {
    for (size_t j = 0; j < cells; ++j) targets_[j * lanes_ + lane] = tables[lane].length[j];
  }
  next_step_ = StepAtTime(events_.front().time, dt_);
}

// As MotorController::Start, for every lane.
template <class T>
void BatchMotorController::Start(long long step, T* rest_length) {
  const Instruction& in = events_[next_event_];
  Transition& t = transition_[in.leg];
  const int w = lanes_;
  const double* target =
      targets_.data() + static_cast<size_t>(in.position) * model_.num_springs() * w;
  for (int s : model_.legs[in.leg].springs) {
    for (int l = 0; l < w; ++l) {
      const size_t e = static_cast<size_t>(s) * w + l;
      from_[e] = rest_length[e];
      to_[e] = target[e];
      if (transition_steps_ == 0) rest_length[e] = static_cast<T>(to_[e]);
    }
  }
  if (transition_steps_ > 0) {
    if (!t.moving) ++num_moving_;
    t.moving = true;
    t.start = step;
  }
  if (++next_event_ == events_.size()) {
    next_event_ = 0;
    ++cycle_;
  }
  next_step_ =
      StepAtTime(static_cast<double>(cycle_) * cycle_period_ + events_[next_event_].time, dt_);
}

// As MotorController::Move: the fraction f is shared, the interpolation is per lane.
template <class T>
void BatchMotorController::Move(long long step, T* rest_length) {
  const int w = lanes_;
  LaneInterpolateFnT<T> interpolate;
  if constexpr (sizeof(T) == sizeof(float)) {
    interpolate = interpolate_float_;
  } else {
    interpolate = interpolate_;
  }
  for (size_t leg = 0; leg < transition_.size(); ++leg) {
    Transition& t = transition_[leg];
    if (!t.moving) continue;
    const long long elapsed = step - t.start + 1;
    const bool done = elapsed >= transition_steps_;
    const double f = done ? 1.0 : static_cast<double>(elapsed) / transition_steps_;
    for (int s : model_.legs[leg].springs) {
      const size_t e = static_cast<size_t>(s) * w;
      interpolate(from_.data() + e, to_.data() + e, f, rest_length + e, w);
    }
    if (done) {
      t.moving = false;
      --num_moving_;
    }
  }
}

template void BatchMotorController::Start<double>(long long, double*);
template void BatchMotorController::Move<double>(long long, double*);
template void BatchMotorController::Start<float>(long long, float*);
template void BatchMotorController::Move<float>(long long, float*);

}  // namespace hexgait
