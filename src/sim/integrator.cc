#include "sim/integrator.h"

#include "sim/forces.h"
#include "sim/integrators/axis_loops.h"
#include "sim/scalar_ops.h"
#include "util/error.h"

namespace hexgait {

std::vector<IntegratorKind> AllIntegrators() {
  return {IntegratorKind::kEuler, IntegratorKind::kSymplecticEuler, IntegratorKind::kVerlet,
          IntegratorKind::kRk4, IntegratorKind::kImplicitEuler};
}

std::vector<std::string> IntegratorNames() {
  std::vector<std::string> names;
  for (IntegratorKind kind : AllIntegrators()) names.push_back(IntegratorName(kind));
  return names;
}

std::string IntegratorName(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::kEuler:
      return "euler";
    case IntegratorKind::kSymplecticEuler:
      return "symplectic-euler";
    case IntegratorKind::kVerlet:
      return "verlet";
    case IntegratorKind::kRk4:
      return "rk4";
    case IntegratorKind::kImplicitEuler:
      return "implicit-euler";
  }
  return "?";
}

int ForceEvaluationsPerStep(IntegratorKind kind) {
  return kind == IntegratorKind::kRk4 ? 4 : 1;
}

IntegratorKind ParseIntegrator(const std::string& name) {
  for (IntegratorKind kind : AllIntegrators()) {
    if (IntegratorName(kind) == name) return kind;
  }
  std::string list;
  for (const std::string& n : IntegratorNames()) list += (list.empty() ? "" : ", ") + n;
  throw InputError("unknown integrator '" + name + "' (expected one of: " + list + ")");
}

void EulerStepper::Step(const CreatureModel& model, SimState& s, double dt) {
  ComputeForces(model, s.rest_length.data(), s.particle_view(), s.force_view());
  const int n = s.num_particles();
  const double* __restrict inv_mass = model.inv_mass.data();
  for (const Axis& axis : Axes(s)) {
    double* __restrict x = axis.position;
    double* __restrict v = axis.velocity;
    const double* __restrict f = axis.force;
    for (int i = 0; i < n; ++i) ScalarPhysics::EulerAxis(dt, dt * inv_mass[i], f[i], x[i], v[i]);
  }
  ++s.step;
}

}  // namespace hexgait
