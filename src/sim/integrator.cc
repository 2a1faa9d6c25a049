#include "sim/integrator.h"

#include "sim/forces.h"
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
  double* __restrict x = s.x.data();
  double* __restrict y = s.y.data();
  double* __restrict z = s.z.data();
  double* __restrict vx = s.vx.data();
  double* __restrict vy = s.vy.data();
  double* __restrict vz = s.vz.data();
  const double* __restrict fx = s.fx.data();
  const double* __restrict fy = s.fy.data();
  const double* __restrict fz = s.fz.data();
  for (int i = 0; i < n; ++i) {
    ScalarPhysics::Euler(dt, dt * inv_mass[i], fx[i], fy[i], fz[i], x[i], y[i], z[i], vx[i], vy[i],
                         vz[i]);
  }
  ++s.step;
}

}  // namespace hexgait
