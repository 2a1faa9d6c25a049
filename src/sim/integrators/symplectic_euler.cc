#include "sim/integrators/symplectic_euler.h"

#include "sim/forces.h"
#include "sim/integrators/axis_loops.h"

namespace hexgait {

void SymplecticEulerStepper::Step(const CreatureModel& model, SimState& s, double dt) {
  ComputeForces(model, s.rest_length.data(), s.particle_view(), s.force_view());
  const int n = s.num_particles();
  for (const Axis& axis : Axes(s)) {
    KickByForce(n, dt, model.inv_mass.data(), axis.force, axis.velocity);
    AddScaled(n, dt, axis.velocity, axis.position);
  }
  ++s.step;
}

}  // namespace hexgait
