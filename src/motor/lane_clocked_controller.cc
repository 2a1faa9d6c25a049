#include "motor/lane_clocked_controller.h"

#include <algorithm>

#include "motor/controller.h"
#include "simd/kernel_table.h"

namespace hexgait {
namespace {

// A start so long ago that the fraction is 1: a leg that has not moved (its change is 0).
constexpr double kLongAgo = -1e15;

}  // namespace

LaneClockedController::LaneClockedController(const CreatureModel& model,
                                             const MotorProgram& program, int lanes, double dt)
    : model_(model),
      lanes_(lanes),
      events_(program.expanded),
      cycle_period_(program.cycle_period),
      dt_(dt),
      transition_steps_(StepAtTime(program.transition_time, dt)),
      lane_(static_cast<size_t>(lanes)),
      from_(static_cast<size_t>(model.num_springs()) * lanes, 0.0),
      change_(from_.size(), 0.0),
      start_(model.legs.size() * lanes, kLongAgo),
      fraction_(start_.size(), 1.0) {
  for (size_t leg = 0; leg < model.legs.size(); ++leg) {
    for (int s : model.legs[leg].springs) {
      leg_springs_.push_back(s);
      leg_of_.push_back(static_cast<int>(leg));
    }
  }
}

template <class T>
void LaneClockedController::StartLane(int l, const RestLengthTable& table, long long step,
                                      const T* rest_length) {
  Lane& lane = lane_[static_cast<size_t>(l)];
  lane.active = true;
  lane.offset = step;
  lane.targets = table.length;  // same size every time: no allocation after the first
  lane.cursor.Reset(events_, dt_);
  for (int s : leg_springs_) {
    const size_t e = static_cast<size_t>(s) * lanes_ + l;
    from_[e] = rest_length[e];
    change_[e] = 0;
  }
  for (size_t leg = 0; leg < model_.legs.size(); ++leg) start_[leg * lanes_ + l] = kLongAgo;
}

// As MotorController::Start, for lane `l` at the batch's step `step`.
template <class T>
void LaneClockedController::Start(int l, long long step, T* rest_length) {
  Lane& lane = lane_[static_cast<size_t>(l)];
  const int ns = model_.num_springs();
  const Instruction& in = events_[lane.cursor.next_event];
  const double* target = lane.targets.data() + static_cast<size_t>(in.position) * ns;
  for (int s : model_.legs[in.leg].springs) {
    const size_t e = static_cast<size_t>(s) * lanes_ + l;
    T& out = rest_length[e];
    const double to = target[s];
    from_[e] = out;
    change_[e] = to - from_[e];  // as MotorController::Move's (to - from)
    if (transition_steps_ == 0) {
      out = static_cast<T>(to);
      from_[e] = to, change_[e] = 0;
    }
  }
  if (transition_steps_ > 0) {
    start_[static_cast<size_t>(in.leg) * lanes_ + l] = static_cast<double>(step);
    moving_until_ = std::max(moving_until_, step + transition_steps_);
  }
  lane.cursor.Advance(events_, cycle_period_, dt_);
}

// MotorController::Move's values for every leg spring of every lane, as vectors over the lanes.
template <class T>
void LaneClockedController::Move(long long step, T* rest_length) {
  const LegMoveArgs args = {.start = start_.data(),
                            .step = static_cast<double>(step),
                            .steps = static_cast<double>(transition_steps_),
                            .fraction = fraction_.data(),
                            .legs = static_cast<int>(model_.legs.size()),
                            .from = from_.data(),
                            .change = change_.data(),
                            .springs = leg_springs_.data(),
                            .leg_of = leg_of_.data(),
                            .count = static_cast<int>(leg_springs_.size()),
                            .lanes = lanes_};
  if constexpr (sizeof(T) == sizeof(float)) {
    kernels_.move_legs_float(args, rest_length);
  } else {
    kernels_.move_legs(args, rest_length);
  }
}

template void LaneClockedController::StartLane<double>(int, const RestLengthTable&, long long,
                                                       const double*);
template void LaneClockedController::StartLane<float>(int, const RestLengthTable&, long long,
                                                      const float*);
template void LaneClockedController::Start<double>(int, long long, double*);
template void LaneClockedController::Move<double>(long long, double*);
template void LaneClockedController::Start<float>(int, long long, float*);
template void LaneClockedController::Move<float>(long long, float*);

}  // namespace hexgait
