#include "motor/controller.h"

#include "motor/rest_transition.h"

namespace hexgait {

long long StepAtTime(double time, double dt) {
  return static_cast<long long>(std::ceil(time / dt - 1e-9));
}

MotorController::MotorController(const CreatureModel& model, const MotorProgram& program,
                                 RestLengthTable table, double dt)
    : model_(model),
      table_(std::move(table)),
      events_(program.expanded),
      cycle_period_(program.cycle_period),
      dt_(dt),
      transition_steps_(StepAtTime(program.transition_time, dt)),
      from_(model.num_springs(), 0.0),
      to_(model.num_springs(), 0.0),
      transition_(model.legs.size()) {
  cursor_.Reset(events_, dt_);
}

void MotorController::Start(long long step, double* rest_length) {
  const Instruction& in = events_[cursor_.next_event];
  Transition& t = transition_[in.leg];
  for (int s : model_.legs[in.leg].springs) {
    from_[s] = rest_length[s];
    to_[s] = table_.at(in.position, s);
    if (transition_steps_ == 0) rest_length[s] = to_[s];
  }
  if (transition_steps_ > 0) {
    if (!t.moving) ++num_moving_;
    t.moving = true;
    t.start = step;
  }
  cursor_.Advance(events_, cycle_period_, dt_);
}

void MotorController::Move(long long step, double* rest_length) {
  for (size_t leg = 0; leg < transition_.size(); ++leg) {
    Transition& t = transition_[leg];
    if (!t.moving) continue;
    const long long elapsed = step - t.start + 1;
    const bool done = elapsed >= transition_steps_;
    const double f =
        StepFraction(static_cast<double>(elapsed), static_cast<double>(transition_steps_));
    for (int s : model_.legs[leg].springs) {
      rest_length[s] = Interpolate<double>(from_[s], f, to_[s] - from_[s]);
    }
    if (done) {
      t.moving = false;
      --num_moving_;
    }
  }
}

}  // namespace hexgait
