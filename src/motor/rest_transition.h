// A leg's transition between rest lengths, written once for every motor controller: the scalar
// MotorController (motor/controller.cc), the batch's (motor/batch_controller.cc), the lanes'
// kernels (sim/batch_kernel_impl.h, compiled once per instruction set) and the schedule of
// continuous time (motor/rest_schedule.cc). A lane gets the scalar controller's bits because
// each of them computes these expressions, in double, and rounds once to the lane's type.
//
// Internal linkage: the kernels' translation units are compiled for different instruction
// sets, and a copy the compiler does not inline must stay in the unit that made it (as
// physics_terms.h's Ops do).
#pragma once

namespace hexgait {

// The fraction of a transition of `steps` steps (> 0) done once `elapsed` of them ran: whole
// numbers held exactly in double, so the quotient is the one correctly rounded value.
static inline double StepFraction(double elapsed, double steps) {
  return elapsed >= steps ? 1.0 : elapsed / steps;
}

// The rest length `fraction` of the way from `from` by `change` (the target less `from`),
// rounded to T once.
template <class T>
static inline T Interpolate(double from, double fraction, double change) {
  return static_cast<T>(from + fraction * change);
}

}  // namespace hexgait
