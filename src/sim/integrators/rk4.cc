#include "sim/integrators/rk4.h"

#include <algorithm>

#include "sim/forces.h"

namespace hexgait {

Rk4Stepper::Rk4Stepper(const CreatureModel& model) {
  const size_t n = model.num_particles();
  for (std::vector<double>* v :
       {&sx_, &sy_, &sz_, &svx_, &svy_, &svz_, &dx_, &dy_, &dz_, &dvx_, &dvy_, &dvz_}) {
    v->assign(n, 0.0);
  }
  rest_start_.assign(model.num_springs(), 0.0);
  rest_mid_.assign(model.num_springs(), 0.0);
}

void Rk4Stepper::Begin(const CreatureModel&, SimState& s) {
  std::copy(s.rest_length.begin(), s.rest_length.end(), rest_start_.begin());
}

void Rk4Stepper::Step(const CreatureModel& model, SimState& s, double dt) {
  const int n = s.num_particles();
  const int ns = model.num_springs();
  for (int k = 0; k < ns; ++k) rest_mid_[k] = 0.5 * (rest_start_[k] + s.rest_length[k]);
  const double* rest[4] = {rest_start_.data(), rest_mid_.data(), rest_mid_.data(),
                           s.rest_length.data()};
  // Stage j's derivative enters the sum with weight[j]; the next stage is taken at
  // y_k + next[j] * dt * (stage j's derivative).
  static constexpr double kWeight[4] = {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0};
  static constexpr double kNext[4] = {0.5, 0.5, 1.0, 0.0};

  const double* __restrict inv_mass = model.inv_mass.data();
  double* __restrict x = s.x.data();
  double* __restrict y = s.y.data();
  double* __restrict z = s.z.data();
  double* __restrict vx = s.vx.data();
  double* __restrict vy = s.vy.data();
  double* __restrict vz = s.vz.data();
  double* __restrict sx = sx_.data();
  double* __restrict sy = sy_.data();
  double* __restrict sz = sz_.data();
  double* __restrict svx = svx_.data();
  double* __restrict svy = svy_.data();
  double* __restrict svz = svz_.data();
  double* __restrict dx = dx_.data();
  double* __restrict dy = dy_.data();
  double* __restrict dz = dz_.data();
  double* __restrict dvx = dvx_.data();
  double* __restrict dvy = dvy_.data();
  double* __restrict dvz = dvz_.data();
  const double* __restrict fx = s.fx.data();
  const double* __restrict fy = s.fy.data();
  const double* __restrict fz = s.fz.data();
  for (int i = 0; i < n; ++i) {
    sx[i] = x[i];
    sy[i] = y[i];
    sz[i] = z[i];
    svx[i] = vx[i];
    svy[i] = vy[i];
    svz[i] = vz[i];
    dx[i] = dy[i] = dz[i] = dvx[i] = dvy[i] = dvz[i] = 0.0;
  }
  for (int stage = 0; stage < 4; ++stage) {
    ComputeForces(model, rest[stage], ParticleView{sx, sy, sz, svx, svy, svz}, s.force_view());
    const double w = kWeight[stage], c = kNext[stage] * dt;
    for (int i = 0; i < n; ++i) {
      // Stage derivative: (velocity, acceleration) = (sv, f / m).
      const double ax = fx[i] * inv_mass[i], ay = fy[i] * inv_mass[i], az = fz[i] * inv_mass[i];
      dx[i] += w * svx[i];
      dy[i] += w * svy[i];
      dz[i] += w * svz[i];
      dvx[i] += w * ax;
      dvy[i] += w * ay;
      dvz[i] += w * az;
      sx[i] = x[i] + c * svx[i];
      sy[i] = y[i] + c * svy[i];
      sz[i] = z[i] + c * svz[i];
      svx[i] = vx[i] + c * ax;
      svy[i] = vy[i] + c * ay;
      svz[i] = vz[i] + c * az;
    }
  }
  for (int i = 0; i < n; ++i) {
    x[i] += dt * dx[i];
    y[i] += dt * dy[i];
    z[i] += dt * dz[i];
    vx[i] += dt * dvx[i];
    vy[i] += dt * dvy[i];
    vz[i] += dt * dvz[i];
  }
  std::copy(s.rest_length.begin(), s.rest_length.end(), rest_start_.begin());
  ++s.step;
}

}  // namespace hexgait
