#include "sim/reference.h"

#include <algorithm>
#include <boost/numeric/odeint.hpp>

#include "sim/forces.h"

namespace hexgait {
namespace {

namespace odeint = boost::numeric::odeint;
using OdeState = std::vector<double>;

// dy/dt = (v, f(x, v, L(t)) / m).
struct CreatureOde {
  const CreatureModel& model;
  const RestLengthSchedule* schedule;  // null: `rest` stays as it is
  std::vector<double>& rest;
  std::vector<double>& force;  // fx, fy, fz, then per-spring scratch (3 * springs)

  void operator()(const OdeState& y, OdeState& dydt, double t) const {
    const int n = model.num_particles();
    const int ns = model.num_springs();
    if (schedule) schedule->At(t, rest.data());
    const double* p = y.data();
    ComputeForces(
        model, rest.data(), ParticleView{p, p + n, p + 2 * n, p + 3 * n, p + 4 * n, p + 5 * n},
        ForceView{force.data(), force.data() + n, force.data() + 2 * n, force.data() + 3 * n,
                  force.data() + 3 * n + ns, force.data() + 3 * n + 2 * ns});
    std::copy(y.begin() + 3 * n, y.end(), dydt.begin());
    for (int c = 0; c < 3; ++c) {
      for (int i = 0; i < n; ++i) dydt[3 * n + c * n + i] = force[c * n + i] * model.inv_mass[i];
    }
  }
};

}  // namespace

ReferenceSolver::ReferenceSolver(const CreatureModel& model, const RestLengthSchedule* schedule,
                                 const SimState& initial, double tolerance)
    : model_(model),
      schedule_(schedule),
      fixed_rest_(initial.rest_length),
      tolerance_(tolerance),
      state_(initial) {
  const int n = model.num_particles();
  y_.resize(6 * n);
  const std::vector<double>* parts[6] = {&initial.x,  &initial.y,  &initial.z,
                                         &initial.vx, &initial.vy, &initial.vz};
  for (int c = 0; c < 6; ++c) std::copy(parts[c]->begin(), parts[c]->end(), y_.begin() + c * n);
  time_ = initial.time;
}

void ReferenceSolver::AdvanceTo(double t) {
  std::vector<double> rest(fixed_rest_);
  std::vector<double> force(3 * model_.num_particles() + 3 * model_.num_springs());
  CreatureOde ode{model_, schedule_, rest, force};
  auto stepper =
      odeint::make_controlled(tolerance_, tolerance_, odeint::runge_kutta_dopri5<OdeState>());
  // Piece by piece between the rest lengths' kinks.
  static const std::vector<double> kNoKinks;
  const std::vector<double>& kinks = schedule_ ? schedule_->breakpoints() : kNoKinks;
  auto next = std::upper_bound(kinks.begin(), kinks.end(), time_);
  while (time_ < t) {
    const double end = (next != kinks.end() && *next < t) ? *next++ : t;
    steps_ += static_cast<long long>(odeint::integrate_adaptive(
        stepper, ode, y_, time_, end, std::min(step_guess_, end - time_)));
    time_ = end;
  }
  Sync();
}

void ReferenceSolver::Sync() {
  const int n = model_.num_particles();
  std::vector<double>* parts[6] = {&state_.x,  &state_.y,  &state_.z,
                                   &state_.vx, &state_.vy, &state_.vz};
  for (int c = 0; c < 6; ++c)
    std::copy(y_.begin() + c * n, y_.begin() + (c + 1) * n, parts[c]->begin());
  if (schedule_) schedule_->At(time_, state_.rest_length.data());
  state_.time = time_;
}

}  // namespace hexgait
